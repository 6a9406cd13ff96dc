#include "core/common/format.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace autoblock {
namespace {

// Plain decimals from kSmallest (inclusive) to kLargest (exclusive) in magnitude.
constexpr double kSmallest = 1e-4;
constexpr double kLargest = 1e15;

// "1.500e+20" -> "1.5e20", "3e-07" -> "3e-7".
std::string tidy_scientific(const std::string& text) {
  const size_t e = text.find('e');
  std::string mantissa = text.substr(0, e);
  if (mantissa.find('.') != std::string::npos) {
    while (mantissa.back() == '0') mantissa.pop_back();
    if (mantissa.back() == '.') mantissa.pop_back();
  }
  std::string exponent = text.substr(e + 1);
  const bool negative = !exponent.empty() && exponent[0] == '-';
  if (!exponent.empty() && (exponent[0] == '-' || exponent[0] == '+')) exponent.erase(0, 1);
  while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
  return mantissa + "e" + (negative ? "-" : "") + exponent;
}

// "12.500" -> "12.5", "3.000" -> "3", "-0.000" -> "0".
std::string tidy_fixed(std::string text) {
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  if (text == "-0") text = "0";
  return text;
}

std::string print(const char* format, int precision, double v) {
  char buf[512];
  std::snprintf(buf, sizeof buf, format, precision, v);
  return buf;
}

}  // namespace

std::string format_number(double v, double tolerance) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  const double magnitude = std::fabs(v);
  const bool tolerant = tolerance > 0 && std::isfinite(tolerance);
  if (v == 0 || (tolerant && magnitude < tolerance)) return "0";
  const bool plain = magnitude >= kSmallest && magnitude < kLargest;
  if (tolerant) {
    // Digits after the point: the step 10^-decimals is the largest power of ten not above the tolerance.
    const int step_exponent = static_cast<int>(std::floor(std::log10(tolerance)));
    if (plain) {
      const int decimals = std::min(std::max(-step_exponent, 0), 20);
      if (step_exponent > 0) {  // a coarse tolerance: round to its power of ten before the point, too
        const double step = std::pow(10.0, step_exponent);
        v = std::round(v / step) * step;
      }
      return tidy_fixed(print("%.*f", decimals, v));
    }
    const int leading = static_cast<int>(std::floor(std::log10(magnitude)));
    const int digits = std::min(std::max(leading - step_exponent, 0), 16);
    return tidy_scientific(print("%.*e", digits, v));
  }
  if (plain) {
    for (int decimals = 0; decimals <= 25; ++decimals) {
      const std::string text = print("%.*f", decimals, v);
      if (std::strtod(text.c_str(), nullptr) == v) return tidy_fixed(text);
    }
  }
  std::string text;
  for (int digits = 0; digits <= 16; ++digits) {
    text = print("%.*e", digits, v);
    if (std::strtod(text.c_str(), nullptr) == v) break;
  }
  return tidy_scientific(text);
}

std::string format_significant(double v, int digits) {
  if (v == 0 || !std::isfinite(v)) return format_number(v);
  const int leading = static_cast<int>(std::floor(std::log10(std::fabs(v))));
  return format_number(v, std::pow(10.0, leading - std::max(digits, 1) + 1));
}

std::string format_point(double x, double y, double tolerance) {
  return "(" + format_number(x, tolerance) + ", " + format_number(y, tolerance) + ")";
}

std::string counted(long long n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural.empty() ? singular + "s" : plural);
}

std::string with_article(const std::string& word) {
  if (word.empty()) return word;
  const char first = static_cast<char>(std::tolower(static_cast<unsigned char>(word[0])));
  const bool vowel = first == 'a' || first == 'e' || first == 'i' || first == 'o' || first == 'u';
  return (vowel ? "an " : "a ") + word;
}

}  // namespace autoblock
