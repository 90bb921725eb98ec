#pragma once
// Running a case: the Kokkos half of the `rouleau` command. Kokkos must be initialized
// by the caller (src/app/main.cpp). This header includes no Kokkos header.
#include <memory>
#include <string>

#include "cli/cli.hpp"
#include "config/case_config.hpp"
#include "io/checkpoint_file.hpp"

namespace rouleau {

struct RunOptions {
  std::string output_dir = "out";  // --out
  bool explain = false;            // --explain: print the stage list with reasons, then stop
  bool progress = true;            // show the progress line
  bool overwrite = false;          // --overwrite: empty an output folder that holds an earlier run first
  // --restart: continue from this checkpoint (of a run in output_dir), or start afresh.
  std::shared_ptr<const FoundCheckpoint> restart;
  // The command that continues a stopped run, given the output folder: a case driver's
  // own program, so that its checks run at the end of the continued run too.
  std::string continue_command = "rouleau run --restart";
};

// The run options a command line asks for (`rouleau run`, a case driver).
inline RunOptions run_options(const CommandLine& command_line) {
  RunOptions options;
  options.output_dir = command_line.output_dir;
  options.explain = command_line.explain;
  options.progress = command_line.progress;
  options.overwrite = command_line.overwrite;
  if (!command_line.restart_dir.empty()) options.output_dir = command_line.restart_dir;
  return options;
}

// Builds the scene's stages, runs the time loop, writes outputs into options.output_dir.
// A transient run writes checkpoints (io/checkpoint_file.hpp) at its start, as the case's
// [checkpoint] asks, on SIGUSR1, and at its end; SIGINT/SIGTERM stop it after the current
// step with a checkpoint (cli/stop_signals.hpp). With options.restart it continues from
// that checkpoint: the diagnostics rows and field steps up to it are kept, later ones
// dropped, and the steps repeat the straight run's bit for bit on the same thread count.
// Returns the process exit code (ExitCode: 4 when a signal stopped it); throws InputError
// for bad input found late (a checkpoint of other meshes), DivergenceError naming the last
// good checkpoint.
int run_case(const CaseConfig& config, const RunOptions& options);

// What a case driver (cases/NAME/main.cpp) runs:
//   case_NAME [CASE.toml] [--out DIR] [--set KEY=VALUE]... [--explain] [--no-progress]
//             [--restart DIR] [--threads N]
// with the driver's own case file and output folder as defaults. Loads the case and runs
// it (Kokkos runs only inside this call, run/kokkos_session.hpp), reporting errors as
// `rouleau run` does (one line, exit code); the driver then checks
// what is special to its case when status is 0.
struct CaseDriverRun {
  CaseConfig config;
  RunOptions options;
  int status = 0;       // the process exit code (ExitCode)
  bool ran = false;     // the case ran to its end: the driver checks its results

};
CaseDriverRun run_case_driver(int argc, char** argv, const std::string& default_case,
                              const std::string& default_output_dir);

}  // namespace rouleau
