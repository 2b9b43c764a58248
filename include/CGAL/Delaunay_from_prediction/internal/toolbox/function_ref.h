// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// A reference to a callable, called through one function pointer. Code that takes a
// Function_ref instead of a template parameter is compiled once, whatever the type of the
// callable each call site passes (every lambda has a type of its own), at the cost of an
// indirect call: for code off the hot loops (a count at the end of a call), so that a program
// compiles it once.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_FUNCTION_REF_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_FUNCTION_REF_H

#include <type_traits>
#include <utility>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

template <class Signature>
class Function_ref;

// The callable must outlive the Function_ref (it is held by address).
template <class Result, class... Arguments>
class Function_ref<Result(Arguments...)>
{
public:
  template <class Callable,
            class = std::enable_if_t<!std::is_same<std::decay_t<Callable>, Function_ref>::value>>
  Function_ref(const Callable& callable)
      : object_(&callable), call_([](const void* object, Arguments... arguments) -> Result {
          return (*static_cast<const Callable*>(object))(std::forward<Arguments>(arguments)...);
        })
  {
  }

  Result operator()(Arguments... arguments) const { return call_(object_, std::forward<Arguments>(arguments)...); }

private:
  const void* object_;
  Result (*call_)(const void*, Arguments...);
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_FUNCTION_REF_H
