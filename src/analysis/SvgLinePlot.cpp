#include "analysis/SvgLinePlot.hpp"

#include "io/AtomicFile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace poro {

namespace {

constexpr double kWidth = 860, kHeight = 500;
constexpr double kLeft = 90, kTop = 50, kBottom = kHeight - 60;
constexpr const char* kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

std::string escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  }
  return out;
}

std::string px(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  return buffer;
}

/// An axis from lo to hi extended to whole multiples of a 1-2-5 tick step, about five ticks.
struct Scale {
  double lo, hi, step;

  static Scale make(double lo, double hi) {
    // One value (or values equal to round-off): a small interval around it.
    if (!(hi - lo > 1e-12 * std::max(std::abs(lo), std::abs(hi)))) {
      const double pad = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
      lo -= pad;
      hi += pad;
    }
    const double raw = (hi - lo) / 5.0;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / magnitude;
    const double step = (f < 1.5 ? 1.0 : f < 3.0 ? 2.0 : f < 7.0 ? 5.0 : 10.0) * magnitude;
    return {std::floor(lo / step + 1e-9) * step, std::ceil(hi / step - 1e-9) * step, step};
  }

  std::vector<double> ticks() const {
    std::vector<double> t;
    const long long n = std::min(std::llround((hi - lo) / step), 100LL);
    for (long long k = 0; k <= n; ++k) t.push_back(lo + static_cast<double>(k) * step);
    return t;
  }

  /// Fixed-point with as many decimals as the step needs ("0.02", "1000"); exponent form for extreme values.
  std::string label(double v) const {
    if (std::abs(v) < 1e-9 * step) v = 0.0;
    char buffer[32];
    const double biggest = std::max(std::abs(lo), std::abs(hi));
    if (step >= 1e-5 && biggest < 1e7) {
      const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
      std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    } else {
      std::snprintf(buffer, sizeof buffer, "%.3g", v);
    }
    return buffer;
  }
};

} // namespace

SvgLinePlot::SvgLinePlot(std::string title, std::string xLabel, std::string yLabel)
    : title_(std::move(title)), xLabel_(std::move(xLabel)), yLabel_(std::move(yLabel)) {}

std::size_t SvgLinePlot::lines() const {
  std::size_t n = 0;
  for (const Series& s : series_)
    n += std::any_of(s.points.begin(), s.points.end(),
                     [](const auto& p) { return std::isfinite(p.first) && std::isfinite(p.second); })
             ? 1
             : 0;
  return n;
}

