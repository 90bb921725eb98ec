#include "run/scene.hpp"

#include <map>
#include <sstream>

#include "config/load_case.hpp"

namespace rouleau {

std::vector<Stage> plan_stages(const CaseConfig& config, const DerivedQuantities& derived) {
  std::vector<Stage> stages;
  std::ostringstream fluid;
  fluid << (derived.stokes ? "Stokes limit: " : "Navier–Stokes: ") << derived.stokes_reason;
  if (config.time.mode == TimeMode::steady)
    fluid << "; steady solve";
  else
    fluid << "; " << (config.time.scheme == TimeScheme::bdf2 ? "BDF2" : "backward Euler") << " steps of "
          << config.time.dt << " s to " << config.time.end << " s";
  stages.push_back({"fluid", true, fluid.str()});
  std::string preconditioner;
  const char* when = derived.stokes ? "built once (the Stokes operator is constant while dt is)"
                                    : "rebuilt every Newton step";
  switch (config.solver.preconditioner) {
    case PreconditionerType::ilu0:
      preconditioner = std::string("ILU(0) of the assembled Jacobian (KokkosKernels spiluk/sptrsv), ") + when;
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
    stages.push_back({"neo-Hookean cell forces", false, no_cells});
    stages.push_back({"Morse cell-cell forces", false, no_cells});
    stages.push_back({"inertia/buoyancy", false, no_cells});
    stages.push_back({"RKPM interpolate/spread", false, no_cells});
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
    cells << "), 4-node tetrahedra meshed with Gmsh once per kind and cached; written with the fields. "
             "They stay in place: the fluid-structure coupling is not implemented yet";
    stages.push_back({"cells", true, cells.str()});
    stages.push_back({"neo-Hookean cell forces", true,
                      "total-Lagrangian tetrahedra, computed for the output steps (zero while the cells are at rest)"});
    const char* not_yet = "skipped: not implemented yet";
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
            << "; neighbour list with a " << interaction.skin
            << " um skin, rebuilt when a surface node moves more than half of it; cells farther apart than "
               "the cut-off do no pair work; computed for the output steps";
      stages.push_back({"Morse cell-cell forces", true, morse.str()});
    } else {
      stages.push_back({"Morse cell-cell forces", false, "skipped: interaction.enabled = false"});
    }
    stages.push_back({"inertia/buoyancy", false, not_yet});
    stages.push_back({"RKPM interpolate/spread", false, not_yet});
  }
  stages.push_back({"output", config.output.write_fields,
                    config.output.write_fields ? "XDMF+HDF5 fields every " +
                                                     std::to_string(config.output.fields_every_steps) +
                                                     " steps, diagnostics.csv"
                                               : "fields off (output.fields = false); diagnostics.csv only"});
  return stages;
}

std::string describe_stages(const CaseConfig& config, const DerivedQuantities& derived,
                            const std::vector<Stage>& stages) {
  std::ostringstream out;
  const auto& d = config.domain;
  out << "case " << config.name << ": " << d.elements[0] << "x" << d.elements[1] << "x" << d.elements[2]
      << " hexahedra; scales L = " << derived.length_scale << " um, U = " << derived.velocity_scale
      << " um/s, P = " << derived.pressure_scale << " Pa; Re = " << derived.reynolds << "\n";
  out << "stages:\n";
  for (const Stage& s : stages) out << "  [" << (s.runs ? "run " : "skip") << "] " << s.name << ": " << s.reason << "\n";
  return out.str();
}

}  // namespace rouleau
