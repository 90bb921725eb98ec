#pragma once
// Per-process temporary folders for tests: TMPDIR/rouleau_test_NAME_PID, made empty on
// request and removed when the test process exits, so a developer's TMPDIR does not
// collect every run of every test. ROULEAU_KEEP_TEST_RUNS=1 keeps them for a look.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace rouleau::testing {

class TemporaryFolders {
 public:
  static void remove_at_exit(const std::filesystem::path& folder) { instance().folders_.push_back(folder); }
  ~TemporaryFolders() {
    if (std::getenv("ROULEAU_KEEP_TEST_RUNS") != nullptr) return;
    std::error_code ignored;
    for (const auto& folder : folders_) std::filesystem::remove_all(folder, ignored);
  }

 private:
  static TemporaryFolders& instance() {
    static TemporaryFolders folders;
    return folders;
  }
  std::vector<std::filesystem::path> folders_;
};

// The path TMPDIR/rouleau_test_NAME_PID, removed at exit; not created.
inline std::filesystem::path temporary_folder_path(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() / ("rouleau_test_" + name + "_" + std::to_string(::getpid()));
  TemporaryFolders::remove_at_exit(folder);
  return folder;
}

// The folder TMPDIR/rouleau_test_NAME_PID, created empty, removed at exit.
inline std::filesystem::path fresh_temporary_folder(const std::string& name) {
  const auto folder = temporary_folder_path(name);
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

// The same folder, created if missing and kept as it is otherwise (several files of a test).
inline std::filesystem::path temporary_folder(const std::string& name) {
  const auto folder = temporary_folder_path(name);
  std::filesystem::create_directories(folder);
  return folder;
}

}  // namespace rouleau::testing
