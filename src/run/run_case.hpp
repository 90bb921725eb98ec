#pragma once
// Running a case: the Kokkos half of the `rouleau` command. Kokkos must be initialized
// by the caller (src/app/main.cpp). This header includes no Kokkos header.
#include <string>
#include <utility>
#include <vector>

#include "cli/cli.hpp"
#include "config/case_config.hpp"

namespace rouleau {

struct RunOptions {
  std::string output_dir = "out";  // --out
  bool explain = false;            // --explain: print the stage list with reasons, then stop
  bool progress = true;            // show the progress line
};

// The run options a command line asks for (`rouleau run`, a case driver).
inline RunOptions run_options(const CommandLine& command_line) {
  RunOptions options;
  options.output_dir = command_line.output_dir;
  options.explain = command_line.explain;
  options.progress = command_line.progress;
  return options;
}

// Builds the scene's stages, runs the time loop, writes outputs into options.output_dir.
// Returns the process exit code (ExitCode); throws InputError for bad input found late.
int run_case(const CaseConfig& config, const RunOptions& options);

// What a case driver (cases/NAME/main.cpp) runs:
//   case_NAME [CASE.toml] [--out DIR] [--set KEY=VALUE]... [--explain] [--no-progress]
// with the driver's own case file and output folder as defaults. Loads the case and runs
// it, reporting errors as `rouleau run` does (one line, exit code); the driver then checks
// what is special to its case when status is 0.
struct CaseDriverRun {
  CaseConfig config;
  RunOptions options;
  int status = 0;       // the process exit code (ExitCode)
  bool ran = false;     // the case ran to its end: the driver checks its results

};
CaseDriverRun run_case_driver(int argc, char** argv, const std::string& default_case,
                              const std::string& default_output_dir);

// Name/value lines for `rouleau info`: Kokkos version and enabled backends, default
// execution space and its concurrency (threads), KokkosKernels version.
std::vector<std::pair<std::string, std::string>> kokkos_runtime_info();

}  // namespace rouleau
