#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace rouleau {

std::string temporary_path_for(const std::string& path) { return path + ".tmp"; }

namespace {
[[noreturn]] void fail(const std::string& what, const std::string& path) {
  throw std::runtime_error("rouleau::" + what + ": " + path + ": " + std::strerror(errno));
}
void sync_file(const std::string& path) {
  int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) fail("sync_file", path);
  ::fsync(fd);
  ::close(fd);
}
}  // namespace

void commit_temporary_file(const std::string& temporary, const std::string& path) {
  sync_file(temporary);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) fail("commit_temporary_file", path);
}

void write_file_atomically(const std::string& path, const std::string& contents) {
  const std::string temporary = temporary_path_for(path);
  std::FILE* f = std::fopen(temporary.c_str(), "wb");
  if (!f) fail("write_file_atomically", temporary);
  const bool ok = std::fwrite(contents.data(), 1, contents.size(), f) == contents.size();
  if (std::fclose(f) != 0 || !ok) fail("write_file_atomically", temporary);
  commit_temporary_file(temporary, path);
}

int remove_leftover_temporary_files(const std::string& directory) {
  int removed = 0;
  std::error_code status;
  for (const auto& entry : std::filesystem::directory_iterator(directory, status)) {
    if (entry.path().extension() != ".tmp" || !entry.is_regular_file(status)) continue;
    removed += std::filesystem::remove(entry.path(), status) ? 1 : 0;
  }
  return removed;
}

}  // namespace rouleau
