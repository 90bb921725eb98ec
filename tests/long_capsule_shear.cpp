// Long tier (ctest -L long; scripts/long_tier.sh): a neo-Hookean capsule in simple shear
// against the published steady Taylor deformation of a thin membrane
// (Ramanujan & Pozrikidis 1998, Doddi & Bagchi 2008: D ≈ 0.27 at Ca = 0.05, ≈ 0.39 at
// Ca = 0.1) and the small-deformation limit D → (25/4) Ca (Barthès-Biesel & Rallison 1981)
// at Ca = 0.0125, with Ca = μ γ̇ a / E_s, E_s = 3 G_s (the references'
// convention). Each runs cases/capsule_shear/case.toml (thin shell, a/h_f = 5.5) with the
// walls set for its Ca, under a minute on 2 cores (44–55 s).
#include <gtest/gtest.h>

#include <cstdio>

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

}  // namespace
