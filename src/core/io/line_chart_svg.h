// Line charts as SVG: panels with axes, ticks, labelled series and dashed reference lines.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace autoblock {

struct ChartSeries {
  std::string label;
  std::string colour;  // "#rrggbb"
  std::vector<std::pair<double, double>> points;
};

struct ChartReference {
  std::string label;
  std::string colour;
  double y = 0.0;
};

struct ChartPanel {
  std::string title, x_label, y_label;
  std::vector<ChartSeries> series;
  std::vector<ChartReference> references;  // dashed horizontal lines
};

// Inputs:  panels, drawn side by side; title, above them.
// Outputs: the SVG document (each panel 560 x 380 px).
std::string line_chart_svg(const std::vector<ChartPanel>& panels, const std::string& title);

}  // namespace autoblock
