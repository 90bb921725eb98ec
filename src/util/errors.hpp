#pragma once
// Error types and exit codes shared by the host and device halves of rouleau.
// Host-only: includes no Kokkos header.
#include <stdexcept>
#include <string>

namespace rouleau {

// Process exit codes (docs/running.md, "Exit codes").
enum class ExitCode : int {
  done = 0,
  internal_error = 1,
  bad_input = 2,
  diverged = 3,
  interrupted = 4,
};

// Bad input found before any work: what() is one line "FILE: KEY: REASON".
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& key, const std::string& reason)
      : std::runtime_error(file + ": " + key + ": " + reason), file_(file), key_(key), reason_(reason) {}
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string file_, key_, reason_;
};

// A run that cannot go on (NaN, solver failure): what() names step, stage and values.
class DivergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rouleau
