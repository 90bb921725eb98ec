// The vessels' radius profile (src/geometry/vessel_profile): a tube, a contraction with
// cosine and conical transitions, the exact lumen volume against numerical quadrature,
// and the refusal of bad geometry with the key and the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "geometry/vessel_profile.hpp"

namespace {

using rouleau::VesselProfile;
using rouleau::VesselTransition;

constexpr double pi = 3.14159265358979323846;

// A contraction like the paper's (Figs. 13–15): 10 μm vessel narrowing to 4 μm.
VesselProfile contraction(VesselTransition transition) {
  VesselProfile p;
  p.radius = 5.0;
  p.throat_radius = 2.0;
  p.inlet_length = 15.0;
  p.contraction_length = 8.0;
  p.throat_length = 12.0;
  p.diffuser_length = 6.0;
  p.outlet_length = 20.0;
  p.transition = transition;
  return p;
}

// π ∫ r² dx by composite Simpson on n intervals per part (the integrand is smooth within
// each part).
double simpson_volume(const VesselProfile& p, int n) {
  const double ends[] = {0.0,
                         p.inlet_length,
                         p.inlet_length + p.contraction_length,
                         p.inlet_length + p.contraction_length + p.throat_length,
                         p.inlet_length + p.contraction_length + p.throat_length + p.diffuser_length,
                         rouleau::vessel_length(p)};
  double volume = 0.0;
  for (int part = 0; part < 5; ++part) {
    const double a = ends[part], b = ends[part + 1], h = (b - a) / n;
    if (b <= a) continue;
    // Sample strictly inside the part so that each piece is evaluated on its own formula.
    auto f = [&](double x) {
      const double r = rouleau::vessel_radius(p, std::min(std::max(x, a + 1e-12 * (b - a)), b - 1e-12 * (b - a)));
      return pi * r * r;
    };
    double sum = f(a) + f(b);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
    volume += sum * h / 3.0;
  }
  return volume;
}

TEST(VesselProfile, TubeIsStraight) {
  VesselProfile tube;
  tube.radius = 3.0;
  tube.throat_radius = 3.0;
  tube.inlet_length = 40.0;
  EXPECT_FALSE(rouleau::vessel_profile_problem(tube).has_value());
  for (double x : {0.0, 10.0, 39.9, 40.0}) EXPECT_EQ(rouleau::vessel_radius(tube, x), 3.0);
  EXPECT_NEAR(rouleau::vessel_volume(tube), pi * 9.0 * 40.0, 1e-12 * pi * 9.0 * 40.0);
}

TEST(VesselProfile, ContractionIsContinuousSmoothAndHasItsExactVolume) {
  for (const VesselTransition transition : {VesselTransition::cosine, VesselTransition::cone}) {
    const VesselProfile p = contraction(transition);
    ASSERT_FALSE(rouleau::vessel_profile_problem(p).has_value());
    const double joints[] = {15.0, 23.0, 35.0, 41.0};
    double largest_jump = 0.0, largest_end_slope = 0.0;
    for (const double x : joints) {
      const double eps = 1e-9;
      largest_jump = std::max(largest_jump, std::fabs(rouleau::vessel_radius(p, x + eps) - rouleau::vessel_radius(p, x - eps)));
      const double d = 1e-4;  // one-sided slopes inside the transitions next to each joint
      const double slope_left = (rouleau::vessel_radius(p, x) - rouleau::vessel_radius(p, x - d)) / d;
      const double slope_right = (rouleau::vessel_radius(p, x + d) - rouleau::vessel_radius(p, x)) / d;
      largest_end_slope = std::max({largest_end_slope, std::fabs(slope_left), std::fabs(slope_right)});
    }
    // Narrowing through the contraction, widening through the diffuser, monotonically.
    bool monotone = true;
    for (double x = 15.0; x < 23.0; x += 0.01)
      monotone = monotone && rouleau::vessel_radius(p, x + 0.01) <= rouleau::vessel_radius(p, x) + 1e-15;
    for (double x = 35.0; x < 41.0; x += 0.01)
      monotone = monotone && rouleau::vessel_radius(p, x + 0.01) >= rouleau::vessel_radius(p, x) - 1e-15;
    const double exact = rouleau::vessel_volume(p), numeric = simpson_volume(p, 2000);
    std::printf("%s contraction: length %.1f um, volume %.6f um^3 (Simpson %.6f, relative %.1e), largest jump at a "
                "joint %.1e um, largest slope at a joint %.2e\n",
                transition == VesselTransition::cosine ? "cosine" : "cone", rouleau::vessel_length(p), exact, numeric,
                std::fabs(exact / numeric - 1.0), largest_jump, largest_end_slope);
    EXPECT_DOUBLE_EQ(rouleau::vessel_length(p), 61.0);
    EXPECT_LT(largest_jump, 1e-8);
    EXPECT_TRUE(monotone);
    EXPECT_NEAR(exact / numeric, 1.0, 1e-10);
    EXPECT_DOUBLE_EQ(rouleau::vessel_radius(p, 29.0), 2.0);
    if (transition == VesselTransition::cosine) EXPECT_LT(largest_end_slope, 1e-3);  // dr/dx → 0 at the joints
    else EXPECT_NEAR(largest_end_slope, 3.0 / 6.0, 1e-9);                             // the diffuser cone's slope
  }
}

TEST(VesselProfile, BadGeometryNamesTheKeyAndTheReason) {
  struct Case {
    const char* what;
    void (*change)(VesselProfile&);
    const char* key;
  };
  const std::vector<Case> cases{
      {"throat wider than the inlet", [](VesselProfile& p) { p.throat_radius = 6.0; }, "throat_radius_um"},
      {"zero radius", [](VesselProfile& p) { p.radius = 0.0; }, "radius_um"},
      {"negative throat radius", [](VesselProfile& p) { p.throat_radius = -1.0; }, "throat_radius_um"},
      {"negative length", [](VesselProfile& p) { p.throat_length = -2.0; }, "throat_length_um"},
      {"no inlet feeder", [](VesselProfile& p) { p.inlet_length = 0.0; }, "inlet_length_um"},
      {"no contraction", [](VesselProfile& p) { p.contraction_length = 0.0; }, "contraction_length_um"},
      {"no diffuser", [](VesselProfile& p) { p.diffuser_length = 0.0; }, "diffuser_length_um"},
      {"no outlet feeder", [](VesselProfile& p) { p.outlet_length = 0.0; }, "outlet_length_um"},
      {"lengths without a throat", [](VesselProfile& p) { p.throat_radius = p.radius; }, "throat_radius_um"},
      {"not a number", [](VesselProfile& p) { p.outlet_length = NAN; }, "outlet_length_um"},
  };
  for (const Case& c : cases) {
    VesselProfile p = contraction(VesselTransition::cosine);
    c.change(p);
    const auto problem = rouleau::vessel_profile_problem(p);
    ASSERT_TRUE(problem.has_value()) << c.what;
    std::printf("%-28s -> %s: %s\n", c.what, problem->key.c_str(), problem->reason.c_str());
    EXPECT_EQ(problem->key, c.key) << c.what;
    EXPECT_FALSE(problem->reason.empty());
  }
}

}  // namespace