std::string SvgLinePlot::svg() const {
  // Finite points per series, and their range.
  const double inf = std::numeric_limits<double>::infinity();
  double xlo = inf, xhi = -inf, ylo = inf, yhi = -inf;
  std::vector<std::vector<std::pair<double, double>>> points(series_.size());
  for (std::size_t s = 0; s < series_.size(); ++s)
    for (const auto& [x, y] : series_[s].points) {
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      points[s].emplace_back(x, y);
      xlo = std::min(xlo, x), xhi = std::max(xhi, x), ylo = std::min(ylo, y), yhi = std::max(yhi, y);
    }
  const bool empty = xlo > xhi;
  if (empty) xlo = xhi = ylo = yhi = 0.0;
  if (zeroX_) xlo = std::min(xlo, 0.0), xhi = std::max(xhi, 0.0);
  if (zeroY_) ylo = std::min(ylo, 0.0), yhi = std::max(yhi, 0.0);
  const Scale sx = Scale::make(xlo, xhi), sy = Scale::make(ylo, yhi);

  std::size_t longest = 0;
  for (std::size_t s = 0; s < series_.size(); ++s)
    if (!points[s].empty()) longest = std::max(longest, series_[s].label.size());
  const double right = kWidth - 30 - std::min(300.0, 50.0 + 7.5 * static_cast<double>(longest));
  const auto mapX = [&](double x) { return kLeft + (x - sx.lo) / (sx.hi - sx.lo) * (right - kLeft); };
  const auto mapY = [&](double y) { return kBottom - (y - sy.lo) / (sy.hi - sy.lo) * (kBottom - kTop); };

  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
      << "\" viewBox=\"0 0 " << kWidth << ' ' << kHeight << "\" font-family=\"sans-serif\" font-size=\"13\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << px((kLeft + right) / 2) << "\" y=\"30\" text-anchor=\"middle\" font-size=\"16\">"
      << escape(title_) << "</text>\n";

  out << "<g stroke=\"#dddddd\" stroke-width=\"1\">\n";
  for (const double t : sx.ticks())
    out << "<line x1=\"" << px(mapX(t)) << "\" y1=\"" << px(kTop) << "\" x2=\"" << px(mapX(t)) << "\" y2=\""
        << px(kBottom) << "\"/>\n";
  for (const double t : sy.ticks())
    out << "<line x1=\"" << px(kLeft) << "\" y1=\"" << px(mapY(t)) << "\" x2=\"" << px(right) << "\" y2=\""
        << px(mapY(t)) << "\"/>\n";
  out << "</g>\n<rect x=\"" << px(kLeft) << "\" y=\"" << px(kTop) << "\" width=\"" << px(right - kLeft)
      << "\" height=\"" << px(kBottom - kTop) << "\" fill=\"none\" stroke=\"black\"/>\n";
  for (const double t : sx.ticks())
    out << "<text x=\"" << px(mapX(t)) << "\" y=\"" << px(kBottom + 18) << "\" text-anchor=\"middle\">" << sx.label(t)
        << "</text>\n";
  for (const double t : sy.ticks())
    out << "<text x=\"" << px(kLeft - 6) << "\" y=\"" << px(mapY(t) + 4) << "\" text-anchor=\"end\">" << sy.label(t)
        << "</text>\n";
  out << "<text x=\"" << px((kLeft + right) / 2) << "\" y=\"" << px(kHeight - 18) << "\" text-anchor=\"middle\">"
      << escape(xLabel_) << "</text>\n"
      << "<text transform=\"translate(22," << px((kTop + kBottom) / 2) << ") rotate(-90)\" text-anchor=\"middle\">"
      << escape(yLabel_) << "</text>\n";
  if (empty)
    out << "<text x=\"" << px((kLeft + right) / 2) << "\" y=\"" << px((kTop + kBottom) / 2)
        << "\" text-anchor=\"middle\" fill=\"#888888\">no data</text>\n";

  double legendY = kTop + 12;
  for (std::size_t s = 0; s < series_.size(); ++s) {
    if (points[s].empty()) continue;
    const Series& series = series_[s];
    const int index = series.colour >= 0 ? series.colour : static_cast<int>(s);
    const std::string colour = kPalette[static_cast<std::size_t>(index) % std::size(kPalette)];
    const std::string style = "fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2\"" +
                              (series.dashed ? " stroke-dasharray=\"7 4\"" : "");
    out << "<polyline " << style << " points=\"";
    for (std::size_t k = 0; k < points[s].size(); ++k)
      out << (k ? " " : "") << px(mapX(points[s][k].first)) << ',' << px(mapY(points[s][k].second));
    out << "\"/>\n";
    if (points[s].size() == 1) // a single point draws no line
      out << "<circle cx=\"" << px(mapX(points[s][0].first)) << "\" cy=\"" << px(mapY(points[s][0].second))
          << "\" r=\"3\" fill=\"" << colour << "\"/>\n";
    out << "<line x1=\"" << px(right + 12) << "\" y1=\"" << px(legendY) << "\" x2=\"" << px(right + 40) << "\" y2=\""
        << px(legendY) << "\" " << style << "/>\n"
        << "<text x=\"" << px(right + 46) << "\" y=\"" << px(legendY + 4) << "\">" << escape(series.label)
        << "</text>\n";
    legendY += 20;
  }
  out << "</svg>\n";
  return out.str();
}

void SvgLinePlot::write(const std::filesystem::path& file) const { writeFileAtomically(file, svg()); }

} // namespace poro
