#include "config/scene_plan.hpp"

#include <map>
#include <sstream>
#include <string>

#include "config/cell_kinds.hpp"
#include "config/derived.hpp"
#include "config/load_case.hpp"

namespace rouleau {

namespace {
// Which path the Stokes operator takes, and whether it is the stencil.
std::string fluid_operator_path(const CaseConfig& config, const DerivedQuantities& derived, bool& stencil) {
  const char* elementwise = "element by element, matrix-free";
  stencil = false;
  if (config.vessel.enabled) return std::string(elementwise) + " (tetrahedra: every element has its own geometry)";
  if (!derived.stokes)
    return std::string(elementwise) + " (Navier–Stokes: the convective term makes every element's matrix differ)";
  for (double grading : config.domain.wall_grading)
    if (grading != 1.0) return std::string(elementwise) + " (a graded box: its elements differ)";
  if (!config.scene.skip_unneeded_stages)
    return std::string(elementwise) + " (scene.skip_unneeded_stages = false; a uniform box would allow the stencil)";
  stencil = true;
  return "stencil from one reference element: a uniform box in the Stokes limit, where every element has the "
         "same matrix (no per-element geometry; the same Aδ as element by element to round-off)";
}
}  // namespace

ScenePlan plan_scene(const CaseConfig& config, const DerivedQuantities& derived) {
  ScenePlan plan;
  std::vector<Stage>& stages = plan.stages;
  const bool skip = config.scene.skip_unneeded_stages;
  plan.rebuild_morse_list_every_step = !skip;
  plan.rkpm_correction_everywhere = !skip;
  std::ostringstream fluid;
  fluid << (derived.stokes ? "Stokes limit: " : "Navier–Stokes: ") << derived.stokes_reason;
  if (config.time.mode == TimeMode::steady)
    fluid << "; steady solve";
  else
    fluid << "; " << (config.time.scheme == TimeScheme::bdf2 ? "BDF2" : "backward Euler") << " steps of "
          << config.time.dt << " s to " << config.time.end << " s";
  stages.push_back({stage_name::fluid_solve, true, fluid.str()});
  stages.push_back({"fluid operator", true, fluid_operator_path(config, derived, plan.stencil)});
  std::string preconditioner;
  const char* when = derived.stokes ? "built once (the Stokes operator is constant while dt is)"
                                    : "rebuilt every Newton step";
  switch (derived.preconditioner) {
    case PreconditionerType::ilu0:
      preconditioner = std::string("ILU(0) of the assembled Jacobian (KokkosKernels spiluk/sptrsv), ") + when;
      break;
    case PreconditionerType::automatic:  // never: derived.preconditioner is resolved
    case PreconditionerType::multigrid:
      preconditioner = std::string("aggregation multigrid W-cycle (pairwise aggregates of up to 4 nodes, ") +
                       (config.solver.multigrid_smoother == MultigridSmoother::block_jacobi
                            ? (config.solver.multigrid_precision == MultigridPrecision::single_precision
                                   ? "3 damped block-Jacobi sweeps reading float copies of the level matrices"
                                   : "3 damped block-Jacobi sweeps")
                            : "ILU(0)") +
                       " smoothing, sparse LU on the coarsest level) of the assembled Jacobian, " + when;
      break;
    case PreconditionerType::fast_diagonalization:
      preconditioner = std::string("fast diagonalization: FFT along the periodic axes, one banded LU per pair of "
                                   "wave numbers across the walls (the Stokes operator's exact inverse up to "
                                   "the pressure pin), ") + when;
      break;
    case PreconditionerType::block_jacobi:
      preconditioner = std::string("point-block Jacobi (4x4 node blocks), ") + when;
      break;
    case PreconditionerType::none:
      preconditioner = "none";
      break;
  }
  stages.push_back({"preconditioner", true, preconditioner});
  if (config.cells.empty()) {
    const char* no_cells = "skipped: the scene has no cells";
    stages.push_back({"cells", false, no_cells});
    for (const char* stage : {stage_name::elastic_forces, stage_name::interaction_forces, stage_name::inertia,
                              stage_name::spread, stage_name::cell_stiffness, stage_name::interpolate,
                              stage_name::move_cells})
      stages.push_back({stage, false, no_cells});
    if (config.vessel.enabled) stages.push_back({stage_name::wall_repulsion, false, no_cells});
  } else {
    std::map<std::string, int> count_per_kind;
    for (const CellPlacement& cell : config.cells) ++count_per_kind[cell.kind];
    std::ostringstream cells;
    cells << config.cells.size() << (config.cells.size() == 1 ? " cell" : " cells") << " (";
    bool first = true;
    for (const auto& [kind, count] : count_per_kind) {
      cells << (first ? "" : ", ") << count << " " << kind;
      first = false;
    }
    cells << "), 4-node tetrahedra meshed with Gmsh once per kind and cached; written with the fields";
    const bool moving = config.time.mode == TimeMode::transient;
    plan.moves_cells = moving;
    plan.semi_implicit = moving && config.coupling.scheme == CouplingScheme::semi_implicit;
    plan.film_drainage = moving && config.coupling.film_open_gap > 0.0 && config.cells.size() >= 2;
    if (plan.semi_implicit) {
      cells << ". Semi-implicit coupling: the fluid solved with the cells' forces at x^n plus their change "
               "over the step, linearized (K dt I u, K by one-sided differences of the forces inside each "
               "GMRES iteration), the cells moved with the interpolated velocity; dt = "
            << config.time.dt << " s (the explicit stable step estimate, " << derived.stable_dt
            << " s, does not bind it)";
    } else if (moving) {
      cells << ". Explicit coupling: the fluid solved with the cells' forces at x^n, the cells moved with "
               "the interpolated velocity; dt = "
            << config.time.dt << " s, stable step estimate " << derived.stable_dt << " s ("
            << derived.stable_dt_reason << ")";
    } else {
      cells << ". A steady solve: the cells stay where they are placed (the coupling is a time loop)";
    }
    if (moving && derived.shear_rate > 0.0) {
      cells << "; the strain per step, shear rate x dt = " << derived.strain_per_step << " ("
            << derived.shear_rate_source << "), "
            << (derived.accuracy_warning.empty() ? "within the " : "BEYOND the ") << accurate_strain_per_step
            << " up to which the coupling was measured accurate";
    }
    stages.push_back({"cells", true, cells.str()});
    const char* steady_only = "skipped: a steady solve does not move the cells (output steps only)";
    stages.push_back({stage_name::elastic_forces, true,
                      moving ? "total-Lagrangian tetrahedra, every step" : "total-Lagrangian tetrahedra, output steps only"});
    const InteractionConfig& interaction = config.interaction;
    if (interaction.enabled) {
      std::ostringstream morse;
      morse << "De " << interaction.morse.well_depth << " pN/um^3 x " << interaction.strength << ", beta "
            << interaction.morse.beta << " /um, r0 " << interaction.morse.zero_force_length << " um, cut-off "
            << interaction.morse.cutoff << " um (" << interaction.pairs.size()
            << " pair laws set apart); quadrature " << toml_name(interaction.quadrature)
            << (interaction.quadrature == InteractionQuadrature::automatic
                    ? " (surface nodes, or 3 Gauss points per triangle when the nodes are more than 1/beta apart)"
                    : "")
            << "; neighbour list with a " << interaction.skin << " um skin, "
            << (skip ? "rebuilt when a surface node moves more than half of it"
                     : "rebuilt every step (scene.skip_unneeded_stages = false)")
            << "; cells farther apart than the cut-off do no pair work; "
            << (moving ? "every step" : "output steps only");
      stages.push_back({stage_name::interaction_forces, true, morse.str()});
      plan.morse_forces = true;
    } else {
      stages.push_back({stage_name::interaction_forces, false, "skipped: interaction.enabled = false"});
    }
    if (config.vessel.enabled) {
      const VesselConfig& vessel = config.vessel;
      std::ostringstream wall;
      wall << "the vessel wall pushes cell surface nodes within " << vessel.wall_repulsion_range
           << " um of it with the pressure " << vessel.wall_repulsion_pressure << " Pa x (1 - d/d0)^2";
      plan.wall_repulsion = moving && vessel.wall_repulsion_pressure > 0.0;
      if (!moving)
        stages.push_back({stage_name::wall_repulsion, false, steady_only});
      else if (plan.wall_repulsion)
        stages.push_back({stage_name::wall_repulsion, true, wall.str()});
      else
        stages.push_back({stage_name::wall_repulsion, false, "skipped: vessel.wall_repulsion_Pa = 0"});
    }
    bool denser = false;
    for (const CellPlacement& cell : config.cells)
      denser = denser || find_cell_kind(config, cell.kind)->density != config.fluid.density;
    plan.inertia = moving && (denser || !skip);
    if (!moving)
      stages.push_back({stage_name::inertia, false, steady_only});
    else if (plan.inertia)
      stages.push_back({stage_name::inertia, true,
                        std::string("(rho_s - rho_f)(g - dv/dt) at the cell nodes, lumped") +
                            (denser ? "" : " (every cell is as dense as the fluid: zero; scene.skip_unneeded_stages = false)")});
    else
      stages.push_back({stage_name::inertia, false, "skipped: every cell is as dense as the fluid (rho_s = rho_f)"});
    if (moving) {
      std::ostringstream rkpm;
      rkpm << "cubic B-spline window, support " << config.coupling.support_elements
           << " elements around each fluid node, fluid-node bins built once, supports found every step; linear "
              "correction (4x4 moment matrix) "
           << (skip ? "only where the plain window does not reproduce linear fields (walls, graded mesh)"
                    : "everywhere (scene.skip_unneeded_stages = false)")
           << "; spreading is the exact transpose of interpolation";
      stages.push_back({stage_name::spread, true, rkpm.str()});
      stages.push_back({stage_name::cell_stiffness, plan.semi_implicit,
                        plan.semi_implicit ? "the cells' forces linearized about x^n: their change K dt I u enters every "
                                             "GMRES iteration"
                                           : "skipped: explicit coupling (coupling.scheme = \"explicit\")"});
      stages.push_back({stage_name::interpolate, true, "the fluid's new velocity at the cell nodes (the same shape functions)"});
      if (plan.film_drainage) {
        std::ostringstream film;
        film << "films between cells thinner than " << config.coupling.film_open_gap
             << (config.coupling.film_model == FilmModel::rigid
                     ? " um open or close at the speed Reynolds' equation gives for the load they hold (each cell "
                       "moved as a whole)"
                     : " um open, close, tilt or dish at the speeds that balance Reynolds' squeeze resistance with "
                       "the cells' forces, implicit in their stiffness (the films' faces deform)");
        stages.push_back({stage_name::film_drainage, true, film.str()});
      } else {
        stages.push_back({stage_name::film_drainage, false,
                          config.cells.size() < 2 ? "skipped: fewer than two cells"
                                                  : "skipped: coupling.film_open_gap_um = 0"});
      }
      stages.push_back({stage_name::move_cells, true, "x^(n+1) = x^n + dt v^(n+1), stopping on a speed that is not finite"});
    } else {
      for (const char* stage : {stage_name::spread, stage_name::cell_stiffness, stage_name::interpolate,
                                stage_name::film_drainage, stage_name::move_cells})
        stages.push_back({stage, false, steady_only});
    }
  }
  stages.push_back({"output", config.output.write_fields,
                    config.output.write_fields ? "XDMF+HDF5 fields every " +
                                                     std::to_string(config.output.fields_every_steps) +
                                                     " steps, diagnostics.csv"
                                               : "fields off (output.fields = false); diagnostics.csv only"});
  return plan;
}

std::string describe_scene(const CaseConfig& config, const DerivedQuantities& derived, const ScenePlan& plan) {
  std::ostringstream out;
  out << "case " << config.name << ": " << describe_fluid_domain(config) << "; scales L = " << derived.length_scale << " um, U = " << derived.velocity_scale
      << " um/s, P = " << derived.pressure_scale << " Pa; Re = " << derived.reynolds << "\n";
  out << "stages:\n";
  for (const Stage& s : plan.stages) out << "  [" << (s.runs ? "run " : "skip") << "] " << s.name << ": " << s.reason << "\n";
  return out.str();
}

}  // namespace rouleau
