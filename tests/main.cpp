// The one entry point of every test binary: starts Kokkos (all backends the build has),
// runs GoogleTest, and finalizes Kokkos after the last test.
#include <Kokkos_Core.hpp>
#include <gtest/gtest.h>
#include <spdlog/cfg/env.h>

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  spdlog::cfg::load_env_levels();  // SPDLOG_LEVEL=debug shows Newton/GMRES progress
  Kokkos::ScopeGuard kokkos(argc, argv);
  return RUN_ALL_TESTS();
}
