// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Sorting object addresses without repeats, for the statistics that count the distinct faces
// a repair touched (up to two per flip: 870,000 addresses at 1e6 points moved by 0.1 spacing).
// A least-significant-digit radix sort on the offsets from the lowest address: faces live in a
// few large blocks, so the offsets need about 24 bits, two or three passes, where std::sort
// took 60 ms.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_SORT_ADDRESSES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_SORT_ADDRESSES_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Sorts `addresses` by address and removes repeats.
inline void sort_unique_addresses(std::vector<const void*>& addresses)
{
  const std::size_t n = addresses.size();
  auto value = [](const void* p) { return std::uint64_t(reinterpret_cast<std::uintptr_t>(p)); };
  if(n < 4096) {
    std::sort(addresses.begin(), addresses.end(),
              [&](const void* a, const void* b) { return value(a) < value(b); });
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
      std::sort(addresses.begin(), addresses.end(),
                [&](const void* a, const void* b) { return value(a) < value(b); });
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

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_SORT_ADDRESSES_H
