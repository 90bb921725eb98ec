#include "io/checkpoint_file.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <stdexcept>

#include "io/hdf5_file.hpp"
#include "util/fnv1a.hpp"

namespace rouleau {

namespace {

constexpr const char* checkpoint_who = "rouleau::checkpoint";
constexpr const char* reals_group = "/reals/";
constexpr const char* integers_group = "/integers/";
constexpr const char* label_prefix = "label_";

// Names become HDF5 paths below /reals and /integers: letters, digits, '_', '-', '.' and
// '/' between parts.
void check_entry_name(const std::string& name) {
  const bool allowed =
      !name.empty() && name.front() != '/' && name.back() != '/' && name.find("//") == std::string::npos &&
      name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./") == std::string::npos;
  if (!allowed) throw std::invalid_argument(std::string(checkpoint_who) + ": bad entry name \"" + name + "\"");
}

[[noreturn]] void missing(const std::string& what, const std::string& name, const std::string& reason) {
  throw std::runtime_error(std::string(checkpoint_who) + ": " + what + " \"" + name + "\" " + reason);
}

// The lines of `text` (the indexes /reals_index, /integers_index, /labels_index hold one
// entry name per line).
std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    lines.push_back(text.substr(start, end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

template <class Map>
std::vector<std::string> names_of(const Map& map) {
  std::vector<std::string> names;
  for (const auto& entry : map) names.push_back(entry.first);
  return names;
}

std::string step_file_name(long long step) {
  char name[48];
  std::snprintf(name, sizeof name, "checkpoint_%09lld.h5", step);
  return name;
}

}  // namespace

namespace {

// The entry `name` of `entries`, of exactly `size` values when `size` >= 0.
template <class Value>
const std::vector<Value>& sized_entry(const std::map<std::string, std::vector<Value>>& entries,
                                      const std::string& name, long long size) {
  const auto found = entries.find(name);
  if (found == entries.end()) missing("entry", name, "is missing");
  if (size >= 0 && static_cast<long long>(found->second.size()) != size)
    missing("entry", name,
            "holds " + std::to_string(found->second.size()) + " values where " + std::to_string(size) + " are needed");
  return found->second;
}

}  // namespace

const std::vector<double>& CheckpointData::real(const std::string& name, long long size) const {
  return sized_entry(reals, name, size);
}

const std::vector<long long>& CheckpointData::integer(const std::string& name, long long size) const {
  return sized_entry(integers, name, size);
}

const std::string& CheckpointData::label(const std::string& name) const {
  const auto found = labels.find(name);
  if (found == labels.end()) missing("label", name, "is missing");
  return found->second;
}

std::string checkpoint_checksum(const CheckpointData& data) {
  Fnv1a64 hash;
  hash.add_word(static_cast<std::uint64_t>(CheckpointData::format_version));
  hash.add_word(static_cast<std::uint64_t>(data.step));
  hash.add_double(data.time);
  hash.add_double(data.wall_seconds);
  hash.add_text(data.resolved_case);
  for (const auto& [name, value] : data.labels) {
    hash.add_text(name);
    hash.add_text(value);
  }
  for (const auto& [name, values] : data.reals) {
    hash.add_text(name);
    hash.add_word(values.size());
    for (double v : values) hash.add_double(v);
  }
  for (const auto& [name, values] : data.integers) {
    hash.add_text(name);
    hash.add_word(values.size());
    for (long long v : values) hash.add_word(static_cast<std::uint64_t>(v));
  }
  return hash.hex_digest();
}

void write_checkpoint_file(const std::string& path, const CheckpointData& data, const Provenance& provenance) {
  for (const auto& entry : data.reals) check_entry_name(entry.first);
  for (const auto& entry : data.integers) check_entry_name(entry.first);
  for (const auto& entry : data.labels) check_entry_name(entry.first);
  write_hdf5_file_atomically(path, checkpoint_who, provenance, [&](const Hdf5File& file) {
    const long long version = CheckpointData::format_version;
    write_dataset(file, "/format_version", H5T_NATIVE_LLONG, H5T_STD_I64LE, &version, {1});
    write_dataset(file, "/step", H5T_NATIVE_LLONG, H5T_STD_I64LE, &data.step, {1});
    write_double_array(file, "/time", &data.time, 1, 1);
    write_double_array(file, "/wall_seconds", &data.wall_seconds, 1, 1);
    write_text_dataset(file, "/case", data.resolved_case);
    write_text_dataset(file, "/reals_index", join_lines(names_of(data.reals)));
    write_text_dataset(file, "/integers_index", join_lines(names_of(data.integers)));
    write_text_dataset(file, "/labels_index", join_lines(names_of(data.labels)));
    for (const auto& [name, values] : data.reals)
      write_dataset(file, reals_group + name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, values.data(),
                    {static_cast<hsize_t>(values.size())});
    for (const auto& [name, values] : data.integers)
      write_dataset(file, integers_group + name, H5T_NATIVE_LLONG, H5T_STD_I64LE, values.data(),
                    {static_cast<hsize_t>(values.size())});
    for (const auto& [name, value] : data.labels) write_root_string_attribute(file, label_prefix + name, value);
    write_root_string_attribute(file, "checksum", checkpoint_checksum(data));
  });
}

CheckpointData read_checkpoint_file(const std::string& path) {
  Hdf5Handle handle = open_hdf5_file(path, checkpoint_who);
  const Hdf5File file{handle.get(), path, checkpoint_who};
  const auto one = [&](const std::string& dataset_path, auto values) {
    if (values.size() != 1)
      throw std::runtime_error(std::string(checkpoint_who) + ": " + path + ": " + dataset_path + ": holds " +
                               std::to_string(values.size()) + " values, not 1");
    return values.front();
  };
  const long long version = one("/format_version", read_integer_dataset(file, "/format_version"));
  if (version != CheckpointData::format_version)
    throw std::runtime_error(std::string(checkpoint_who) + ": " + path + ": format version " + std::to_string(version) +
                             "; this rouleau reads version " + std::to_string(CheckpointData::format_version));
  CheckpointData data;
  data.step = one("/step", read_integer_dataset(file, "/step"));
  data.time = one("/time", read_double_dataset(file, "/time"));
  data.wall_seconds = one("/wall_seconds", read_double_dataset(file, "/wall_seconds"));
  data.resolved_case = read_text_dataset(file, "/case");
  for (const std::string& name : split_lines(read_text_dataset(file, "/reals_index"))) {
    check_entry_name(name);
    data.reals[name] = read_double_dataset(file, reals_group + name);
  }
  for (const std::string& name : split_lines(read_text_dataset(file, "/integers_index"))) {
    check_entry_name(name);
    data.integers[name] = read_integer_dataset(file, integers_group + name);
  }
  for (const std::string& name : split_lines(read_text_dataset(file, "/labels_index"))) {
    check_entry_name(name);
    data.labels[name] = read_root_string_attribute(file, label_prefix + name);
  }
  const std::string stored = read_root_string_attribute(file, "checksum");
  const std::string computed = checkpoint_checksum(data);
  if (stored != computed)
    throw std::runtime_error(std::string(checkpoint_who) + ": " + path + ": checksum " + computed + " of the contents, " +
                             stored + " stored: the file is damaged");
  return data;
}

// ---- CheckpointStore

CheckpointStore::CheckpointStore(std::string run_directory, int kept)
    : run_directory_(std::move(run_directory)), kept_(kept) {
  if (kept_ < 1) throw std::invalid_argument(std::string(checkpoint_who) + ": keep at least one checkpoint, not " + std::to_string(kept));
}

std::string CheckpointStore::directory() const {
  return (std::filesystem::path(run_directory_) / "checkpoints").string();
}

std::string CheckpointStore::path_of(long long step) const {
  return (std::filesystem::path(directory()) / step_file_name(step)).string();
}

std::vector<std::pair<long long, std::string>> CheckpointStore::list() const {
  std::vector<std::pair<long long, std::string>> found;
  std::error_code status;
  if (!std::filesystem::is_directory(directory(), status)) return found;
  static const std::regex pattern("checkpoint_([0-9]{9,18})\\.h5");
  for (const auto& entry : std::filesystem::directory_iterator(directory(), status)) {
    std::smatch match;
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file(status) && std::regex_match(name, match, pattern))
      found.emplace_back(std::stoll(match[1].str()), entry.path().string());
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  return found;
}

std::string CheckpointStore::write(const CheckpointData& data, const Provenance& provenance) {
  std::filesystem::create_directories(directory());
  const std::string path = path_of(data.step);
  write_checkpoint_file(path, data, provenance);
  last_path_ = path;
  int newer_or_same_kept = 0;
  for (const auto& [step, existing] : list()) {
    std::error_code ignored;
    if (step > data.step)
      std::filesystem::remove(existing, ignored);
    else if (++newer_or_same_kept > kept_)
      std::filesystem::remove(existing, ignored);
  }
  return path;
}

FoundCheckpoint newest_valid_checkpoint(const std::string& run_directory) {
  FoundCheckpoint found;
  const CheckpointStore store(run_directory, 1);
  const auto checkpoints = store.list();
  for (const auto& [step, path] : checkpoints) {
    try {
      found.data = read_checkpoint_file(path);
      found.path = path;
      return found;
    } catch (const std::exception& error) {
      found.refused.push_back(error.what());
    }
  }
  std::string reason = checkpoints.empty() ? "no checkpoint in " + store.directory()
                                           : "no usable checkpoint in " + store.directory() + " (" +
                                                 std::to_string(checkpoints.size()) + " refused: " +
                                                 found.refused.front() + ")";
  throw std::runtime_error(reason);
}

}  // namespace rouleau
