#pragma once
// Wall time spent per stage of a run: summed over the run, printed at its end, and read
// by the diagnostics. Each timed stage ends with a fence, so that kernels launched
// asynchronously (GPUs) are charged to the stage that launched them.
#include <Kokkos_Core.hpp>
#include <algorithm>
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
  // The table at a run's end: each stage that ran, its seconds and share of `wall_seconds`
  // (the run's wall time over the same segments), the time outside every stage (start-up,
  // the loop's own work) and the total.
  void print(std::ostream& out, double wall_seconds) const {
    out << "time per stage:\n";
    double in_stages = 0.0;
    auto line = [&out, wall_seconds](const std::string& name, double s) {
      char text[160];
      std::snprintf(text, sizeof text, "  %-28s %10.3f s %5.1f %%\n", name.c_str(), s,
                    wall_seconds > 0.0 ? 100.0 * s / wall_seconds : 0.0);
      out << text;
    };
    for (const auto& [stage, s] : seconds_) {
      if (s <= 0.0) continue;  // carried over from a checkpoint, never run
      line(stage, s);
      in_stages += s;
    }
    line("outside the stages", std::max(0.0, wall_seconds - in_stages));
    line("total", wall_seconds);
  }

 private:
  std::map<std::string, double> seconds_;
};

}  // namespace rouleau
