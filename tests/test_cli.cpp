// The `rouleau` command line: argv parsing in process, the real executable's exit codes
// and stderr, and the progress line's rate limiting with an injected clock.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Kokkos_Core.hpp>

#include "cli/cli.hpp"
#include "cli/progress.hpp"
#include "io/provenance.hpp"
#include "rouleau_version.hpp"
#include "util/errors.hpp"
#include "run/thread_binding.hpp"
#include "run_rouleau.hpp"
#include "bad_case_files.hpp"

namespace {

const std::string data_dir = ROULEAU_TEST_DATA_DIR;
const std::string good_case = data_dir + "/good_case.toml";

rouleau::CommandLine parse(std::vector<const char*> arguments, std::string* out_text = nullptr,
                           std::string* err_text = nullptr) {
  arguments.insert(arguments.begin(), "rouleau");
  std::ostringstream out, err;
  const auto result = rouleau::parse_command_line(static_cast<int>(arguments.size()), arguments.data(), out, err);
  if (out_text) *out_text = out.str();
  if (err_text) *err_text = err.str();
  return result;
}

TEST(CliParse, RunWithEveryOption) {
  const auto command_line = parse({"run", "case.toml", "--out", "results", "--set", "time.dt_s=0.1", "--set",
                                   "case.name=x", "--threads", "3", "--explain", "--no-progress"});
  EXPECT_EQ(command_line.command, rouleau::Command::run);
  EXPECT_EQ(command_line.case_path, "case.toml");
  EXPECT_EQ(command_line.output_dir, "results");
  EXPECT_EQ(command_line.overrides, (std::vector<std::string>{"time.dt_s=0.1", "case.name=x"}));
  EXPECT_EQ(command_line.threads, 3);
  EXPECT_TRUE(command_line.explain);
  EXPECT_FALSE(command_line.progress);
}

TEST(CliParse, RunDefaults) {
  const auto command_line = parse({"run", "case.toml"});
  EXPECT_EQ(command_line.command, rouleau::Command::run);
  EXPECT_EQ(command_line.output_dir, "out");
  EXPECT_EQ(command_line.threads, 0);
  EXPECT_TRUE(command_line.overrides.empty());
  EXPECT_FALSE(command_line.explain);
  EXPECT_TRUE(command_line.progress);
}

TEST(CliParse, RestartTakesTheRunFolderAsOutputAndOverrides) {
  const auto command_line = parse({"run", "--restart", "runs/stack", "--set", "time.end_s=4", "--threads", "2"});
  EXPECT_EQ(command_line.command, rouleau::Command::run);
  EXPECT_TRUE(command_line.case_path.empty());
  EXPECT_EQ(command_line.restart_dir, "runs/stack");
  EXPECT_EQ(command_line.overrides, std::vector<std::string>{"time.end_s=4"});
}

TEST(CliParse, CheckAndInfo) {
  const auto check = parse({"check", "case.toml", "--set", "a.b=1"});
  EXPECT_EQ(check.command, rouleau::Command::check);
  EXPECT_EQ(check.overrides, std::vector<std::string>{"a.b=1"});
  const auto info = parse({"info", "--threads", "2"});
  EXPECT_EQ(info.command, rouleau::Command::info);
  EXPECT_EQ(info.threads, 2);
}

TEST(CliParse, UsageErrorsFinishWithExitCode2) {
  const std::vector<std::vector<const char*>> usage_errors{
      {},                                       // no subcommand
      {"frobnicate"},                           // unknown subcommand
      {"run"},                                  // no case file
      {"check", "case.toml", "--bogus"},        // unknown option
      {"run", "case.toml", "--threads", "0"},   // out of range
      {"run", "case.toml", "--threads", "two"}, // not a number
      {"check", "case.toml", "--explain"},      // an option of another subcommand
      {"run", "case.toml", "--restart", "old"}, // a case file and a run to continue
      {"run", "--restart", "old", "--out", "x"},  // a restart writes into its own folder
  };
  for (const auto& arguments : usage_errors) {
    std::string err;
    const auto command_line = parse(arguments, nullptr, &err);
    EXPECT_EQ(command_line.command, rouleau::Command::finished);
    EXPECT_EQ(command_line.exit_code, 2);
    EXPECT_FALSE(err.empty());
  }
}

TEST(CliParse, HelpAndVersionFinishWithExitCode0) {
  for (const auto& arguments : std::vector<std::vector<const char*>>{
           {"--help"}, {"help"}, {"run", "--help"}, {"check", "--help"}, {"info", "--help"}}) {
    std::string out;
    const auto command_line = parse(arguments, &out);
    EXPECT_EQ(command_line.command, rouleau::Command::finished);
    EXPECT_EQ(command_line.exit_code, 0);
    EXPECT_NE(out.find("Usage"), std::string::npos) << out;
  }
  for (const char* version : {"--version", "version"}) {
    std::string out;
    const auto command_line = parse({version}, &out);
    EXPECT_EQ(command_line.command, rouleau::Command::finished);
    EXPECT_EQ(command_line.exit_code, 0);
    EXPECT_NE(out.find(ROULEAU_VERSION), std::string::npos) << version;
  }
  // No subcommand at all: the help, on stderr, as a usage error.
  std::string out, err;
  EXPECT_EQ(parse({}, &out, &err).exit_code, 2);
  EXPECT_NE(err.find("Subcommands"), std::string::npos) << err;
}

TEST(CliParse, OverwriteAndNoMemoryCheck) {
  const auto plain = parse({"run", "case.toml"});
  EXPECT_FALSE(plain.overwrite);
  EXPECT_TRUE(plain.memory_check);
  const auto both = parse({"run", "case.toml", "--overwrite", "--no-memory-check"});
  EXPECT_TRUE(both.overwrite);
  EXPECT_FALSE(both.memory_check);
  EXPECT_FALSE(parse({"check", "case.toml", "--no-memory-check"}).memory_check);
  // A restart continues its own folder: nothing to overwrite.
  EXPECT_EQ(parse({"run", "--restart", "old", "--overwrite"}).exit_code, 2);
}

TEST(CliParse, CaseDriverTakesTheRunOptionsWithItsOwnDefaults) {
  auto parse_driver = [](std::vector<const char*> arguments, std::string* err_text = nullptr) {
    arguments.insert(arguments.begin(), "case_capsule_shear");
    std::ostringstream out, err;
    const auto result = rouleau::parse_driver_command_line(static_cast<int>(arguments.size()), arguments.data(),
                                                           "cases/capsule_shear/case.toml", "runs/capsule_shear",
                                                           out, err);
    if (err_text) *err_text = err.str();
    return result;
  };
  const auto defaults = parse_driver({});
  EXPECT_EQ(defaults.command, rouleau::Command::run);
  EXPECT_EQ(defaults.case_path, "cases/capsule_shear/case.toml");
  EXPECT_EQ(defaults.output_dir, "runs/capsule_shear");
  EXPECT_TRUE(defaults.progress);

  const auto every = parse_driver({"other.toml", "--out", "runs/ca01", "--set", "time.end_s=0.01", "--set",
                                   "case.name=x", "--no-progress", "--explain"});
  EXPECT_EQ(every.command, rouleau::Command::run);
  EXPECT_EQ(every.case_path, "other.toml");
  EXPECT_EQ(every.output_dir, "runs/ca01");
  EXPECT_EQ(every.overrides, (std::vector<std::string>{"time.end_s=0.01", "case.name=x"}));
  EXPECT_FALSE(every.progress);
  EXPECT_TRUE(every.explain);

  // The thread count as `rouleau run` takes it (Kokkos never sees the command line, so its
  // own deprecated `--threads` can not abort the driver).
  EXPECT_EQ(parse_driver({"--threads", "3"}).threads, 3);
  EXPECT_EQ(defaults.threads, 0);
  std::string err;
  const auto zero_threads = parse_driver({"--threads", "0"}, &err);
  EXPECT_EQ(zero_threads.command, rouleau::Command::finished);
  EXPECT_EQ(zero_threads.exit_code, 2);
  EXPECT_FALSE(err.empty());
}

TEST(CliParse, KokkosThreadsFlagDependsOnTheKokkosVersion) {
  EXPECT_EQ(rouleau::kokkos_threads_flag(4, 30401), "--kokkos-threads=4");
  EXPECT_EQ(rouleau::kokkos_threads_flag(4, 40600), "--kokkos-num-threads=4");
}

// The CPUs a run binds its threads to (run/thread_binding.hpp): distinct cores first, spread.
TEST(ThreadBinding, ThreadsGoToDistinctCoresFirstAndSpreadOverThem) {
  using rouleau::spread_threads_over_cores;
  // Two cores, no SMT: one thread per core.
  EXPECT_EQ(spread_threads_over_cores(2, {0, 1}, {0, 1}), (std::vector<int>{0, 1}));
  // Eight cores, two threads: spread, not packed on cores 0 and 1.
  EXPECT_EQ(spread_threads_over_cores(2, {0, 1, 2, 3, 4, 5, 6, 7}, {0, 1, 2, 3, 4, 5, 6, 7}),
            (std::vector<int>{0, 4}));
  // SMT with siblings numbered next to each other (CPUs 0, 1 on core 0; 2, 3 on core 1):
  // two threads go to two cores, never to the two hardware threads of one core.
  EXPECT_EQ(spread_threads_over_cores(2, {0, 1, 2, 3}, {0, 0, 2, 2}), (std::vector<int>{0, 2}));
  // SMT with siblings numbered half the machine apart (0 and 2 on core 0): the same.
  EXPECT_EQ(spread_threads_over_cores(2, {0, 1, 2, 3}, {0, 1, 0, 1}), (std::vector<int>{0, 1}));
  // More threads than cores: every core's first CPU, then the siblings.
  EXPECT_EQ(spread_threads_over_cores(4, {0, 1, 2, 3}, {0, 0, 2, 2}), (std::vector<int>{0, 2, 1, 3}));
  // A process confined to some CPUs binds within them.
  EXPECT_EQ(spread_threads_over_cores(2, {4, 5, 6, 7}, {4, 5, 6, 7}), (std::vector<int>{4, 6}));
  // Nothing to bind: one thread, or more threads than CPUs.
  EXPECT_TRUE(spread_threads_over_cores(1, {0, 1}, {0, 1}).empty());
  EXPECT_TRUE(spread_threads_over_cores(3, {0, 1}, {0, 1}).empty());
}

TEST(CliErrors, ExceptionsBecomeOneLineAndAnExitCode) {
  std::ostringstream err;
  EXPECT_EQ(rouleau::run_reporting_errors([] { return 0; }, err), 0);
  EXPECT_EQ(err.str(), "");
  EXPECT_EQ(rouleau::run_reporting_errors([]() -> int { throw rouleau::InputError("c.toml", "a.b", "bad\nthing"); }, err), 2);
  EXPECT_EQ(err.str(), "rouleau: c.toml: a.b: bad thing\n");
  err.str("");
  EXPECT_EQ(rouleau::run_reporting_errors([]() -> int { throw rouleau::DivergenceError("step 3: NaN"); }, err), 3);
  EXPECT_EQ(err.str(), "rouleau: step 3: NaN\n");
  err.str("");
  EXPECT_EQ(rouleau::run_reporting_errors([]() -> int { throw std::logic_error("oops"); }, err), 1);
  EXPECT_EQ(err.str(), "rouleau: internal error: oops\n");
}

TEST(CliInfo, LinesAreAligned) {
  EXPECT_EQ(rouleau::format_info_lines({{"a", "1"}, {"long name", "2"}}), "a:          1\nlong name:  2\n");
}

// ---- the real executable

std::size_t line_count(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }


TEST(CliExecutable, CheckGoodCasePrintsItsSummary) {
  const Outcome outcome = run_rouleau("check '" + good_case + "'");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("shear_box"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("8 x 16 x 4"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("Stokes    yes"), std::string::npos) << outcome.out;
  EXPECT_EQ(outcome.err, "");
}

TEST(CliExecutable, CasesTooLargeAreRefusedBeforeAnyWork) {
  // Inside the range of each component of domain.elements, these crashed: 4096³ (a 32-bit
  // node count wrapped; a segmentation fault) and 1000³ (Kokkos failed to allocate 22.4
  // GiB). Both are refused now, with one line and exit 2, before a file is written, also
  // with --no-memory-check (their indices overflow 32 bits); 300³ needs some 500 GiB.
  const std::string shear = std::string(ROULEAU_SOURCE_DIR) + "/cases/shear_flow/case.toml";
  for (const std::string size : {"4096", "1000"})
    for (const std::string command : {"check", "run", "run --no-memory-check"}) {
      const std::string out = fresh_output_dir("too_large");
      const std::string elements = " --set domain.elements=[" + size + "," + size + "," + size + "]";
      SCOPED_TRACE(command + elements);
      const Outcome outcome = run_rouleau(command + " " + shear + elements +
                                          (command == "check" ? std::string() : " --no-progress --out " + out));
      EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
      EXPECT_EQ(line_count(outcome.err), 1u) << outcome.err;
      EXPECT_NE(outcome.err.find("domain.elements: the mesh is too large for rouleau's 32-bit indices"),
                std::string::npos)
          << outcome.err;
      EXPECT_FALSE(std::filesystem::exists(out)) << "a refused run wrote " << out;
    }
  const Outcome check = run_rouleau("check " + shear + " --set domain.elements=[300,300,300]");
  if (check.exit_code == 0) GTEST_SKIP() << "a machine with some 500 GiB to spare:\n" << check.out;
  const Outcome run = run_rouleau("run " + shear + " --set domain.elements=[300,300,300] --no-progress --out " +
                                  fresh_output_dir("too_large_memory"));
  for (const Outcome& outcome : {check, run}) {
    EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
    EXPECT_NE(outcome.err.find("domain.elements: the case needs about "), std::string::npos) << outcome.err;
    EXPECT_NE(outcome.err.find("more than the "), std::string::npos) << outcome.err;
  }
  EXPECT_NE(check.out.find("memory    about "), std::string::npos) << check.out;
}

TEST(CliExecutable, CheckBadCasesExitWith2AndOneLineNamingTheKey) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(data_dir + "/bad_cases")) {
    const std::string path = entry.path().string();
    SCOPED_TRACE(path);
    const Outcome outcome = run_rouleau("check '" + path + "'");
    EXPECT_EQ(outcome.exit_code, 2);
    EXPECT_EQ(line_count(outcome.err), 1u) << outcome.err;
    EXPECT_EQ(outcome.err.rfind("rouleau: " + path + ": " + expected_key_of(path), 0), 0u) << outcome.err;
    ++files;
  }
  EXPECT_GE(files, 25);
}

