#pragma once
// A transient run's checkpoints (io/checkpoint_file.hpp) and restarting from one. Each
// checkpoint carries the resolved case, the simulation's state, the run's wall time so far,
// the run id and the hashes of the meshes it was made on; a restart refuses a checkpoint of
// other meshes. When to write one is the time loop's decision (run/time_loop.hpp).
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "config/derived.hpp"
#include "io/checkpoint_file.hpp"
#include "io/provenance.hpp"
#include "run/run_clock.hpp"
#include "run/simulation.hpp"

namespace rouleau {

// The provenance entries that name a mesh's hash ("fluid_mesh_hash",
// "cell_mesh_hash_KIND"), by name.
std::map<std::string, std::string> mesh_hash_labels(
    const std::vector<std::pair<std::string, std::string>>& provenance_entries);

// Continues `simulation` from `restart`: checks that it was made on the meshes this case
// builds (`mesh_hashes`, mesh_hash_labels() of the run's provenance: a changed mesher or
// cell kind would move every node; throws InputError naming the checkpoint and the mesh
// otherwise), restores the state, and on the first rank (`writes_files`) removes the
// unfinished temporary files the stopped run left in `output_dir`.
void restart_simulation(Simulation& simulation, const FoundCheckpoint& restart,
                        const std::map<std::string, std::string>& mesh_hashes, const std::string& output_dir,
                        bool writes_files);

class RunCheckpoints {
 public:
  // The checkpoints of the run in `output_dir` (config.checkpoint.kept of them stay); after a
  // `restart`, the one it continues from counts as the last written. Only the first rank
  // (`writes_files`) writes files; every rank takes part in saving the state.
  RunCheckpoints(const CaseConfig& config, const DerivedQuantities& derived, const std::string& output_dir,
                 const FoundCheckpoint* restart, Provenance provenance, std::map<std::string, std::string> mesh_hashes,
                 std::string run_id, bool writes_files);

  // The checkpoint of the simulation's current step (timed as the stage "checkpoint"), with
  // the run's wall time from `clock`.
  void write(Simulation& simulation, const RunClock& clock);

  // The step of the last checkpoint written (or restarted from), -1 before any.
  int last_step() const { return last_step_; }
  // Minutes since the last checkpoint was written (or since this segment started).
  double minutes_since_last() const;
  // The path of the last checkpoint written (the first rank's file, on every rank), or "".
  const std::string& last_path() const { return store_.last_path(); }
  // The same for messages: "none written" when there is none.
  std::string last_good() const;

 private:
  const CaseConfig& config_;
  const DerivedQuantities& derived_;
  CheckpointStore store_;
  Provenance provenance_;
  std::map<std::string, std::string> mesh_hashes_;
  std::string run_id_;
  bool writes_files_;
  RunClock::Clock::time_point last_time_;
  int last_step_;
};

}  // namespace rouleau
