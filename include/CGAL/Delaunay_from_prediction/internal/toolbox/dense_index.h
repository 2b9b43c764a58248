// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Dense indices of the faces or vertices of a CGAL triangulation data structure, for arrays
// indexed by face or vertex (the t-division's regions and its DT(V_B)).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_DENSE_INDEX_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_DENSE_INDEX_H

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Dense indices 0..size-1 of the objects of a CGAL Compact_container (a TDS's faces or
// vertices), in iteration order, from their addresses. The container keeps its objects in a
// few hundred blocks, so iteration yields runs of consecutive addresses. A table over the
// address span, one entry per 16 KiB chunk, gives the first run that reaches into each chunk;
// an index is then one table load, a step or two along the runs, and an offset (about 5 ns,
// against 20 ns for a binary search among the runs, used when the span is too wide for the
// table). (Compact_container::index() scans every block.)
template <class Container>
class Dense_index
{
public:
  using Object = typename Container::value_type;

  explicit Dense_index(const Container& container)
  {
    const Object* last = nullptr;
    for(auto it = container.begin(); it != container.end(); ++it, ++size_) {
      const Object* p = &*it;
      if(last == nullptr || p != last + 1) {
        if(!runs_.empty())
          runs_.back().end = address(last + 1);
        runs_.push_back(Run{address(p), 0, size_});
      }
      last = p;
    }
    if(runs_.empty())
      return;
    runs_.back().end = address(last + 1);
    std::sort(runs_.begin(), runs_.end(), [](const Run& a, const Run& b) { return a.first < b.first; });
    low_ = runs_.front().first;
    const std::uintptr_t span = runs_.back().end - low_;
    if((span >> chunk_bits) < (std::uintptr_t(1) << 24)) {
      chunk_first_run_.resize(std::size_t(span >> chunk_bits) + 1);
      std::size_t r = 0;
      for(std::size_t c = 0; c < chunk_first_run_.size(); ++c) {
        const std::uintptr_t chunk_start = low_ + (std::uintptr_t(c) << chunk_bits);
        while(r + 1 < runs_.size() && runs_[r].end <= chunk_start)
          ++r;
        chunk_first_run_[c] = std::uint32_t(r);
      }
    }
  }

  std::size_t size() const { return size_; }

  std::size_t operator()(const Object* object) const
  {
    const std::uintptr_t p = address(object);
    const Run* run;
    if(!chunk_first_run_.empty()) {
      run = runs_.data() + chunk_first_run_[(p - low_) >> chunk_bits];
      while(run->end <= p)
        ++run;
    } else {
      run = runs_.data();
      std::size_t count = runs_.size();
      while(count > 1) {
        const std::size_t half = count / 2;
        run = run[half].first <= p ? run + half : run;
        count -= half;
      }
    }
    return run->index + std::size_t((p - run->first) / sizeof(Object));
  }
  template <class Handle>
  std::size_t of(const Handle& h) const { return (*this)(&*h); }

private:
  static constexpr int chunk_bits = 14;
  static std::uintptr_t address(const Object* p) { return reinterpret_cast<std::uintptr_t>(p); }
  struct Run
  {
    std::uintptr_t first, end; // addresses of the first object and one past the last
    std::size_t index;         // dense index of the first object
  };
  std::vector<Run> runs_;
  std::vector<std::uint32_t> chunk_first_run_;
  std::uintptr_t low_ = 0;
  std::size_t size_ = 0;
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_DENSE_INDEX_H
