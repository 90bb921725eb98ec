// The fluid solver's entries of a checkpoint: the state the next step needs, in the
// global numbering, so that a checkpoint written on P ranks restarts on Q
// (fluid/fluid_solver.hpp).
#include "fluid/fluid_solver.hpp"

#include "util/view_transfer.hpp"

namespace rouleau {

void FluidSolver::save_state(CheckpointData& data) const {
  // In the global numbering: a checkpoint written on P ranks restarts on Q.
  data.reals["fluid/state"] = global_values(state_);
  data.reals["fluid/previous_state"] = global_values(previous_state_);
  data.reals["fluid/time"] = {time_};
  data.integers["fluid/steps"] = {steps_};
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
}

}  // namespace rouleau
