#include "cli/cli.hpp"

#include <CLI/CLI.hpp>
#include <sched.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <thread>

#include "config/case_file_reference.hpp"
#include "config/derived.hpp"
#include "config/load_case.hpp"
#include "config/memory_estimate.hpp"
#include "io/run_folder.hpp"
#include "parallel/mpi_session.hpp"
#include "rouleau_version.hpp"
#include "util/errors.hpp"

namespace rouleau {
namespace {

constexpr int usage_error_exit_code = static_cast<int>(ExitCode::bad_input);

// The options `run` and a case driver share: --out, --explain, --no-progress, --restart.
void add_run_options(CLI::App& command, CommandLine& result, bool& no_progress) {
  CLI::Option* out =
      command.add_option("--out", result.output_dir, "Output folder")->type_name("DIR")->capture_default_str();
  command.add_flag("--explain", result.explain, "Print the stages with the reason for each skip, then stop");
  command.add_flag("--no-progress", no_progress, "Do not show the progress line");
  command
      .add_option("--restart", result.restart_dir,
                  "Continue the run in DIR from its newest valid checkpoint (its case, with any --set "
                  "overrides, e.g. a later time.end_s); the outputs go on in DIR")
      ->type_name("DIR")
      ->excludes(out);
  command.add_flag("--overwrite", result.overwrite,
                   "Empty the output folder first when it holds an earlier run (without it, a run refuses a "
                   "folder that holds files)")
      ->excludes("--restart");
}

void add_memory_check_option(CLI::App& command, CommandLine& result) {
  command.add_flag("--no-memory-check{false}", result.memory_check,
                   "Go ahead when the case's estimated memory exceeds what the machine has available");
}

void add_overrides_option(CLI::App& command, CommandLine& result) {
  command.add_option("--set", result.overrides, "Override a case key, e.g. --set time.dt_s=0.01 (repeatable)")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);
}

// Parses argv into `result` through `app`; a parse error or --help gives
// Command::finished with its exit code. Returns whether parsing succeeded.
bool parse_or_finish(CLI::App& app, int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                     CommandLine& result) {
  try {
    app.parse(argc, argv);
    return true;
  } catch (const CLI::ParseError& error) {
    result.command = Command::finished;
    const int cli_exit_code = app.exit(error, out, err);
    result.exit_code = cli_exit_code == 0 ? 0 : usage_error_exit_code;
    return false;
  }
}

void add_case_arguments(CLI::App& command, CommandLine& result, bool required = true) {
  CLI::Option* case_file = command.add_option("case", result.case_path, "Case file (TOML)")->type_name("CASE.toml");
  if (required) case_file->required();
  add_overrides_option(command, result);
}

void add_threads_option(CLI::App& command, CommandLine& result) {
  command.add_option("--threads", result.threads, "Host threads (default: OMP_NUM_THREADS)")
      ->check(CLI::Range(1, 65536));
}

// A message on one line (an InputError names keys that may hold control characters).
std::string single_line(std::string text) {
  std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return text;
}

// A driver's own case file: for a driver installed by `cmake --install`,
// PREFIX/share/rouleau/cases/NAME/case.toml beside PREFIX/bin, found from the executable's
// own path (the install can be moved); otherwise where the build found it (the source tree).
std::string driver_case_file(const std::string& default_case) {
  namespace fs = std::filesystem;
  std::error_code status;
  const fs::path executable = fs::read_symlink("/proc/self/exe", status);
  if (status) return default_case;
  const fs::path case_folder = fs::path(default_case).parent_path().filename();
  const fs::path installed =
      executable.parent_path().parent_path() / "share" / "rouleau" / "cases" / case_folder / "case.toml";
  return fs::exists(installed, status) ? installed.string() : default_case;
}

}  // namespace

