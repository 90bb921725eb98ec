#pragma once
// Restarted GMRES(m) with right preconditioning, for the matrix-free fluid operator.
//
// Solves A x = b. With right preconditioning A M⁻¹ y = b, x = M⁻¹ y, the residual that
// GMRES minimizes is the true residual b − A x, so the tolerance means what it says.
// The Krylov basis is a LayoutLeft (n × m+1) View; orthogonalization is classical
// Gram–Schmidt applied twice (CGS2, solver/gram_schmidt.hpp): three sweeps over the basis
// per iteration, each with one reduction of all its dot products, instead of m separate
// ones. The small Hessenberg least
// squares problem is solved on the host with Givens rotations.
#include <Kokkos_Core.hpp>

#include "parallel/communicator.hpp"
#include "solver/gram_schmidt.hpp"
#include "solver/linear_operator.hpp"

namespace rouleau {

struct GmresSettings {
  int restart = 60;
  double relative_tolerance = 1e-8;  // on ‖b − A x‖ / ‖b‖
  double absolute_tolerance = 0.0;
  int max_iterations = 3000;
};

struct GmresResult {
  bool converged = false;
  int iterations = 0;
  double initial_residual = 0.0;  // ‖b − A x0‖
  double final_residual = 0.0;    // ‖b − A x‖ (recomputed at the end)
};

class Gmres {
 public:
  // With a communicator of more than one rank, n is this rank's share of the unknowns (its
  // owned entries), A and M act on those shares, and every norm and product is summed over
  // the ranks; the iterates are those of one rank up to round-off.
  Gmres(int n, const GmresSettings& settings, const Communicator* communicator = nullptr);
  // x holds the initial guess on entry and the solution on exit. `relative_tolerance`
  // overrides the settings' one for this solve when positive (inexact Newton).
  GmresResult solve(const LinearOperator& A, const Preconditioner& M, const Kokkos::View<const double*>& b,
                    const Kokkos::View<double*>& x, double relative_tolerance = 0.0);
  const GmresSettings& settings() const { return settings_; }

 private:
  // ‖v‖ over all ranks
  double norm(const Kokkos::View<const double*>& v) const;
  GmresSettings settings_;
  const Communicator* communicator_;
  // Makes room for `columns` basis vectors (at most m + 1), keeping those held: the basis
  // grows with the iterations solves have needed, by doubling, so a preconditioner that
  // solves in a few iterations does not pay m + 1 vectors of memory. It grows in the first
  // solves of a run, not once the iteration counts have settled.
  void reserve_basis(int columns);
  Kokkos::View<double**, Kokkos::LayoutLeft> basis_;  // V: n × (columns held, ≤ m+1)
  GramSchmidt gram_schmidt_;
  Kokkos::View<double*> work_, preconditioned_, correction_;
  Kokkos::View<double*> projection_;  // h: m+1 coefficients of one Gram–Schmidt pass
};

}  // namespace rouleau
