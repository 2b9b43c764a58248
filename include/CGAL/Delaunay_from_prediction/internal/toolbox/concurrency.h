// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// CGAL's concurrency tags for the entry points, and the one loop that runs blocks of work on
// TBB's threads (or in order, without TBB or with CGAL::Sequential_tag).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_CONCURRENCY_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_CONCURRENCY_H

#include <CGAL/tags.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Whether this translation unit can run work on several threads: only with TBB. Without it
// every call is sequential (runs_in_parallel()), and the code that only runs on several threads
// stands behind `if constexpr(threads_available)`, so that it is not compiled.
#ifdef CGAL_LINKED_WITH_TBB
constexpr bool threads_available = true;
#else
constexpr bool threads_available = false;
#endif

// The `parallel` argument of the package's stages is a bool, or std::true_type or
// std::false_type where it is known at compile time (the entry points pass their
// ConcurrencyTag's as such, so that a sequential call compiles no code that only runs on
// several threads, even with TBB). Whether code given one of type `Parallel` may run on
// several threads:
template <class Parallel>
constexpr bool may_run_in_parallel()
{
  return threads_available && !std::is_same<Parallel, std::false_type>::value;
}

// A bool `parallel` passed on as an argument of type Parallel would have: itself, or
// std::false_type where code given a Parallel never runs on several threads.
template <class Parallel>
auto parallel_argument(bool parallel)
{
  if constexpr(may_run_in_parallel<Parallel>())
    return parallel;
  else
    return std::false_type();
}

// The `parallel` argument the stages of a call pass, known at compile time.
template <bool Parallel>
using Parallel_constant = std::integral_constant<bool, Parallel>;

// Whether an entry point called with `ConcurrencyTag` runs its parallel parts on TBB's threads.
// CGAL::Parallel_if_available_tag is CGAL::Parallel_tag when CGAL_LINKED_WITH_TBB is defined
// and CGAL::Sequential_tag otherwise (<CGAL/tags.h>), so it needs no case of its own.
template <class ConcurrencyTag>
constexpr bool runs_in_parallel()
{
  static_assert(std::is_same<ConcurrencyTag, Sequential_tag>::value ||
                    std::is_same<ConcurrencyTag, Parallel_tag>::value,
                "Delaunay_from_prediction: the ConcurrencyTag must be CGAL::Sequential_tag, CGAL::Parallel_tag "
                "or CGAL::Parallel_if_available_tag");
#ifdef CGAL_LINKED_WITH_TBB
  return std::is_same<ConcurrencyTag, Parallel_tag>::value;
#else
  static_assert(!std::is_same<ConcurrencyTag, Parallel_tag>::value,
                "Delaunay_from_prediction: CGAL::Parallel_tag needs TBB. Link the target with "
                "CGAL::TBB_support (find_package(TBB) and include(CGAL_TBB_support) in CMake), which "
                "defines CGAL_LINKED_WITH_TBB, or use CGAL::Parallel_if_available_tag, which runs "
                "sequentially without TBB.");
  return false;
#endif
}

// Calls body(b) for every b in [0, blocks): on TBB's threads when `parallel` (then the bodies
// must only write what block b owns), in increasing order otherwise. The number of threads is
// TBB's: a tbb::task_arena or tbb::global_control around the call limits it.
template <class Parallel, class Body>
void for_each_block(Parallel parallel, std::size_t blocks, const Body& body)
{
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(may_run_in_parallel<Parallel>()) {
    if(parallel && blocks > 1) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for(std::size_t b = r.begin(); b != r.end(); ++b)
          body(b);
      });
      return;
    }
  }
#endif
  (void)parallel;
  for(std::size_t b = 0; b < blocks; ++b)
    body(b);
}

// Calls body(first, last) for the ranges [first, last) that cut [0, n) into pieces of `size`
// items (the last one shorter), through for_each_block().
template <class Parallel, class Body>
void for_each_range(Parallel parallel, std::size_t n, std::size_t size, const Body& body)
{
  for_each_block(parallel, (n + size - 1) / size,
                 [&](std::size_t b) { body(b * size, (std::min)(n, (b + 1) * size)); });
}

// The number of threads for_each_block() may use: TBB's limit in the current arena (and
// global_control), 1 without TBB.
inline std::size_t available_threads()
{
#ifdef CGAL_LINKED_WITH_TBB
  const std::size_t arena = std::size_t((std::max)(1, tbb::this_task_arena::max_concurrency()));
  const std::size_t allowed = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  return (std::max)(std::size_t(1), (std::min)(arena, allowed));
#else
  return 1;
#endif
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_CONCURRENCY_H