TEST(CliExecutable, BadOverrideNamesTheSetOption) {
  const Outcome outcome = run_rouleau("check '" + good_case + "' --set fluid.viscosity_Pa_s=-1");
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.err, "rouleau: --set: fluid.viscosity_Pa_s: must be > 0, got -1\n");
}

TEST(CliExecutable, RunOnBadCaseStopsBeforeAnyWork) {
  const auto output_dir = rouleau::testing::temporary_folder_path("cli_out");
  std::filesystem::remove_all(output_dir);
  const std::string path = data_dir + "/bad_cases/negative_viscosity.toml";
  const Outcome outcome = run_rouleau("run '" + path + "' --out '" + output_dir.string() + "' --threads 2");
  EXPECT_EQ(outcome.exit_code, 2);
  // one line: Kokkos was not even started (it would warn or print on start-up)
  EXPECT_EQ(outcome.err, "rouleau: " + path + ": fluid.viscosity_Pa_s: must be > 0, got -1\n");
  EXPECT_FALSE(std::filesystem::exists(output_dir));
}

TEST(CliExecutable, UsageErrorsExitWith2) {
  for (const std::string& arguments : std::vector<std::string>{"", "frobnicate", "check",
                                                              "check '" + good_case + "' --bogus",
                                                              "run '" + good_case + "' --threads 0"}) {
    SCOPED_TRACE(arguments);
    const Outcome outcome = run_rouleau(arguments);
    EXPECT_EQ(outcome.exit_code, 2);
    EXPECT_FALSE(outcome.err.empty());
  }
}

