// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The division of a graph into connected regions of about t nodes that both t-division
// algorithms use: the faces of a prediction (Theorem 2.1, t_division_repair.h) and the cells
// of a sample's Delaunay triangulation (Theorem 4.1's supercells, supercells.h). Breadth-first
// region growing, not Frederickson's t-division: compact regions on well-shaped meshes, but no
// O(sqrt t) bound on a region's boundary (regions squeezed between others come out as small
// fragments, which then join a neighbour).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_REGION_GROWING_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_REGION_GROWING_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/union_find.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

constexpr std::uint32_t no_region = std::uint32_t(-1);
constexpr std::uint32_t outside_regions = std::uint32_t(-2);

// Labels the nodes k with region[k] == no_region with regions 0, 1, ..., connected in the
// graph, of at most t nodes each: seeds in index order, each region grown breadth-first
// until it has t nodes. Regions boxed in by others come out small: those under t/4 nodes
// join a neighbouring region (union-find). Nodes with region[k] == outside_regions stay
// outside and are never crossed. `for_each_neighbor(k, f)` calls f(g) for every neighbour g
// of node k. Returns the number of regions.
template <class ForEachNeighbor>
std::uint32_t grow_regions(std::vector<std::uint32_t>& region, std::size_t t, ForEachNeighbor for_each_neighbor)
{
  const std::size_t nodes = region.size();
  std::vector<std::uint32_t> queue, size;
  for(std::size_t s = 0; s < nodes; ++s) {
    if(region[s] != no_region)
      continue;
    const std::uint32_t r = std::uint32_t(size.size());
    region[s] = r;
    queue.assign(1, std::uint32_t(s));
    for(std::size_t head = 0; head < queue.size() && queue.size() < t; ++head)
      for_each_neighbor(queue[head], [&](std::uint32_t g) {
        if(queue.size() < t && region[g] == no_region) {
          region[g] = r;
          queue.push_back(g);
        }
      });
    size.push_back(std::uint32_t(queue.size()));
  }
  Union_find joined(size.size());
  auto find = [&](std::uint32_t r) { return std::uint32_t(joined.find(r)); };
  for(std::size_t k = 0; k < nodes; ++k) {
    const std::uint32_t r = region[k];
    if(r == outside_regions || 4 * std::size_t(size[r]) >= t || find(r) != r)
      continue;
    bool done = false;
    for_each_neighbor(std::uint32_t(k), [&](std::uint32_t g) {
      const std::uint32_t q = region[g];
      if(!done && q != outside_regions && find(q) != r) {
        joined.join(r, q);
        done = true;
      }
    });
  }
  std::uint32_t regions = 0;
  std::vector<std::uint32_t> label(size.size(), no_region);
  for(std::uint32_t r = 0; r < size.size(); ++r)
    if(find(r) == r)
      label[r] = regions++;
  for(std::size_t k = 0; k < nodes; ++k)
    if(region[k] != outside_regions)
      region[k] = label[find(region[k])];
  return regions;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_REGION_GROWING_H
