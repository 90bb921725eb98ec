#include "config/case_keys.hpp"

#include <stdexcept>

#include "config/case_file_names.hpp"

namespace rouleau {
namespace {

using Kind = ValueKind;
const Range any = Range::any();
const Range positive = Range::above(0);
const Range non_negative = Range::at_least(0);
const Range fraction = Range::open(0, 1);
const Range count = Range::at_least(1);

// The Morse law's keys, in [interaction] and in an [[interaction.pair]] entry (paper eq. 3).
void add_morse_keys(std::vector<CaseKey>& keys, std::string_view section, bool pair) {
  const auto default_of = [&](std::string_view value) { return pair ? std::string_view("[interaction]'s") : value; };
  keys.push_back({section, "well_depth_pN_um3", Kind::number, "pN/μm³", default_of("0.35238"), non_negative, {},
                  "De: the well depth of φ(r) = De [e^{2β(r0−r)} − 2 e^{β(r0−r)}], an energy per area per area"});
  keys.push_back({section, "beta_per_um", Kind::number, "1/μm", default_of("4"), positive, {},
                  "β: the well's width; must be > ln 2 / r0, so that flat faces balance at a positive gap"});
  keys.push_back({section, "zero_force_length_um", Kind::number, "μm", default_of("0.25"), positive, {},
                  "r0: the distance at which the force vanishes"});
  keys.push_back({section, "cutoff_um", Kind::number, "μm", default_of("3"), positive, {},
                  "the distance beyond which surfaces do not interact; must be > zero_force_length_um"});
}

std::vector<CaseKey> make_case_keys() {
  std::vector<CaseKey> keys{
      {"case", "name", Kind::text, "", "the file's name without .toml", any, {}, "the case's name; not empty"},
      {"case", "description", Kind::text, "", "\"\"", any, {}, "free text, copied to the resolved case"},

      {"fluid", "density_kg_m3", Kind::number, "kg/m³", "1025", positive, {}, "ρ_f, the plasma's density"},
      {"fluid", "viscosity_Pa_s", Kind::number, "Pa·s", "0.0012", positive, {}, "μ, the plasma's viscosity"},
      {"fluid", "body_force_Pa_um", Kind::number3, "Pa/μm", "[0, 0, 0]", any, {},
       "a uniform force per volume on the fluid (a pressure gradient that drives a periodic flow)"},

      {"domain", "lower_um", Kind::number3, "μm", "required", any, {}, "the box's lowest corner"},
      {"domain", "upper_um", Kind::number3, "μm", "required", any, {},
       "the box's highest corner; each component > lower_um's"},
      {"domain", "elements", Kind::integer3, "", "required", Range::closed(1, 4096), {},
       "hexahedra along x, y, z; ≥ 2 along a periodic direction"},
      {"domain", "wall_grading", Kind::number3, "", "[1, 1, 1]", Range::closed(1, 100), {},
       "largest over smallest element along each direction, the smallest at both ends; 1 = uniform"},

      {"boundary.SIDE", "type", Kind::choice, "", "\"wall\"", any, spellings<BoundaryType>(),
       "the condition on the side; periodic sides come in pairs (x_min with x_max, ...)"},
      {"boundary.SIDE", "velocity_um_s", Kind::number3, "μm/s", "[0, 0, 0]", any, {},
       "wall: the wall's velocity; its component along the side's normal must be 0"},
      {"boundary.SIDE", "mean_speed_um_s", Kind::number, "μm/s", "required for inflow", positive, {},
       "inflow: the mean speed into the domain"},
      {"boundary.SIDE", "profile", Kind::choice, "", "\"parabolic\"", any, spellings<InflowProfile>(),
       "inflow: the velocity profile across the side"},
      {"boundary.SIDE", "pressure_Pa", Kind::number, "Pa", "0", any, {},
       "traction: the pressure p of the normal traction −p n (0 is a free outflow)"},
      {"boundary.SIDE", "parallel_flow", Kind::boolean, "", "false", any, {},
       "traction: the flow crosses the side normally (tangential velocity 0)"},

      {"vessel", "radius_um", Kind::number, "μm", "required", any, {}, "R, the lumen's radius at the inlet and outlet; > 0"},
      {"vessel", "throat_radius_um", Kind::number, "μm", "radius_um", any, {},
       "R_t, the throat's radius; > 0 and ≤ radius_um"},
      {"vessel", "inlet_length_um", Kind::number, "μm", "required", any, {}, "the straight inlet feeder's length; > 0"},
      {"vessel", "contraction_length_um", Kind::number, "μm", "0", any, {},
       "the transition from R to R_t; ≥ 0, > 0 when the throat is narrower, else 0"},
      {"vessel", "throat_length_um", Kind::number, "μm", "0", any, {}, "the straight throat's length; ≥ 0, 0 when the throat is as wide as the inlet"},
      {"vessel", "diffuser_length_um", Kind::number, "μm", "0", any, {},
       "the transition from R_t back to R; ≥ 0, > 0 when the throat is narrower, else 0"},
      {"vessel", "outlet_length_um", Kind::number, "μm", "0", any, {},
       "the straight outlet feeder's length; ≥ 0, > 0 after a diffuser"},
      {"vessel", "transition", Kind::choice, "", "\"cosine\"", any, spellings<VesselTransition>(),
       "the radius across a transition: a cosine (smooth) or a straight cone"},
      {"vessel", "element_size_um", Kind::number, "μm", "required", any, {},
       "h, the tetrahedra's size on the feeders' axis (scaled with the local radius); > 0"},
      {"vessel", "wall_element_size_um", Kind::number, "μm", "0", any, {},
       "h_w, the size on the feeders' wall, at most h; 0 = element_size_um"},
      {"vessel", "refined_element_scale", Kind::number, "", "1", any, {},
       "s_r in (0, 1]: the sizes between refined_from_um and refined_to_um are multiplied by it "
       "(where the cells squeeze), returning to 1 over 2 element_size_um; 1 = no refined stretch"},
      {"vessel", "refined_from_um", Kind::number, "μm", "0", any, {}, "x_a, where the refined stretch starts"},
      {"vessel", "refined_to_um", Kind::number, "μm", "0", any, {}, "x_b, where it ends; above refined_from_um"},
      {"vessel", "allow_squeeze", Kind::boolean, "", "false", any, {},
       "allow cells wider than the throat (they must deform to pass it)"},
      {"vessel", "wall_repulsion_Pa", Kind::number, "Pa", "2", non_negative, {},
       "p_w of the wall's repulsion p_w (1 − d/d0)² of cell surface nodes within d0 of it; 0 = off"},
      {"vessel", "wall_repulsion_range_um", Kind::number, "μm", "0.5", positive, {},
       "d0, the repulsion's range; below throat_radius_um"},

      {"boundary.END", "type", Kind::choice, "", "required", any, spellings({BoundaryType::inflow, BoundaryType::traction}),
       "the inlet: \"inflow\" or \"traction\"; the outlet: \"traction\""},
      {"boundary.END", "mean_speed_um_s", Kind::number, "μm/s", "required for inflow", positive, {},
       "inflow: the mean speed into the vessel"},
      {"boundary.END", "profile", Kind::choice, "", "\"parabolic\"", any, spellings<InflowProfile>(),
       "inflow: the velocity profile across the end"},
      {"boundary.END", "pressure_Pa", Kind::number, "Pa", "0", any, {}, "traction: the pressure p of the traction −p n"},
      {"boundary.END", "parallel_flow", Kind::boolean, "", "false", any, {},
       "traction: the flow crosses the end normally (tangential velocity 0)"},

      {"boundary.wall", "type", Kind::choice, "", "\"wall\"", any, spellings({BoundaryType::wall}),
       "the vessel's wall is at rest"},

      {"time", "mode", Kind::choice, "", "\"transient\"", any, spellings<TimeMode>(),
       "march in time, or solve for the steady flow"},
      {"time", "scheme", Kind::choice, "", "\"bdf2\"", any, spellings<TimeScheme>(), "the time discretization"},
      {"time", "dt_s", Kind::number, "s", "required when transient", positive, {}, "the time step"},
      {"time", "end_s", Kind::number, "s", "required when transient", positive, {}, "the end time; ≥ dt_s"},

      {"solver", "stokes", Kind::choice, "", "\"auto\"", any, spellings<StokesChoice>(),
       "drop the convective term; auto: when the Reynolds number is below stokes_reynolds_threshold"},
      {"solver", "stokes_reynolds_threshold", Kind::number, "", "0.01", positive, {},
       "the Reynolds number below which stokes = \"auto\" drops the convective term"},
      {"solver", "newton_rtol", Kind::number, "", "1e-08", fraction, {}, "Newton's tolerance on the scaled residual, relative"},
      {"solver", "newton_atol", Kind::number, "", "1e-10", non_negative, {}, "Newton's tolerance on the scaled residual, absolute"},
      {"solver", "newton_step_rtol", Kind::number, "", "1e-08", non_negative, {},
       "also converged when the Newton update ‖δ‖ ≤ newton_step_rtol ‖U‖"},
      {"solver", "newton_max_iterations", Kind::integer, "", "15", count, {}, "Newton iterations per step at most"},
      {"solver", "gmres_restart", Kind::integer, "", "60", Range::closed(1, 1000), {}, "GMRES's Krylov basis size"},
      {"solver", "gmres_rtol", Kind::number, "", "1e-08", fraction, {}, "GMRES's tolerance relative to the right-hand side"},
      {"solver", "gmres_max_iterations", Kind::integer, "", "3000", count, {}, "GMRES iterations per solve at most"},
      {"solver", "preconditioner", Kind::choice, "", "\"auto\"", any, spellings<PreconditionerType>(),
       "the fluid solve's preconditioner; auto: fast_diagonalization (FFT along the periodic axes, the Stokes "
       "operator's exact inverse) on a box uniform and periodic along two axes in the Stokes limit on one rank "
       "and CPU threads, multigrid elsewhere"},
      {"solver", "multigrid_smoother", Kind::choice, "", "\"block_jacobi\"", any, spellings<MultigridSmoother>(),
       "the multigrid's smoother: block_jacobi (fully parallel sweeps) or ilu0 (triangular solves)"},
      {"solver", "multigrid_precision", Kind::choice, "", "\"single\"", any, spellings<MultigridPrecision>(),
       "what the multigrid's block-Jacobi sweeps and residuals read its matrices in: single (float copies, half "
       "the memory traffic; the arithmetic, the coarse operators and GMRES stay in double) or double"},
      {"solver", "starting_guess_solutions", Kind::integer, "", "4", Range::closed(0, 16), {},
       "Stokes steps start GMRES from the least-residual combination of the last this many solutions; 0: the last "
       "solution extrapolated linearly"},

      {"scales", "length_um", Kind::number, "μm", "0", non_negative, {},
       "the length scale of the nondimensional solve; 0 = derived from the case"},
      {"scales", "velocity_um_s", Kind::number, "μm/s", "0", non_negative, {},
       "the velocity scale of the nondimensional solve; 0 = derived from the case"},

      {"output", "fields", Kind::boolean, "", "true", any, {}, "write the fields (XDMF + HDF5)"},
      {"output", "fields_every_steps", Kind::integer, "", "1", count, {}, "write the fields every N steps"},
      {"output", "diagnostics_every_steps", Kind::integer, "", "1", count, {}, "write a diagnostics row every N steps"},
      {"output", "cell_gaps_max_cells", Kind::integer, "", "32", non_negative, {},
       "the gaps and contact areas of every pair of cells are written while the case has at most this many cells"},

      {"checkpoint", "every_steps", Kind::integer, "", "0", non_negative, {}, "also a checkpoint every N steps; 0 = not by steps"},
      {"checkpoint", "every_minutes", Kind::number, "min", "30", non_negative, {},
       "also a checkpoint after M minutes of wall time; 0 = not by time"},
      {"checkpoint", "keep", Kind::integer, "", "2", Range::closed(1, 1000), {}, "the newest K checkpoints stay on disk"},

      {"cell_kinds.NAME", "shape", Kind::choice, "", "\"rbc\"", any, spellings<CellShape>(),
       "Evans–Fung biconcave disc, crescent (an ellipsoid bent along an arc), sphere, or spheroid (about its "
       "local z axis; filled only)"},
      {"cell_kinds.NAME", "body", Kind::choice, "", "\"shell\"", any, spellings<CellBody>(),
       "a membrane layer enclosing fluid, or a solid body"},
      {"cell_kinds.NAME", "diameter_um", Kind::number, "μm", "7.82", positive, {},
       "rbc, sphere: the diameter; spheroid: the equatorial diameter"},
      {"cell_kinds.NAME", "axis_ratio", Kind::number, "", "1", Range::closed(0.05, 20), {},
       "spheroid: polar over equatorial semi-axis, < 1 oblate (a disc), > 1 prolate (a rod)"},
      {"cell_kinds.NAME", "length_um", Kind::number, "μm", "14", positive, {}, "sickle: the centre line's length"},
      {"cell_kinds.NAME", "width_um", Kind::number, "μm", "4.2", positive, {}, "sickle: the width in the bending plane"},
      {"cell_kinds.NAME", "thickness_um", Kind::number, "μm", "3", positive, {}, "sickle: the thickness across it"},
      {"cell_kinds.NAME", "arc_radius_um", Kind::number, "μm", "8", positive, {},
       "sickle: the radius of the arc the centre line is bent along; > width_um / 2"},
      {"cell_kinds.NAME", "shell_thickness_um", Kind::number, "μm", "0.36", positive, {},
       "shell: the membrane's thickness h; below the body's smallest half-dimension"},
      {"cell_kinds.NAME", "resolution", Kind::choice, "", "\"paper\"", any, spellings<MeshResolution>(),
       "the mesh's element size preset"},
      {"cell_kinds.NAME", "mesh_size_um", Kind::number, "μm", "0", non_negative, {},
       "the element size; 0 = the resolution's preset"},
      {"cell_kinds.NAME", "shear_modulus_Pa", Kind::number, "Pa", "11.6667", positive, {},
       "G, the shear modulus (neo-Hookean, paper eq. 2)"},
      {"cell_kinds.NAME", "membrane_shear_modulus_pN_um", Kind::number, "pN/μm", "4.2", positive, {},
       "shell: G_s, the membrane's shear modulus, instead of shear_modulus_Pa (G = G_s / h)"},
      {"cell_kinds.NAME", "bulk_modulus_Pa", Kind::number, "Pa", "from poisson_ratio", positive, {},
       "K, the bulk modulus, instead of poisson_ratio"},
      {"cell_kinds.NAME", "poisson_ratio", Kind::number, "", "0.45", Range::open(-1, 0.5), {},
       "ν, which gives K = 2G(1+ν) / (3(1−2ν))"},
      {"cell_kinds.NAME", "density_kg_m3", Kind::number, "kg/m³", "1100", positive, {}, "ρ_s, the cell's density"},
      {"cell_kinds.NAME", "morse_well_depth_factor", Kind::number, "", "1", non_negative, {},
       "f: the Morse well depth between kinds a and b is De √(f_a f_b) (built-in sickle: 5)"},
      {"cell_kinds.NAME", "strain_hardening_ratio", Kind::number, "", "0", non_negative, {},
       "C3 / G of the strain-hardening term W += C3 (J1 − 3)³; 0 = off (Mills et al. 2004: 1/30)"},
      {"cell_kinds.NAME", "area_modulus_pN_um", Kind::number, "pN/μm", "0", non_negative, {},
       "k_A of the area constraint E_A = k_A (A − A0)² / (2 A0) on the outer surface; 0 = off"},
      {"cell_kinds.NAME", "volume_modulus_Pa", Kind::number, "Pa", "0", non_negative, {},
       "k_V of the volume constraint E_V = k_V (V − V0)² / (2 V0) on the enclosed volume; 0 = off"},

      {"cells", "kind", Kind::kind_name, "", "\"normal\"", any, {}, "the cell's kind: a [cell_kinds] name"},
      {"cells", "center_um", Kind::number3, "μm", "required", any, {},
       "the body's centroid; the cell must lie inside the domain and overlap no other"},
      {"cells", "orientation_deg", Kind::number3, "°", "[0, 0, 0]", any, {},
       "rotations of the body about the fixed x, then y, then z axes"},

      {"interaction", "enabled", Kind::boolean, "", "false", any, {}, "the Morse attraction between cells acts (needs [[cells]])"},
      {"interaction", "quadrature", Kind::choice, "", "\"auto\"", any, spellings<InteractionQuadrature>(),
       "where the surface integral is sampled: the nodes, 3 or 6 Gauss points per triangle; auto: the nodes when at "
       "most 1/β apart, else gauss3"},
      {"interaction", "strength_multiplier", Kind::number, "", "1", non_negative, {}, "multiplies every well depth"},
      {"interaction", "skin_um", Kind::number, "μm", "0.3", positive, {}, "the neighbour list's skin"},
  };
  add_morse_keys(keys, "interaction", false);
  keys.push_back({"interaction.pair", "kind_a", Kind::kind_name, "", "required", any, {}, "one kind of the pair"});
  keys.push_back({"interaction.pair", "kind_b", Kind::kind_name, "", "required", any, {},
                  "the other kind; each pair at most once"});
  add_morse_keys(keys, "interaction.pair", true);
  const std::vector<CaseKey> coupling_and_scene{
      {"coupling", "scheme", Kind::choice, "", "\"explicit\"", any, spellings<CouplingScheme>(),
       "explicit: the forces at the step's start; semi_implicit: linearized at its end (not bound by the stable step)"},
      // Below one element a point's support may hold too few fluid nodes for the moment matrix.
      {"coupling", "support_elements", Kind::number, "", "2", Range::closed(1, 8), {},
       "the RKPM support radius in local fluid element sizes"},
      {"coupling", "stable_step_factor", Kind::number, "", "1", positive, {},
       "C in the explicit coupling's stable step Δt ≤ C μ h_f / G_s"},
      {"coupling", "allow_unstable_step", Kind::boolean, "", "false", any, {},
       "run even when time.dt_s exceeds the explicit coupling's stable step"},
      {"coupling", "gravity_m_s2", Kind::number3, "m/s²", "[0, 0, 0]", any, {},
       "g of the buoyancy (ρ_s − ρ_f) g on the cells (paper eq. 7)"},
      {"coupling", "volume_tolerance", Kind::number, "", "0.1", fraction, {},
       "a cell whose volume changed by more than this fraction stops the run as diverged"},
      {"coupling", "forces_in_stabilization", Kind::boolean, "", "false", any, {},
       "the spread forces' density enters SUPG/PSPG's strong residual"},
      {"coupling", "subscale_velocity", Kind::boolean, "", "true", any, {},
       "the cells move with u_h + u', u' PSPG's subscale velocity; not with forces_in_stabilization under "
       "semi_implicit"},
      {"coupling", "film_open_gap_um", Kind::number, "μm", "0", non_negative, {},
       "the sub-grid film model: films between cells thinner than this open or close at Reynolds' lubrication "
       "speed for the load they hold; 0: off"},
      {"coupling", "film_model", Kind::choice, "", "\"rigid\"", any, spellings<FilmModel>(),
       "how films move the cells: rigid (each cell as a whole) or deforming (the cells as wholes and the films' faces, "
       "smoothly, implicit in the cells' stiffness; needs scheme = \"semi_implicit\"; the one that runs with the "
       "interaction)"},
      {"scene", "skip_unneeded_stages", Kind::boolean, "", "true", any, {},
       "leave out the stages that cannot change the result; false runs them all"},
  };
  keys.insert(keys.end(), coupling_and_scene.begin(), coupling_and_scene.end());
  return keys;
}

}  // namespace

const std::vector<CaseSection>& case_sections() {
  static const std::vector<CaseSection> sections{
      {"case", "[case]", "The case's name and description."},
      {"fluid", "[fluid]", "The plasma."},
      {"domain", "[domain]",
       "A box of hexahedra. A case has either a [domain] with [boundary.SIDE] tables or a [vessel]."},
      {"boundary.SIDE", "[boundary.SIDE]",
       "One table per side of the box: SIDE is x_min, x_max, y_min, y_max, z_min or z_max. Each type takes only "
       "its own keys (named before the colon below)."},
      {"vessel", "[vessel]",
       "An axisymmetric vessel along x meshed with tetrahedra: inlet feeder, contraction, throat, diffuser, outlet "
       "feeder. Its boundaries are [boundary.inlet] (x = 0), [boundary.outlet] and [boundary.wall]."},
      {"boundary.END", "[boundary.inlet], [boundary.outlet]",
       "The vessel's two ends, both required. Each type takes only its own keys."},
      {"boundary.wall", "[boundary.wall]", "The vessel's wall (no slip)."},
      {"time", "[time]", ""},
      {"solver", "[solver]", "Newton's method around GMRES for the fluid."},
      {"scales", "[scales]", "The scales of the nondimensional solver variables."},
      {"output", "[output]", ""},
      {"checkpoint", "[checkpoint]",
       "A run writes a checkpoint at its start, at its end and on SIGINT/SIGTERM; these add periodic ones."},
      {"cell_kinds.NAME", "[cell_kinds.NAME]",
       "A kind of cell. The built-in kinds \"normal\" (the Evans–Fung RBC), \"sickle\" and \"capsule\" (a sphere "
       "with the RBC's volume) are changed by a table of their name; a new NAME starts from \"normal\", whose "
       "values are the defaults below. Size keys belong to their shape; shell_thickness_um and "
       "membrane_shear_modulus_pN_um to a shell body. Give either shear_modulus_Pa or membrane_shear_modulus_pN_um, "
       "and either bulk_modulus_Pa or poisson_ratio."},
      {"cells", "[[cells]]", "One entry per cell placed in the domain; none for a fluid-only case."},
      {"interaction", "[interaction]", "The Morse attraction between cell surfaces (paper eqs. 3, 4, 11)."},
      {"interaction.pair", "[[interaction.pair]]",
       "The Morse law between two kinds, replacing the mixed one; keys not given are [interaction]'s."},
      {"coupling", "[coupling]", "The fluid–structure coupling."},
      {"scene", "[scene]", ""},
  };
  return sections;
}

const std::vector<CaseKey>& case_keys() {
  static const std::vector<CaseKey> keys = make_case_keys();
  return keys;
}

const CaseKey& case_key(std::string_view section, std::string_view name) {
  for (const CaseKey& key : case_keys())
    if (key.section == section && key.name == name) return key;
  throw std::logic_error("rouleau::case_key: no key " + std::string(name) + " in the table of [" + std::string(section) + "]");
}

std::vector<std::string_view> case_key_names(std::string_view section) {
  std::vector<std::string_view> names;
  for (const CaseKey& key : case_keys())
    if (key.section == section) names.push_back(key.name);
  return names;
}

}  // namespace rouleau
