#include "fluid/fast_diagonalization.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "config/derived.hpp"
#include "util/profiling_region.hpp"
#include "util/constants.hpp"

// LAPACK's banded LU (Fortran; the trailing length is gfortran's hidden string length).
extern "C" {
void zgbtrf_(const int* m, const int* n, const int* kl, const int* ku, std::complex<double>* ab, const int* ldab,
             int* ipiv, int* info);
void zgbtrs_(const char* trans, const int* n, const int* kl, const int* ku, const int* nrhs,
             const std::complex<double>* ab, const int* ldab, const int* ipiv, std::complex<double>* b, const int* ldb,
             int* info, std::size_t trans_length);
}

namespace rouleau {

namespace {
using HostExec = Kokkos::DefaultHostExecutionSpace;
constexpr bool host_readable =
    Kokkos::SpaceAccessibility<Kokkos::HostSpace, Vector::memory_space>::accessible;
constexpr int components = 4;  // u, v, w, p per dof node
constexpr int plane_reach = 2;  // wall planes a row reaches on either side
// The probes sit half a box from the pinned dof node 0 along a periodic axis; the box rule
// read by the case loader must keep them beyond a row's reach of it.
static_assert(fast_diagonalization_min_periodic_elements >= 2 * plane_reach + 2,
              "the box rule lets a probe fall within reach of the pressure pin");
}  // namespace

struct FastDiagonalization::Plans {
  fftw_plan forward = nullptr, inverse = nullptr;
  ~Plans() {
    if (forward) fftw_destroy_plan(forward);
    if (inverse) fftw_destroy_plan(inverse);
  }
};

std::string FastDiagonalization::unavailable_reason(const FluidMesh& mesh) {
  if (mesh.structured_elements[0] == 0) return "the fluid mesh is not a structured box";
  const std::string shape = fast_diagonalization_box_obstacle(mesh.periodic, mesh.structured_elements);
  if (!shape.empty()) return "the box " + shape;
  if (!host_readable) return "it runs on the host and the fluid's vectors live on the device";
  return "";
}

FastDiagonalization::FastDiagonalization(const FluidMesh& mesh) : plans_(std::make_unique<Plans>()) {
  const std::string reason = unavailable_reason(mesh);
  if (!reason.empty()) throw std::runtime_error("rouleau::FastDiagonalization: not available: " + reason);
  int planes[3];
  for (int d = 0; d < 3; ++d) planes[d] = mesh.structured_elements[d] + (mesh.periodic[d] ? 0 : 1);
  wall_ = !mesh.periodic[0] ? 0 : (!mesh.periodic[1] ? 1 : 2);
  first_ = wall_ == 0 ? 1 : 0;
  last_ = wall_ == 2 ? 1 : 2;
  // Unknown 4 n + c of dof node n = i + d_x (j + d_y k).
  const int stride[3] = {components, components * planes[0], components * planes[0] * planes[1]};
  wall_planes_ = planes[wall_];
  first_count_ = planes[first_];
  last_count_ = planes[last_];
  wall_stride_ = stride[wall_];
  first_stride_ = stride[first_];
  last_stride_ = stride[last_];
  unknowns_per_wave_ = components * wall_planes_;
  const int last_waves = last_count_ / 2 + 1;  // the real transform's halved direction
  waves_ = first_count_ * last_waves;
  band_rows_ = 2 * lower_bands_ + upper_bands_ + 1;
  bands_.assign(static_cast<std::size_t>(waves_) * band_rows_ * unknowns_per_wave_, 0.0);
  pivots_.assign(static_cast<std::size_t>(waves_) * unknowns_per_wave_, 0);
  spectrum_.assign(static_cast<std::size_t>(waves_) * unknowns_per_wave_, 0.0);
  const int n = mesh.num_unknowns();
  num_unknowns_ = n;

  // One plane's 2D transform of its 4 components: input strides along the periodic
  // directions, output [wave][plane][c] with wave = k_first (N_last/2 + 1) + k_last.
  const int spectrum_stride = unknowns_per_wave_;
  fftw_iodim64 dims[2] = {{first_count_, first_stride_, static_cast<std::ptrdiff_t>(last_waves) * spectrum_stride},
                          {last_count_, last_stride_, spectrum_stride}};
  fftw_iodim64 batch[1] = {{components, 1, 1}};
  std::vector<double> real_scratch(static_cast<std::size_t>(n));
  plans_->forward = fftw_plan_guru64_dft_r2c(2, dims, 1, batch, real_scratch.data(),
                                             reinterpret_cast<fftw_complex*>(spectrum_.data()),
                                             FFTW_ESTIMATE | FFTW_UNALIGNED);
  fftw_iodim64 inverse_dims[2] = {
      {first_count_, static_cast<std::ptrdiff_t>(last_waves) * spectrum_stride, first_stride_},
      {last_count_, spectrum_stride, last_stride_}};
  plans_->inverse = fftw_plan_guru64_dft_c2r(2, inverse_dims, 1, batch,
                                             reinterpret_cast<fftw_complex*>(spectrum_.data()), real_scratch.data(),
                                             FFTW_ESTIMATE | FFTW_UNALIGNED);
  if (!plans_->forward || !plans_->inverse)
    throw std::runtime_error("rouleau::FastDiagonalization: FFTW could not plan the transforms");
}

FastDiagonalization::~FastDiagonalization() = default;

void FastDiagonalization::transform(const double* x) const {
  fftw_plan plan = plans_->forward;
  auto* spectrum = reinterpret_cast<fftw_complex*>(spectrum_.data());
  const int wall_stride = wall_stride_;
  // Plane by plane, in parallel (FFTW's new-array execution is thread-safe).
  Kokkos::parallel_for(
      "rouleau::FastDiagonalization::transform", Kokkos::RangePolicy<HostExec>(0, wall_planes_),
      [=](const int j) {
        fftw_execute_dft_r2c(plan, const_cast<double*>(x) + static_cast<std::ptrdiff_t>(j) * wall_stride,
                             spectrum + components * j);
      });
}

void FastDiagonalization::inverse_transform(double* x) const {
  fftw_plan plan = plans_->inverse;
  auto* spectrum = reinterpret_cast<fftw_complex*>(spectrum_.data());
  const int wall_stride = wall_stride_, first_stride = first_stride_, last_stride = last_stride_;
  const int first_count = first_count_, last_count = last_count_;
  const double scale = 1.0 / (static_cast<double>(first_count_) * last_count_);
  Kokkos::parallel_for(
      "rouleau::FastDiagonalization::inverse_transform", Kokkos::RangePolicy<HostExec>(0, wall_planes_),
      [=](const int j) {
        double* plane = x + static_cast<std::ptrdiff_t>(j) * wall_stride;
        fftw_execute_dft_c2r(plan, spectrum + components * j, plane);
        for (int a = 0; a < first_count; ++a)
          for (int b = 0; b < last_count; ++b)
            for (int c = 0; c < components; ++c) plane[a * first_stride + b * last_stride + c] *= scale;
      });
}

void FastDiagonalization::factor(const FluidOperator& op, const ConstVector&) {
  ProfilingRegion region("rouleau::FastDiagonalization::factor");
  const int n = unknowns_per_wave_, kl = lower_bands_, ku = upper_bands_, ldab = band_rows_;
  std::fill(bands_.begin(), bands_.end(), std::complex<double>(0.0));
  const int last_waves = last_count_ / 2 + 1;
  // The probes sit at the middle of the periodic directions, away from the pinned node 0.
  const int probe_first = first_count_ / 2, probe_last = last_count_ / 2;
  // Is the pressure's level pinned (at dof node 0: no traction side)? Then the zero wave
  // number's block is singular and gets the pin's counterpart below.
  bool pressure_pinned = false;
  {
    auto dirichlet = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), op.dirichlet_dofs());
    for (std::size_t k = 0; k < dirichlet.extent(0); ++k) pressure_pinned = pressure_pinned || dirichlet(k) == 3;
  }
  const int group_spacing = 2 * plane_reach + 1;
  // Set-up scratch, freed when the factors are made (once per time-step size).
  Vector probe_vector("rouleau::FastDiagonalization::probe", num_unknowns_);
  Vector response("rouleau::FastDiagonalization::response", num_unknowns_);
  auto probe = Kokkos::create_mirror_view(probe_vector);  // the same View on the host spaces
  for (int group = 0; group < group_spacing; ++group) {
    for (int c = 0; c < components; ++c) {
      Kokkos::deep_copy(probe, 0.0);
      for (int j = group; j < wall_planes_; j += group_spacing)
        probe(static_cast<std::size_t>(j) * wall_stride_ + probe_first * first_stride_ + probe_last * last_stride_ +
              c) = 1.0;
      Kokkos::deep_copy(probe_vector, probe);
      op.linear_action(probe_vector, response);
      Kokkos::fence();
      transform(response.data());
      Kokkos::fence();
      // Column (j', c) of Â_κ: the response at planes j' − 2 … j' + 2, shifted back by the
      // probe's position: Â_κ = ŷ_κ e^(i κ·m_probe).
      for (int wave = 0; wave < waves_; ++wave) {
        const int k_first = wave / last_waves, k_last = wave % last_waves;
        const double angle = 2.0 * pi *
                             (static_cast<double>(k_first) * probe_first / first_count_ +
                              static_cast<double>(k_last) * probe_last / last_count_);
        const std::complex<double> shift(std::cos(angle), std::sin(angle));
        const std::complex<double>* column_values = spectrum_.data() + static_cast<std::size_t>(wave) * n;
        std::complex<double>* band = bands_.data() + static_cast<std::size_t>(wave) * ldab * n;
        for (int jp = group; jp < wall_planes_; jp += group_spacing) {
          const int column = components * jp + c;
          for (int j = std::max(0, jp - plane_reach); j <= std::min(wall_planes_ - 1, jp + plane_reach); ++j)
            for (int row_c = 0; row_c < components; ++row_c) {
              const int row = components * j + row_c;
              // LAPACK band storage: A(row, column) at ab(kl + ku + row − column, column).
              band[kl + ku + row - column + static_cast<std::size_t>(column) * ldab] =
                  column_values[row] * shift;
            }
        }
      }
    }
  }
  // The zero wave number: the mean pressure of the pinned node's plane (dof node 0 lies on
  // wall plane 0) instead of its continuity row (the shift-invariant operator leaves a
  // uniform pressure free).
  if (pressure_pinned) {
    const int row = 3;
    std::complex<double>* band = bands_.data();
    for (int column = std::max(0, row - kl); column <= std::min(n - 1, row + ku); ++column)
      band[kl + ku + row - column + static_cast<std::size_t>(column) * ldab] = column == row ? 1.0 : 0.0;
  }
  int failures = 0;
  Kokkos::parallel_reduce(
      "rouleau::FastDiagonalization::factor_waves", Kokkos::RangePolicy<HostExec>(0, waves_),
      [&](const int wave, int& failed) {
        int info = 0;
        zgbtrf_(&n, &n, &kl, &ku, bands_.data() + static_cast<std::size_t>(wave) * ldab * n, &ldab,
                pivots_.data() + static_cast<std::size_t>(wave) * n, &info);
        if (info != 0) ++failed;
      },
      failures);
  if (failures > 0) {
    std::ostringstream msg;
    msg << "rouleau::FastDiagonalization: " << failures << " of " << waves_
        << " wave-number blocks are singular (is the operator the Stokes stencil of a periodic box?)";
    throw std::runtime_error(msg.str());
  }
}

void FastDiagonalization::apply(const ConstVector& r, const Vector& z) const {
  ProfilingRegion region("rouleau::FastDiagonalization::apply");
  Kokkos::fence();
  transform(r.data());
  const int n = unknowns_per_wave_, kl = lower_bands_, ku = upper_bands_, ldab = band_rows_, one = 1;
  const std::complex<double>* bands = bands_.data();
  const int* pivots = pivots_.data();
  std::complex<double>* spectrum = spectrum_.data();
  Kokkos::parallel_for(
      "rouleau::FastDiagonalization::solve_waves", Kokkos::RangePolicy<HostExec>(0, waves_), [=](const int wave) {
        int info = 0;
        const char no_transpose = 'N';
        zgbtrs_(&no_transpose, &n, &kl, &ku, &one, bands + static_cast<std::size_t>(wave) * ldab * n, &ldab,
                pivots + static_cast<std::size_t>(wave) * n, spectrum + static_cast<std::size_t>(wave) * n, &n, &info,
                1);
      });
  inverse_transform(z.data());
  HostExec().fence();
}

}  // namespace rouleau
