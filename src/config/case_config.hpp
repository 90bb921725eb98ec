#pragma once
// A case (scene) as typed structs, in rouleau's internal units: μm, s, pN.
// Then pressure and stress are in Pa (1 pN/μm² = 1 Pa), viscosity in Pa·s,
// density in pN·s²/μm⁴ (1000 kg/m³ = 1e-9). Keys in the TOML file carry their unit in
// their name (density_kg_m3, dt_s, ...); load_case() converts once, at load.
// Host-only: includes no Kokkos header.
#include <array>
#include <string>
#include <vector>

#include "geometry/cell_geometry.hpp"
#include "geometry/vessel_mesh.hpp"
#include "solver/multigrid_smoother.hpp"

namespace rouleau {

// Kinds of boundary on the sides of the box domain.
enum class BoundaryType {
  periodic,  // paired with the opposite side (both sides must say periodic)
  wall,      // prescribed velocity: no-slip when zero, a moving wall otherwise
  inflow,    // prescribed inflow profile with a mean normal speed into the domain
  traction,  // prescribed normal traction -p n (pressure inlet/outlet; p = 0 is a free outflow)
};
enum class InflowProfile { uniform, parabolic };

struct BoundaryConfig {
  BoundaryType type = BoundaryType::wall;
  std::array<double, 3> velocity{0.0, 0.0, 0.0};  // wall velocity [μm/s]      key velocity_um_s
  double mean_speed = 0.0;                         // inflow mean speed [μm/s]   key mean_speed_um_s
  InflowProfile profile = InflowProfile::parabolic;  //                         key profile
  double pressure = 0.0;                           // traction pressure [Pa]     key pressure_Pa
  // traction: the flow crosses the side normally (tangential velocity 0), as a fully
  // developed inflow/outflow does; the tangential traction is then a reaction.  key parallel_flow
  bool parallel_flow = false;
};

// The six sides, in this order, with these TOML names.
enum Side : int { x_min = 0, x_max = 1, y_min = 2, y_max = 3, z_min = 4, z_max = 5 };
inline constexpr std::array<const char*, 6> side_names{"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};

struct DomainConfig {
  std::array<double, 3> lower{0.0, 0.0, 0.0};  // [μm]   key lower_um
  std::array<double, 3> upper{1.0, 1.0, 1.0};  // [μm]   key upper_um
  std::array<int, 3> elements{8, 8, 8};        // 8-node hexahedra per direction
  // Ratio of the largest to the smallest element along each direction, the smallest
  // at both ends (refinement toward walls); 1 = uniform.   key wall_grading
  std::array<double, 3> wall_grading{1.0, 1.0, 1.0};
  std::array<BoundaryConfig, 6> boundary{};  // [boundary.x_min] ... [boundary.z_max]
};

// [vessel]: the fluid domain is the lumen of an axisymmetric vessel along x (a tube, a
// contraction, a capillary with feeders), meshed with tetrahedra by Gmsh, instead of the
// [domain] box. Its boundaries are [boundary.inlet] (x = 0), [boundary.outlet] (x = L) and
// the no-slip wall.
struct VesselConfig {
  bool enabled = false;       // the case has a [vessel] section
  // keys radius_um, throat_radius_um, inlet_length_um, contraction_length_um,
  // throat_length_um, diffuser_length_um, outlet_length_um, transition = "cosine" | "cone"
  VesselProfile profile;
  VesselMeshSizes sizes;      // keys element_size_um, wall_element_size_um
  // Cells wider than the throat (that must deform to pass it, the capillary scene) are
  // allowed only when this is set.   key allow_squeeze
  bool allow_squeeze = false;
  // The wall's short-range repulsion of cell surface nodes (kernels/wall_repulsion.hpp): a
  // pressure p_w (1 − d/d0)² within d0 of the wall; 0 turns it off.
  double wall_repulsion_pressure = 2.0;  // p_w [Pa]     key wall_repulsion_Pa
  double wall_repulsion_range = 0.5;     // d0 [μm]      key wall_repulsion_range_um
  BoundaryConfig inlet, outlet;  // [boundary.inlet]: inflow or traction; [boundary.outlet]: traction
};

struct FluidConfig {
  double density = 1.025e-9;   // [pN·s²/μm⁴]  key density_kg_m3 (plasma: 1025 kg/m³)
  double viscosity = 1.2e-3;   // [Pa·s]       key viscosity_Pa_s (plasma: 1.2 mPa·s)
  std::array<double, 3> body_force{0.0, 0.0, 0.0};  // [pN/μm³ = Pa/μm]  key body_force_Pa_um
};

enum class TimeMode { steady, transient };
enum class TimeScheme { backward_euler, bdf2 };

struct TimeConfig {
  TimeMode mode = TimeMode::transient;
  TimeScheme scheme = TimeScheme::bdf2;
  double dt = 0.01;   // [s]  key dt_s
  double end = 0.1;   // [s]  key end_s
};

enum class StokesChoice { automatic, on, off };
// automatic: fast_diagonalization where it applies (a uniform box periodic along two axes,
// Stokes), multigrid elsewhere (DerivedQuantities::preconditioner).
enum class PreconditionerType { none, block_jacobi, ilu0, multigrid, fast_diagonalization, automatic };

struct SolverConfig {
  StokesChoice stokes = StokesChoice::automatic;  // key stokes = "auto" | "on" | "off"
  double stokes_reynolds_threshold = 1e-2;        // Stokes limit used below this Reynolds number
  double newton_rtol = 1e-8;                      // on the scaled residual
  double newton_atol = 1e-10;
  // Also converged when the Newton update is this small relative to the state: ‖δ‖ ≤
  // newton_step_rtol ‖U‖: the update is then below the accuracy newton_rtol asks for. The
  // scaled residual has a round-off floor (1.1–1.5e-10 with semi-implicit cells at 100
  // 1/s, where Newton's updates fall to 2.5e-10 ‖U‖ and stay) that newton_atol can sit below.
  double newton_step_rtol = 1e-8;
  int newton_max_iterations = 15;
  int gmres_restart = 60;
  double gmres_rtol = 1e-8;                       // relative to the right-hand side
  int gmres_max_iterations = 3000;
  // The aggregation multigrid: on the work–precision study (bench/work_precision.md) it is on the
  // Pareto front from about 2e4 unknowns on, where every paper scene lies, and its 2–5×
  // fewer GMRES iterations save the semi-implicit cells' force evaluation per iteration.
  PreconditionerType preconditioner = PreconditionerType::automatic;
  // The multigrid's smoother: block-Jacobi sweeps (fully parallel, 2.5–6.5× faster fluid
  // solves than ILU(0) on the paper scenes) or ILU(0) (fewer GMRES iterations, launch-bound).
  MultigridSmoother multigrid_smoother = MultigridSmoother::block_jacobi;
  // What the block-Jacobi sweeps and the cycle's residuals read the level matrices in:
  // float copies halve the traffic of the multigrid's memory-bound passes.
  MultigridPrecision multigrid_precision = MultigridPrecision::single_precision;
  // A Stokes step's starting guess: the combination of the last this many solutions with the
  // least residual (fluid/fluid_solver.hpp); 0: 2 U^n − U^{n−1}.
  int starting_guess_solutions = 4;
};

// Scales of the nondimensional solver variables; 0 = derive from the case.
struct ScalesConfig {
  double length = 0.0;    // [μm]    key length_um
  double velocity = 0.0;  // [μm/s]  key velocity_um_s
};

// ---- cells (the Lagrangian bodies)

// A kind of cell: its geometry (shape, body, sizes, mesh resolution: CellGeometry,
// geometry/cell_geometry.hpp) and its material. Built-in kinds "normal", "sickle" and
// "capsule" have defaults (builtin_cell_kinds(), config/cell_kinds.hpp); a case may
// change them or add its own under [cell_kinds.NAME].
struct CellKindConfig : CellGeometry {
  // Material, paper eq. (2) with C1 = G/2, C2 = K. In the file either
  // shear_modulus_Pa (3D) or membrane_shear_modulus_pN_um (shell only; G = G_s / h),
  // and either bulk_modulus_Pa or poisson_ratio (K = 2G(1+ν) / (3(1−2ν))).
  double shear_modulus = 4.2 / 0.36;  // G [Pa]
  double bulk_modulus = 0.0;          // K [Pa]; set from poisson_ratio when not given
  double poisson_ratio = 0.45;        // ν, the one that gives K from G (reported)
  double density = 1.1e-9;            // [pN·s²/μm⁴]   key density_kg_m3 (RBC: 1100 kg/m³)
  // Options beyond the paper's law (0 = off, the default), for a membrane that hardens
  // and keeps its area (Mills et al. 2004's stretch) and a cell that keeps the volume of
  // the fluid it encloses (kernels/neo_hookean.hpp, kernels/global_constraints.hpp):
  // C3 / G of the strain-hardening term W += C3 (J1 − 3)³ (Mills et al.: 1/30)
  //                                                          key strain_hardening_ratio
  double strain_hardening_ratio = 0.0;
  // k_A of the global area constraint E_A = k_A (A − A0)² / (2 A0) on each cell's outer
  // surface [pN/μm]                                          key area_modulus_pN_um
  double area_modulus = 0.0;
  // k_V of the global volume constraint E_V = k_V (V − V0)² / (2 V0) on the volume each
  // cell's outer surface encloses [Pa]                       key volume_modulus_Pa
  double volume_modulus = 0.0;
  // The Morse well depth of this kind relative to [interaction]'s: the depth between
  // kinds a and b is De √(f_a f_b) unless an [[interaction.pair]] sets it (sickle: 5,
  // "stickier").                                             key morse_well_depth_factor
  double morse_well_depth_factor = 1.0;
};

// One cell placed in the domain.
struct CellPlacement {
  std::string kind = "normal";                 // key kind: a [cell_kinds] name
  std::array<double, 3> center{0.0, 0.0, 0.0};  // [μm] the body's centroid   key center_um
  // Rotation of the body from its local frame (RBC and sphere axis along z; sickle
  // centre line an arc in the x–y plane about a centre on the −y axis, so its tips point
  // toward −y): rotations about the fixed x, then y, then z axes, in degrees.
  //                                                          key orientation_deg
  std::array<double, 3> orientation{0.0, 0.0, 0.0};
};

// ---- cell–cell interaction (paper eqs. 3, 4, 11)

// The Morse law φ(r) = De [e^{2β(r0−r)} − 2 e^{β(r0−r)}] between two surfaces' points,
// an energy per area per area. Defaults: r0 and the cut-off are the paper's; β = 4/μm
// (> ln 2 / r0, so that flat faces balance at a positive gap h* = r0 − ln 2/β = 0.077 μm);
// De calibrated as the paper did, on its four-cell stack with the cells moving with
// u_h + u' (cases/stack_shear/README.md): with this De the stack holds at 0.25 1/s to
// the paper's 4 s and comes apart at 1 1/s; with twice it the chain of four pairs into
// doublets by 4 s at 0.25 1/s. It gives flat faces an adhesion energy of 0.5 μJ/m² =
// 0.5 pN/μm at h* (−2π∫_{h*}^{r_c} φ r dr), half the low end of Neu & Meiselman's
// 1–10 μJ/m² for depletion-mediated aggregation; the paper's two-cell scene multiplies
// it by five.
struct MorseConfig {
  double well_depth = 0.35238;       // De [pN/μm³ = pN·μm/μm⁴]   key well_depth_pN_um3
  double beta = 4.0;                 // β [1/μm]                  key beta_per_um
  double zero_force_length = 0.25;   // r0 [μm]                   key zero_force_length_um
  double cutoff = 3.0;               // [μm]                      key cutoff_um
};

// The law between one pair of kinds, replacing the mixed default.
struct MorsePairConfig {
  std::string kind_a, kind_b;  // keys kind_a, kind_b: [cell_kinds] names
  MorseConfig morse;           // the [interaction] values, changed by the entry's keys
};

// Where the surface integral is sampled: at the surface nodes, or at 3 or 6 Gauss points
// per surface triangle; "auto" takes the nodes when they are at most 1/β apart and 3
// Gauss points otherwise (docs/method.md, "Quadrature").
enum class InteractionQuadrature { automatic, nodes, gauss3, gauss6 };

struct InteractionConfig {
  bool enabled = false;          // key enabled: the Morse stage runs (cells needed)
  InteractionQuadrature quadrature = InteractionQuadrature::automatic;  // key quadrature
  MorseConfig morse;             // every pair of kinds, De scaled by the kinds' factors
  double strength = 1.0;         // key strength_multiplier: multiplies every De (the paper: 5 in its two-cell scene)
  double skin = 0.3;             // [μm] neighbour-list skin   key skin_um
  std::vector<MorsePairConfig> pairs;  // [[interaction.pair]]
};

// ---- the fluid–structure coupling (paper eqs. 5–7, 15, 16; docs/method.md, "The coupling")
// How the cells' forces meet the fluid solve (ImmersedCoupling):
//   explicit:      the forces at x^n are spread and the fluid solved; stable
//                  only below Δt ≈ C μ h_f / G_eff;
//   semi_implicit: the forces at x^{n+1} = x^n + Δt I u^{n+1}, linearized about x^n
//                  (f^n + K Δt I u^{n+1}), enter the fluid solve, so the cells' stiffness
//                  no longer bounds the step (coupling/cell_stiffness.hpp).
enum class CouplingScheme { explicit_forces, semi_implicit };

// How the sub-grid film model moves the cells (coupling/film_drainage.hpp):
//   rigid:     each film opens at V = w T / ζ for the load T its nodes hold, the cells moved
//              as wholes (shapes kept);
//   deforming: each film's faces move by smooth modes (a uniform opening, two tilts, three
//              dishings) at the speeds that balance the films' squeeze resistance with the
//              cells' forces, backward Euler in the cells' stiffness; the cells deform.
enum class FilmModel { rigid, deforming };

struct CouplingConfig {
  CouplingScheme scheme = CouplingScheme::explicit_forces;  // key scheme
  // RKPM support radius a_J = support_elements × the local element size at fluid node J.
  double support_elements = 2.0;     // key support_elements
  // C in the explicit coupling's stable step Δt ≤ C μ h_f / G_s (derive_quantities()).
  double stable_step_factor = 1.0;   // key stable_step_factor
  // Run even when time.dt_s exceeds the stable step (stability studies).  key allow_unstable_step
  bool allow_unstable_step = false;
  // Gravity for the buoyancy term (ρ_s − ρ_f) g of eq. (7) [μm/s²].   key gravity_m_s2
  std::array<double, 3> gravity{0.0, 0.0, 0.0};
  // A cell whose enclosed volume has changed by more than this fraction of its initial
  // volume stops the run as diverged (the cells are incompressible).   key volume_tolerance
  double volume_tolerance = 0.1;
  // The spread forces also enter SUPG/PSPG's strong residual as the force density they
  // stand for (FluidOperator::load_stabilization). Off (the design's default: nodal loads
  // only), PSPG drives a flux τ ∇p through a loaded membrane; on, τ (∇p − f_h): 3.5-7
  // times less spurious flow around a pressurized shell (tests/test_fluid_flows.cpp),
  // and the explicit coupling stays stable at ten times its step estimate in the reduced
  // aggregation. Off by default until the scenes are recalibrated with it on.
  bool forces_in_stabilization = false;   // key forces_in_stabilization
  // The cells move with the fluid's whole velocity u_h + u', u' = −τ_M r PSPG's subscale
  // velocity projected onto the nodes (FluidOperator::subscale_velocity), instead of u_h:
  // the weak continuity equation conserves the flux of u_h + u', so plasma no longer
  // seeps through cells where their membrane force makes ∇p large (a cell plugging a
  // throat: 60-90 % of the flow passed it in u' alone). The one coupling of every scene,
  // box and vessel, and the one the Morse depth is calibrated on; off, the cells move with
  // u_h (each GMRES iteration of the semi-implicit step then costs about 0.6 times as much).
  //   key subscale_velocity
  bool subscale_velocity = true;
  // The sub-grid film model (coupling/film_drainage.hpp): where two cells' outer surfaces
  // are closer than this [μm], the film between them opens or closes at the speed Reynolds'
  // lubrication equation gives for the load it holds, which the fluid mesh cannot
  // resolve. 0: off.   key film_open_gap_um
  double film_open_gap = 0.0;
  FilmModel film_model = FilmModel::rigid;  // key film_model
};

// What the scene builds and runs (docs/design.md, "The scene decides what runs").
struct SceneConfig {
  // Leave out the stages that cannot change the result (beyond round-off): the Morse
  // stage between cells apart, the inertia/buoyancy stage when ρ_s = ρ_f, the RKPM
  // correction where the plain window reproduces linear fields, neighbour-list rebuilds
  // while no node moved half the skin. false runs them all (to check that they agree).
  bool skip_unneeded_stages = true;  // key skip_unneeded_stages
};

struct OutputConfig {
  bool write_fields = true;       // key fields
  int fields_every_steps = 1;     // key fields_every_steps
  int diagnostics_every_steps = 1;
  // The gap and contact area of every pair of cells go into the diagnostics while the scene
  // has at most this many cells: their cost (every pair's two surfaces, cells/cell_gaps.hpp)
  // and their columns grow with the square of the cell count.
  int cell_gaps_max_cells = 32;
};

// [checkpoint]: when a run writes its state (io/checkpoint_file.hpp). It always writes one
// at the start, at the end and when a signal stops it; these add periodic ones.
struct CheckpointConfig {
  int every_steps = 0;          // key every_steps: also every N steps (0 = not by steps)
  double every_minutes = 30.0;  // key every_minutes: also after M minutes of wall time (0 = not by time)
  int kept = 2;                 // key keep: the newest K stay on disk
};

struct CaseConfig {
  std::string source_file;  // the TOML file it was loaded from
  std::string name;
  std::string description;
  FluidConfig fluid;
  DomainConfig domain;                     // [domain] and the box's [boundary.SIDE]s
  VesselConfig vessel;                     // or [vessel] and [boundary.inlet|outlet|wall]
  TimeConfig time;
  SolverConfig solver;
  ScalesConfig scales;
  OutputConfig output;
  CheckpointConfig checkpoint;             // [checkpoint]
  std::vector<CellKindConfig> cell_kinds;  // [cell_kinds.NAME]: the built-in kinds, changed or added to
  std::vector<CellPlacement> cells;        // [[cells]]: empty = fluid only
  InteractionConfig interaction;           // [interaction]
  CouplingConfig coupling;                 // [coupling]
  SceneConfig scene;                       // [scene]
};

// Values derived from a case (written to the resolved configuration).
struct DerivedQuantities {
  double length_scale = 0.0;    // L [μm]
  double velocity_scale = 0.0;  // U [μm/s]
  double pressure_scale = 0.0;  // μU/L [Pa]
  double reynolds = 0.0;        // ρUL/μ
  bool stokes = false;          // the Stokes limit is used
  std::string stokes_reason;    // why (or why not), for --explain
  // The fluid's preconditioner: solver.preconditioner, with "auto" resolved; and why fast
  // diagonalization does not apply (empty when it does).
  PreconditionerType preconditioner = PreconditionerType::multigrid;
  std::string fast_diagonalization_obstacle;
  // The explicit coupling's stable step estimate [s] (0 when the case has no cells or
  // does not step in time), and how it was found, for --explain and the log.
  double stable_dt = 0.0;
  std::string stable_dt_reason;
  // The flow's largest shear rate as the case sets it [1/s] (0 when no estimate applies)
  // and where it comes from; the strain per step γ̇ Δt; and, when that is beyond the range
  // where the coupling was measured accurate (accurate_strain_per_step), what to change,
  // in one sentence (empty otherwise). Only for cells that move.
  double shear_rate = 0.0;
  std::string shear_rate_source;
  double strain_per_step = 0.0;
  std::string accuracy_warning;
};

}  // namespace rouleau
