// Short number formatting for messages and reports: the shortest text that reads back to the same
// double ("%.17g" trimmed), and a point as "(x, y)".
#pragma once

#include <string>

namespace autoblock {

// Inputs: v, any double. Output: the shortest decimal text that round-trips, e.g. "0.1", "3", "1e-12".
std::string format_number(double v);

// Inputs: x, y. Output: "(x, y)" with format_number for both.
std::string format_point(double x, double y);

}  // namespace autoblock