TEST(CliExecutable, InfoReportsVersionsAndTheOpenMPBackend) {
  const Outcome outcome = run_rouleau("info --threads 3");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  for (const char* expected : {"rouleau:", ROULEAU_VERSION, "toml++:", "CLI11:", "spdlog:", "Eigen:", "HDF5:",
                               "kokkos:", "OpenMP"})
    EXPECT_NE(outcome.out.find(expected), std::string::npos) << expected << " not in\n" << outcome.out;
  // The "threads:" line carries the requested thread count.
  std::istringstream lines(outcome.out);
  std::string line, threads;
  while (std::getline(lines, line))
    if (line.rfind("threads:", 0) == 0) threads = line.substr(line.find_last_of(' ') + 1);
  EXPECT_EQ(threads, "3") << outcome.out;
}

// "3.4.01" or "4.6.1" as major * 10000 + minor * 100 + patch (KOKKOS_VERSION's encoding).
int encoded_version(const std::string& dotted) {
  int major = -1, minor = -1, patch = -1;
  if (std::sscanf(dotted.c_str(), "%d.%d.%d", &major, &minor, &patch) != 3) return -1;
  return major * 10000 + minor * 100 + patch;
}

TEST(Provenance, NamesTheKokkosVersionsTheBuildFound) {
  // Compared with what the compiler sees (Kokkos's own KOKKOS_VERSION macro) and what CMake
  // found (KokkosKernels 3.4 has no version macro), not with the macro the provenance
  // itself is made from: that one was empty when it was written before Kokkos was found.
  const rouleau::Provenance provenance = rouleau::build_provenance();
  ASSERT_NE(provenance.find("kokkos_version"), nullptr);
  EXPECT_EQ(encoded_version(*provenance.find("kokkos_version")), KOKKOS_VERSION) << *provenance.find("kokkos_version");
  ASSERT_NE(provenance.find("kokkoskernels_version"), nullptr);
  const std::string kernels = *provenance.find("kokkoskernels_version");
  EXPECT_GT(encoded_version(kernels), 30000) << kernels;
  EXPECT_EQ(kernels, ROULEAU_FOUND_KOKKOSKERNELS_VERSION);
}

