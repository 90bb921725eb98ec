#include "io/run_folder.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>

#include "io/hdf5_file.hpp"
#include "util/errors.hpp"

namespace rouleau {
namespace {

namespace fs = std::filesystem;

constexpr const char* run_folder_who = "rouleau::run_folder";
// The first line of run.log starts with this, then the id, then ':'.
constexpr const char* log_id_prefix = "rouleau run id ";

// The names a run writes at the top of its folder: its log, resolved case, diagnostics, the
// paper's checks (a case driver's, after the run), the fields' XDMF and HDF5 files, each
// also as NAME.tmp while it is written; checkpoints/ holds checkpoint_SSSSSSSSS.h5 files,
// and figures/ the plot and render scripts' PNG files.
const std::regex& run_file_name() {
  static const std::regex name(
      "(run\\.log|case\\.resolved\\.toml|diagnostics\\.csv|paper_checks\\.csv|fields(_[A-Za-z0-9.-]+)?\\.xdmf|"
      "fields_mesh\\.h5|fields_[0-9]{6,}\\.h5)(\\.tmp)?");
  return name;
}

// The first entry under `entry` that a run does not write there, or "" when there is none.
std::string foreign_entry(const fs::path& entry) {
  std::error_code status;
  const std::string name = entry.filename().string();
  const bool folder = fs::is_directory(fs::symlink_status(entry, status));
  if (!folder) return std::regex_match(name, run_file_name()) ? "" : entry.string();
  static const std::regex checkpoint("checkpoint_[0-9]{9,18}\\.h5(\\.tmp)?"), figure("[A-Za-z0-9_.-]+\\.png(\\.tmp)?");
  const std::regex* inside = name == "checkpoints" ? &checkpoint : name == "figures" ? &figure : nullptr;
  if (!inside) return entry.string();
  for (const auto& item : fs::directory_iterator(entry, status))
    if (!item.is_regular_file(status) || !std::regex_match(item.path().filename().string(), *inside))
      return item.path().string();
  return "";
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
    const Hdf5Handle file = open_hdf5_file(path.string(), run_folder_who);
    try {
      return read_root_string_attribute(Hdf5File{file.get(), path.string(), run_folder_who}, "run_id");
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
  const fs::path folder(directory);
  // A run's log names its run id on its first line; a run of an earlier version left its
  // resolved case.
  if (fs::is_regular_file(folder / run_log_name, status) && !run_id_in_log(folder / run_log_name).empty()) return true;
  return fs::is_regular_file(folder / "case.resolved.toml", status);
}

void prepare_new_run_folder(const std::string& directory, bool overwrite) {
  std::error_code status;
  if (fs::exists(directory, status) && !fs::is_directory(directory, status))
    throw InputError(directory, "--out", "names a file, not a folder");
  // Not inside another run's folder (its checkpoints/, its figures/).
  const fs::path absolute = fs::weakly_canonical(fs::absolute(directory), status);
  for (fs::path parent = absolute.parent_path(); !parent.empty() && parent != parent.root_path();
       parent = parent.parent_path())
    if (holds_a_run(parent.string()))
      throw InputError(directory, "--out", "lies inside the folder of a run, " + parent.string() + ": choose another folder");
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
  const std::string listed = entries.front().filename().string() + (entries.size() > 1 ? ", ..." : "");
  if (!holds_a_run(directory))
    throw InputError(directory, "--out",
                     "the folder holds files that no rouleau run wrote (" + listed +
                         "); a run starts only in a missing or empty folder: choose another folder");
  if (!overwrite) {
    const std::string id = run_id_in_log(fs::path(directory) / run_log_name);
    throw InputError(directory, "--out",
                     "the folder holds an earlier run" + (id.empty() ? std::string() : " (run id " + id + ")") +
                         "; a run never writes over another: choose another folder, continue that run with --restart " +
                         directory + ", or pass --overwrite to empty the folder first");
  }
  // --overwrite: every entry must be one a run writes, checked before anything is removed.
  for (const fs::path& entry : entries)
    if (const std::string foreign = foreign_entry(entry); !foreign.empty())
      throw InputError(directory, "--out",
                       "--overwrite empties only what a run wrote, and the folder also holds " + foreign +
                           ": move it away or choose another folder");
  const fs::path working = fs::weakly_canonical(fs::current_path(status), status);
  for (const fs::path& entry : entries) {
    const fs::path canonical = fs::weakly_canonical(entry, status);
    if (working == canonical || working.string().rfind(canonical.string() + "/", 0) == 0)
      throw InputError(directory, "--out", "--overwrite would remove the current folder, " + working.string());
  }
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
