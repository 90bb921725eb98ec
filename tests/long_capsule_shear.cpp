// Long tier (ctest -L long; scripts/long_tier.sh): a neo-Hookean capsule in simple shear
// against the published steady Taylor deformation of a thin membrane
// (Ramanujan & Pozrikidis 1998, Doddi & Bagchi 2008: D ≈ 0.27 at Ca = 0.05, ≈ 0.39 at
// Ca = 0.1) and the small-deformation limit D → (25/4) Ca (Barthès-Biesel & Rallison 1981)
// at Ca = 0.0125, with Ca = μ γ̇ a / E_s, E_s = 3 G_s (the references'
// convention). Each runs cases/capsule_shear/case.toml (thin shell, a/h_f = 5.5) with the
// walls set for its Ca, under a minute on 2 cores (44–55 s); the last test runs it without
// the volume constraint at three resolutions (948 s).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "capsule_expectations.hpp"

namespace {

using rouleau::testing::CapsuleResult;
using rouleau::testing::expect_steady_and_volume_kept;
using rouleau::testing::run_capsule;

TEST(CapsuleShearLong, SmallDeformationLimitConfirmsTheConvention) {
  // D → (25/4) Ca = 0.078 at Ca = 0.0125: within 15 % (the O(Ca²) correction and the
  // resolution, both lowering D, stay within it; the convention with G_s in place of E_s
  // would give 0.026, and with the outer radius 0.081).
  const CapsuleResult r = run_capsule(0.0125);
  const double limit = 25.0 / 4.0 * 0.0125;
  std::printf("small-deformation limit %.4f: D / limit = %.3f\n", limit, r.deformation / limit);
  EXPECT_NEAR(r.deformation / limit, 1.0, 0.15);
  expect_steady_and_volume_kept(r);
}

TEST(CapsuleShearLong, TaylorDeformationAtCa005MatchesThePublishedValue) {
  const CapsuleResult r = run_capsule(0.05);
  std::printf("published 0.27: D - published = %+.4f\n", r.deformation - 0.27);
  EXPECT_NEAR(r.deformation, 0.27, 0.03);
  expect_steady_and_volume_kept(r);
}

TEST(CapsuleShearLong, TaylorDeformationAtCa01MatchesThePublishedValue) {
  const CapsuleResult r = run_capsule(0.1);
  std::printf("published 0.39: D - published = %+.4f\n", r.deformation - 0.39);
  EXPECT_NEAR(r.deformation, 0.39, 0.03);
  expect_steady_and_volume_kept(r);
}

// The volume kept without the volume constraint (k_V = 0), over a shear strain γ̇t = 10 at
// Ca = 0.05, at a/h_f = 4.1, 5.5 and 8.2 (27×34×27 to 54×68×54 elements, the explicit step
// scaled with h_f), with the coupling that removes the membrane's leak: the cells move with
// u_h + u' (PSPG's subscale velocity), the spread loads enter the stabilization's strong
// residual, and the RKPM support spans 2.5 elements (docs/validation.md, "Resolution near
// the cells"). Thresholds, set by the requirement: the volume within 0.3 % throughout the
// run at the finest resolution, and at the end from a/h_f = 5.5 on; the largest excursion
// falling with each refinement; D within 0.02 of the published 0.27 at the finest, its
// change from 5.5 to 8.2 smaller than from 4.1 to 5.5 (converging). Before: with the
// default coupling the capsule lost 2.3, 3.4 and 4.7 % at these resolutions. Measured:
// at the end +0.45, +0.04, +0.01 %, largest excursions 0.50, 0.36, 0.26 %; D = 0.240,
// 0.267, 0.276. 948 s on 2 cores.
TEST(CapsuleShearLong, VolumeKeptWithoutTheConstraintAndDConverges) {
  struct Resolution {
    const char* elements;
    const char* dt;
  };
  const Resolution resolutions[] = {{"[27, 34, 27]", "1.3333e-4"}, {"[36, 45, 36]", "1e-4"}, {"[54, 68, 54]", "6.6667e-5"}};
  std::vector<CapsuleResult> results;
  for (const Resolution& resolution : resolutions) {
    // γ̇ = 192.3 /s at Ca = 0.05: γ̇t = 10 at t = 0.052 s.
    results.push_back(run_capsule(0.05, {std::string("domain.elements=") + resolution.elements,
                                         std::string("time.dt_s=") + resolution.dt, "time.end_s=0.052",
                                         "cell_kinds.capsule.volume_modulus_Pa=0", "coupling.subscale_velocity=true",
                                         "coupling.forces_in_stabilization=true", "coupling.support_elements=2.5"}));
  }
  for (const CapsuleResult& r : results)
    std::printf("capsule without the volume constraint: a/h_f = %.2f: volume change at the end %+.3f %%, largest "
                "%.3f %%, D = %.4f\n",
                r.a_over_h, 100.0 * r.final_volume_change, 100.0 * r.largest_volume_change, r.deformation);
  EXPECT_LT(results[2].largest_volume_change, 0.003);
  EXPECT_LT(std::fabs(results[1].final_volume_change), 0.003);
  EXPECT_LT(std::fabs(results[2].final_volume_change), 0.003);
  EXPECT_LT(results[1].largest_volume_change, results[0].largest_volume_change);
  EXPECT_LT(results[2].largest_volume_change, results[1].largest_volume_change);
  EXPECT_NEAR(results[2].deformation, 0.27, 0.02);
  EXPECT_LT(std::fabs(results[2].deformation - results[1].deformation),
            std::fabs(results[1].deformation - results[0].deformation));
}

}  // namespace
