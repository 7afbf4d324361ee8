#include "optics/csv_table.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

#include "core/bounded_file.h"
#include "optics/embedded_text.h"

namespace lagoon::optics {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Splits one line into cells. A cell may be quoted; returns an error text for an unterminated quote or
// text after a closing quote.
Result<std::vector<std::string>> split_line(std::string_view line) {
  std::vector<std::string> cells;
  std::size_t i = 0;
  while (true) {
    std::string cell;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i < line.size() && line[i] == '"') {
      ++i;
      bool closed = false;
      while (i < line.size()) {
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            cell += '"';
            i += 2;
            continue;
          }
          ++i;
          closed = true;
          break;
        }
        cell += line[i++];
      }
      if (!closed) return make_error("unterminated quote");
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
      if (i < line.size() && line[i] != ',') return make_error("text after a closing quote");
    } else {
      const std::size_t end = std::min(line.find(',', i), line.size());
      cell = std::string(trim(line.substr(i, end - i)));
      i = end;
    }
    cells.push_back(std::move(cell));
    if (i >= line.size()) break;
    ++i;                     // the comma
    if (i == line.size()) {  // a trailing comma: one more, empty cell
      cells.emplace_back();
      break;
    }
  }
  return cells;
}

// The cell as a finite number, or an error text.
Result<double> parse_number(std::string_view cell) {
  if (cell.empty()) return make_error("empty cell, a number was expected");
  std::string_view s = cell;
  if (s.front() == '+') s.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  std::string quoted = "'";  // built by appending: GCC 12 -Wrestrict misfires on "'" + std::string(...)
  quoted.append(cell).append("'");
  if (ec != std::errc() || end != s.data() + s.size() || s.empty())
    return make_error(quoted + " is not a number");
  if (!std::isfinite(value)) return make_error(quoted + " is not a finite number");
  return value;
}

}  // namespace

Result<CsvTable> CsvTable::parse(std::string_view text, std::string source, CsvOptions options) {
  CsvTable table;
  table.source_ = std::move(source);
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  int line_number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (trim(line).empty()) continue;
    auto cells = split_line(line);
    const std::string at = table.source_ + " line " + std::to_string(line_number);
    if (!cells) return make_error(at + ": " + cells.error().message);
    if (table.header_.empty()) {
      for (std::size_t c = 0; c < cells->size(); ++c) {
        const std::string& name = (*cells)[c];
        if (name.empty()) return make_error(at + ": header column " + std::to_string(c + 1) + " has no name");
        for (std::size_t d = 0; d < c; ++d)
          if ((*cells)[d] == name) return make_error(at + ": header names column '" + name + "' twice");
      }
      table.header_ = std::move(*cells);
      continue;
    }
    const std::size_t want = table.header_.size();
    if (options.last_column_free_text && cells->size() > want) {
      for (std::size_t c = want; c < cells->size(); ++c) (*cells)[want - 1] += "," + (*cells)[c];
      cells->resize(want);
    }
    if (cells->size() != want)
      return make_error(at + ": " + std::to_string(cells->size()) + " cells, the header has " +
                        std::to_string(want));
    table.cells_.push_back(std::move(*cells));
    table.lines_.push_back(line_number);
  }
  if (table.header_.empty()) return make_error(table.source_ + ": empty table (no header row)");
  return table;
}

Result<CsvTable> CsvTable::read_file(const std::filesystem::path& path, CsvOptions options) {
  // Spectral tables are kilobytes; checked before reading (core/bounded_file.h), so /dev/zero or a FIFO
  // named as a water table is refused, not read for ever.
  constexpr std::uintmax_t kMaxTableBytes = std::uintmax_t{16} << 20;
  Result<std::string> text = read_bounded_file(path, kMaxTableBytes);
  if (!text) return make_error(path.string() + ": " + text.error().message + " (a table is a CSV file)");
  return parse(*text, path.string(), options);
}

Result<CsvTable> CsvTable::embedded(std::string_view name, CsvOptions options) {
  const std::string_view text = embedded_text(name);
  const std::string source = std::string(name) + " (embedded)";
  if (text.empty()) return make_error(source + ": no such embedded table");
  return parse(text, source, options);
}

std::optional<std::size_t> CsvTable::column_index(std::string_view name) const {
  for (std::size_t c = 0; c < header_.size(); ++c)
    if (header_[c] == name) return c;
  return std::nullopt;
}

Result<std::size_t> CsvTable::require_column(std::string_view name) const {
  if (auto c = column_index(name)) return *c;
  std::string columns;
  for (const std::string& h : header_) columns += (columns.empty() ? "" : ", ") + h;
  return make_error(source_ + ": no column '" + std::string(name) + "' (the header has: " + columns + ")");
}

std::string CsvTable::where(std::size_t row, std::string_view column) const {
  return source_ + " line " + std::to_string(lines_[row]) + ", column '" + std::string(column) + "'";
}

Result<std::vector<double>> CsvTable::numbers(std::string_view column) const {
  auto c = require_column(column);
  if (!c) return c.error();
  std::vector<double> out;
  out.reserve(cells_.size());
  for (std::size_t r = 0; r < cells_.size(); ++r) {
    auto v = parse_number(cells_[r][*c]);
    if (!v) return make_error(where(r, column) + ": " + v.error().message);
    out.push_back(*v);
  }
  return out;
}

Result<std::vector<std::optional<double>>> CsvTable::numbers_or_empty(std::string_view column) const {
  auto c = require_column(column);
  if (!c) return c.error();
  std::vector<std::optional<double>> out;
  out.reserve(cells_.size());
  for (std::size_t r = 0; r < cells_.size(); ++r) {
    if (cells_[r][*c].empty()) {
      out.push_back(std::nullopt);
      continue;
    }
    auto v = parse_number(cells_[r][*c]);
    if (!v) return make_error(where(r, column) + ": " + v.error().message);
    out.push_back(*v);
  }
  return out;
}

Result<std::vector<std::string>> CsvTable::texts(std::string_view column) const {
  auto c = require_column(column);
  if (!c) return c.error();
  std::vector<std::string> out;
  out.reserve(cells_.size());
  for (const auto& row : cells_) out.push_back(row[*c]);
  return out;
}

void abort_table_defect(const std::string& message) {
  std::fprintf(stderr, "lagoon: defect in an embedded optics table: %s\n", message.c_str());
  std::abort();
}

CsvTable embedded_table_or_abort(std::string_view name, CsvOptions options) {
  auto table = CsvTable::embedded(name, options);
  if (!table) abort_table_defect(table.error().message);
  return std::move(table).value();
}

std::vector<double> numbers_or_abort(const CsvTable& table, std::string_view column) {
  auto values = table.numbers(column);
  if (!values) abort_table_defect(values.error().message);
  return std::move(values).value();
}

Spectrum grid_column_or_abort(const CsvTable& table, std::string_view column) {
  const std::vector<double> wavelengths = numbers_or_abort(table, "wavelength_nm");
  const std::vector<double> values = numbers_or_abort(table, column);
  if (values.size() != static_cast<std::size_t>(kSamples))
    abort_table_defect(table.source() + ": " + std::to_string(values.size()) + " rows, the 5 nm grid has " +
                       std::to_string(kSamples));
  Spectrum out{};
  for (int i = 0; i < kSamples; ++i) {
    if (wavelengths[i] != wavelength_nm(i))
      abort_table_defect(table.where(i, "wavelength_nm") + ": not on the 380-780 nm 5 nm grid");
    out[i] = values[i];
  }
  return out;
}

}  // namespace lagoon::optics
