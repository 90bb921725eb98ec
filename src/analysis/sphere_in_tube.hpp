#pragma once
// A rigid sphere freely suspended on the axis of Poiseuille flow in a circular tube: the
// speed it moves at, and a run's sphere against it. Host-only.
#include "analysis/scene_checks.hpp"

namespace rouleau {

// U / V_mean of a force- and torque-free sphere of radius a on the axis of a tube of
// radius R, λ = a/R in [0, 1), in Stokes flow, V_mean the tube's mean speed far from the
// sphere: Bungay & Brenner's (1973) composite formula (their close-fitting lubrication
// asymptotics joined to the small-sphere reflection results), as Dechadilok & Deen (2006)
// use it, U / V_mean = K_s / K_t with, ε = 1 − λ,
//   K_t = (9/4)π²√2 ε^{−5/2} [1 − (73/60) ε + (77293/50400) ε²]
//         − 22.5083 − 5.6117 λ − 0.3363 λ² − 1.216 λ³ + 1.647 λ⁴,
//   K_s = (9/4)π²√2 ε^{−5/2} [1 + (7/60) ε − (2227/50400) ε²]
//         + 4.0180 − 3.9788 λ − 1.9215 λ² + 4.392 λ³ + 5.006 λ⁴.
// Limits: 2 at λ = 0 (K_t = 6π, K_s = 12π: a small sphere moves with the centre line,
// 2 V_mean), 1 + (4/3) ε near λ = 1 (the lubrication limit). Values: 1.679 at λ = 0.5,
// 1.276 at 0.8, 1.136 at 0.9.
double sphere_in_tube_speed_ratio(double radius_ratio);

// Cell `cell`'s speed along the tube over a run: the least-squares slope of its centroid's
// x against time over the rows at or after `from_time` [s] (the start-up excluded).
struct PlugSpeed {
  double speed = 0.0;       // [μm/s]
  double speed_spread = 0.0;  // [μm/s] largest − smallest speed between successive rows used
  int rows = 0;
};
PlugSpeed measure_plug_speed(const DiagnosticsRows& rows, double from_time, int cell = 0);

}  // namespace rouleau
