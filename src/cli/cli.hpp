#pragma once
// The `rouleau` command line: parsing argv into a plain struct, the `check` and `info`
// subcommands, and turning exceptions into one line on stderr and an exit code.
// Host-only: includes no Kokkos header (src/app/main.cpp starts Kokkos).
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "config/case_config.hpp"
#include "io/checkpoint_file.hpp"

namespace rouleau {

enum class Command {
  run,       // rouleau run CASE.toml ...
  check,     // rouleau check CASE.toml ...: validate only, no Kokkos
  info,      // rouleau info: versions and the Kokkos configuration
  finished,  // help, version, keys or a usage error was handled; exit with exit_code
};

// What the command line asked for.
struct CommandLine {
  Command command = Command::finished;
  int exit_code = 0;                   // for Command::finished
  std::string case_path;               // run, check
  std::string restart_dir;             // run --restart DIR (then no case_path; output goes to DIR)
  std::vector<std::string> overrides;  // --set key=value, in order
  std::string output_dir = "out";      // run --out
  bool overwrite = false;              // run --overwrite: empty the output folder of an earlier run first
  bool memory_check = true;            // run/check --no-memory-check clears it
  int threads = 0;                     // run/info --threads; 0 = leave it to OMP_NUM_THREADS
  bool explain = false;                // run --explain
  bool progress = true;                // run --no-progress clears it
};

// Parses argv (argv[0] is the program name) without touching Kokkos. `help` (or --help),
// `version` (or --version) and `keys` (the case-file reference) print to `out`; usage
// errors print CLI11's message to `err`, and no subcommand at all prints the help there.
// All give Command::finished with exit_code 0 (help, version, keys) or 2 (usage error, no
// subcommand).
CommandLine parse_command_line(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

// A case driver's command line (cases/NAME/main.cpp), the options of `rouleau run`:
//   case_NAME [CASE.toml] [--out DIR] [--set KEY=VALUE]... [--explain] [--no-progress]
//             [--restart DIR]
// with the driver's own case file and output folder as defaults. Kokkos's own flags
// (--kokkos-...) are taken by Kokkos before this sees argv. Gives Command::run, or
// Command::finished for --help and usage errors as parse_command_line.
CommandLine parse_driver_command_line(int argc, const char* const* argv, const std::string& default_case,
                                      const std::string& default_output_dir, std::ostream& out, std::ostream& err);

// The case a `run` command line asks for: the case file with its overrides, or, with
// --restart DIR, the case stored in DIR's newest valid checkpoint with the overrides
// (`restart` receives that checkpoint; each damaged one passed over is reported on `log`).
// Throws InputError: a bad case, or "DIR: --restart: no checkpoint in DIR/checkpoints".
CaseConfig load_run_case(const CommandLine& command_line, std::shared_ptr<const FoundCheckpoint>& restart,
                         std::ostream& log);

// `rouleau check`: loads and validates the case with its overrides, derives its scales
// and prints a short summary (name, mesh, Re, Stokes, the memory it needs) to `out`.
// Throws InputError, also when the case does not fit in memory (check_memory).
int check_case(const CommandLine& command_line, std::ostream& out);

// The host threads a run will use: --threads, OMP_NUM_THREADS, or the cores this process may run on.
int host_threads(const CommandLine& command_line);

// The case's memory estimate (config/memory_estimate.hpp); throws InputError when a 32-bit
// index would overflow, or when the case does not fit in the memory available and the
// command line does not say --no-memory-check.
void check_memory(const CaseConfig& config, const CommandLine& command_line);

// The summary `check` prints: name, mesh size, scales, Re and the Stokes decision.
std::string case_summary(const CaseConfig& config, const DerivedQuantities& derived);

// The Kokkos command-line flag that sets the thread count: --kokkos-threads=N before
// Kokkos 4 (kokkos_version < 40000, as KOKKOS_VERSION), --kokkos-num-threads=N after.
std::string kokkos_threads_flag(int threads, int kokkos_version);

// "name: value" lines with the values aligned, for `rouleau info`.
std::string format_info_lines(const std::vector<std::pair<std::string, std::string>>& lines);

// Runs `command` and maps what it throws to an exit code, writing one line to `err`:
//   InputError       -> "rouleau: FILE: KEY: REASON", 2
//   DivergenceError  -> "rouleau: MESSAGE", 3
//   std::exception   -> "rouleau: internal error: MESSAGE", 1
// Returns command()'s result when it throws nothing.
int run_reporting_errors(const std::function<int()>& command, std::ostream& err);

}  // namespace rouleau
