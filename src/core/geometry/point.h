// Plain 2-D value types: a point and an axis-aligned box.
#pragma once

#include <algorithm>

namespace autoblock {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
};

inline bool operator==(const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }

struct Box {
  double xmin = 0.0, ymin = 0.0, xmax = 0.0, ymax = 0.0;
  double width() const { return xmax - xmin; }
  double height() const { return ymax - ymin; }
  double longer_side() const { return std::max(width(), height()); }
  double shorter_side() const { return std::min(width(), height()); }
  // Longer over shorter side: 1 for a square, grows as the box gets thinner.
  double aspect_ratio() const { return longer_side() / shorter_side(); }
  double area() const { return width() * height(); }
};

}  // namespace autoblock
