// What the time loop allocates and moves between memory spaces, counted through Kokkos'
// profiling hooks: after warm-up, a time step (of the fluid alone, and coupled with cells)
// allocates nothing, and may copy whole fields between device Views (BDF history,
// preconditioner input), but nothing through a host mirror. On a GPU build a
// host mirror is the only way a field reaches the host, so this guards the hot path
// against per-step host-device copies (docs/design.md: the host only reads scalars).
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <cstdint>
#include <cstring>
#include <string>

#include "config/load_case.hpp"
#include "fluid/fluid_solver.hpp"
#include "run/simulation.hpp"
#include "temporary_folder.hpp"

namespace rouleau {
namespace {

struct CopyCount {
  int copies = 0;          // deep copies between Views (fills excluded)
  int fills = 0;           // deep_copy(View, scalar)
  int through_mirror = 0;  // copies whose source or destination is a host mirror
  std::uint64_t bytes = 0;
  int allocations = 0;     // Kokkos allocations (Views, scatter buffers)
  std::string first_allocation;
};
CopyCount counted;

bool is_mirror(const char* label) {
  const std::size_t n = std::strlen(label);
  return n >= 7 && std::strcmp(label + n - 7, "_mirror") == 0;
}

// Kokkos_Profiling_beginDeepCopyFunction: destination handle/name/pointer, source
// handle/name/pointer, size in bytes. deep_copy(View, value) reports the source "Scalar".
void count_deep_copy(Kokkos_Profiling_SpaceHandle, const char* destination, const void*, Kokkos_Profiling_SpaceHandle,
                     const char* source, const void*, std::uint64_t size) {
  if (std::strcmp(source, "Scalar") == 0) {
    ++counted.fills;
    return;
  }
  ++counted.copies;
  counted.bytes += size;
  if (is_mirror(destination) || is_mirror(source)) ++counted.through_mirror;
}

// Kokkos_Profiling_allocateDataFunction: space handle, label, pointer, size in bytes.
void count_allocation(Kokkos_Profiling_SpaceHandle, const char* label, const void*, std::uint64_t) {
  if (counted.allocations++ == 0) counted.first_allocation = label;
}

// Counts from start_counting() to stop_counting() into `counted`.
void start_counting() {
  counted = CopyCount{};
  Kokkos::Tools::Experimental::set_begin_deep_copy_callback(count_deep_copy);
  Kokkos::Tools::Experimental::set_allocate_data_callback(count_allocation);
}
void stop_counting() {
  Kokkos::Tools::Experimental::set_begin_deep_copy_callback(nullptr);
  Kokkos::Tools::Experimental::set_allocate_data_callback(nullptr);
}

// A shear box's transient Stokes steps after warm-up, with the multigrid and with the fast
// diagonalization (the shear boxes' default).
class HotPathPreconditioners : public ::testing::TestWithParam<PreconditionerType> {};

TEST_P(HotPathPreconditioners, TimeStepsAllocateNothingAndCopyNothingThroughAHostMirror) {
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {2, 1, 1}, {8, 8, 4}, {1, 1, 1}, {true, false, true});
  std::array<BoundaryConfig, 6> sides{};
  sides[Side::x_min].type = sides[Side::x_max].type = BoundaryType::periodic;
  sides[Side::z_min].type = sides[Side::z_max].type = BoundaryType::periodic;
  sides[Side::y_max].velocity = {1.0, 0.0, 0.0};
  FluidConfig fluid;
  fluid.viscosity = 1.0;
  fluid.density = 1.0;
  FluidScales scales;
  scales.reynolds = 1.0;
  SolverConfig settings;
  settings.preconditioner = GetParam();
  FluidSolver solver(mesh, fluid, sides, settings, scales, true);
  for (int step = 0; step < 2; ++step) ASSERT_TRUE(solver.advance(0.01, TimeScheme::bdf2).converged);

  start_counting();
  const int steps = 3;
  int gmres_iterations = 0;
  for (int step = 0; step < steps; ++step) {
    const FluidSolveReport report = solver.advance(0.01, TimeScheme::bdf2);
    ASSERT_TRUE(report.converged) << report.failure;
    gmres_iterations += report.gmres_iterations;
  }
  stop_counting();

  const double field_bytes = 8.0 * mesh.num_unknowns();
  std::printf("per step: %.1f copies (%.1f whole fields), %.1f fills, %d through a host mirror, %.1f allocations "
              "(first: %s); %.1f GMRES iterations\n",
              double(counted.copies) / steps, counted.bytes / field_bytes / steps, double(counted.fills) / steps,
              counted.through_mirror, double(counted.allocations) / steps, counted.first_allocation.c_str(),
              double(gmres_iterations) / steps);
  EXPECT_GT(counted.copies, 0);  // the hook is live: BDF shifts its history every step
  EXPECT_EQ(counted.through_mirror, 0);
  EXPECT_EQ(counted.allocations, 0) << "first: " << counted.first_allocation;
}

INSTANTIATE_TEST_SUITE_P(HotPath, HotPathPreconditioners,
                         ::testing::Values(PreconditionerType::multigrid, PreconditionerType::fast_diagonalization),
                         [](const ::testing::TestParamInfo<PreconditionerType>& info) {
                           return info.param == PreconditionerType::multigrid ? std::string("Multigrid")
                                                                              : std::string("FastDiagonalization");
                         });

TEST(HotPath, CoupledStepsWithCellsAllocateNothingAndCopyNothingThroughAHostMirror) {
  // The aggregation scene (two red cells face to face, the Morse interaction on, the
  // semi-implicit coupling) at h_f = 1 μm: after warm-up (the interaction's neighbour list
  // and the RKPM supports built), a coupled step, with its cell forces, spreading, the cells'
  // stiffness inside GMRES, interpolation and move, allocates nothing and copies nothing
  // through a host mirror.
  const CaseConfig config = load_case(std::string(ROULEAU_SOURCE_DIR) + "/cases/aggregation/case.toml",
                                      {"domain.elements=[12, 12, 10]"});
  Simulation simulation(config, (testing::temporary_folder("hot_path_cells") / "meshes").string());
  ASSERT_NE(simulation.coupling(), nullptr);
  for (int step = 0; step < 3; ++step) simulation.advance();

  start_counting();
  const int steps = 3;
  int gmres_iterations = 0;
  for (int step = 0; step < steps; ++step) gmres_iterations += simulation.advance().fluid.gmres_iterations;
  stop_counting();

  std::printf("per coupled step: %.1f copies (%.2f MB), %.1f fills, %d through a host mirror, %.1f allocations "
              "(first: %s); %.1f GMRES iterations\n",
              double(counted.copies) / steps, counted.bytes / 1e6 / steps, double(counted.fills) / steps,
              counted.through_mirror, double(counted.allocations) / steps, counted.first_allocation.c_str(),
              double(gmres_iterations) / steps);
  EXPECT_GT(gmres_iterations, 0);
  EXPECT_EQ(counted.through_mirror, 0);
  EXPECT_EQ(counted.allocations, 0) << "first: " << counted.first_allocation;
}

}  // namespace
}  // namespace rouleau
