#include "util/svg_chart.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/numbers.h"

namespace assetlint {
namespace {

constexpr int kLeft = 86, kRight = 24, kTop = 44, kPanelGap = 64, kBottom = 56, kLegendRow = 20;

std::string escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string num(double v) { return fmt::format("{:.2f}", v); }

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return !(lo <= hi); }
};

Range y_range_of(const ChartPanel& panel, bool& clipped) {
  clipped = false;
  if (panel.y_range) return Range{panel.y_range->first, panel.y_range->second};
  Range r;
  for (const auto& m : panel.markers) r.add(m.y);
  for (const auto& s : panel.series)
    for (double v : s.y) {
      if (panel.clip && (v < panel.clip->first || v > panel.clip->second || !std::isfinite(v))) {
        clipped = true;
        continue;
      }
      r.add(v);
    }
  if (r.empty()) r = Range{0, 1};
  if (r.hi - r.lo < 1e-12 * std::max(1.0, std::abs(r.hi))) {
    r.lo -= 1;
    r.hi += 1;
  }
  const double pad = 0.06 * (r.hi - r.lo);
  return Range{r.lo - pad, r.hi + pad};
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int count) {
  std::vector<double> ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  const double raw = (hi - lo) / std::max(1, count);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double factor : {1.0, 2.0, 5.0, 10.0})
    if (factor * magnitude >= raw) {
      step = factor * magnitude;
      break;
    }
  for (double t = std::ceil(lo / step) * step; t <= hi + step * 1e-9; t += step)
    ticks.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  return ticks;
}

std::string render_svg(const Chart& chart) {
  const int plot_w = chart.width - kLeft - kRight;
  std::vector<int> legend_rows;
  int height = kTop;
  for (const auto& panel : chart.panels) {
    const int rows = static_cast<int>(panel.series.size() + panel.markers.size() + (panel.bands.empty() ? 0 : 1));
    legend_rows.push_back((rows + 1) / 2);
    height += chart.panel_height + kPanelGap + legend_rows.back() * kLegendRow;
  }
  height += kBottom - kPanelGap;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"DejaVu Sans, Arial, sans-serif\" font-size=\"14\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text x=\"{2}\" y=\"26\" font-size=\"17\" font-weight=\"bold\">{3}</text>\n",
      chart.width, height, kLeft, escape(chart.title));
  const double x_span = chart.x_max > chart.x_min ? chart.x_max - chart.x_min : 1.0;
  const auto sx = [&](double x) { return kLeft + (x - chart.x_min) / x_span * plot_w; };
  int top = kTop;
  for (std::size_t p = 0; p < chart.panels.size(); ++p) {
    const ChartPanel& panel = chart.panels[p];
    bool clipped = false;
    const Range yr = y_range_of(panel, clipped);
    const int h = chart.panel_height;
    const auto sy = [&](double y) { return top + h - (y - yr.lo) / (yr.hi - yr.lo) * h; };
    const std::string clip_id = fmt::format("panel{}", p);
    svg += fmt::format("<clipPath id=\"{}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>\n", clip_id,
                       kLeft, top, plot_w, h);
    for (const auto& band : panel.bands)
      svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\" fill-opacity=\"0.18\"/>\n",
                         num(sx(band.from)), top, num(std::max(1.0, sx(band.to) - sx(band.from))), h, band.color);
    // Grid and ticks.
    for (double t : nice_ticks(yr.lo, yr.hi, 6))
      svg += fmt::format(
          "<line x1=\"{0}\" x2=\"{1}\" y1=\"{2}\" y2=\"{2}\" stroke=\"#dddddd\"/>"
          "<text x=\"{3}\" y=\"{4}\" text-anchor=\"end\">{5}</text>\n",
          kLeft, kLeft + plot_w, num(sy(t)), kLeft - 6, num(sy(t) + 5), escape(format_number(t, 4)));
    for (double t : nice_ticks(chart.x_min, chart.x_max, 8))
      svg += fmt::format(
          "<line x1=\"{0}\" x2=\"{0}\" y1=\"{1}\" y2=\"{2}\" stroke=\"#dddddd\"/>"
          "<text x=\"{0}\" y=\"{3}\" text-anchor=\"middle\">{4}</text>\n",
          num(sx(t)), top, top + h, top + h + 18, escape(format_number(t, 4)));
    svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#333333\"/>\n", kLeft,
                       top, plot_w, h);
    svg += fmt::format("<text transform=\"translate({},{}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n", 18,
                       top + h / 2, escape(panel.y_label));
    svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", kLeft + plot_w / 2, top + h + 38,
                       escape(chart.x_label));
    for (const auto& marker : panel.markers)
      svg += fmt::format(
          "<line x1=\"{0}\" x2=\"{1}\" y1=\"{2}\" y2=\"{2}\" stroke=\"{3}\" stroke-width=\"1.5\" "
          "stroke-dasharray=\"8 4\" clip-path=\"url(#{4})\"/>\n",
          kLeft, kLeft + plot_w, num(sy(marker.y)), marker.color, clip_id);
    for (const auto& series : panel.series) {
      // A polyline per finite run; points outside the clip range break it too.
      std::string points;
      const auto flush = [&] {
        if (points.empty()) return;
        svg += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\"{} clip-path=\"url(#{})\" points=\"{}\"/>\n",
                           series.color, series.dashed ? " stroke-dasharray=\"6 3\"" : "", clip_id, points);
        points.clear();
      };
      for (std::size_t i = 0; i < series.x.size() && i < series.y.size(); ++i) {
        const double y = series.y[i];
        const bool out = !std::isfinite(y) || (panel.clip && (y < panel.clip->first || y > panel.clip->second));
        if (out) {
          flush();
          continue;
        }
        points += fmt::format("{}{},{}", points.empty() ? "" : " ", num(sx(series.x[i])), num(sy(y)));
      }
      flush();
    }
    // Legend under the panel, two columns.
    std::vector<std::pair<std::string, std::string>> entries;  // colour, text
    std::vector<int> kinds;                                    // 0 line, 1 dashed, 2 band
    for (const auto& s : panel.series) {
      entries.emplace_back(s.color, s.label);
      kinds.push_back(s.dashed ? 1 : 0);
    }
    for (const auto& m : panel.markers) {
      if (m.label.empty()) continue;  // a second line of the same marker (−max force)
      entries.emplace_back(m.color, m.label);
      kinds.push_back(1);
    }
    if (!panel.bands.empty()) {
      entries.emplace_back(panel.bands.front().color, panel.band_label);
      kinds.push_back(2);
    }
    const int legend_top = top + h + 50;
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const int x = kLeft + static_cast<int>(i % 2) * (plot_w / 2);
      const int y = legend_top + static_cast<int>(i / 2) * kLegendRow;
      if (kinds[i] == 2)
        svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"24\" height=\"12\" fill=\"{}\" fill-opacity=\"0.35\"/>", x,
                           y - 10, entries[i].first);
      else
        svg += fmt::format("<line x1=\"{0}\" x2=\"{1}\" y1=\"{2}\" y2=\"{2}\" stroke=\"{3}\" stroke-width=\"2\"{4}/>",
                           x, x + 24, y - 4, entries[i].first, kinds[i] == 1 ? " stroke-dasharray=\"6 3\"" : "");
      svg += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", x + 32, y + 1, escape(entries[i].second));
    }
    if (clipped)
      svg += fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#b00020\" text-anchor=\"end\">some values off scale (not drawn)</text>\n",
                         kLeft + plot_w - 6, top + 18);
    top += h + kPanelGap + legend_rows[p] * kLegendRow;
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace assetlint
