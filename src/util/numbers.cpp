#include "util/numbers.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdio>

namespace assetlint {

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

std::optional<double> parse_double(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

std::optional<std::vector<double>> parse_doubles(std::string_view text) {
  std::vector<double> values;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const auto begin = text.find_first_not_of(" \t\r\n", pos);
    if (begin == std::string_view::npos) break;
    auto end = text.find_first_of(" \t\r\n", begin);
    if (end == std::string_view::npos) end = text.size();
    auto value = parse_double(text.substr(begin, end - begin));
    if (!value) return std::nullopt;
    values.push_back(*value);
    pos = end;
  }
  return values;
}

std::string format_number(double value, int significant) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (value == 0.0) return "0";
  char buffer[64];
  // Round to the requested precision first, then print that rounded value in plain
  // positional notation with no trailing zeros.
  std::snprintf(buffer, sizeof buffer, "%.*e", significant - 1, value);
  const double rounded = std::strtod(buffer, nullptr);
  const double magnitude = std::fabs(rounded);
  if (magnitude >= 1e-4 && magnitude < 1e7) {
    const int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
    const int decimals = std::max(0, significant - 1 - exponent);
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, rounded);
    std::string text = buffer;
    if (text.find('.') != std::string::npos) {
      while (text.back() == '0') text.pop_back();
      if (text.back() == '.') text.pop_back();
    }
    if (text == "-0") text = "0";
    return text;
  }
  // Tiny or huge: exponent form, with a trimmed mantissa.
  std::string text = buffer;
  const auto e = text.find('e');
  std::string mantissa = text.substr(0, e);
  if (mantissa.find('.') != std::string::npos) {
    while (mantissa.back() == '0') mantissa.pop_back();
    if (mantissa.back() == '.') mantissa.pop_back();
  }
  const int exponent = std::atoi(text.c_str() + e + 1);
  return mantissa + "e" + std::to_string(exponent);
}

std::string format_number_at_least(double value, int significant) {
  for (int digits = significant; digits < 17; ++digits) {
    std::string text = format_number(value, digits);
    // Within 1e-9 counts as equal: the value itself carries rounding error.
    if (auto back = parse_double(text); back && *back >= value - 1e-9 * std::fabs(value)) return text;
  }
  return format_number(value, 17);
}

std::string format_number_rounded_up(double value, int significant) {
  if (value <= 0 || !std::isfinite(value)) return format_number(value, significant);
  const double step = std::pow(10.0, std::floor(std::log10(value)) - significant + 1);
  // Values already on a step (20.000000000000004) stay where they are.
  const double up = std::ceil(value / step - 1e-9) * step;
  return format_number(up, significant);
}

std::string format_number_at_most(double value, int significant) {
  for (int digits = significant; digits < 17; ++digits) {
    std::string text = format_number(value, digits);
    if (auto back = parse_double(text); back && *back <= value + 1e-9 * std::fabs(value)) return text;
  }
  return format_number(value, 17);
}

double half_unit_in_last_digit(double value) {
  if (value == 0) return 0.0;
  const std::string text = fmt::format("{}", std::fabs(value));
  const auto e = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, e);
  const int exponent = e == std::string::npos ? 0 : std::stoi(text.substr(e + 1));
  const auto dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  return 0.5 * std::pow(10.0, exponent - decimals);
}

std::size_t columns(std::string_view text) {
  std::size_t n = 0;
  for (unsigned char c : text) n += (c & 0xC0) != 0x80;
  return n;
}

}  // namespace assetlint
