#pragma once
// A run folder holds the files of exactly one run: the files a run writes, over all the
// segments a restart joins, and nothing of another run's.
//
// Each run gets a run id when it starts (a restart keeps it). The id is written into every
// file that can carry it: the provenance of every HDF5 file (fields and checkpoints,
// attribute "run_id"), the XDMF's Information, and the first line of run.log. Then:
//   - a new run (`--out DIR`) starts only in a folder that is missing or empty; with
//     `--overwrite` it first empties a folder that holds an earlier run (and refuses one
//     that holds anything else: rouleau removes only what a run of its own wrote);
//   - a restart (`--restart DIR`) refuses a folder whose files carry different run ids.
// Host-only: includes no Kokkos header.
#include <string>
#include <vector>

namespace rouleau {

// The name of the run's log in its folder (what the run printed on stderr, segment by segment).
inline constexpr const char* run_log_name = "run.log";

// A new run id: 16 hexadecimal digits from the clock and the system's random source.
std::string new_run_id();

// The line that starts run.log, and each segment a restart appends to it:
// "rouleau run id ID: DESCRIPTION" (e.g. "case NAME, started UTC-TIME").
std::string run_log_first_line(const std::string& run_id, const std::string& description);

// Whether `directory` holds files of a rouleau run (its log, resolved case, checkpoints or
// fields).
bool holds_a_run(const std::string& directory);

// Makes `directory` ready for a new run: creates it when missing; with `overwrite`, empties
// it when it holds a run. Throws InputError(directory, "--out", reason) when it names a file,
// when it holds files and `overwrite` is false (naming the run it holds), or when `overwrite`
// is true and it holds files that no rouleau run wrote. Call it before any work.
void prepare_new_run_folder(const std::string& directory, bool overwrite);

// One file of a run folder and the run id it carries ("" for a file written before run ids).
struct RunFileId {
  std::string path;
  std::string run_id;
};

// The run id of each file in `directory` that carries one: run.log, every HDF5 file at its
// top and under checkpoints/. A file that cannot be read is left out (the restart's own
// checks name a damaged checkpoint).
std::vector<RunFileId> run_ids_in_folder(const std::string& directory);

// The run id that every file of `directory` carries. Throws InputError(directory,
// "--restart", reason) naming two files of different runs when they disagree.
std::string single_run_id(const std::string& directory);

}  // namespace rouleau
