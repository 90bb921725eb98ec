// Never lose a run: checkpoints, restart and signals through the real
// executable. A restart repeats the straight run bit for bit on the same thread count and
// to round-off on another; a damaged checkpoint is passed over; SIGTERM finishes the step
// and checkpoints (exit 4), a second signal exits at once (128 + N) leaving no damaged
// file; and SIGKILL at random moments, during checkpoint writes too, never loses the run:
// resumed again and again it ends bit for bit where the straight run ends.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <signal.h>
#include <sys/wait.h>

#include "io/checkpoint_file.hpp"
#include "io/diagnostics_reader.hpp"
#include "reduced_aggregation.hpp"
#include "run_rouleau.hpp"

namespace {

// The checkpoints of step `step` of two runs hold the same state to the bit (wall times
// apart), and their diagnostics have one row per step, identical but for wall times.
void expect_identical_runs(const std::string& run_a, const std::string& run_b, int step) {
  const auto a = rouleau::read_checkpoint_file(rouleau::CheckpointStore(run_a, 1).path_of(step));
  const auto b = rouleau::read_checkpoint_file(rouleau::CheckpointStore(run_b, 1).path_of(step));
  EXPECT_EQ(a.time, b.time);
  int compared = 0;
  for (const auto& [name, values] : a.reals) {
    if (is_wall_time(name)) continue;
    ASSERT_TRUE(b.reals.count(name)) << name;
    ASSERT_EQ(values.size(), b.reals.at(name).size()) << name;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < values.size(); ++i) differing += values[i] != b.reals.at(name)[i];
    EXPECT_EQ(differing, 0u) << name << ": entries that differ";
    ++compared;
  }
  EXPECT_GE(compared, 7);
  EXPECT_EQ(a.integers, b.integers);

  const auto rows_a = rouleau::read_diagnostics(run_a + "/diagnostics.csv");
  const auto rows_b = rouleau::read_diagnostics(run_b + "/diagnostics.csv");
  // a row per step, after the row of t = 0
  ASSERT_EQ(rows_a.size(), static_cast<std::size_t>(step) + 1);
  ASSERT_EQ(rows_b.size(), static_cast<std::size_t>(step) + 1);
  for (std::size_t r = 0; r < rows_a.size(); ++r)
    for (const auto& [column, value] : rows_a[r]) {
      if (is_wall_time(column)) continue;
      const double other = rows_b[r].at(column);
      if (std::isnan(value) && std::isnan(other)) continue;  // a column without meaning here
      EXPECT_EQ(value, other) << "row " << r << " column " << column;
    }
}

// The field files fields.xdmf lists, in order.
std::vector<std::string> listed_field_files(const std::string& run) {
  const std::string xdmf = file_contents(run + "/fields.xdmf");
  static const std::regex file_name("fields_[0-9]+\\.h5");
  std::vector<std::string> files;
  for (auto it = std::sregex_iterator(xdmf.begin(), xdmf.end(), file_name); it != std::sregex_iterator(); ++it)
    files.push_back(it->str());
  return files;
}

// Whether `directory` holds a temporary file (one being written, or left by a kill).
bool holds_temporary_file(const std::string& directory) {
  std::error_code status;
  for (const auto& entry : std::filesystem::directory_iterator(directory, status))
    if (entry.path().extension() == ".tmp") return true;
  return false;
}

TEST(Restart, RestartedRunRepeatsTheStraightRunBitForBit) {
  // The reduced two-cell aggregation (semi-implicit, Morse on): 8 steps straight through,
  // against 4 steps, then --restart to the same end, on 2 threads. Every sum runs in the
  // same order on a given thread count (static partitions, a coloured CRS assembly, no
  // atomics on doubles), so the final state (fluid U^n and U^{n-1}, cell positions and
  // velocities, the inertia term's v^{n-1}, the list's build positions) must be identical
  // to the bit, and so must every physical column of every diagnostics row.
  const std::string straight = fresh_output_dir("straight");
  const std::string split = fresh_output_dir("split");
  const Outcome whole = run_rouleau(reduced_aggregation(straight, 2, 8));
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const Outcome first = run_rouleau(reduced_aggregation(split, 2, 4));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const Outcome second = run_rouleau("run --restart " + split + " --threads 2 --no-progress" + end_after(8));
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(second.err.find("restarted from"), std::string::npos) << second.err;

  expect_identical_runs(straight, split, 8);
  // The field series goes on: steps 0 and 4 from the first segment, 8 from the second.
  const std::string xdmf = file_contents(split + "/fields.xdmf");
  for (const char* step : {"fields_000000.h5", "fields_000004.h5", "fields_000008.h5"})
    EXPECT_NE(xdmf.find(step), std::string::npos) << step;
}

