#include "solver/ilu0_preconditioner.hpp"

#include <KokkosKernels_config.h>
#include <KokkosSparse_spiluk.hpp>

#include "util/profiling_region.hpp"

namespace rouleau {

namespace {
// spiluk_symbolic/spiluk_numeric left KokkosSparse::Experimental in KokkosKernels 4.6 (the
// old names are deprecated there). KOKKOSKERNELS_VERSION (KokkosKernels_config.h) exists
// from 4.0 on; 3.4.01 defines no version macro. SPILUKAlgorithm stays in Experimental.
#if defined(KOKKOSKERNELS_VERSION) && KOKKOSKERNELS_VERSION >= 40600
namespace spiluk_api = KokkosSparse;
#else
namespace spiluk_api = KokkosSparse::Experimental;
#endif
using KokkosSparse::Experimental::SPILUKAlgorithm;
}  // namespace

Ilu0Preconditioner::Ilu0Preconditioner(const Kokkos::View<std::size_t*>& row_map, const Kokkos::View<int*>& entries)
    : num_rows_(static_cast<int>(row_map.extent(0)) - 1), row_map_(row_map), entries_(entries) {
  ProfilingRegion region("rouleau::Ilu0Preconditioner::symbolic");
  const std::size_t nnz = entries.extent(0);
  factor_handle_.create_spiluk_handle(SPILUKAlgorithm::SEQLVLSCHD_TP1, num_rows_, nnz, nnz);
  auto* spiluk = factor_handle_.get_spiluk_handle();
  lower_row_map_ = Kokkos::View<std::size_t*>("rouleau::Ilu0Preconditioner::lower_row_map", num_rows_ + 1);
  upper_row_map_ = Kokkos::View<std::size_t*>("rouleau::Ilu0Preconditioner::upper_row_map", num_rows_ + 1);
  lower_entries_ = Kokkos::View<int*>("rouleau::Ilu0Preconditioner::lower_entries", spiluk->get_nnzL());
  upper_entries_ = Kokkos::View<int*>("rouleau::Ilu0Preconditioner::upper_entries", spiluk->get_nnzU());
  const int fill_level = 0;
  spiluk_api::spiluk_symbolic(&factor_handle_, fill_level, row_map_, entries_, lower_row_map_, lower_entries_,
                              upper_row_map_, upper_entries_);
  Kokkos::resize(lower_entries_, spiluk->get_nnzL());
  Kokkos::resize(upper_entries_, spiluk->get_nnzU());
  lower_values_ = Kokkos::View<double*>("rouleau::Ilu0Preconditioner::lower_values", spiluk->get_nnzL());
  upper_values_ = Kokkos::View<double*>("rouleau::Ilu0Preconditioner::upper_values", spiluk->get_nnzU());
  intermediate_ = Kokkos::View<double*>("rouleau::Ilu0Preconditioner::intermediate", num_rows_);
  lower_solver_ = std::make_unique<TriangularSolver>(lower_row_map_, lower_entries_, TriangularPart::lower);
  upper_solver_ = std::make_unique<TriangularSolver>(upper_row_map_, upper_entries_, TriangularPart::upper);
}

Ilu0Preconditioner::~Ilu0Preconditioner() { factor_handle_.destroy_spiluk_handle(); }

void Ilu0Preconditioner::factor(const Kokkos::View<double*>& values) {
  ProfilingRegion region("rouleau::Ilu0Preconditioner::numeric");
  const int fill_level = 0;
  spiluk_api::spiluk_numeric(&factor_handle_, fill_level, row_map_, entries_, values, lower_row_map_, lower_entries_,
                             lower_values_, upper_row_map_, upper_entries_, upper_values_);
}

void Ilu0Preconditioner::apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const {
  // L y = r, U z = y.
  lower_solver_->solve(lower_values_, r, intermediate_);
  upper_solver_->solve(upper_values_, intermediate_, z);
}

}  // namespace rouleau
