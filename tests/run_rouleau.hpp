#pragma once
// Running the real `rouleau` executable from a test, with stdout and stderr captured.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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

// Runs `rouleau ARGUMENTS` with stdout and stderr captured separately.
Outcome run_rouleau(const std::string& arguments) {
  const auto folder = std::filesystem::temp_directory_path() / ("rouleau_test_run_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  const std::string out_path = (folder / "stdout").string(), err_path = (folder / "stderr").string();
  const std::string command =
      std::string(ROULEAU_EXECUTABLE) + " " + arguments + " >'" + out_path + "' 2>'" + err_path + "'";
  const int status = std::system(command.c_str());
  Outcome outcome;
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  outcome.out = file_contents(out_path);
  outcome.err = file_contents(err_path);
  return outcome;
}

// An empty output folder for a run, unique to this process: TMPDIR/rouleau_run_NAME_PID.
std::string fresh_output_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("rouleau_run_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir.string();
}

}  // namespace
