// Numbers and counts as people read them in messages and reports.
//
// Numbers: plain decimals as a CAD user writes them ("80", "2.5", "-0.125"), rounded to a tolerance
// when one is given (noise below it reads "0"), and scientific notation ("1.5e20", "3e-7") only for
// values of magnitude 1e15 and above or below 1e-4. Counts: "1 cut", "3 cuts". Articles: "an edge".
#pragma once

#include <string>

namespace autoblock {

// Inputs:  v, any double; tolerance >= 0, the size below which differences are noise (0: none, v
//          is printed exactly: the shortest text that reads back to the same double).
// Output:  v as text. With a tolerance, v is rounded to the largest power of ten not above the
//          tolerance and |v| < tolerance prints "0"; never "-0". Examples: (80) -> "80",
//          (0.1) -> "0.1", (-2.22e-15, 1e-5) -> "0", (83.0000001, 1e-5) -> "83", (1e20) -> "1e20",
//          (2.5e-9) -> "2.5e-9", (8.3e-6, 8.3e-9) -> "8.3e-6".
std::string format_number(double v, double tolerance = 0.0);

// Inputs: v; digits >= 1. Output: v rounded to that many significant digits, printed by
// format_number: (0.61234, 3) -> "0.612", (12345.6, 4) -> "12350".
std::string format_significant(double v, int digits);

// Inputs: x, y; tolerance as for format_number. Output: "(x, y)".
std::string format_point(double x, double y, double tolerance = 0.0);

// Inputs: n; singular ("cut"); plural (empty: singular + "s"). Output: "1 cut", "0 cuts", "2 cuts".
std::string counted(long long n, const std::string& singular, const std::string& plural = "");

// Inputs: word ("edge", "solid"). Output: the word with its indefinite article: "an edge", "a solid"
// (by the first letter: a, e, i, o, u take "an").
std::string with_article(const std::string& word);

}  // namespace autoblock
