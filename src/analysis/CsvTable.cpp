#include "analysis/CsvTable.hpp"

#include "io/AtomicFile.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace poro {

CsvTable::CsvTable(std::vector<std::string> columns) : columns_(std::move(columns)) {}

CsvTable& CsvTable::row() {
  rows_.emplace_back();
  return *this;
}

CsvTable& CsvTable::add(const std::string& text) {
  if (rows_.empty() || rows_.back().size() >= columns_.size())
    throw std::logic_error("CsvTable: cell '" + text + "' beyond the last column or before row()");
  rows_.back().push_back(text);
  return *this;
}

CsvTable& CsvTable::add(double value) { return add(formatNumber(value)); }
CsvTable& CsvTable::add(std::size_t value) { return add(std::to_string(value)); }
CsvTable& CsvTable::add(long long value) { return add(std::to_string(value)); }
CsvTable& CsvTable::add(const std::optional<double>& value) {
  return add(value ? formatNumber(*value) : std::string());
}

std::string CsvTable::text() const {
  std::string out;
  const auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      if (c > 0) out += ',';
      if (c < cells.size()) out += quote(cells[c]);
    }
    out += '\n';
  };
  line(columns_);
  for (const auto& cells : rows_) line(cells);
  return out;
}

void CsvTable::write(const std::filesystem::path& file) const { writeFileAtomically(file, text()); }

std::string CsvTable::formatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

std::string CsvTable::quote(const std::string& cell) {
  if (cell.find_first_of(",\"\r\n") == std::string::npos) return cell;
  std::string quoted = "\"";
  for (const char c : cell) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

} // namespace poro
