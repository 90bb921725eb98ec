#pragma once
// What every capsule-in-shear test expects of a run (tests/capsule_in_shear.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "capsule_in_shear.hpp"

namespace rouleau::testing {

// What every run must show: steady (D moved by less than 0.005 over the last 20 %) and
// the enclosed volume kept within 1 %.
inline void expect_steady_and_volume_kept(const CapsuleResult& r) {
  EXPECT_LT(std::fabs(r.deformation_drift), 0.005);
  EXPECT_LT(r.largest_volume_change, 0.01);
}

}  // namespace rouleau::testing
