// A spherical capsule in simple shear: runs cases/capsule_shear/case.toml (or the file
// given) and compares the steady Taylor deformation with the small-deformation theory and
// the published thin-membrane values at the case's capillary number.
//   case_capsule_shear [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cmath>
#include <cstdio>

#include "config/cell_kinds.hpp"
#include "config/derived.hpp"
#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/capsule_shear");
  if (!run.ran) return run.status;
  // What is special to this case: Ca and the steady Taylor deformation.
  const rouleau::CaseConfig& config = run.config;
  const rouleau::CellKindConfig& capsule = *rouleau::find_cell_kind(config, config.cells.at(0).kind);
  const auto& domain = config.domain;
  const double shear_rate = rouleau::derive_quantities(config).shear_rate;  // the walls' γ̇
  // The thin membrane the shell stands for is its mid-surface, of radius a = D/2 − h/2;
  // D is measured there too (src/cells/cell_shape.hpp).
  const double radius = 0.5 * (capsule.diameter - capsule.shell_thickness);
  // Ca as the references define it, with the neo-Hookean membrane's surface Young's
  // modulus E_s = 3 G_s (G_s = G h, the shell's membrane shear modulus).
  const double surface_young_modulus = 3.0 * capsule.shear_modulus * capsule.shell_thickness;
  const double ca = config.fluid.viscosity * shear_rate * radius / surface_young_modulus;
  const double h = (domain.upper[0] - domain.lower[0]) / domain.elements[0];
  const auto last = rouleau::read_last_diagnostics(run.options.output_dir + "/diagnostics.csv");
  // Published steady D of a thin neo-Hookean capsule (Ramanujan & Pozrikidis 1998; Doddi &
  // Bagchi 2008), where the issue quotes them.
  const double published = std::fabs(ca - 0.05) < 1e-3 ? 0.27 : std::fabs(ca - 0.1) < 1e-3 ? 0.39 : NAN;
  std::printf("Ca = mu gamma a / E_s = %.4f (shear rate %.2f /s, a/h = %.2f), gamma t = %.2f: D = %.4f; small-deformation 25/4 Ca = "
              "%.4f; published %s%.2f (D - published = %+.3f); inclination %.1f deg; largest volume change %.2e\n",
              ca, shear_rate, radius / h, shear_rate * last.at("time_s"), last.at("cell0_taylor_deformation"),
              25.0 / 4.0 * ca, std::isnan(published) ? "(none at this Ca) " : "", published,
              last.at("cell0_taylor_deformation") - published,
              last.at("cell0_inclination_deg"), last.at("largest_relative_volume_change"));
  return 0;
}
