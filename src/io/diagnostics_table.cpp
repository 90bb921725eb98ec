#include "io/diagnostics_table.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <set>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace rouleau {

namespace {

void check_column_names(const std::string& path, const std::vector<std::string>& columns) {
  const std::string where = "rouleau::DiagnosticsTable: " + path + ": ";
  if (columns.empty()) throw std::invalid_argument(where + "no columns");
  std::set<std::string> seen;
  for (const std::string& column : columns) {
    if (column.empty()) throw std::invalid_argument(where + "empty column name");
    if (column.find_first_of(",\"\r\n") != std::string::npos)
      throw std::invalid_argument(where + "column name \"" + column + "\" contains ',', '\"' or a line break");
    if (!seen.insert(column).second) throw std::invalid_argument(where + "duplicate column name \"" + column + "\"");
  }
}

void create_parent_directory(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
}

}  // namespace

DiagnosticsTable::DiagnosticsTable(std::string path, std::vector<std::string> columns,
                                   const std::vector<std::map<std::string, double>>& earlier_rows,
                                   std::size_t rows_per_flush, double seconds_per_flush)
    : path_(std::move(path)),
      columns_(std::move(columns)),
      rows_per_flush_(rows_per_flush),
      seconds_per_flush_(seconds_per_flush) {
  check_column_names(path_, columns_);
  create_parent_directory(path_);
  for (const auto& row : earlier_rows)
    for (const std::string& column : columns_) {
      const auto found = row.find(column);
      values_.push_back(found == row.end() ? std::numeric_limits<double>::quiet_NaN() : found->second);
    }
  flush();
}

DiagnosticsTable::~DiagnosticsTable() {
  if (unflushed_rows_ == 0) return;
  try {
    flush();
  } catch (const std::exception& error) {
    std::cerr << "rouleau::DiagnosticsTable: " << unflushed_rows_ << " rows not written: " << error.what() << '\n';
  }
}

void DiagnosticsTable::add_row(const std::vector<double>& values) {
  if (values.size() != columns_.size())
    throw std::invalid_argument("rouleau::DiagnosticsTable::add_row: " + path_ + ": got " +
                                std::to_string(values.size()) + " values for " + std::to_string(columns_.size()) +
                                " columns");
  values_.insert(values_.end(), values.begin(), values.end());
  ++unflushed_rows_;
  const bool rows_due = rows_per_flush_ > 0 && unflushed_rows_ >= rows_per_flush_;
  const bool time_due =
      seconds_per_flush_ > 0 &&
      std::chrono::duration<double>(std::chrono::steady_clock::now() - last_flush_).count() >= seconds_per_flush_;
  if (rows_due || time_due) flush();
}

void DiagnosticsTable::flush() {
  std::string text;
  text.reserve((values_.size() + columns_.size()) * 24);
  for (std::size_t column = 0; column < columns_.size(); ++column) {
    if (column > 0) text += ',';
    text += columns_[column];
  }
  text += '\n';
  char number[32];
  for (std::size_t i = 0; i < values_.size(); ++i) {
    std::snprintf(number, sizeof number, "%.17g", values_[i]);
    text += number;
    text += (i + 1) % columns_.size() == 0 ? '\n' : ',';
  }
  write_file_atomically(path_, text);
  unflushed_rows_ = 0;
  last_flush_ = std::chrono::steady_clock::now();
}

}  // namespace rouleau
