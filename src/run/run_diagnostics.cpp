#include "run/run_diagnostics.hpp"

#include "cells/cell_shape.hpp"
#include "fluid/flow_rates.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace rouleau {

FluidDiagnostics::FluidDiagnostics(const CaseConfig& config, const FluidMesh& mesh) : config_(config) {
  if (config.vessel.enabled) boundary_integrals_ = std::make_unique<BoundaryIntegrals>(mesh);
}

std::vector<std::string> FluidDiagnostics::columns() const {
  const CaseConfig& config = config_;
  std::vector<std::string> names{"step", "time_s", "newton_iterations", "gmres_iterations", "momentum_residual",
                                 "continuity_residual", "mean_velocity_x_um_s", "mean_velocity_y_um_s",
                                 "mean_velocity_z_um_s", "fluid_kinetic_energy_pN_um"};
  if (config.vessel.enabled)
    names.insert(names.end(), {"flow_rate_inlet_um3_s", "flow_rate_outlet_um3_s", "driving_pressure_Pa",
                               "mean_wall_shear_stress_Pa", "relative_apparent_viscosity"});
  else
    names.insert(names.end(), {"wall_shear_stress_y_min_Pa", "wall_shear_stress_y_max_Pa", "relative_apparent_viscosity"});
  names.push_back("wall_time_s");
  return names;
}

// Flow rates in and out, driving pressure, mean wall shear stress, relative apparent viscosity.
std::vector<double> FluidDiagnostics::vessel_row(FluidSolver& solver, const ImmersedTerms& immersed) const {
  const BoundaryIntegrals& integrals = *boundary_integrals_;
  std::vector<double> velocity, pressure;
  solver.velocity_and_pressure(velocity, pressure);
  const double inflow = -integrals.flow_rate(velocity, "inlet");
  const double outflow = integrals.flow_rate(velocity, "outlet");
  const double driving_pressure = integrals.mean_pressure(pressure, "inlet") - integrals.mean_pressure(pressure, "outlet");
  // The force the fluid exerts on the wall along the axis, per wall area.
  const double wall_shear = solver.boundary_forces({"wall"}, immersed)[0][0] / integrals.area("wall");
  const double plasma_drop = vessel_poiseuille_drop(config_.vessel.profile, config_.fluid.viscosity, outflow);
  return {inflow, outflow, driving_pressure, wall_shear, plasma_drop != 0.0 ? driving_pressure / plasma_drop : NAN};
}

// Wall shear stress on the y walls and τ_w / (μ γ̇).
std::vector<double> FluidDiagnostics::shear_box_row(FluidSolver& solver, const ImmersedTerms& immersed) const {
  const DomainConfig& domain = config_.domain;
  const double area = (domain.upper[0] - domain.lower[0]) * (domain.upper[2] - domain.lower[2]);
  double shear[2] = {NAN, NAN};
  std::vector<std::string> walls;
  for (int k = 0; k < 2; ++k)
    if (domain.boundary[Side::y_min + k].type == BoundaryType::wall) walls.push_back(side_names[Side::y_min + k]);
  const auto forces = solver.boundary_forces(walls, immersed);
  for (size_t w = 0; w < walls.size(); ++w) {
    const int k = walls[w] == side_names[Side::y_min] ? 0 : 1;
    // τ_w = μ ∂u_x/∂y at the wall = −n_y F_x / A, with F the force the fluid exerts on the
    // wall and n_y the fluid's outward normal: positive on both walls in simple shear.
    const double outward_normal_y = k == 0 ? -1.0 : 1.0;
    shear[k] = -outward_normal_y * forces[w][0] / area;
  }
  // Simple shear between the y walls: γ̇ = (U_top − U_bottom)/H, τ_w = μ γ̇ for plasma alone.
  double relative_viscosity = NAN;
  const double height = domain.upper[1] - domain.lower[1];
  const double shear_rate =
      (domain.boundary[Side::y_max].velocity[0] - domain.boundary[Side::y_min].velocity[0]) / height;
  if (std::isfinite(shear[1]) && shear_rate != 0.0)
    relative_viscosity = shear[1] / (config_.fluid.viscosity * shear_rate);
  return {shear[0], shear[1], relative_viscosity};
}

std::vector<double> FluidDiagnostics::row(FluidSolver& solver, int step, const FluidSolveReport& report,
                                          double wall_time, const ImmersedTerms& immersed) const {
  const auto u = solver.mean_velocity();
  std::vector<double> values{double(step),
                             solver.time(),
                             double(report.newton_iterations),
                             double(report.gmres_iterations),
                             report.momentum_residual,
                             report.continuity_residual,
                             u[0],
                             u[1],
                             u[2],
                             solver.kinetic_energy()};
  const std::vector<double> domain_values = boundary_integrals_ ? vessel_row(solver, immersed) : shear_box_row(solver, immersed);
  values.insert(values.end(), domain_values.begin(), domain_values.end());
  values.push_back(wall_time);
  return values;
}

CellDiagnostics::CellDiagnostics(const CaseCells& cells, const CaseConfig& config, const Communicator* ranks)
    : ranks_(ranks) {
  if (cells.population)
    for (const CellMeasures& m : cells.population->measures()) initial_volumes_.push_back(m.volume);
  if (cells.population && cells.population->num_cells() > 1 &&
      cells.population->num_cells() <= config.output.cell_gaps_max_cells)
    gaps_ = std::make_unique<CellGaps>(*cells.population, config.interaction.morse.zero_force_length);
  if (cells.population && cells.interaction) rim_band_ = std::make_unique<RimBand>(*cells.population);
}

