#pragma once
// Fast diagonalization of the Stokes operator of a periodic box (Lynch, Rice & Thomas
// 1964), the fluid's preconditioner on the shear boxes.
//
// On a structured box of identical hexahedra in the Stokes limit the operator A does not
// change under a shift by whole elements along a periodic direction: A_(n,m) depends on the
// two nodes' wall planes j, j' and on their offset along the periodic directions only. A
// discrete Fourier transform along the two periodic directions (wave numbers κ = 2π k / N)
// therefore turns A into one small problem per pair of wave numbers, coupling the wall
// planes:
//     Â_κ(j, j') = Σ_m A_((m, j), (0, j')) e^(−i κ·m),    Â_κ ŵ_κ = r̂_κ,
// a banded complex matrix of 4 unknowns per plane (each row reaches two planes either side:
// the stencil's neighbours and the PSPG viscous term's projected gradient at theirs). Each
// is factored once (LAPACK's banded LU with partial pivoting), and an application is a
// forward transform, one banded solve per wave-number pair and an inverse transform: the
// exact inverse of the fluid's operator (in a stack_shear profile its banded solves take
// 3 % of a step, the stencil 6 %).
//
// The blocks Â_κ are not derived by hand but read off the operator itself, so they are
// exactly what GMRES applies: the operator is applied to unit vectors at one node of every
// fifth wall plane (planes five apart do not reach each other), four components at a time,
// and the responses are transformed. The pressure's level, pinned at dof node 0, is the
// one row that is not shift-invariant; the zero wave number instead fixes the mean pressure
// of the node's wall plane. The two differ by a rank-one term, which GMRES removes in one
// iteration. What the cells add (the semi-implicit stiffness) is left to GMRES.
//
// Needs: a structured box (make_box_mesh) of hexahedra uniform along its two periodic
// directions (graded across the walls or not), at least 6 elements along one of them, the
// Stokes operator (no convection), one rank, and a memory space the host can read (FFTW and
// LAPACK run on the host threads).
#include <Kokkos_Core.hpp>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "fluid/fluid_preconditioner.hpp"
#include "mesh/fluid_mesh.hpp"

namespace rouleau {

class FastDiagonalization final : public FluidPreconditioner {
 public:
  // Why `mesh` does not allow it; empty when it does (the operator's own conditions, the
  // uniform elements and the Stokes limit, are checked by factor()).
  static std::string unavailable_reason(const FluidMesh& mesh);

  explicit FastDiagonalization(const FluidMesh& mesh);
  ~FastDiagonalization() override;
  FastDiagonalization(const FastDiagonalization&) = delete;
  FastDiagonalization& operator=(const FastDiagonalization&) = delete;

  // Reads the blocks Â_κ off `op` (its Stokes operator; the state does not enter) and
  // factors them. Throws when a block is singular (an operator that is not shift-invariant
  // is not detected otherwise: it makes a weaker preconditioner).
  void factor(const FluidOperator& op, const ConstVector& state) override;
  // z = M⁻¹ r.
  void apply(const ConstVector& r, const Vector& z) const override;

  // Unknowns per wave-number pair (4 per wall plane), and the pairs.
  int unknowns_per_wave() const { return unknowns_per_wave_; }
  int waves() const { return waves_; }

 private:
  // Forward transform of the rank's vector `x` into spectrum_ (layout [wave][plane][c]).
  void transform(const double* x) const;
  // Inverse transform of spectrum_ into `x` (scaled: the exact inverse of transform()).
  void inverse_transform(double* x) const;

  struct Plans;  // FFTW's plans (fftw3.h stays in the .cpp)
  std::unique_ptr<Plans> plans_;
  int wall_ = 1;                     // the direction that is not periodic
  int first_ = 0, last_ = 2;         // the periodic directions; `last_`'s spectrum is halved
  int wall_planes_ = 0, first_count_ = 0, last_count_ = 0;
  int wall_stride_ = 0;              // entries between consecutive wall planes
  int first_stride_ = 0, last_stride_ = 0;
  int unknowns_per_wave_ = 0, waves_ = 0;
  // Bands either side: a row reaches 2 wall planes of 4 unknowns either way.
  static constexpr int bands = 4 * (2 + 1) - 1;
  int lower_bands_ = bands, upper_bands_ = bands, band_rows_ = 0;
  std::vector<std::complex<double>> bands_;  // LAPACK band storage, [wave][band_rows × n]
  std::vector<int> pivots_;                  // [wave][n]
  mutable std::vector<std::complex<double>> spectrum_;
  int num_unknowns_ = 0;
};

}  // namespace rouleau
