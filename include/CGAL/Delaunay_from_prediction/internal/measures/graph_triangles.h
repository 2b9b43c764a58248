// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The triangles of a predicted graph (every three points pairwise joined by an edge), the faces
// that delaunay_from_predicted_edges() hands to delaunay_from_prediction().

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_MEASURES_GRAPH_TRIANGLES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_MEASURES_GRAPH_TRIANGLES_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// The triangles of the graph: every three points pairwise joined by an edge, found by
// intersecting the sorted neighbour lists of the two ends of each edge (each triangle once,
// from its two smallest indices). Purely combinatorial: O(m log m + m d) for m edges of degree
// at most d (the edges sorted, then the lists intersected). In a graph that is DT(P) with edges missing these are the triangular faces, plus,
// rarely, a separating triangle around a vertex of degree 3: the importer leaves out what
// overlaps (faces on the same side of an edge), and the faces with more than three sides
// become holes that the local repair fills (ear clipping, then flips).
inline std::vector<std::array<std::size_t, 3>>
graph_triangles(std::size_t n, std::vector<std::pair<std::size_t, std::size_t>>& edges)
{
  std::vector<std::uint64_t> keys(edges.size());
  for(std::size_t k = 0; k < edges.size(); ++k) {
    const std::uint64_t a = (std::min)(edges[k].first, edges[k].second);
    const std::uint64_t b = (std::max)(edges[k].first, edges[k].second);
    keys[k] = a << 32 | b;
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  // Compressed adjacency, each list increasing: the neighbours of v are
  // neighbour[start[v] .. start[v + 1]) (smaller ones from edges (u, v), then larger ones).
  std::vector<std::size_t> start(n + 1, 0);
  for(const std::uint64_t key : keys) {
    ++start[(key >> 32) + 1];
    ++start[(key & 0xffffffffu) + 1];
  }
  for(std::size_t v = 0; v < n; ++v)
    start[v + 1] += start[v];
  std::vector<std::uint32_t> neighbour(2 * keys.size());
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for(const std::uint64_t key : keys) {
      const std::size_t a = std::size_t(key >> 32), b = std::size_t(key & 0xffffffffu);
      neighbour[fill[a]++] = std::uint32_t(b);
      neighbour[fill[b]++] = std::uint32_t(a);
    }
  }
  std::vector<std::array<std::size_t, 3>> triangles;
  triangles.reserve(2 * n);
  for(const std::uint64_t key : keys) {
    const std::size_t a = std::size_t(key >> 32), b = std::size_t(key & 0xffffffffu);
    // Common neighbours w > b of a and b.
    std::size_t i = start[a], j = start[b];
    const std::size_t i_end = start[a + 1], j_end = start[b + 1];
    while(i < i_end && neighbour[i] <= b)
      ++i;
    while(j < j_end && neighbour[j] <= b)
      ++j;
    while(i < i_end && j < j_end) {
      if(neighbour[i] < neighbour[j])
        ++i;
      else if(neighbour[j] < neighbour[i])
        ++j;
      else {
        triangles.push_back({a, b, std::size_t(neighbour[i])});
        ++i;
        ++j;
      }
    }
  }
  return triangles;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_MEASURES_GRAPH_TRIANGLES_H