std::vector<std::string> CellDiagnostics::columns() const {
  std::vector<std::string> names{"elastic_energy_pN_um", "interaction_energy_pN_um", "neighbor_list_rebuilds",
                                 "largest_relative_volume_change", "smallest_volume_ratio"};
  for (std::size_t c = 0; c < initial_volumes_.size(); ++c) {
    const std::string cell = "cell" + std::to_string(c) + "_";
    for (const char* name : {"volume_um3", "centroid_x_um", "centroid_y_um", "centroid_z_um", "inclination_deg",
                             "taylor_deformation", "extent_x_um", "extent_y_um", "extent_z_um", "radius_front_um",
                             "radius_rear_um"})
      names.push_back(cell + name);
  }
  for (std::size_t a = 0; a < initial_volumes_.size() && gaps_; ++a)
    for (std::size_t b = a + 1; b < initial_volumes_.size(); ++b) {
      const std::string pair = std::to_string(a) + "_" + std::to_string(b);
      names.push_back("gap_" + pair + "_um");
      names.push_back("contact_area_" + pair + "_um2");
    }
  if (rim_band_) {
    names.push_back("interaction_rim_share");
    names.push_back("rim_area_share");
  }
  return names;
}

std::vector<double> CellDiagnostics::row(const CaseCells& cells, const CellForceState& forces) const {
  double energies[2] = {forces.elastic_energy, forces.interaction_energy};
  // Each rank's share of the cells' work: the energies are the sums of the shares.
  if (ranks_ && cells.population->work_is_shared()) ranks_->sum(energies, 2);
  const double elastic = energies[0], interaction = energies[1];
  const double rebuilds = cells.interaction ? cells.interaction->rebuild_count() : 0.0;
  double largest_change = 0.0;
  const std::vector<CellMeasures> now = cells.population->measures();
  const std::vector<ShearPlaneShape> shapes = shear_plane_shapes(*cells.population, now, cells.membrane_depth);
  // J = det F of the most compressed element of all cells (every rank holds every cell's
  // positions, so no reduction).
  const double smallest_volume_ratio = cells.population->most_compressed_element().volume_ratio;
  std::vector<double> values{elastic, interaction, rebuilds, 0.0, smallest_volume_ratio};
  for (std::size_t c = 0; c < now.size(); ++c) {
    largest_change = std::max(largest_change, std::fabs(now[c].volume / initial_volumes_[c] - 1.0));
    values.insert(values.end(), {now[c].volume, now[c].centroid[0], now[c].centroid[1], now[c].centroid[2],
                                 shapes[c].inclination_deg, shapes[c].taylor_deformation, shapes[c].extent[0],
                                 shapes[c].extent[1], shapes[c].extent[2], shapes[c].radius_front,
                                 shapes[c].radius_rear});
  }
  values[3] = largest_change;
  if (gaps_)
    for (const CellPairGap& pair : gaps_->measure()) values.insert(values.end(), {pair.gap, pair.contact_area});
  if (rim_band_) {
    // Node-major on the host, whatever the device's layout.
    auto mirror = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), forces.interaction);
    std::vector<double> interaction(3 * mirror.extent(0));
    for (std::size_t n = 0; n < mirror.extent(0); ++n)
      for (int i = 0; i < 3; ++i) interaction[3 * n + i] = mirror(n, i);
    // Each rank's share of the cells' work: the forces are the sums of the shares.
    if (ranks_ && cells.population->work_is_shared())
      ranks_->sum(interaction.data(), static_cast<int>(interaction.size()));
    const bool computed = interaction.size() == 3 * rim_band_->in_band().size();  // none when the stage is skipped
    values.insert(values.end(), {computed ? rim_band_->force_share(interaction.data()) : 0.0, rim_band_->area_share()});
  }
  return values;
}

namespace {
const std::vector<const char*> coupling_stages{
    ImmersedCoupling::elastic_stage, ImmersedCoupling::interaction_stage, ImmersedCoupling::wall_stage,
    ImmersedCoupling::inertia_stage,
    ImmersedCoupling::spread_stage,  ImmersedCoupling::stiffness_stage,   ImmersedCoupling::fluid_stage,
    ImmersedCoupling::interpolate_stage, ImmersedCoupling::film_stage, ImmersedCoupling::move_stage};

// "RKPM spread" → "time_rkpm_spread_s", "cell stiffness (semi-implicit)" →
// "time_cell_stiffness_semi_implicit_s": letters and digits, one '_' for each run of others.
std::string time_column(const std::string& stage) {
  std::string name = "time_";
  for (char c : stage) {
    if (std::isalnum(static_cast<unsigned char>(c)))
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (name.back() != '_')
      name += '_';
  }
  if (name.back() == '_') name.pop_back();
  return name + "_s";
}
}  // namespace

std::vector<std::string> CouplingDiagnostics::columns() const {
  std::vector<std::string> names{"power_spread_pN_um_s", "power_interpolated_pN_um_s", "largest_cell_speed_um_s",
                                 "rkpm_corrected_points"};
  for (const char* stage : coupling_stages) names.push_back(time_column(stage));
  return names;
}

std::vector<double> CouplingDiagnostics::row(const ImmersedCoupling::StepReport& report, const StageTimes& times) {
  std::vector<double> values{report.power_spread, report.power_interpolated, report.largest_cell_speed,
                             double(report.corrected_points)};
  seconds_at_last_row_.resize(coupling_stages.size(), 0.0);
  for (std::size_t s = 0; s < coupling_stages.size(); ++s) {
    const double total = times.seconds(coupling_stages[s]);
    values.push_back(total - seconds_at_last_row_[s]);
    seconds_at_last_row_[s] = total;
  }
  return values;
}

}  // namespace rouleau
