// A small strict CSV reader for the optics tables: the first row is the header, cells are read by column
// name, and every error message names the table (file), the line and the column.
//
// Accepted: comma separators, optional double quotes around a cell ("" inside quotes is a quote), CRLF line
// ends, a UTF-8 byte-order mark, spaces around cells, blank lines (skipped). Rejected: a row whose cell count
// differs from the header's, duplicate or empty header names, a numeric cell that is empty (unless asked
// for), not a complete number, or not finite (nan, inf).
#pragma once
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"
#include "optics/spectrum.h"

namespace lagoon::optics {

struct CsvOptions {
  // The last column is free text that may hold unquoted commas (the source notes of
  // srgb_xyz_to_linear_rgb_d65.csv, e.g. "white (0.3127,0.3290)"): surplus cells are joined back into it.
  bool last_column_free_text = false;
};

class CsvTable {
 public:
  // `source` names the table in error messages (a file path or an embedded table's name).
  static Result<CsvTable> parse(std::string_view text, std::string source, CsvOptions options = {});
  static Result<CsvTable> read_file(const std::filesystem::path& path, CsvOptions options = {});
  // A table from compute/optics/data, embedded at build time (optics/embedded_text.h).
  static Result<CsvTable> embedded(std::string_view name, CsvOptions options = {});

  const std::string& source() const { return source_; }
  const std::vector<std::string>& header() const { return header_; }
  std::size_t rows() const { return cells_.size(); }
  int line(std::size_t row) const { return lines_[row]; }  // 1-based line in the text, for messages
  bool has_column(std::string_view name) const { return column_index(name).has_value(); }

  // Every cell of the column as a finite number.
  Result<std::vector<double>> numbers(std::string_view column) const;
  // Empty cells give nullopt; the others must be finite numbers.
  Result<std::vector<std::optional<double>>> numbers_or_empty(std::string_view column) const;
  Result<std::vector<std::string>> texts(std::string_view column) const;

  // "<source> line N, column 'name'": the prefix of a message about one cell.
  std::string where(std::size_t row, std::string_view column) const;

 private:
  std::optional<std::size_t> column_index(std::string_view name) const;
  Result<std::size_t> require_column(std::string_view name) const;

  std::string source_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> cells_;  // [row][column], trimmed, quotes removed
  std::vector<int> lines_;
};

// The embedded tables are part of the build, so a defect in one is a programming error rather than
// something a user can fix: these print the message to stderr and abort. The unit tests load every table.
[[noreturn]] void abort_table_defect(const std::string& message);
CsvTable embedded_table_or_abort(std::string_view name, CsvOptions options = {});
std::vector<double> numbers_or_abort(const CsvTable& table, std::string_view column);
// A column of a table whose `wavelength_nm` column is exactly the 5 nm grid of spectrum.h.
Spectrum grid_column_or_abort(const CsvTable& table, std::string_view column);

}  // namespace lagoon::optics