TEST(Restart, RestartRefusesAFolderWithoutCheckpointsAndADamagedCheckpoint) {
  const std::string empty = fresh_output_dir("no_checkpoint");
  std::filesystem::create_directories(empty);
  const Outcome none = run_rouleau("run --restart " + empty + " --no-progress");
  EXPECT_EQ(none.exit_code, 2) << none.err;
  EXPECT_NE(none.err.find("--restart: no checkpoint in"), std::string::npos) << none.err;

  // A run of the plasma shear flow, its newest checkpoint then cut to half its length (a
  // copy that did not finish): the restart passes over it, says so, and continues from
  // the one before.
  const std::string out = fresh_output_dir("damaged");
  const Outcome run = run_rouleau("run " + cases_dir + "/shear_flow/case.toml --no-progress --out " + out +
                                  " --set time.end_s=0.2 --set checkpoint.every_steps=1 --set checkpoint.keep=3");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const rouleau::CheckpointStore store(out, 3);
  const auto listed = store.list();
  ASSERT_EQ(listed.size(), 3u);
  EXPECT_EQ(listed.front().first, 4);
  std::filesystem::resize_file(listed.front().second, std::filesystem::file_size(listed.front().second) / 2);
  const Outcome resumed = run_rouleau("run --restart " + out + " --no-progress --set time.end_s=0.3");
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("passed over a damaged checkpoint"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("restarted from " + listed[1].second), std::string::npos) << resumed.err;
}

TEST(Restart, RestartWithAnotherStepEndsAtTheEndTime) {
  // The plasma shear flow to 0.04 s in steps of 0.01 s, continued with steps of 0.005 s to
  // 0.06 s: the run ends at 0.06 s after four more steps. (Counting the steps from zero with
  // the new step, 0.06 / 0.005 = 12, it ran eight more, to 0.08 s: the capillary's run,
  // restarted at half its step, went on past its end.)
  const std::string out = fresh_output_dir("restart_new_step");
  const Outcome run = run_rouleau("run " + cases_dir + "/shear_flow/case.toml --no-progress --out " + out +
                                  " --set time.dt_s=0.01 --set time.end_s=0.04 --set output.fields=false"
                                  " --set output.diagnostics_every_steps=1");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Outcome resumed = run_rouleau("run --restart " + out +
                                      " --no-progress --set time.dt_s=0.005 --set time.end_s=0.06");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const auto rows = rouleau::read_diagnostics(out + "/diagnostics.csv");
  ASSERT_EQ(rows.size(), 9u);  // t = 0, 4 steps of 0.01 s, 4 of 0.005 s
  EXPECT_NEAR(rows.front().at("time_s"), 0.0, 1e-12);
  EXPECT_NEAR(rows.back().at("time_s"), 0.06, 1e-12);
  EXPECT_NEAR(rows[5].at("time_s"), 0.045, 1e-12);
}

