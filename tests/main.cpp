// The one entry point of every test binary: starts Kokkos (all backends the build has),
// runs GoogleTest, and finalizes Kokkos after the last test.
#include <Kokkos_Core.hpp>
#include <gtest/gtest.h>
#include <spdlog/cfg/env.h>

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  spdlog::cfg::load_env_levels();  // SPDLOG_LEVEL=debug shows Newton/GMRES progress
  // Listing the tests (ctest's discovery) needs no Kokkos, and Kokkos' start-up warnings
  // would otherwise be read as test names.
  if (::testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();
  Kokkos::ScopeGuard kokkos(argc, argv);
  return RUN_ALL_TESTS();
}
