#include "cli/progress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <unistd.h>
#include <utility>

namespace rouleau {
namespace {

// "42s", "3m05s", "1h02m".
std::string format_duration(double seconds) {
  const long total = std::lround(seconds);
  char text[32];
  if (total < 60) std::snprintf(text, sizeof(text), "%lds", total);
  else if (total < 3600) std::snprintf(text, sizeof(text), "%ldm%02lds", total / 60, total % 60);
  else std::snprintf(text, sizeof(text), "%ldh%02ldm", total / 3600, (total % 3600) / 60);
  return text;
}

}  // namespace

bool stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

double monotonic_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

ProgressReporter::ProgressReporter(int total_steps, double end_time, bool terminal, std::ostream& out)
    : ProgressReporter(total_steps, end_time, terminal, out, Settings{}) {}

ProgressReporter::ProgressReporter(int total_steps, double end_time, bool terminal, std::ostream& out,
                                   Settings settings)
    : total_steps_(total_steps), end_time_(end_time), terminal_(terminal), out_(out),
      settings_(std::move(settings)), start_s_(settings_.clock()) {}

std::string ProgressReporter::line(int step, double time, int newton_iterations, int gmres_iterations) const {
  const double elapsed_s = settings_.clock() - start_s_;
  const double steps_per_s = elapsed_s > 0 ? step / elapsed_s : 0.0;
  const std::string eta =
      steps_per_s > 0 ? format_duration(std::max(0, total_steps_ - step) / steps_per_s) : std::string("--");
  char text[256];
  std::snprintf(text, sizeof(text), "step %d/%d  t = %.4g/%.4g s  %.3g steps/s  Newton %d  GMRES %d  ETA %s", step,
                total_steps_, time, end_time_, steps_per_s, newton_iterations, gmres_iterations, eta.c_str());
  return text;
}

void ProgressReporter::update(int step, double time, int newton_iterations, int gmres_iterations) {
  const double now_s = settings_.clock();
  const double interval_s = terminal_ ? settings_.terminal_interval_s : settings_.log_interval_s;
  const std::string text = line(step, time, newton_iterations, gmres_iterations);
  if (shown_any_ && now_s - last_shown_s_ < interval_s) {
    pending_line_ = text;
    return;
  }
  last_shown_s_ = now_s;
  shown_any_ = true;
  show(text);
}

void ProgressReporter::finish() {
  if (finished_) return;
  finished_ = true;
  if (!pending_line_.empty()) show(std::string(pending_line_));  // a copy: show() clears it
  if (line_open_) out_ << "\n" << std::flush;
  line_open_ = false;
}

void ProgressReporter::show(const std::string& text) {
  pending_line_.clear();
  if (terminal_) {
    out_ << "\r\033[K" << text << std::flush;
    line_open_ = true;
  } else {
    out_ << text << "\n" << std::flush;
  }
}

}  // namespace rouleau
