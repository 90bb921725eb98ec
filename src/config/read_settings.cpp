// The readers of the run's settings: [case], [fluid], [time], [solver], [scales], [output],
// [checkpoint], [coupling], [scene], and the check of the time step against the explicit
// coupling's stable step.
#include <filesystem>

#include "config/case_section_readers.hpp"
#include "config/derived.hpp"
#include "config/load_case.hpp"
#include "util/number_text.hpp"
#include "util/errors.hpp"

namespace rouleau {

std::optional<double> read_density(const TableReader& section) {
  const auto density = section.number("density_kg_m3");
  if (!density) return std::nullopt;
  return *density * density_kg_m3_to_internal;
}

void read_case_section(const TableReader& root, const std::string& path, CaseConfig& config) {
  const TableReader section = root.table("case");
  config.name = section.text("name").value_or(std::filesystem::path(path).stem().string());
  if (config.name.empty()) section.fail("name", "must not be empty");
  assign(config.description, section.text("description"));
}

void read_fluid(const TableReader& root, FluidConfig& fluid) {
  const TableReader section = root.table("fluid");
  assign(fluid.density, read_density(section));
  assign(fluid.viscosity, section.number("viscosity_Pa_s"));
  assign(fluid.body_force, section.number3("body_force_Pa_um"));
}

void read_time(const TableReader& root, TimeConfig& time) {
  const TableReader section = root.table("time");
  assign(time.mode, section.choice<TimeMode>("mode"));
  assign(time.scheme, section.choice<TimeScheme>("scheme"));
  const auto dt = section.number("dt_s");
  const auto end = section.number("end_s");
  if (time.mode == TimeMode::transient) {
    require(section, "dt_s", dt);
    require(section, "end_s", end);
  }
  assign(time.dt, dt);
  assign(time.end, end);
  if (time.end < time.dt)
    section.fail("end_s", "must be ≥ dt_s (" + format_number(time.dt) + "), got " + format_number(time.end));
}

void read_solver(const TableReader& root, SolverConfig& solver) {
  const TableReader section = root.table("solver");
  assign(solver.stokes, section.choice<StokesChoice>("stokes"));
  assign(solver.stokes_reynolds_threshold, section.number("stokes_reynolds_threshold"));
  assign(solver.newton_rtol, section.number("newton_rtol"));
  assign(solver.newton_atol, section.number("newton_atol"));
  assign(solver.newton_step_rtol, section.number("newton_step_rtol"));
  assign(solver.newton_max_iterations, section.integer("newton_max_iterations"));
  assign(solver.gmres_restart, section.integer("gmres_restart"));
  assign(solver.gmres_rtol, section.number("gmres_rtol"));
  assign(solver.gmres_max_iterations, section.integer("gmres_max_iterations"));
  assign(solver.preconditioner, section.choice<PreconditionerType>("preconditioner"));
  assign(solver.multigrid_smoother, section.choice<MultigridSmoother>("multigrid_smoother"));
  assign(solver.multigrid_precision, section.choice<MultigridPrecision>("multigrid_precision"));
  assign(solver.starting_guess_solutions, section.integer("starting_guess_solutions"));
}

void read_scales(const TableReader& root, ScalesConfig& scales) {
  const TableReader section = root.table("scales");
  assign(scales.length, section.number("length_um"));
  assign(scales.velocity, section.number("velocity_um_s"));
}

void read_output(const TableReader& root, OutputConfig& output) {
  const TableReader section = root.table("output");
  assign(output.write_fields, section.boolean("fields"));
  assign(output.fields_every_steps, section.integer("fields_every_steps"));
  assign(output.diagnostics_every_steps, section.integer("diagnostics_every_steps"));
  assign(output.cell_gaps_max_cells, section.integer("cell_gaps_max_cells"));
}

void read_checkpoint(const TableReader& root, CheckpointConfig& checkpoint) {
  const TableReader section = root.table("checkpoint");
  assign(checkpoint.every_steps, section.integer("every_steps"));
  assign(checkpoint.every_minutes, section.number("every_minutes"));
  assign(checkpoint.kept, section.integer("keep"));
}

void read_coupling(const TableReader& root, CouplingConfig& coupling, const InteractionConfig& interaction) {
  const TableReader section = root.table("coupling");
  assign(coupling.scheme, section.choice<CouplingScheme>("scheme"));
  assign(coupling.support_elements, section.number("support_elements"));
  assign(coupling.stable_step_factor, section.number("stable_step_factor"));
  assign(coupling.allow_unstable_step, section.boolean("allow_unstable_step"));
  assign(coupling.forces_in_stabilization, section.boolean("forces_in_stabilization"));
  assign(coupling.subscale_velocity, section.boolean("subscale_velocity"));
  assign(coupling.film_open_gap, section.number("film_open_gap_um"));
  assign(coupling.film_model, section.choice<FilmModel>("film_model"));
  assign(coupling.volume_tolerance, section.number("volume_tolerance"));
  // With the loads in the stabilization, u' = −τ (r − f_h) holds τ f_h: the cells would
  // move with their own forces times a mobility the semi-implicit step does not linearize,
  // explicitly in the stiffest force (the capillary's capsule: +2.8 % volume in 10 steps of
  // 5e-4 s, diverged at step 12).
  if (coupling.forces_in_stabilization && coupling.subscale_velocity &&
      coupling.scheme == CouplingScheme::semi_implicit)
    section.fail("forces_in_stabilization",
                 "cannot be combined with subscale_velocity under scheme = \"semi_implicit\": the subscale velocity "
                 "then carries the cells' own forces, which the semi-implicit step does not linearize (use one of "
                 "the two, or scheme = \"explicit\")");
  // With the Morse law the rigid film's load holds the adhesion, which rigid cells cannot
  // balance short of overlap: the four-cell stack in contact closed its rim films from
  // 0.085 to 0.02 um in 6 steps of 2e-3 s, then sprang 6.7 um apart. Deforming films let
  // the faces flatten instead, implicit in the cells' stiffness (which only the
  // semi-implicit coupling has).
  if (coupling.film_open_gap > 0.0 && interaction.enabled && coupling.film_model == FilmModel::rigid)
    section.fail("film_model",
                 "rigid films do not run with the Morse interaction (interaction.enabled = true): rigid cells cannot "
                 "balance the adhesion short of overlap; use film_model = \"deforming\"");
  if (coupling.film_open_gap > 0.0 && coupling.film_model == FilmModel::deforming &&
      coupling.scheme != CouplingScheme::semi_implicit)
    section.fail("film_model",
                 "deforming films need scheme = \"semi_implicit\": their update is implicit in the cells' stiffness, "
                 "which only the semi-implicit coupling linearizes");
  if (const auto gravity = section.number3("gravity_m_s2"))
    for (int d = 0; d < 3; ++d) coupling.gravity[d] = (*gravity)[d] * 1e6;  // m/s² → μm/s²
}

void read_scene(const TableReader& root, SceneConfig& scene) {
  const TableReader section = root.table("scene");
  assign(scene.skip_unneeded_stages, section.boolean("skip_unneeded_stages"));
}

void check_time_step(const CaseConfig& config) {
  if (config.coupling.scheme == CouplingScheme::semi_implicit) return;
  const DerivedQuantities derived = derive_quantities(config);
  if (derived.stable_dt <= 0.0 || config.time.dt <= derived.stable_dt || config.coupling.allow_unstable_step) return;
  throw InputError(config.source_file, "time.dt_s",
                   format_number(config.time.dt) + " s exceeds the explicit coupling's stable step " +
                       format_number(derived.stable_dt) + " s (" + derived.stable_dt_reason +
                       "); lower time.dt_s, or set coupling.allow_unstable_step = true to run it anyway");
}

void check_preconditioner(const CaseConfig& config) {
  if (config.solver.preconditioner != PreconditionerType::fast_diagonalization) return;
  const std::string obstacle = derive_quantities(config).fast_diagonalization_obstacle;
  if (!obstacle.empty())
    throw InputError(config.source_file, "solver.preconditioner",
                     "\"fast_diagonalization\" needs a uniform box periodic along two axes in the Stokes limit, and " +
                         obstacle + "; use \"multigrid\" or \"auto\"");
}

}  // namespace rouleau
