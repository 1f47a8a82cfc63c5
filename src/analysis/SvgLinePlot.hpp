#pragma once
/// A small line chart written as SVG (opens in any browser and most image viewers): a title, axes with ticks
/// and labelled with units, one polyline per series, and a legend. No plotting library needed.

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace poro {

class SvgLinePlot {
public:
  struct Series {
    std::string label;
    std::vector<std::pair<double, double>> points; ///< (x, y), drawn in this order; non-finite points are left out
    bool dashed = false;
    int colour = -1; ///< index into the palette; -1: the series' own index
  };

  SvgLinePlot(std::string title, std::string xLabel, std::string yLabel);

  void add(Series series) { series_.push_back(std::move(series)); }
  /// The y axis (x axis) reaches 0 even when the data do not.
  void includeZeroY() { zeroY_ = true; }
  void includeZeroX() { zeroX_ = true; }

  /// Series with at least one point, i.e. the number of <polyline> elements of svg().
  std::size_t lines() const;
  /// The whole SVG document (UTF-8). Without any points it shows "no data".
  std::string svg() const;
  /// Writes svg() atomically; throws OutputError naming the file.
  void write(const std::filesystem::path& file) const;

private:
  std::string title_, xLabel_, yLabel_;
  std::vector<Series> series_;
  bool zeroX_ = false, zeroY_ = false;
};

} // namespace poro