TEST(CliExecutable, HelpOnEverySubcommandAndVersion) {
  for (const std::string arguments : {"--help", "help", "run --help", "check --help", "info --help", "--version", "version"}) {
    SCOPED_TRACE(arguments);
    const Outcome outcome = run_rouleau(arguments);
    EXPECT_EQ(outcome.exit_code, 0);
    EXPECT_FALSE(outcome.out.empty());
  }
}

// ---- the progress line

struct FakeClock {
  double now_s = 0.0;
  rouleau::ProgressReporter::Settings settings(double terminal_interval_s, double log_interval_s) {
    rouleau::ProgressReporter::Settings settings;
    settings.terminal_interval_s = terminal_interval_s;
    settings.log_interval_s = log_interval_s;
    settings.clock = [this] { return now_s; };
    return settings;
  }
};

TEST(ProgressReporter, LineShowsStepTimeSpeedIterationsAndEta) {
  FakeClock clock;
  std::ostringstream out;
  rouleau::ProgressReporter progress(100, 1.0, false, out, clock.settings(0.1, 5.0));
  clock.now_s = 10.0;
  EXPECT_EQ(progress.line(50, 0.5, 3, 45), "step 50/100  t = 0.5/1 s  5 steps/s  Newton 3  GMRES 45  ETA 10s");
}