// Starts the plasma shear flow with 20 000 steps of 1 ms (and `settings`, "key=value")
// in the background, stderr into `err_path`, and returns once its step-0 checkpoint is
// written (setup done) and `settle` more has passed, so that steps are under way.
pid_t start_long_shear_flow(const std::string& out, const std::string& err_path,
                            const std::vector<std::string>& settings, std::chrono::milliseconds settle) {
  std::vector<std::string> arguments{"run", cases_dir + "/shear_flow/case.toml", "--no-progress", "--threads", "1",
                                     "--out", out, "--set", "time.dt_s=0.001", "--set", "time.end_s=20",
                                     "--set", "output.fields=false"};
  for (const std::string& setting : settings) arguments.insert(arguments.end(), {"--set", setting});
  const pid_t pid = start_rouleau(arguments, err_path);
  if (pid <= 0) return pid;
  const std::string first = out + "/checkpoints/checkpoint_000000000.h5";
  for (int i = 0; i < 600 && !std::filesystem::exists(first); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_TRUE(std::filesystem::exists(first)) << file_contents(err_path);
  std::this_thread::sleep_for(settle);
  return pid;
}

TEST(Restart, SigtermStopsAfterTheStepWithACheckpointAndExitCode4) {
  // The plasma shear flow with 20 000 steps of 1 ms: SIGTERM once the run has started must
  // end it after the step under way, with a checkpoint of that step, exit code 4 and the
  // restart command; the restart then continues from that step to a nearby end.
  const std::string out = fresh_output_dir("signal");
  const std::string err_path = out + "_stderr";
  const pid_t pid = start_long_shear_flow(out, err_path, {}, std::chrono::milliseconds(500));
  ASSERT_GT(pid, 0);
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  const std::string err = file_contents(err_path);
  ASSERT_TRUE(WIFEXITED(status)) << err;
  EXPECT_EQ(WEXITSTATUS(status), 4) << err;
  EXPECT_NE(err.find("stopped by signal 15 after step"), std::string::npos) << err;
  EXPECT_NE(err.find("rouleau run --restart " + out), std::string::npos) << err;

  const rouleau::FoundCheckpoint last = rouleau::newest_valid_checkpoint(out);
  EXPECT_GT(last.data.step, 0);
  EXPECT_LT(last.data.step, 20000);
  // The diagnostics end at the same step (one row per step).
  const auto rows = rouleau::read_diagnostics(out + "/diagnostics.csv");
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.back().at("step"), static_cast<double>(last.data.step));
  // No temporary file is left behind.
  for (const auto& entry : std::filesystem::recursive_directory_iterator(out))
    EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();

  const double end = (last.data.step + 5) * 0.001;
  const Outcome resumed = run_rouleau("run --restart " + out + " --threads 1 --no-progress --set time.end_s=" +
                                      std::to_string(end));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const auto resumed_rows = rouleau::read_diagnostics(out + "/diagnostics.csv");
  EXPECT_EQ(resumed_rows.back().at("step"), static_cast<double>(last.data.step + 5));
  EXPECT_EQ(resumed_rows.size(), rows.size() + 5);
  std::filesystem::remove(err_path);
}

TEST(Restart, SecondStopSignalExitsAtOnceLeavingNoDamagedFile) {
  // Two SIGTERMs 20 ms apart while a step (~0.5 s on this mesh with the multigrid; the fast
  // diagonalization, this box's default, takes a fraction of it) is under way: the second
  // ends the process at once with 128 + 15, without waiting for the step or writing a
  // checkpoint. (Sent back to back, the two would merge into one pending signal.) Every
  // checkpoint left reads and passes its checksum, and the run restarts from the newest.
  const std::string out = fresh_output_dir("second_signal");
  const std::string err_path = out + "_stderr";
  const pid_t pid = start_long_shear_flow(out, err_path, {"domain.elements=[24,24,12]", "checkpoint.every_steps=1", "solver.preconditioner=multigrid"},
                                          std::chrono::milliseconds(300));
  ASSERT_GT(pid, 0);
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  const std::string err = file_contents(err_path);
  ASSERT_TRUE(WIFEXITED(status)) << err;
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << err;
  EXPECT_NE(err.find("second stop signal: exiting at once"), std::string::npos) << err;
  EXPECT_EQ(err.find("continue with"), std::string::npos) << err;  // no checkpoint was written for the stop

  const rouleau::CheckpointStore store(out, 1);
  for (const auto& [step, path] : store.list()) EXPECT_NO_THROW(rouleau::read_checkpoint_file(path)) << path;
  const rouleau::FoundCheckpoint newest = rouleau::newest_valid_checkpoint(out);
  EXPECT_TRUE(newest.refused.empty());
  const Outcome resumed = run_rouleau("run --restart " + out + " --threads 1 --no-progress --set time.end_s=" +
                                      std::to_string((newest.data.step + 2) * 0.001) +
                                      " --set checkpoint.every_steps=0");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  std::filesystem::remove(err_path);
}

TEST(Restart, RestartOnAnotherThreadCountAgreesToRoundOff) {
  // 8 steps straight on 2 threads, against 4 on 1 thread and a restart on 2: the sums
  // are grouped differently on 1 thread, so the states differ. The difference starts at
  // round-off and each solve passes it on at the level of its stopping test (GMRES and
  // Newton stop at a relative 1e-8, and where in that band they stop depends on the
  // rounding): it must stay within ten times that tolerance.
  const std::string straight = fresh_output_dir("threads_straight");
  const std::string split = fresh_output_dir("threads_split");
  ASSERT_EQ(run_rouleau(reduced_aggregation(straight, 2, 8)).exit_code, 0);
  ASSERT_EQ(run_rouleau(reduced_aggregation(split, 1, 4)).exit_code, 0);
  const Outcome second = run_rouleau("run --restart " + split + " --threads 2 --no-progress" + end_after(8));
  ASSERT_EQ(second.exit_code, 0) << second.err;
  const bool any_difference = expect_states_agree(straight, split, 8, 1e-7);
  std::printf("the states %s\n", any_difference ? "differ (as sums grouped differently must)" : "are identical");
}

