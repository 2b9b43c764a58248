// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Counting the distinct faces a repair touched, for the statistics (up to two per flip:
// 870,000 addresses at 1e6 points moved by 0.1 spacing). The addresses are marked in a bitmap
// with one bit per object-sized slot from the lowest address: faces live in a few large
// blocks, so the bitmap is about a bit per face of the triangulation (250 KB at 1e6 points)
// and stays in cache, where sorting took 22 ms (radix) to 60 ms (std::sort). Addresses spread
// too far apart for a bitmap (objects not in one container) are sorted instead: a
// least-significant-digit radix sort on the offsets from the lowest address.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_SORT_ADDRESSES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_SORT_ADDRESSES_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/code_size.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/function_ref.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Sorts `addresses` by address (as integers: a total order): every sort of addresses in the
// package, one std::sort compiled (code_size.h).
CGAL_DFP_OUT_OF_LINE inline void sort_by_address(std::vector<const void*>& addresses)
{
  std::sort(addresses.begin(), addresses.end(), [](const void* a, const void* b) {
    return reinterpret_cast<std::uintptr_t>(a) < reinterpret_cast<std::uintptr_t>(b);
  });
}

// Whether `p` is among `sorted`, sorted by sort_by_address().
CGAL_DFP_OUT_OF_LINE inline bool contains_address(const std::vector<const void*>& sorted, const void* p)
{
  return std::binary_search(sorted.begin(), sorted.end(), p, [](const void* a, const void* b) {
    return reinterpret_cast<std::uintptr_t>(a) < reinterpret_cast<std::uintptr_t>(b);
  });
}

// Sorts `addresses` by address and removes repeats.
inline void sort_unique_addresses(std::vector<const void*>& addresses)
{
  const std::size_t n = addresses.size();
  auto value = [](const void* p) { return std::uint64_t(reinterpret_cast<std::uintptr_t>(p)); };
  if(n < 4096) {
    sort_by_address(addresses);
  } else {
    // Objects of the containers sorted here are at least 8-byte aligned: the 3 low bits of
    // an offset are 0 and are skipped; addresses that differ there still sort right, by the
    // comparison fallback below (never taken for CGAL's faces).
    const std::uint64_t first = value(addresses[0]);
    std::uint64_t low = first, high = first, low_bits_differ = 0;
    for(const void* p : addresses) {
      low = std::min(low, value(p));
      high = std::max(high, value(p));
      low_bits_differ |= (value(p) ^ first) & 7;
    }
    const bool aligned = low_bits_differ == 0;
    const std::uint64_t span = (high - low) >> 3;
    int bits = 0;
    while(bits < 64 && (span >> bits) != 0)
      ++bits;
    if(!aligned || bits > 48) {
      sort_by_address(addresses);
    } else {
      const int passes = std::max(1, (bits + 11) / 12);
      const int digit_bits = (bits + passes - 1) / passes;
      const std::size_t buckets = std::size_t(1) << digit_bits;
      std::vector<const void*> other(n);
      std::vector<std::size_t> start(buckets + 1);
      for(int pass = 0; pass < passes; ++pass) {
        const int shift = 3 + pass * digit_bits;
        auto digit = [&](const void* p) { return std::size_t(((value(p) - low) >> shift) & (buckets - 1)); };
        std::fill(start.begin(), start.end(), 0);
        for(const void* p : addresses)
          ++start[digit(p) + 1];
        for(std::size_t b = 1; b <= buckets; ++b)
          start[b] += start[b - 1];
        for(const void* p : addresses)
          other[start[digit(p)]++] = p;
        addresses.swap(other);
      }
    }
  }
  addresses.erase(std::unique(addresses.begin(), addresses.end()), addresses.end());
}

// A set of addresses of objects of type `Object` whose storage no other shares (slots of one
// CGAL container, used or freed since): a bitmap of the object-sized slots from `low` to
// `high`. Distinct objects differ by at least sizeof(Object), so they never share a bit.
template <class Object>
class Slot_bitmap
{
public:
  static std::uint64_t value(const void* p) { return std::uint64_t(reinterpret_cast<std::uintptr_t>(p)); }

