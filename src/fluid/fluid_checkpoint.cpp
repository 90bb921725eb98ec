// The fluid solver's entries of a checkpoint: the state the next step needs, in the
// global numbering, so that a checkpoint written on P ranks restarts on Q
// (fluid/fluid_solver.hpp).
#include "fluid/fluid_solver.hpp"

#include <algorithm>

#include "util/view_transfer.hpp"

namespace rouleau {

void FluidSolver::save_state(CheckpointData& data) const {
  // In the global numbering: a checkpoint written on P ranks restarts on Q.
  data.reals["fluid/state"] = global_values(state_);
  data.reals["fluid/previous_state"] = global_values(previous_state_);
  data.reals["fluid/time"] = {time_};
  data.integers["fluid/steps"] = {steps_};
  // The last solutions, newest first (the next step's starting guess is made from them).
  std::vector<double> past;
  for (int i = 0; i < past_count_; ++i) {
    const int column = (past_newest_ - i + past_solutions_.extent_int(1)) % past_solutions_.extent_int(1);
    const std::vector<double> values = global_values(Kokkos::subview(past_solutions_, Kokkos::ALL(), column));
    past.insert(past.end(), values.begin(), values.end());
  }
  data.reals["fluid/past_solutions"] = past;
  data.integers["fluid/past_solutions_count"] = {past_count_};
}

void FluidSolver::restore_state(const CheckpointData& data) {
  const long long n = num_global_unknowns_;
  Vector global("rouleau::FluidSolver::restored", n);
  const std::pair<const char*, Vector> entries[] = {{"fluid/state", state_}, {"fluid/previous_state", previous_state_}};
  for (const auto& [name, local] : entries) {
    from_flat_vector(data.real(name, n), global, name);
    exchange_->localize(global, local);
  }
  time_ = data.real("fluid/time", 1).front();
  steps_ = static_cast<int>(data.integer("fluid/steps", 1).front());
  // The last solutions, written newest first: the newest `kept` of them go to columns
  // kept − 1 (newest) … 0. A checkpoint written before solutions were kept has none.
  const int written = data.integers.count("fluid/past_solutions_count")
                          ? static_cast<int>(data.integer("fluid/past_solutions_count", 1).front())
                          : 0;
  allocate_past_solutions();
  const int kept = std::min(written, past_solutions_.extent_int(1));
  static const std::vector<double> none;
  const std::vector<double>& past =
      written > 0 ? data.real("fluid/past_solutions", static_cast<long long>(written) * n) : none;
  for (int i = kept - 1; i >= 0; --i) {
    const std::vector<double> one(past.begin() + static_cast<long long>(i) * n,
                                  past.begin() + static_cast<long long>(i + 1) * n);
    from_flat_vector(one, global, "fluid/past_solutions");
    exchange_->localize(global, Kokkos::subview(past_solutions_, Kokkos::ALL(), kept - 1 - i));
  }
  past_count_ = kept;
  past_newest_ = kept - 1;
}

}  // namespace rouleau
