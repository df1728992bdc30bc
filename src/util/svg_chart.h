#pragma once
// A small SVG line chart: panels stacked over one shared time axis, each with its own
// y axis, lines, horizontal markers and shaded intervals. Made to be read at 800 px:
// 14 px text, ticks at round numbers, a legend per panel.
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace assetlint {

struct ChartSeries {
  std::string label;
  std::string color;  // any SVG colour
  std::vector<double> x, y;
  bool dashed = false;
};

// A horizontal reference line (a target, a force limit).
struct ChartMarker {
  std::string label;
  std::string color;
  double y = 0;
};

// A shaded range of x (when a clamp was active).
struct ChartBand {
  double from = 0, to = 0;
  std::string color;
};

struct ChartPanel {
  std::string y_label;  // with its unit: "position (deg)"
  std::vector<ChartSeries> series;
  std::vector<ChartMarker> markers;
  std::vector<ChartBand> bands;
  std::string band_label;  // legend text of the bands ("max force clamps")
  // Fixed y range; otherwise from the markers and the series, clipped to `clip` when
  // a series runs away (a diverging spring), which the legend then says.
  std::optional<std::pair<double, double>> y_range;
  std::optional<std::pair<double, double>> clip;
};

struct Chart {
  std::string title;
  std::string x_label;  // "time (s)"
  double x_min = 0, x_max = 1;
  std::vector<ChartPanel> panels;
  int width = 800;
  int panel_height = 300;
};

// The chart as a standalone SVG document.
std::string render_svg(const Chart& chart);

// Round tick positions covering [lo, hi] (about `count` of them, steps of 1, 2 or 5 × 10ⁿ).
std::vector<double> nice_ticks(double lo, double hi, int count = 6);

}  // namespace assetlint
