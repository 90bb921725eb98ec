#include "coupling/cell_fluid_transfer.hpp"

#include <stdexcept>
#include <vector>

#include "config/cell_kinds.hpp"
#include "kernels/scatter_sum.hpp"
#include "kernels/shell_midsurface.hpp"
#include "run/profiling_region.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;
}

CellFluidTransfer::CellFluidTransfer(const FluidMesh& mesh, double support_factor, const CaseCells& cells,
                                     const CaseConfig& config, bool shell_midsurface)
    : at_nodes_(mesh, support_factor) {
  if (!shell_midsurface || !cells.population) return;
  const CellPopulation& population = *cells.population;
  const int nodes = population.num_nodes();
  std::vector<std::array<int, 3>> triangles;
  std::vector<double> depth(nodes, 0.0);
  for (int c = 0; c < population.num_cells(); ++c) {
    if (cells.membrane_depth.at(c) <= 0.0) continue;
    const CellKindConfig* kind = find_cell_kind(config, config.cells.at(c).kind);
    if (!kind) throw std::logic_error("rouleau::CellFluidTransfer: unknown cell kind " + config.cells[c].kind);
    const CellMesh& cell_mesh = cells.meshes.at(kind->name);
    const int first = population.cell_first_node()[c];
    // The outer surface's normals point out of the cell and the cavity wall's into the
    // cavity: both out of the solid.
    for (const auto* surface : {&cell_mesh.outer_surface, &cell_mesh.inner_surface})
      for (const auto& t : *surface) triangles.push_back({first + t[0], first + t[1], first + t[2]});
    for (std::size_t n = 0; n < cell_mesh.nodes.size(); ++n) depth[first + n] = cells.membrane_depth[c];
  }
  midsurface_.reset(new Midsurface{RkpmCoupler(mesh, support_factor),
                                   Kokkos::View<int* [3]>("rouleau::CellFluidTransfer::triangles", triangles.size()),
                                   Kokkos::View<double*>("rouleau::CellFluidTransfer::depth", nodes),
                                   NodeVectors("rouleau::CellFluidTransfer::normals", nodes),
                                   NodeVectors("rouleau::CellFluidTransfer::points", nodes),
                                   NodeVectors("rouleau::CellFluidTransfer::values", nodes),
                                   NodeVectors("rouleau::CellFluidTransfer::tangential", nodes),
                                   NodeVectors("rouleau::CellFluidTransfer::normal", nodes),
                                   Scatter("rouleau::CellFluidTransfer::normal_scatter", nodes)});
  auto triangles_host = Kokkos::create_mirror_view(midsurface_->triangles);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) triangles_host(t, k) = triangles[t][k];
  Kokkos::deep_copy(midsurface_->triangles, triangles_host);
  auto depth_host = Kokkos::create_mirror_view(midsurface_->depth);
  for (int n = 0; n < nodes; ++n) depth_host(n) = depth[n];
  Kokkos::deep_copy(midsurface_->depth, depth_host);
}

void CellFluidTransfer::update(const NodeVectors& positions) {
  at_nodes_.update(positions);
  if (!midsurface_) return;
  ProfilingRegion region("rouleau::CellFluidTransfer::midsurface_points");
  Midsurface& m = *midsurface_;
  m.normal_scatter.reset();
  SurfaceNormalSumFunctor<Scatter> normal_sums{positions, m.triangles, m.normal_scatter};
  Kokkos::parallel_for("rouleau::CellFluidTransfer::normal_sums",
                       Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(m.triangles.extent(0))), normal_sums);
  gather_into(m.normals, m.normal_scatter);
  MidsurfacePointsFunctor points{positions, m.depth, m.normals, m.points};
  Kokkos::parallel_for("rouleau::CellFluidTransfer::midsurface_points",
                       Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(positions.extent(0))), points);
  m.rkpm.update(m.points);
}

void CellFluidTransfer::interpolate(const Kokkos::View<const double*>& nodal, int stride,
                                    const NodeVectors& values) const {
  at_nodes_.interpolate(nodal, stride, values);
  if (!midsurface_) return;
  const Midsurface& m = *midsurface_;
  m.rkpm.interpolate(nodal, stride, m.values);
  Kokkos::parallel_for("rouleau::CellFluidTransfer::shell_velocity",
                       Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(values.extent(0))),
                       ShellVelocityFunctor{m.normals, m.values, values});
}

void CellFluidTransfer::spread(const NodeVectors& forces, const Kokkos::View<double*>& nodal, int stride) const {
  if (!midsurface_) {
    at_nodes_.spread(forces, nodal, stride);
    return;
  }
  const Midsurface& m = *midsurface_;
  Kokkos::parallel_for("rouleau::CellFluidTransfer::split_forces",
                       Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(forces.extent(0))),
                       ShellForceSplitFunctor{m.normals, forces, m.tangential, m.normal});
  at_nodes_.spread(m.tangential, nodal, stride);
  m.rkpm.spread(m.normal, nodal, stride);
}

int CellFluidTransfer::corrected_points() const {
  return at_nodes_.corrected_points() + (midsurface_ ? midsurface_->rkpm.corrected_points() : 0);
}

void CellFluidTransfer::always_correct(bool yes) {
  at_nodes_.always_correct(yes);
  if (midsurface_) midsurface_->rkpm.always_correct(yes);
}

}  // namespace rouleau
