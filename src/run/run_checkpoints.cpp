// A run's checkpoints: the mesh hashes they carry, restarting from one after checking
// them, and writing one (run/run_checkpoints.hpp).
#include "run/run_checkpoints.hpp"

#include <iostream>

#include "config/resolved_case.hpp"
#include "io/atomic_file.hpp"
#include "util/errors.hpp"

namespace rouleau {

namespace {
// The (name, value) entries whose name is a mesh hash's.
template <class Entries>
std::map<std::string, std::string> mesh_hashes_among(const Entries& entries) {
  std::map<std::string, std::string> hashes;
  for (const auto& [key, value] : entries)
    if (key.find("mesh_hash") != std::string::npos) hashes[key] = value;
  return hashes;
}

// A checkpoint restarts only on the meshes it was made on: its mesh hashes must be those
// of the meshes this case builds (a changed mesher or cell kind would move every node).
void check_checkpoint_meshes(const FoundCheckpoint& checkpoint, const std::map<std::string, std::string>& built) {
  const std::map<std::string, std::string> stored = mesh_hashes_among(checkpoint.data.labels);
  for (const auto& [key, value] : built) {
    const auto found = stored.find(key);
    if (found == stored.end() || found->second != value)
      throw InputError(checkpoint.path, key,
                       "the checkpoint was made on " +
                           (found == stored.end() ? std::string("no such mesh") : "a mesh of hash " + found->second) +
                           "; this case builds one of hash " + value + " (another case, or another mesher version)");
  }
  for (const auto& [key, value] : stored)
    if (!built.count(key))
      throw InputError(checkpoint.path, key, "the checkpoint has this mesh; the case builds none like it");
}
}  // namespace

std::map<std::string, std::string> mesh_hash_labels(
    const std::vector<std::pair<std::string, std::string>>& provenance_entries) {
  return mesh_hashes_among(provenance_entries);
}

void restart_simulation(Simulation& simulation, const FoundCheckpoint& restart,
                        const std::map<std::string, std::string>& mesh_hashes, const std::string& output_dir,
                        const bool writes_files) {
  check_checkpoint_meshes(restart, mesh_hashes);
  simulation.restore_state(restart.data);
  std::cerr << "restarted from " << restart.path << ": step " << restart.data.step << ", t = " << restart.data.time
            << " s\n";
  const int leftovers = writes_files ? remove_leftover_temporary_files(output_dir) +
                                           remove_leftover_temporary_files(output_dir + "/checkpoints")
                                     : 0;
  if (leftovers > 0) std::cerr << "removed " << leftovers << " unfinished temporary file(s) of the stopped run\n";
}

RunCheckpoints::RunCheckpoints(const CaseConfig& config, const DerivedQuantities& derived,
                               const std::string& output_dir, const FoundCheckpoint* restart, Provenance provenance,
                               std::map<std::string, std::string> mesh_hashes, std::string run_id,
                               const bool writes_files)
    : config_(config), derived_(derived), store_(output_dir, config.checkpoint.kept),
      provenance_(std::move(provenance)), mesh_hashes_(std::move(mesh_hashes)), run_id_(std::move(run_id)),
      writes_files_(writes_files), last_time_(RunClock::Clock::now()),
      last_step_(restart ? static_cast<int>(restart->data.step) : -1) {
  if (restart) store_.set_last_path(restart->path);
}

void RunCheckpoints::write(Simulation& simulation, const RunClock& clock) {
  simulation.times().time("checkpoint", [&] {
    CheckpointData data;
    data.resolved_case = resolved_case_toml(config_, derived_);
    simulation.save_state(data);
    data.wall_seconds = clock.seconds();
    for (const auto& [key, value] : mesh_hashes_) data.labels[key] = value;
    data.labels["run_id"] = run_id_;
    if (writes_files_)
      store_.write(data, provenance_);
    else  // the first rank's file, for the messages
      store_.set_last_path(store_.path_of(simulation.steps()));
  });
  last_time_ = RunClock::Clock::now();
  last_step_ = simulation.steps();
}

double RunCheckpoints::minutes_since_last() const {
  return std::chrono::duration<double>(RunClock::Clock::now() - last_time_).count() / 60.0;
}

std::string RunCheckpoints::last_good() const {
  return store_.last_path().empty() ? std::string("none written") : store_.last_path();
}

}  // namespace rouleau
