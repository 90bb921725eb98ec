#pragma once
// Files are written to a temporary name beside the target and renamed over it, so an
// interrupted run never leaves a half-written file. Host-only.
#include <string>

namespace rouleau {

// The temporary name used for `path` while it is being written ("PATH.tmp").
std::string temporary_path_for(const std::string& path);

// Writes `contents` to PATH.tmp, flushes it to disk and renames it to `path`.
// Throws std::runtime_error naming the path and the system's reason on failure.
void write_file_atomically(const std::string& path, const std::string& contents);

// Renames a finished temporary file onto its final name (after fsync of the data).
void commit_temporary_file(const std::string& temporary, const std::string& path);

// Removes the temporary files ("*.tmp") directly in `directory`: what a process that was
// killed while writing left behind (a run folder has one writer at a time, so at a
// restart every such file is dead). Returns how many were removed.
int remove_leftover_temporary_files(const std::string& directory);

}  // namespace rouleau
