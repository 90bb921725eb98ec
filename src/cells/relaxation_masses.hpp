#pragma once
// The fictitious masses of the static solve's dynamic relaxation (Underwood 1983), its
// preconditioner: a block-Gershgorin bound of the small-strain stiffness per unit modulus,
//   m_a = Σ_{e ∋ a} V0_e |∇N_a| Σ_b |∇N_b|,
// so that every node has about the same stable step; computed once, from the reference
// configuration, with 1/√m_a for the mass-scaled variables y = M^(1/2) x.
#include <Kokkos_Core.hpp>

#include "cells/cell_population.hpp"

namespace rouleau {

template <class ExecSpace>
class BasicRelaxationMasses {
 public:
  explicit BasicRelaxationMasses(const BasicCellPopulation<ExecSpace>& cells);

  const Kokkos::View<double*>& masses() const { return mass_; }                            // m_a
  const Kokkos::View<double*>& inverse_sqrt_masses() const { return inverse_sqrt_mass_; }  // 1/√m_a (0 where m_a = 0)

  // (public: CUDA lambdas may not live in constructors or private members)
  void compute(const BasicCellPopulation<ExecSpace>& cells);

 private:
  Kokkos::View<double*> mass_, inverse_sqrt_mass_;
};

extern template class BasicRelaxationMasses<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
