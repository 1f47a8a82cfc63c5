#pragma once
/// A CSV table (RFC 4180): a header row of column names, then rows of cells. Numbers are written with the
/// fewest digits that read back to the same double, so a reader gets exactly the computed values.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace poro {

class CsvTable {
public:
  explicit CsvTable(std::vector<std::string> columns);

  /// Starts a new row; cells are then appended left to right (a row may end early: the rest stay empty).
  CsvTable& row();
  CsvTable& add(const std::string& text);
  CsvTable& add(double value);
  CsvTable& add(std::size_t value);
  CsvTable& add(long long value);
  /// An empty cell when there is no value.
  CsvTable& add(const std::optional<double>& value);

  std::size_t columns() const { return columns_.size(); }
  std::size_t rows() const { return rows_.size(); }
  std::string text() const;
  /// Writes text() atomically (io/AtomicFile.hpp); throws OutputError naming the file.
  void write(const std::filesystem::path& file) const;

  /// Shortest decimal that reads back to exactly `value` ("0.1", "6.4e-05"); "nan", "inf", "-inf" otherwise.
  static std::string formatNumber(double value);
  /// The cell as CSV writes it: quoted, with quotes doubled, if it holds a comma, quote or line break.
  static std::string quote(const std::string& cell);

private:
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;
};

} // namespace poro
