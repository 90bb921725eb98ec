#pragma once
// Checkpoint files: everything the next time step needs, in one HDF5 file per checkpoint,
// kept in the run's folder as checkpoints/checkpoint_SSSSSSSSS.h5 (S = step).
//
// A checkpoint holds the step, the time, the wall time so far, the resolved case (TOML,
// so a restart needs nothing else), the hashes of the meshes it was made on, and named
// state arrays. Each class that holds state writes and reads its own arrays under its
// own prefix ("fluid/state", "cells/positions", ...), so this file knows no physics.
//
// Layout (format version 1): /format_version, /step (int64), /time, /wall_seconds
// (float64), /case (the TOML as bytes), /reals/NAME (float64), /integers/NAME (int64);
// root attributes: the provenance, "label_NAME" per label, and "checksum", an FNV-1a
// 64-bit hash of every name and value above, checked on reading (a damaged file is
// refused, not restarted from). Files are written to PATH.tmp, synced and renamed: a
// process killed at any moment leaves the earlier checkpoints intact.
// Host-only: includes no Kokkos header.
#include <map>
#include <string>
#include <vector>

#include "io/provenance.hpp"

namespace rouleau {

struct CheckpointData {
  static constexpr long long format_version = 1;

  long long step = 0;
  double time = 0.0;           // [s]
  double wall_seconds = 0.0;   // wall time of the run up to this checkpoint, over all its segments
  std::string resolved_case;   // resolved_case_toml() of the case that made it
  std::map<std::string, std::string> labels;                // e.g. mesh hashes
  std::map<std::string, std::vector<double>> reals;         // state arrays
  std::map<std::string, std::vector<long long>> integers;   // counters, flags, lists

  // The entry `name`; throws std::runtime_error naming it when it is missing or, with
  // `size` >= 0, does not hold exactly `size` values.
  const std::vector<double>& real(const std::string& name, long long size = -1) const;
  const std::vector<long long>& integer(const std::string& name, long long size = -1) const;
  const std::string& label(const std::string& name) const;
};

// The checksum stored with the data (FNV-1a, 64 bits, as 16 hex digits).
std::string checkpoint_checksum(const CheckpointData& data);

// Writes `data` to `path` atomically (PATH.tmp, sync, rename), with `provenance` as root
// attributes. Throws std::runtime_error naming the file on failure (`path` untouched then).
void write_checkpoint_file(const std::string& path, const CheckpointData& data, const Provenance& provenance);

// Reads a checkpoint back. Throws std::runtime_error naming the file and the reason when
// it is not a readable HDF5 file, has another format version, misses an entry, or its
// checksum does not match its contents.
CheckpointData read_checkpoint_file(const std::string& path);

// The checkpoints of one run folder: RUN_DIR/checkpoints/checkpoint_SSSSSSSSS.h5.
class CheckpointStore {
 public:
  // `kept` >= 1: how many of the newest checkpoints stay on disk.
  CheckpointStore(std::string run_directory, int kept);

  std::string directory() const;
  std::string path_of(long long step) const;
  // The checkpoints present (complete files only: a .tmp is never listed), newest first.
  std::vector<std::pair<long long, std::string>> list() const;
  // Writes `data` as the checkpoint of its step, then deletes the oldest beyond `kept` and
  // any checkpoint of a later step (the future of an abandoned branch after a restart).
  // Returns the path written.
  std::string write(const CheckpointData& data, const Provenance& provenance);
  // The path of the last checkpoint written or found, or "" when there is none.
  const std::string& last_path() const { return last_path_; }
  void set_last_path(std::string path) { last_path_ = std::move(path); }

 private:
  std::string run_directory_;
  int kept_;
  std::string last_path_;
};

// The newest checkpoint of a run folder that reads and passes its checksum, trying older
// ones when the newest is damaged. `refused` receives one line per checkpoint passed over
// (path: reason). Throws std::runtime_error when there is none.
struct FoundCheckpoint {
  std::string path;
  CheckpointData data;
  std::vector<std::string> refused;
};
FoundCheckpoint newest_valid_checkpoint(const std::string& run_directory);

}  // namespace rouleau
