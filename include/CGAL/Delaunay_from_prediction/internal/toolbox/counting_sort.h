// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The one bucketing of the package: a stable counting sort, on one thread or on TBB's. The
// spatial orders, the flips' cells and BrioDC's nearest-neighbour cells sort their points or
// edges into the cells of a grid (toolbox/grid.h) with it.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_COUNTING_SORT_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_COUNTING_SORT_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

template <class KeyAt, class ItemAt, class Place>
void counting_sort_in_blocks(std::size_t m, std::size_t buckets, const KeyAt& key_at, const ItemAt& item_at,
                             const Place& place, std::unique_ptr<std::uint32_t[]>& key, std::vector<std::uint32_t>& end);

// Stable counting sort of the items 0..m-1 by key_at(k) < buckets: calls place(position,
// item_at(k)) once for each item, positions in key order and, among equal keys, in item
// order, and sets end[b] to the position after the last item of bucket b. With `parallel`
// (and m large enough to pay), on TBB's threads in three passes with the same positions:
// blocks of items count their keys' coarse buckets (the high bits), then copy their items
// with their keys into a buffer in coarse order, then each coarse bucket is counting-sorted by
// the low bits from its stretch of the buffer, which the cache holds; every pass writes only
// what its block or bucket owns. key_at, item_at and place are then called from several
// threads; key_at in item order within each block of items.
template <class KeyAt, class ItemAt, class Place, class Parallel>
void counting_sort(std::size_t m, std::size_t buckets, const KeyAt& key_at, const ItemAt& item_at, const Place& place,
                   Parallel parallel, std::vector<std::uint32_t>& end)
{
  std::unique_ptr<std::uint32_t[]> key(new std::uint32_t[m]); // not zero-filled: written before read
  end.assign(buckets, 0);
  if(!may_run_in_parallel<Parallel>() || !parallel || m < (std::size_t(1) << 16)) {
    std::vector<std::uint32_t> start(buckets + 1, 0);
    for(std::size_t k = 0; k < m; ++k) {
      key[k] = std::uint32_t(key_at(k));
      ++start[key[k] + 1];
    }
    for(std::size_t b = 1; b <= buckets; ++b)
      start[b] += start[b - 1];
    for(std::size_t k = 0; k < m; ++k)
      place(std::size_t(start[key[k]]++), item_at(k));
    std::copy(start.begin(), start.end() - 1, end.begin());
    return;
  }
  if constexpr(may_run_in_parallel<Parallel>())
    counting_sort_in_blocks(m, buckets, key_at, item_at, place, key, end);
}

// counting_sort() on TBB's threads; `key` has room for m keys.
template <class KeyAt, class ItemAt, class Place>
void counting_sort_in_blocks(std::size_t m, std::size_t buckets, const KeyAt& key_at, const ItemAt& item_at,
                             const Place& place, std::unique_ptr<std::uint32_t[]>& key, std::vector<std::uint32_t>& end)
{
  using Item = std::decay_t<decltype(item_at(std::size_t(0)))>;
  int shift = 0; // coarse bucket = key >> shift, at most 1024 of them
  while(((buckets - 1) >> shift) >= 1024)
    ++shift;
  const std::size_t coarse = ((buckets - 1) >> shift) + 1, fine = std::size_t(1) << shift;
  const std::size_t block = 1 << 16, blocks = (m + block - 1) / block;
  std::vector<std::uint32_t> offset(blocks * coarse, 0), coarse_start(coarse + 1, 0);
  for_each_block(true, blocks, [&](std::size_t b) {
    std::uint32_t* count = offset.data() + b * coarse;
    for(std::size_t k = b * block, last = (std::min)(m, k + block); k < last; ++k) {
      key[k] = std::uint32_t(key_at(k));
      ++count[key[k] >> shift];
    }
  });
  std::uint32_t sum = 0; // offsets in (coarse bucket, block) order
  for(std::size_t c = 0; c < coarse; ++c) {
    coarse_start[c] = sum;
    for(std::size_t b = 0; b < blocks; ++b) {
      const std::uint32_t count = offset[b * coarse + c];
      offset[b * coarse + c] = sum;
      sum += count;
    }
  }
  coarse_start[coarse] = sum;
  std::vector<std::uint32_t> key_in_coarse_order(m);
  std::vector<Item> item_in_coarse_order(m);
  for_each_block(true, blocks, [&](std::size_t b) {
    std::uint32_t* next = offset.data() + b * coarse;
    for(std::size_t k = b * block, last = (std::min)(m, k + block); k < last; ++k) {
      const std::uint32_t i = next[key[k] >> shift]++;
      key_in_coarse_order[i] = key[k];
      item_in_coarse_order[i] = item_at(k);
    }
  });
  key.reset();
  for_each_block(true, coarse, [&](std::size_t c) {
    const std::size_t first_key = c << shift, keys = (std::min)(fine, buckets - first_key);
    std::vector<std::uint32_t> next(keys + 1, 0);
    for(std::uint32_t i = coarse_start[c]; i < coarse_start[c + 1]; ++i)
      ++next[key_in_coarse_order[i] - first_key + 1];
    next[0] = coarse_start[c];
    for(std::size_t j = 1; j <= keys; ++j)
      next[j] += next[j - 1];
    for(std::uint32_t i = coarse_start[c]; i < coarse_start[c + 1]; ++i)
      place(std::size_t(next[key_in_coarse_order[i] - first_key]++), item_in_coarse_order[i]);
    std::copy(next.begin(), next.begin() + std::ptrdiff_t(keys), end.begin() + std::ptrdiff_t(first_key));
  });
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_COUNTING_SORT_H
