#pragma once
// Wall time spent per stage of a run: summed over the run, printed at its end, and read
// by the diagnostics. Each timed stage ends with a fence, so that kernels launched
// asynchronously (GPUs) are charged to the stage that launched them.
#include <Kokkos_Core.hpp>
#include <chrono>
#include <cstdio>
#include <map>
#include <ostream>
#include <string>

namespace rouleau {

class StageTimes {
 public:
  // Runs f(), adds its wall time to `stage`, and returns f's result.
  template <class F>
  auto time(const std::string& stage, F&& f) {
    const auto start = std::chrono::steady_clock::now();
    if constexpr (std::is_void_v<decltype(f())>) {
      f();
      Kokkos::fence();
      seconds_[stage] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } else {
      auto result = f();
      Kokkos::fence();
      seconds_[stage] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return result;
    }
  }
  // Seconds spent in `stage` so far (0 if it never ran).
  double seconds(const std::string& stage) const {
    const auto found = seconds_.find(stage);
    return found == seconds_.end() ? 0.0 : found->second;
  }
  // Every stage's seconds so far, and adding to them (a restarted run carries on the times
  // of the run it continues).
  const std::map<std::string, double>& seconds_by_stage() const { return seconds_; }
  void add(const std::string& stage, double seconds) { seconds_[stage] += seconds; }
  void print(std::ostream& out) const {
    out << "time per stage:\n";
    for (const auto& [stage, s] : seconds_) {
      char line[160];
      std::snprintf(line, sizeof line, "  %-28s %10.3f s\n", stage.c_str(), s);
      out << line;
    }
  }

 private:
  std::map<std::string, double> seconds_;
};

}  // namespace rouleau
