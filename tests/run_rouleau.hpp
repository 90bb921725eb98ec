#pragma once
// Running the real `rouleau` executable from a test, with stdout and stderr captured.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "temporary_folder.hpp"

namespace {

struct Outcome {
  int exit_code = -1;
  std::string out, err;
};

std::string file_contents(const std::string& path) {
  std::ifstream file(path);
  std::stringstream contents;
  contents << file.rdbuf();
  return contents.str();
}

// Runs `rouleau ARGUMENTS` with stdout and stderr captured separately; with a `launcher`
// (an mpiexec command line), `LAUNCHER rouleau ARGUMENTS`.
Outcome run_rouleau(const std::string& arguments, const std::string& launcher = "") {
  const auto folder = rouleau::testing::temporary_folder("run");
  const std::string out_path = (folder / "stdout").string(), err_path = (folder / "stderr").string();
  const std::string command = (launcher.empty() ? std::string() : launcher + " ") + std::string(ROULEAU_EXECUTABLE) +
                              " " + arguments + " >'" + out_path + "' 2>'" + err_path + "'";
  const int status = std::system(command.c_str());
  Outcome outcome;
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  outcome.out = file_contents(out_path);
  outcome.err = file_contents(err_path);
  return outcome;
}

// An output folder for a run, unique to this process, not yet there (the run makes it):
// TMPDIR/rouleau_test_run_NAME_PID, removed when the test process exits.
std::string fresh_output_dir(const std::string& name) {
  const auto dir = rouleau::testing::temporary_folder_path("run_" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

// Starts `rouleau ARGUMENTS...` in the background with stderr into `err_path` (stdout
// discarded); returns its process id, or -1.
pid_t start_rouleau(const std::vector<std::string>& arguments, const std::string& err_path) {
  std::vector<std::string> argv_strings{ROULEAU_EXECUTABLE};
  argv_strings.insert(argv_strings.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& a : argv_strings) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int status = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return status == 0 ? pid : -1;
}

}  // namespace
