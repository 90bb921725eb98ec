#pragma once
// The diagnostics time series of a run: one CSV row per step (time, energies, volumes,
// residuals, ...). Rows stay in memory; every flush rewrites the whole file through PATH.tmp
// and a rename, so the file on disk is always a complete table. Host-only: no Kokkos header.
#include <chrono>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace rouleau {

class DiagnosticsTable {
 public:
  // A table written to `path` (its directory is created if missing) with these column
  // names, which must be non-empty, unique, and free of ',', '"' and line breaks, starting
  // with `earlier_rows` given by column name (a restarted run takes over the rows of the
  // run it continues, io/diagnostics_reader.hpp; a column a row does not have gets NaN,
  // names not among the columns are dropped). The file is written at once with the header
  // and the earlier rows, so a run killed at any moment leaves them on disk. add_row
  // flushes by itself after every
  // `rows_per_flush` rows (0: only explicit flushes and the destructor), and when
  // `seconds_per_flush` of wall time have passed since the last flush (0: never), so that
  // a long run's file follows it.
  // Throws std::invalid_argument for bad columns, std::runtime_error if the file cannot be written.
  DiagnosticsTable(std::string path, std::vector<std::string> columns,
                   const std::vector<std::map<std::string, double>>& earlier_rows = {},
                   std::size_t rows_per_flush = 100, double seconds_per_flush = 10.0);

  // Flushes unwritten rows; an error is reported on stderr, never thrown.
  ~DiagnosticsTable();

  DiagnosticsTable(const DiagnosticsTable&) = delete;
  DiagnosticsTable& operator=(const DiagnosticsTable&) = delete;

  // Appends one row, one value per column in column order (NaN and ±inf are kept as
  // "nan", "inf", "-inf"). Throws std::invalid_argument when the count differs from the
  // number of columns.
  void add_row(const std::vector<double>& values);

  // Writes the header and every row so far to PATH.tmp, syncs it and renames it to PATH.
  // Each value is printed with "%.17g", which reads back to the identical double.
  void flush();

  const std::string& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t row_count() const { return values_.size() / columns_.size(); }

 private:
  std::string path_;
  std::vector<std::string> columns_;
  std::vector<double> values_;  // row-major, row_count() x columns_.size()
  std::size_t rows_per_flush_;
  double seconds_per_flush_;
  std::chrono::steady_clock::time_point last_flush_;
  std::size_t unflushed_rows_ = 0;
};

}  // namespace rouleau
