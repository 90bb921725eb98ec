#pragma once
// Which copy of a level matrix's values a multigrid pass reads. With
// solver.multigrid_precision = "single" each level but the coarsest keeps its values
// rounded to float as well, and the passes bound by the matrix's bytes (the block-Jacobi
// sweeps, the diagonal blocks, the power iteration for ρ(D⁻¹A), the level residuals) read
// that copy; with "double" the copy is empty and they read the double values.
#include <utility>

namespace rouleau {

// Calls `pass(values_read)` with the float copy when it is not empty, else with `values`.
template <class Values, class RoundedValues, class Pass>
void with_values_read(const Values& values, const RoundedValues& rounded_values, Pass&& pass) {
  if (rounded_values.extent(0) > 0)
    std::forward<Pass>(pass)(rounded_values);
  else
    std::forward<Pass>(pass)(values);
}

}  // namespace rouleau