TEST(ProgressReporter, LogPrintsAFullLineAtMostEveryInterval) {
  FakeClock clock;
  std::ostringstream out;
  rouleau::ProgressReporter progress(100, 1.0, false, out, clock.settings(0.1, 5.0));
  for (int step = 1; step <= 100; ++step) {
    clock.now_s = 0.25 * step;  // 25 s in all
    progress.update(step, 0.01 * step, 2, 10);
  }
  // shown at 0.25, 5.25, 10.25, 15.25 and 20.25 s; step 100 (at 25 s) waits for finish()
  EXPECT_EQ(line_count(out.str()), 5u) << out.str();
  EXPECT_EQ(out.str().find('\r'), std::string::npos);
  progress.finish();  // the last state had not been shown
  EXPECT_EQ(line_count(out.str()), 6u);
  EXPECT_NE(out.str().find("step 100/100"), std::string::npos) << out.str();
  progress.finish();
  EXPECT_EQ(line_count(out.str()), 6u);
}

TEST(ProgressReporter, TerminalRedrawsOneLineAtMostTenTimesASecond) {
  FakeClock clock;
  std::ostringstream out;
  rouleau::ProgressReporter progress(1000, 1.0, true, out, clock.settings(0.1, 5.0));
  for (int step = 1; step <= 1000; ++step) {
    clock.now_s = 0.001 * step;  // 1 s in all
    progress.update(step, 0.001 * step, 1, 5);
  }
  const std::string text = out.str();
  const auto redraws = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\r'));
  EXPECT_GE(redraws, 9u);
  EXPECT_LE(redraws, 11u);
  EXPECT_EQ(text.find('\n'), std::string::npos);
  EXPECT_EQ(text.rfind("\r\033[K", 0), 0u);
  progress.finish();
  EXPECT_EQ(out.str().back(), '\n');
  EXPECT_NE(out.str().find("step 1000/1000"), std::string::npos);
}

}  // namespace