  // Whether a bitmap for `count` addresses between `low` and `high` takes at most 4 bytes an
  // address (objects spread over memory, not in one container, would need far more).
  static bool fits(std::uint64_t low, std::uint64_t high, std::size_t count)
  {
    return low <= high && (high - low) / sizeof(Object) + 1 <= 32 * std::uint64_t(count) + (std::uint64_t(1) << 16);
  }

  Slot_bitmap(std::uint64_t low, std::uint64_t high)
      : low_(low), high_(high), bits_(std::size_t(((high - low) / sizeof(Object) + 1 + 63) / 64), 0)
  {}

  // Adds p, between low and high; returns whether it was absent.
  bool insert(const void* p)
  {
    const std::uint64_t s = (value(p) - low_) / sizeof(Object);
    std::uint64_t& word = bits_[std::size_t(s >> 6)];
    const std::uint64_t bit = std::uint64_t(1) << (s & 63);
    const bool fresh = (word & bit) == 0;
    word |= bit;
    return fresh;
  }

  bool contains(const void* p) const
  {
    const std::uint64_t v = value(p);
    if(v < low_ || v > high_)
      return false;
    const std::uint64_t s = (v - low_) / sizeof(Object);
    return ((bits_[std::size_t(s >> 6)] >> (s & 63)) & 1) != 0;
  }

private:
  std::uint64_t low_, high_;
  std::vector<std::uint64_t> bits_;
};

// The number of distinct addresses among `listed` and those of the objects behind
// `handles[first..]` for which `keep(address)` holds (asked once per distinct address that is
// not in `listed`). Every address is that of an object of type `Object` as in Slot_bitmap.
// (`keep` is a Function_ref: each call site's lambda would otherwise compile all of this again.)
template <class Object, class Handle>
std::size_t count_distinct_addresses(const std::vector<const void*>& listed, const std::vector<Handle>& handles,
                                     std::size_t first, Function_ref<bool(const void*)> keep)
{
  using Bitmap = Slot_bitmap<Object>;
  first = (std::min)(first, handles.size());
  const std::size_t count = listed.size() + (handles.size() - first);
  if(count == 0)
    return 0;
  std::uint64_t low = ~std::uint64_t(0), high = 0;
  for(const void* p : listed) {
    low = (std::min)(low, Bitmap::value(p));
    high = (std::max)(high, Bitmap::value(p));
  }
  for(std::size_t k = first; k < handles.size(); ++k) {
    const std::uint64_t p = Bitmap::value(&*handles[k]);
    low = (std::min)(low, p);
    high = (std::max)(high, p);
  }
  if(Bitmap::fits(low, high, count)) {
    Bitmap seen(low, high);
    std::size_t distinct = 0;
    for(const void* p : listed)
      distinct += seen.insert(p) ? 1 : 0;
    for(std::size_t k = first; k < handles.size(); ++k) {
      const void* p = &*handles[k];
      if(seen.insert(p) && keep(p))
        ++distinct;
    }
    return distinct;
  }
  std::vector<const void*> sorted(listed);
  sort_unique_addresses(sorted);
  std::vector<const void*> more;
  more.reserve(handles.size() - first);
  for(std::size_t k = first; k < handles.size(); ++k)
    more.push_back(&*handles[k]);
  sort_unique_addresses(more);
  std::size_t distinct = sorted.size();
  for(const void* p : more)
    if(!std::binary_search(sorted.begin(), sorted.end(), p,
                           [](const void* x, const void* y) { return Bitmap::value(x) < Bitmap::value(y); }) &&
       keep(p))
      ++distinct;
  return distinct;
}

// Number of distinct faces in `faces`, not counting those whose address is in `except`.
template <class Face_handle>
std::size_t count_distinct(const std::vector<Face_handle>& faces,
                           std::vector<const void*> except = std::vector<const void*>())
{
  using Face = std::remove_cv_t<std::remove_reference_t<decltype(*faces.front())>>;
  sort_by_address(except);
  return count_distinct_addresses<Face>(std::vector<const void*>(), faces, 0, [&](const void* a) {
    return !contains_address(except, a);
  });
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_SORT_ADDRESSES_H
