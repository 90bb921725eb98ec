// Strong and weak scaling of the distributed fluid solve (bench/mpi.md): run under
// `mpiexec -n P`, it times on the shear box (periodic in x and z, moving walls in y,
// Stokes limit, the element path on every rank) the pieces of a GMRES iteration across
// ranks and writes one CSV row (rank 0):
//   action_s      one distributed Stokes action: update_copies, the rank's elements with
//                 their node sums (sum_into_owners) travelling while the interior elements
//                 are summed, Dirichlet rows (median of --repeats)
//   action_after_loop_s  the same with every exchange completed where it is posted (no
//                 overlap), timed in alternation with action_s
//   boundary_elements  elements touching a shared node (largest over ranks)
//   exchange_s    update_copies + sum_into_owners alone (the halo's share of an action)
//   allreduce_s   one MPI_Allreduce of 61 doubles (a CGS2 pass over a GMRES(60) basis)
//   iteration_s   a GMRES(30) iteration with point-block Jacobi: 30 iterations, timed,
//                 with NodeSums' default overlap (off on CPU threads, on on GPUs)
//   halo_values   values one rank sends per update_copies (largest over ranks)
//
//   mpiexec -n P bench/mpi_scaling --elements NX NY NZ [--repeats 20]
// bench/mpi_scaling.py runs it for 1 and 2 ranks (strong: one box; weak: the box grown in
// x with the ranks) and writes bench/mpi_scaling.csv with the communication model.
#include <mpi.h>

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "distributed/distributed_fluid_operator.hpp"
#include "distributed/local_mesh.hpp"
#include "distributed/node_halo.hpp"
#include "distributed/node_sums.hpp"
#include "fluid/boundary_conditions.hpp"
#include "fluid/fluid_operator.hpp"
#include "parallel/communicator.hpp"
#include "solver/gmres.hpp"

namespace {

using namespace rouleau;

// The median over ranks' maxima: each repeat takes the slowest rank's time.
template <class Work>
double median_time(const Communicator& world, int repeats, const Work& work) {
  std::vector<double> times;
  work();  // warm-up
  for (int r = 0; r < repeats; ++r) {
    Kokkos::fence();
    world.barrier();
    Kokkos::Timer timer;
    work();
    Kokkos::fence();
    times.push_back(world.max(timer.seconds()));
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  return times[times.size() / 2];
}

// The medians of two variants timed in alternation (a, b, a, b, ...), so that a slow spell
// of a shared machine weighs on both alike; their ratio is the figure to read.
template <class First, class Second>
std::pair<double, double> paired_median_times(const Communicator& world, int repeats, const First& first,
                                              const Second& second) {
  std::vector<double> first_times, second_times;
  for (int r = 0; r < repeats; ++r) {
    first_times.push_back(median_time(world, 1, first));
    second_times.push_back(median_time(world, 1, second));
  }
  const auto median = [](std::vector<double>& t) {
    std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
    return t[t.size() / 2];
  };
  return {median(first_times), median(second_times)};
}

int run(int argc, char** argv) {
  std::array<int, 3> elements{32, 16, 16};
  int repeats = 20;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--elements") && i + 3 < argc) {
      for (int d = 0; d < 3; ++d) elements[d] = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--repeats") && i + 1 < argc) {
      repeats = std::atoi(argv[++i]);
    }
  }
  const Communicator world = Communicator::world();
  // 1 μm elements
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {1.0 * elements[0], 1.0 * elements[1], 1.0 * elements[2]},
                                       elements, {1, 1, 1}, {true, false, true});
  std::array<BoundaryConfig, 6> sides{};
  sides[Side::x_min].type = sides[Side::x_max].type = BoundaryType::periodic;
  sides[Side::z_min].type = sides[Side::z_max].type = BoundaryType::periodic;
  sides[Side::y_min].velocity = {-1.0, 0.0, 0.0};
  sides[Side::y_max].velocity = {1.0, 0.0, 0.0};
  const FluidBoundaryConditions bc = build_boundary_conditions(mesh, sides, FluidScales{});
  FluidCoefficients c;
  c.convection = 0;
  c.reynolds = 1e-3;
  c.mass_coefficient = 1.5 / 0.05;
  c.inverse_dt = 1.0 / 0.05;

  const ElementPartition partition = partition_fluid_mesh(mesh, world.rank(), world.size());
  FluidOperator local(make_local_mesh(mesh, partition), 1.0);
  local.set_coefficients(c);
  NodeSums sums(world, partition);
  local.set_node_sums(&sums);
  const NodeHalo halo(world, partition, 4);
  const std::vector<int> dirichlet = owned_local_unknowns(partition, bc.dirichlet_dofs);
  const DistributedStokesOperator A(local, partition, dirichlet);
  DistributedBlockJacobi jacobi(world, partition, dirichlet);
  Vector local_zero("local_zero", 4 * partition.num_local_nodes());
  jacobi.factor(local, local_zero);
  const int owned = A.num_owned_unknowns();
  Vector x("x", owned), y("y", owned), local_vector("local_vector", 4 * partition.num_local_nodes());
  Kokkos::deep_copy(x, 1.0);

  // overlapped, and the baseline: every exchange completed where it is posted
  const bool default_overlap = sums.overlaps();  // the GMRES iteration below runs the default
  const auto [action, action_after_loop] = paired_median_times(
      world, repeats,
      [&] {
        sums.set_overlap(true);
        A.apply(x, y);
      },
      [&] {
        sums.set_overlap(false);
        A.apply(x, y);
      });
  sums.set_overlap(default_overlap);
  const double exchange = median_time(world, repeats, [&] {
    halo.update_copies(local_vector);
    halo.sum_into_owners(local_vector);
  });
  std::vector<double> coefficients(61, 1.0);
  const double allreduce = median_time(world, repeats, [&] { world.sum(coefficients.data(), 61); });
  GmresSettings settings;
  settings.restart = 30;
  settings.max_iterations = 30;
  settings.relative_tolerance = 1e-300;  // exactly 30 iterations
  Gmres gmres(owned, settings, &world);
  Vector b("b", owned), solution("solution", owned);
  Kokkos::deep_copy(b, 1.0);
  const double thirty = median_time(world, std::max(3, repeats / 5), [&] {
    Kokkos::deep_copy(solution, 0.0);
    gmres.solve(A, jacobi, b, solution);
  });

  const double halo_values = world.max(static_cast<double>(halo.values_per_update()));
  const double elements_per_rank = world.max(static_cast<double>(partition.elements.size()));
  const double boundary_elements = world.max(static_cast<double>(partition.num_boundary_elements));
  if (world.rank() == 0) {
    std::printf("ranks,threads,elements_x,elements_y,elements_z,unknowns,elements_per_rank,halo_values,action_s,"
                "action_after_loop_s,exchange_s,allreduce_s,iteration_s,boundary_elements\n");
    std::printf("%d,%d,%d,%d,%d,%d,%.0f,%.0f,%.6e,%.6e,%.6e,%.6e,%.6e,%.0f\n", world.size(),
                Kokkos::DefaultExecutionSpace().concurrency(), elements[0], elements[1], elements[2],
                mesh.num_unknowns(), elements_per_rank, halo_values, action, action_after_loop, exchange, allreduce,
                thirty / 30.0, boundary_elements);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  int provided = 0;  // OpenMP threads beside MPI; only the main thread calls MPI
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int status = 0;
  {
    Kokkos::ScopeGuard kokkos(argc, argv);
    status = run(argc, argv);
  }
  MPI_Finalize();
  return status;
}
