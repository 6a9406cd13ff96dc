#include "core/io/line_chart_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "core/io/xml_escape.h"

namespace autoblock {
namespace {

// A "nice" tick step giving about `count` ticks over span.
double tick_step(double span, int count) {
  const double raw = span / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (m * power >= raw) return m * power;
  }
  return 10 * power;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", std::fabs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

void draw_panel(std::ostringstream& svg, const ChartPanel& panel, double ox, double oy) {
  const double w = 560, h = 380, left = 62, right = 16, top = 30, bottom = 46;
  const double pw = w - left - right, ph = h - top - bottom;
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const ChartSeries& s : panel.series) {
    for (const auto& [x, y] : s.points) {
      x0 = std::min(x0, x);
      x1 = std::max(x1, x);
      y0 = std::min(y0, y);
      y1 = std::max(y1, y);
    }
  }
  for (const ChartReference& r : panel.references) {
    y0 = std::min(y0, r.y);
    y1 = std::max(y1, r.y);
  }
  if (!std::isfinite(x0)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (x1 <= x0) x1 = x0 + 1;
  if (y1 <= y0) y1 = y0 + 1;
  const double pad = 0.05 * (y1 - y0);
  y0 -= pad;
  y1 += pad;
  auto sx = [&](double x) { return ox + left + (x - x0) / (x1 - x0) * pw; };
  auto sy = [&](double y) { return oy + top + (y1 - y) / (y1 - y0) * ph; };
  svg << "<text x=\"" << ox + left << "\" y=\"" << oy + 20 << "\" font-family=\"sans-serif\" font-size=\"14\">"
      << xml_escape(panel.title) << "</text>\n";
  svg << "<rect x=\"" << ox + left << "\" y=\"" << oy + top << "\" width=\"" << pw << "\" height=\"" << ph
      << "\" fill=\"none\" stroke=\"#444\"/>\n";
  const double ystep = tick_step(y1 - y0, 6);
  for (double t = std::ceil(y0 / ystep) * ystep; t <= y1; t += ystep) {
    svg << "<line x1=\"" << ox + left << "\" x2=\"" << ox + left + pw << "\" y1=\"" << sy(t) << "\" y2=\"" << sy(t)
        << "\" stroke=\"#e4e4e4\"/><text x=\"" << ox + left - 6 << "\" y=\"" << sy(t) + 4
        << "\" text-anchor=\"end\" font-family=\"sans-serif\" font-size=\"11\">" << number(t) << "</text>\n";
  }
  const double xstep = tick_step(x1 - x0, 6);
  for (double t = std::ceil(x0 / xstep) * xstep; t <= x1; t += xstep) {
    svg << "<line x1=\"" << sx(t) << "\" x2=\"" << sx(t) << "\" y1=\"" << oy + top + ph << "\" y2=\"" << oy + top + ph + 4
        << "\" stroke=\"#444\"/><text x=\"" << sx(t) << "\" y=\"" << oy + top + ph + 17
        << "\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"11\">" << number(t) << "</text>\n";
  }
  svg << "<text x=\"" << ox + left + pw / 2 << "\" y=\"" << oy + h - 8
      << "\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"12\">" << xml_escape(panel.x_label) << "</text>\n";
  svg << "<text transform=\"translate(" << ox + 14 << "," << oy + top + ph / 2
      << ") rotate(-90)\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"12\">" << xml_escape(panel.y_label)
      << "</text>\n";
  int legend = 0;
  for (const ChartReference& r : panel.references) {
    svg << "<line x1=\"" << ox + left << "\" x2=\"" << ox + left + pw << "\" y1=\"" << sy(r.y) << "\" y2=\"" << sy(r.y)
        << "\" stroke=\"" << r.colour << "\" stroke-dasharray=\"6 4\" stroke-width=\"1.5\"/>\n";
  }
  for (const ChartSeries& s : panel.series) {
    if (s.points.empty()) continue;
    svg << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"1.6\" points=\"";
    for (const auto& [x, y] : s.points) svg << sx(x) << ',' << sy(y) << ' ';
    svg << "\"/>\n";
  }
  auto legend_entry = [&](const std::string& label, const std::string& colour, bool dashed) {
    const double ly = oy + top + 14 + 16 * legend++;
    svg << "<line x1=\"" << ox + left + 10 << "\" x2=\"" << ox + left + 34 << "\" y1=\"" << ly - 4 << "\" y2=\"" << ly - 4
        << "\" stroke=\"" << colour << "\" stroke-width=\"2\"" << (dashed ? " stroke-dasharray=\"6 4\"" : "")
        << "/><text x=\"" << ox + left + 40 << "\" y=\"" << ly
        << "\" font-family=\"sans-serif\" font-size=\"11\">" << xml_escape(label) << "</text>\n";
  };
  const size_t entries = panel.series.size() + panel.references.size();
  size_t longest = 0;
  for (const ChartSeries& s : panel.series) longest = std::max(longest, s.label.size());
  for (const ChartReference& r : panel.references) longest = std::max(longest, r.label.size());
  svg << "<rect x=\"" << ox + left + 4 << "\" y=\"" << oy + top + 3 << "\" width=\"" << 44 + 6.2 * static_cast<double>(longest)
      << "\" height=\"" << 16 * static_cast<double>(entries) + 6 << "\" fill=\"white\" fill-opacity=\"0.85\"/>\n";
  for (const ChartSeries& s : panel.series) legend_entry(s.label, s.colour, false);
  for (const ChartReference& r : panel.references) legend_entry(r.label, r.colour, true);
}

}  // namespace

std::string line_chart_svg(const std::vector<ChartPanel>& panels, const std::string& title) {
  const double w = 560, h = 380, head = 34;
  std::ostringstream svg;
  svg.precision(6);
  const double width = w * static_cast<double>(std::max<size_t>(1, panels.size())), height = h + head;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 "
      << width << ' ' << height << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"16\" y=\"24\" font-family=\"sans-serif\" font-size=\"16\">" << xml_escape(title) << "</text>\n";
  for (size_t p = 0; p < panels.size(); ++p) draw_panel(svg, panels[p], w * static_cast<double>(p), head);
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace autoblock