CommandLine parse_command_line(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CommandLine result;
  CLI::App app("rouleau: immersed finite-element simulation of red blood cells in plasma", "rouleau");
  const std::string version_text = std::string("rouleau ") + ROULEAU_VERSION + " (" + ROULEAU_GIT_HASH + ")";
  app.set_version_flag("--version", version_text);
  app.require_subcommand(0, 1);

  CLI::App* run = app.add_subcommand("run", "Run a case: validate it, then simulate and write outputs");
  add_case_arguments(*run, result, false);
  bool no_progress = false;
  add_run_options(*run, result, no_progress);
  // A case file, or --restart DIR (whose checkpoint holds the case), not both.
  run->get_option("--restart")->excludes(run->get_option("case"));
  run->callback([&] {
    if (result.case_path.empty() && result.restart_dir.empty())
      throw CLI::RequiredError("run needs a case file (CASE.toml) or --restart DIR");
  });
  add_threads_option(*run, result);
  add_memory_check_option(*run, result);

  CLI::App* check = app.add_subcommand("check", "Validate a case, estimate its memory and print its summary (no simulation)");
  add_case_arguments(*check, result);
  add_memory_check_option(*check, result);

  CLI::App* info = app.add_subcommand("info", "Print versions and the Kokkos configuration");
  add_threads_option(*info, result);
  CLI::App* keys = app.add_subcommand(
      "keys", "Print the case-file reference: every key with its unit, default, allowed values and meaning (Markdown)");
  CLI::App* help = app.add_subcommand("help", "Print this help");
  CLI::App* version = app.add_subcommand("version", "Print the version");

  if (!parse_or_finish(app, argc, argv, out, err, result)) return result;
  if (help->parsed() || version->parsed() || keys->parsed() || app.get_subcommands().empty()) {
    result.command = Command::finished;
    if (version->parsed()) out << version_text << "\n";
    else if (keys->parsed()) out << case_file_reference();
    else  // the whole command's help (app.help() would give the `help` subcommand's)
      (help->parsed() ? out : err) << app.get_formatter()->make_help(&app, "rouleau", CLI::AppFormatMode::Normal);
    result.exit_code = help->parsed() || version->parsed() || keys->parsed() ? 0 : usage_error_exit_code;
    return result;
  }
  result.progress = !no_progress;
  result.command = run->parsed() ? Command::run : check->parsed() ? Command::check : Command::info;
  return result;
}

CommandLine parse_driver_command_line(int argc, const char* const* argv, const std::string& default_case,
                                      const std::string& default_output_dir, std::ostream& out, std::ostream& err) {
  CommandLine result;
  result.case_path = driver_case_file(default_case);
  result.output_dir = default_output_dir;
  const std::string program = argc > 0 ? argv[0] : "case";
  CLI::App app("Runs a case and checks what is special to it (the options of `rouleau run`)", program);
  CLI::Option* case_file =
      app.add_option("case", result.case_path, "Case file (TOML)")->type_name("CASE.toml")->capture_default_str();
  add_overrides_option(app, result);
  bool no_progress = false;
  add_run_options(app, result, no_progress);
  add_threads_option(app, result);
  add_memory_check_option(app, result);
  app.get_option("--restart")->excludes(case_file);
  if (!parse_or_finish(app, argc, argv, out, err, result)) return result;
  result.progress = !no_progress;
  result.command = Command::run;
  return result;
}

std::string case_summary(const CaseConfig& config, const DerivedQuantities& derived) {
  char text[768];
  std::snprintf(text, sizeof(text),
                "case      %s\n"
                "mesh      %s\n"
                "scales    L = %g μm, U = %g μm/s, pressure %g Pa\n"
                "Re        %.3g\n"
                "Stokes    %s: %s\n",
                config.name.c_str(), describe_fluid_domain(config).c_str(), derived.length_scale,
                derived.velocity_scale, derived.pressure_scale, derived.reynolds, derived.stokes ? "yes" : "no",
                derived.stokes_reason.c_str());
  std::string summary = text;
  // The explicit coupling's stable step, which the stability study (bench/stability.py)
  // sets its time steps against.
  if (derived.stable_dt > 0.0 && config.time.mode == TimeMode::transient) {
    char step[160];
    std::snprintf(step, sizeof(step), "dt        %g s; explicit stable step estimate %g s (", config.time.dt,
                  derived.stable_dt);
    summary += step + derived.stable_dt_reason + ")\n";
  }
  // How far the flow strains the cells in one step, against the measured accurate range.
  if (derived.shear_rate > 0.0) {
    char strain[80], limit[64];
    std::snprintf(strain, sizeof(strain), "accuracy  strain per step %.3g (shear rate %.3g 1/s: ",
                  derived.strain_per_step, derived.shear_rate);
    std::snprintf(limit, sizeof(limit), "); measured accurate up to %g\n", accurate_strain_per_step);
    summary += strain + derived.shear_rate_source + limit;
  }
  if (!derived.accuracy_warning.empty()) summary += "WARNING   " + derived.accuracy_warning + "\n";
  return summary;
}

