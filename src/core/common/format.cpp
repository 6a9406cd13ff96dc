#include "core/common/format.h"

#include <cstdio>
#include <cstdlib>

namespace autoblock {

std::string format_number(double v) {
  char buf[64];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string format_point(double x, double y) {
  return "(" + format_number(x) + ", " + format_number(y) + ")";
}

}  // namespace autoblock
