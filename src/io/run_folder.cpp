#include "io/run_folder.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include "io/hdf5_file.hpp"
#include "util/errors.hpp"

namespace rouleau {
namespace {

namespace fs = std::filesystem;

constexpr const char* who = "rouleau::run_folder";
// The first line of run.log starts with this, then the id, then ':'.
constexpr const char* log_id_prefix = "rouleau run id ";

// The names a run writes at the top of its folder (and the plot script's figures/).
bool written_by_a_run(const fs::path& entry) {
  const std::string name = entry.filename().string();
  static const char* const exact[] = {run_log_name, "case.resolved.toml", "diagnostics.csv", "checkpoints", "figures"};
  if (std::find(std::begin(exact), std::end(exact), name) != std::end(exact)) return true;
  const std::string extension = entry.extension().string();
  return extension == ".h5" || extension == ".xdmf" || extension == ".tmp";
}

std::string run_id_in_log(const fs::path& log) {
  std::ifstream in(log);
  std::string first;
  if (!std::getline(in, first) || first.rfind(log_id_prefix, 0) != 0) return "";
  const std::string rest = first.substr(std::char_traits<char>::length(log_id_prefix));
  return rest.substr(0, rest.find(':'));
}

// The "run_id" provenance attribute of an HDF5 file: "" when it has none (written before
// run ids), nullopt-like `readable = false` when the file cannot be read at all.
std::string run_id_in_hdf5(const fs::path& path, bool& readable) {
  readable = true;
  try {
    const Hdf5Handle file = open_hdf5_file(path.string(), who);
    try {
      return read_root_string_attribute(Hdf5File{file.get(), path.string(), who}, "run_id");
    } catch (const std::runtime_error&) {
      return "";
    }
  } catch (const std::runtime_error&) {
    readable = false;
    return "";
  }
}

}  // namespace

std::string new_run_id() {
  std::random_device device;
  const std::uint64_t clock =
      static_cast<std::uint64_t>(std::chrono::system_clock::now().time_since_epoch().count());
  const std::uint64_t random = (static_cast<std::uint64_t>(device()) << 32) ^ device();
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(random ^ (clock * 0x9e3779b97f4a7c15ull)));
  return text;
}

std::string run_log_first_line(const std::string& run_id, const std::string& description) {
  return log_id_prefix + run_id + ": " + description;
}

bool holds_a_run(const std::string& directory) {
  std::error_code status;
  for (const auto& entry : fs::directory_iterator(directory, status))
    if (written_by_a_run(entry.path())) return true;
  return false;
}

void prepare_new_run_folder(const std::string& directory, bool overwrite) {
  std::error_code status;
  if (fs::exists(directory, status) && !fs::is_directory(directory, status))
    throw InputError(directory, "--out", "names a file, not a folder");
  if (!fs::exists(directory, status)) {
    fs::create_directories(directory, status);
    if (status) throw InputError(directory, "--out", "cannot create the folder: " + status.message());
    return;
  }
  std::vector<fs::path> entries;
  for (const auto& entry : fs::directory_iterator(directory, status)) entries.push_back(entry.path());
  if (status) throw InputError(directory, "--out", "cannot read the folder: " + status.message());
  if (entries.empty()) return;
  std::sort(entries.begin(), entries.end());
  if (!overwrite) {
    std::string held = "files (" + entries.front().filename().string() + (entries.size() > 1 ? ", ..." : "") + ")";
    if (holds_a_run(directory)) {
      const auto ids = run_ids_in_folder(directory);
      held = "an earlier run";
      if (!ids.empty() && !ids.front().run_id.empty()) held += " (run id " + ids.front().run_id + ")";
    }
    throw InputError(directory, "--out",
                     "the folder holds " + held +
                         "; a run never writes over another: choose another folder, continue that run with --restart " +
                         directory + ", or pass --overwrite to empty the folder first");
  }
  if (!holds_a_run(directory))
    throw InputError(directory, "--out",
                     "--overwrite empties only a folder that holds a rouleau run, and this one holds none (" +
                         entries.front().filename().string() + (entries.size() > 1 ? ", ..." : "") +
                         "): choose another folder");
  for (const fs::path& entry : entries) {
    fs::remove_all(entry, status);
    if (status) throw InputError(directory, "--out", "--overwrite could not remove " + entry.string() + ": " + status.message());
  }
}

std::vector<RunFileId> run_ids_in_folder(const std::string& directory) {
  std::vector<RunFileId> found;
  std::error_code status;
  const fs::path log = fs::path(directory) / run_log_name;
  if (fs::is_regular_file(log, status)) found.push_back({log.string(), run_id_in_log(log)});
  std::vector<fs::path> hdf5_files;
  for (const fs::path& folder : {fs::path(directory), fs::path(directory) / "checkpoints"}) {
    if (!fs::is_directory(folder, status)) continue;
    for (const auto& entry : fs::directory_iterator(folder, status))
      if (entry.path().extension() == ".h5" && entry.is_regular_file(status)) hdf5_files.push_back(entry.path());
  }
  std::sort(hdf5_files.begin(), hdf5_files.end());
  for (const fs::path& path : hdf5_files) {
    bool readable = false;
    const std::string id = run_id_in_hdf5(path, readable);
    if (readable) found.push_back({path.string(), id});
  }
  return found;
}

std::string single_run_id(const std::string& directory) {
  const std::vector<RunFileId> files = run_ids_in_folder(directory);
  if (files.empty()) return "";
  auto describe = [](const RunFileId& file) {
    return file.path + " (" + (file.run_id.empty() ? std::string("no run id: an earlier version's") : "run " + file.run_id) + ")";
  };
  for (const RunFileId& file : files)
    if (file.run_id != files.front().run_id)
      throw InputError(directory, "--restart",
                       "the folder holds files of different runs: " + describe(files.front()) + " and " + describe(file) +
                           "; restart from a folder of one run (a new run needs --out and an empty folder)");
  return files.front().run_id;
}

}  // namespace rouleau
