#include "hinf/common/number_text.hpp"

#include <cmath>
#include <cstdio>
#include <charconv>

namespace hinf {

std::string number_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (value == 0) return std::signbit(value) ? "-0" : "0";
  // fewest significant digits that read back exactly: std::to_chars's shortest
  // round-trip form, in scientific notation so that its mantissa holds just those digits
  char buf[48];
  const std::to_chars_result shortest =
      std::to_chars(buf, buf + sizeof buf, value, std::chars_format::scientific);
  int digits = 0;
  for (const char* c = buf; c != shortest.ptr && *c != 'e'; ++c) digits += (*c >= '0' && *c <= '9');
  // %g switches to an exponent once the exponent reaches the digit count ("1e+01" for 10);
  // integers and plain decimals up to 1e15 read better without one.
  const int exponent = static_cast<int>(std::floor(std::log10(std::abs(value))));
  if (exponent >= digits && exponent < 16) digits = exponent + 1;
  std::snprintf(buf, sizeof buf, "%.*g", digits, value);
  // "7.2722e-05" -> "7.2722e-5", "1e+20" -> "1e20"
  std::string text = buf;
  const size_t e = text.find('e');
  if (e != std::string::npos) {
    std::string mantissa = text.substr(0, e);
    std::string exp = text.substr(e + 1);
    const bool negative = exp[0] == '-';
    size_t first = 1;
    while (first + 1 < exp.size() && exp[first] == '0') ++first;
    text = mantissa + "e" + (negative ? "-" : "") + exp.substr(first);
  }
  return text;
}

bool is_decimal_number(const std::string& s) {
  const auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
  size_t i = 0;
  const size_t n = s.size();
  if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
  size_t int_digits = 0, frac_digits = 0;
  while (i < n && is_digit(s[i])) ++i, ++int_digits;
  if (i < n && s[i] == '.') {
    ++i;
    while (i < n && is_digit(s[i])) ++i, ++frac_digits;
  }
  if (int_digits == 0 && frac_digits == 0) return false;
  if (i < n && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    size_t exp_digits = 0;
    while (i < n && is_digit(s[i])) ++i, ++exp_digits;
    if (exp_digits == 0) return false;
  }
  return i == n;
}

std::string significant_text(double value, int digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, value);
  return buf;
}

std::string duration_text(double seconds) {
  char buf[32];
  if (seconds < 100) std::snprintf(buf, sizeof buf, "%.2g s", seconds);
  else if (seconds < 6000) std::snprintf(buf, sizeof buf, "%.2g min", seconds / 60);
  else std::snprintf(buf, sizeof buf, "%.2g h", seconds / 3600);
  return buf;
}

}  // namespace hinf
