#pragma once
// Running a case: the Kokkos half of the `rouleau` command. Kokkos must be initialized
// by the caller (src/app/main.cpp). This header includes no Kokkos header.
#include <string>
#include <utility>
#include <vector>

#include "config/case_config.hpp"

namespace rouleau {

struct RunOptions {
  std::string output_dir = "out";  // --out
  bool explain = false;            // --explain: print the stage list with reasons, then stop
  bool progress = true;            // show the progress line
};

// Builds the scene's stages, runs the time loop, writes outputs into options.output_dir.
// Returns the process exit code (ExitCode); throws InputError for bad input found late.
int run_case(const CaseConfig& config, const RunOptions& options);

// Name/value lines for `rouleau info`: Kokkos version and enabled backends, default
// execution space and its concurrency (threads), KokkosKernels version.
std::vector<std::pair<std::string, std::string>> kokkos_runtime_info();

}  // namespace rouleau
