#include "geometry/vessel_profile.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include "util/constants.hpp"

namespace rouleau {
namespace {

// The transition's radius from `from` (s = 0) to `to` (s = 1).
double transition_radius(VesselTransition transition, double from, double to, double s) {
  const double weight = transition == VesselTransition::cosine ? 0.5 * (1.0 - std::cos(pi * s)) : s;
  return from + (to - from) * weight;
}

// π ∫₀ᴸ r² dx across a transition between radii a and b:
//   cosine: r = (a + b)/2 + (a − b)/2 cos(π s) gives L [((a + b)/2)² + ((a − b)/2)²/2]
//           = L (3a² + 2ab + 3b²)/8;
//   cone:   L (a² + ab + b²)/3.
double transition_volume(VesselTransition transition, double length, double a, double b) {
  const double mean_square = transition == VesselTransition::cosine ? (3 * a * a + 2 * a * b + 3 * b * b) / 8.0
                                                                     : (a * a + a * b + b * b) / 3.0;
  return pi * length * mean_square;
}

}  // namespace

double vessel_length(const VesselProfile& p) {
  return p.inlet_length + p.contraction_length + p.throat_length + p.diffuser_length + p.outlet_length;
}

double vessel_radius(const VesselProfile& p, double x) {
  const double contraction_start = p.inlet_length;
  const double throat_start = contraction_start + p.contraction_length;
  const double diffuser_start = throat_start + p.throat_length;
  const double outlet_start = diffuser_start + p.diffuser_length;
  if (x < contraction_start) return p.radius;
  if (x < throat_start)
    return transition_radius(p.transition, p.radius, p.throat_radius, (x - contraction_start) / p.contraction_length);
  if (x < diffuser_start) return p.throat_radius;
  if (x < outlet_start)
    return transition_radius(p.transition, p.throat_radius, p.radius, (x - diffuser_start) / p.diffuser_length);
  return p.radius;
}

double vessel_radius_slope(const VesselProfile& p, double x) {
  // d/dx of from + (to − from) w(s), s = (x − start)/L: (to − from) w'(s)/L with
  // w' = (π/2) sin(π s) (cosine) or 1 (cone).
  const auto transition_slope = [&](double from, double to, double s, double length) {
    const double dw = p.transition == VesselTransition::cosine ? 0.5 * pi * std::sin(pi * s) : 1.0;
    return (to - from) * dw / length;
  };
  const double contraction_start = p.inlet_length;
  const double throat_start = contraction_start + p.contraction_length;
  const double diffuser_start = throat_start + p.throat_length;
  const double outlet_start = diffuser_start + p.diffuser_length;
  if (x < contraction_start) return 0.0;
  if (x < throat_start)
    return transition_slope(p.radius, p.throat_radius, (x - contraction_start) / p.contraction_length,
                            p.contraction_length);
  if (x < diffuser_start) return 0.0;
  if (x < outlet_start)
    return transition_slope(p.throat_radius, p.radius, (x - diffuser_start) / p.diffuser_length, p.diffuser_length);
  return 0.0;
}

double vessel_volume(const VesselProfile& p) {
  const double straight = pi * p.radius * p.radius * (p.inlet_length + p.outlet_length) +
                          pi * p.throat_radius * p.throat_radius * p.throat_length;
  return straight + transition_volume(p.transition, p.contraction_length, p.radius, p.throat_radius) +
         transition_volume(p.transition, p.diffuser_length, p.throat_radius, p.radius);
}

double vessel_poiseuille_drop(const VesselProfile& p, double viscosity, double flow_rate) {
  // ∫ dx / r⁴: exact on the straight parts, composite Simpson (200 intervals) across each
  // transition, whose r(x) is smooth.
  const auto across_transition = [&](double start, double length) {
    if (!(length > 0.0)) return 0.0;
    const int n = 200;
    double sum = 0.0;
    for (int k = 0; k <= n; ++k) {
      const double x = start + length * k / n;
      const double r = vessel_radius(p, std::clamp(x, start + 1e-12 * length, start + length * (1.0 - 1e-12)));
      sum += (k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0)) / (r * r * r * r);
    }
    return sum * length / (3.0 * n);
  };
  const double r4 = std::pow(p.radius, 4), t4 = std::pow(p.throat_radius, 4);
  const double integral = (p.inlet_length + p.outlet_length) / r4 + p.throat_length / t4 +
                          across_transition(p.inlet_length, p.contraction_length) +
                          across_transition(p.inlet_length + p.contraction_length + p.throat_length, p.diffuser_length);
  return 8.0 * viscosity * flow_rate / pi * integral;
}

std::optional<VesselProfileProblem> vessel_profile_problem(const VesselProfile& p) {
  auto problem = [](std::string key, std::string reason) {
    return std::optional<VesselProfileProblem>(VesselProfileProblem{std::move(key), std::move(reason)});
  };
  if (!(p.radius > 0.0)) return problem("radius_um", "must be > 0");
  if (!(p.throat_radius > 0.0)) return problem("throat_radius_um", "must be > 0");
  if (p.throat_radius > p.radius)
    return problem("throat_radius_um", "the throat is wider than the inlet (a contraction narrows the vessel)");
  const std::pair<const char*, double> lengths[] = {{"inlet_length_um", p.inlet_length},
                                                    {"contraction_length_um", p.contraction_length},
                                                    {"throat_length_um", p.throat_length},
                                                    {"diffuser_length_um", p.diffuser_length},
                                                    {"outlet_length_um", p.outlet_length}};
  for (const auto& [key, length] : lengths)
    if (!(length >= 0.0) || !std::isfinite(length)) return problem(key, "must be a length >= 0");
  if (!(p.inlet_length > 0.0)) return problem("inlet_length_um", "the inlet needs a straight feeder of length > 0");
  const bool narrows = p.throat_radius < p.radius;
  const bool contracts = p.contraction_length > 0.0 || p.throat_length > 0.0 || p.diffuser_length > 0.0;
  if (narrows && !(p.contraction_length > 0.0))
    return problem("contraction_length_um", "a throat narrower than the inlet needs a contraction of length > 0");
  if (narrows && !(p.diffuser_length > 0.0))
    return problem("diffuser_length_um", "a throat narrower than the inlet needs a diffuser of length > 0");
  if (narrows && !(p.outlet_length > 0.0))
    return problem("outlet_length_um", "the outlet needs a straight feeder of length > 0 after the diffuser");
  if (!narrows && contracts)
    return problem("throat_radius_um", "contraction, throat or diffuser lengths are set but the throat is as wide "
                                       "as the inlet (set throat_radius_um below radius_um, or the lengths to 0)");
  return std::nullopt;
}

}  // namespace rouleau