CaseConfig load_run_case(const CommandLine& command_line, std::shared_ptr<const FoundCheckpoint>& restart,
                         std::ostream& log) {
  restart.reset();
  if (command_line.restart_dir.empty()) return load_case(command_line.case_path, command_line.overrides);
  const std::string& directory = command_line.restart_dir;
  std::error_code status;
  if (!std::filesystem::is_directory(directory, status))
    throw InputError(directory, "--restart", "no such run folder");
  single_run_id(directory);  // the folder holds one run's files
  FoundCheckpoint found;
  try {
    found = newest_valid_checkpoint(directory);
  } catch (const std::runtime_error& error) {
    throw InputError(directory, "--restart", error.what());
  }
  for (const std::string& refusal : found.refused) log << "rouleau: passed over a damaged checkpoint: " << refusal << "\n";
  CaseConfig config = load_case_text(found.data.resolved_case, found.path + " (its case)", command_line.overrides);
  restart = std::make_shared<const FoundCheckpoint>(std::move(found));
  return config;
}

int host_threads(const CommandLine& command_line) {
  if (command_line.threads > 0) return command_line.threads;
  if (const char* openmp = std::getenv("OMP_NUM_THREADS"); openmp && std::atoi(openmp) > 0) return std::atoi(openmp);
  // the cores this process may run on (a batch job's share, taskset), as OpenMP counts them
  cpu_set_t allowed;
  if (sched_getaffinity(0, sizeof allowed, &allowed) == 0) return std::max(1, CPU_COUNT(&allowed));
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void check_memory(const CaseConfig& config, const CommandLine& command_line) {
  require_memory(config, estimate_memory(config, host_threads(command_line)), available_memory_bytes(),
                 command_line.memory_check);
}

int check_case(const CommandLine& command_line, std::ostream& out) {
  const CaseConfig config = load_case(command_line.case_path, command_line.overrides);
  const MemoryEstimate estimate = estimate_memory(config, host_threads(command_line));
  const double available = available_memory_bytes();
  out << case_summary(config, derive_quantities(config)) << describe_memory(estimate, available);
  require_memory(config, estimate, available, command_line.memory_check);
  out << "ok: " << command_line.case_path << " is a valid case\n";
  return static_cast<int>(ExitCode::done);
}

std::string kokkos_threads_flag(int threads, int kokkos_version) {
  return (kokkos_version < 40000 ? "--kokkos-threads=" : "--kokkos-num-threads=") + std::to_string(threads);
}

std::string format_info_lines(const std::vector<std::pair<std::string, std::string>>& lines) {
  std::size_t width = 0;
  for (const auto& line : lines) width = std::max(width, line.first.size());
  std::string text;
  for (const auto& [name, value] : lines) text += name + ":" + std::string(width + 2 - name.size(), ' ') + value + "\n";
  return text;
}

int run_reporting_errors(const std::function<int()>& command, std::ostream& err) {
  // On several ranks an error may have reached only some of them, and the others would
  // wait for them forever: the first to report one stops all with its exit code.
  auto report = [&err](ExitCode code, const std::string& line) {
    let_the_first_rank_report();
    err << "rouleau: " << line << std::endl;
    stop_all_ranks(static_cast<int>(code));
    return static_cast<int>(code);
  };
  try {
    return command();
  } catch (const InputError& error) {
    return report(ExitCode::bad_input, single_line(error.what()));
  } catch (const DivergenceError& error) {
    return report(ExitCode::diverged, error.what());
  } catch (const std::exception& error) {
    return report(ExitCode::internal_error, "internal error: " + single_line(error.what()));
  }
}

}  // namespace rouleau