TEST(Restart, KilledAtRandomMomentsTheRunResumesToTheStraightRunBitForBit) {
  // The reduced aggregation for 60 steps with a checkpoint after every step, killed with
  // SIGKILL 24 times and each time continued with --restart (or started afresh when no
  // checkpoint exists yet, with --overwrite), as a cluster's requeued job would be: two kills in three at a
  // random moment (20-600 ms after the start; a start takes ~0.15 s and a step ~0.12 s on
  // 2 threads), one in three the moment the 1st-3rd checkpoint write's temporary file
  // appears (in the middle of that write). The last resume runs to the end. The run must
  // end bit for bit where the straight run ends, with one diagnostics row per step, the
  // same field files and no temporary file left. The 24 kills let about 40 steps pass
  // (1–2 per run): with 40 steps a quiet machine reached the end after 19 kills, so 60.
  constexpr int steps = 60, planned_kills = 24;
  const std::string straight = fresh_output_dir("kill_straight");
  const std::string killed = fresh_output_dir("kill_loop");
  std::vector<std::string> fresh = reduced_aggregation_arguments(straight, 2, steps);
  fresh.insert(fresh.end(), {"--set", "checkpoint.every_steps=1"});
  {
    std::string command;
    for (const std::string& argument : fresh) command += argument + " ";
    ASSERT_EQ(run_rouleau(command).exit_code, 0);
  }
  fresh[3] = killed;
  // A run killed before its first checkpoint left its log and resolved case: it is started
  // afresh over them, as a requeued job's script does (a new run refuses a run's folder).
  fresh.push_back("--overwrite");
  const std::vector<std::string> resume{"run", "--restart", killed, "--threads", "2", "--no-progress"};
  const std::string err_path = killed + "_stderr";
  const std::string checkpoints = killed + "/checkpoints";

  std::mt19937 random(20261123);
  int runs = 0, kills = 0, kills_in_write = 0, fresh_starts = 0;
  bool finished = false;
  while (!finished) {
    const bool has_checkpoint = !rouleau::CheckpointStore(killed, 1).list().empty();
    fresh_starts += has_checkpoint ? 0 : 1;
    const pid_t pid = start_rouleau(has_checkpoint ? resume : fresh, err_path);
    ASSERT_GT(pid, 0);
    ++runs;
    const bool kill_now = kills < planned_kills;
    const bool kill_in_write = kill_now && runs % 3 == 0;
    const auto deadline =
        std::chrono::steady_clock::now() +
        std::chrono::milliseconds(kill_now && !kill_in_write ? std::uniform_int_distribution<int>(20, 600)(random)
                                                             : 60000);
    const int writes_to_let_pass = std::uniform_int_distribution<int>(0, 2)(random);
    int writes_seen = 0;
    bool writing = false;
    int status = 0;
    while (std::chrono::steady_clock::now() < deadline) {
      if (::waitpid(pid, &status, WNOHANG) == pid) {
        finished = true;
        break;
      }
      if (kill_in_write) {
        const bool now_writing = holds_temporary_file(checkpoints);
        if (now_writing && !writing && writes_seen++ == writes_to_let_pass) break;
        writing = now_writing;
        std::this_thread::sleep_for(std::chrono::microseconds(100));
      } else {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
      }
    }
    if (finished) {
      ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << file_contents(err_path);
      break;
    }
    ASSERT_TRUE(kill_now) << "the last run did not finish in 60 s: " << file_contents(err_path);
    ASSERT_EQ(::kill(pid, SIGKILL), 0);
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ++kills;
    kills_in_write += holds_temporary_file(checkpoints) ? 1 : 0;
  }
  std::printf("kill-and-resume: %d SIGKILLs (%d in the middle of a checkpoint write, %d before the first "
              "checkpoint), %d runs in all, the last to the end\n",
              kills, kills_in_write, fresh_starts - 1, runs);
  EXPECT_GE(kills, 20);  // fewer only if 60 steps went by in fewer runs than planned
  EXPECT_GE(kills_in_write, 3);
  expect_identical_runs(straight, killed, steps);
  for (const std::string& folder : {killed, checkpoints})
    EXPECT_FALSE(holds_temporary_file(folder)) << folder;
  EXPECT_EQ(listed_field_files(killed), listed_field_files(straight));
  std::filesystem::remove(err_path);
}

}  // namespace
