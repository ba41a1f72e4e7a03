#pragma once
// Loops written for a size fixed at compile time (unrolled and vectorized,
// with the same operations per entry as the loop over a size known at run
// time): with_fixed_size<4, 6, 8>(n, f) calls
// f(std::integral_constant<unsigned int, n>{}) where n is one of the sizes
// listed and f(std::integral_constant<unsigned int, 0>{}) otherwise, 0
// meaning "the size at run time". The cell loops use it for the dofs per
// cell (fe/discretization.h), the band LU for the bandwidth
// (numerics/tangent_solver.cc).

#include <type_traits>
#include <utility>

namespace cdea
{
  template <unsigned int... Sizes, typename F>
  void with_fixed_size(const unsigned int n, F &&f)
  {
    const bool listed =
      ((n == Sizes && (f(std::integral_constant<unsigned int, Sizes>{}), true)) || ...);
    if (!listed)
      f(std::integral_constant<unsigned int, 0>{});
  }
} // namespace cdea
