#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace assetlint {

// Parses a whole string as one floating-point number (leading '+' allowed, no spaces).
std::optional<double> parse_double(std::string_view text);
// Parses whitespace-separated numbers; nullopt if any token is not a number.
std::optional<std::vector<double>> parse_doubles(std::string_view text);
std::string_view trim(std::string_view text);

// Shortest decimal text that reads back as `value` at `significant` digits of precision
// (e.g. 275.86206896551727 at 3 digits -> "276", 0.0612 -> "0.0612"), never in
// exponent form for ordinary magnitudes.
std::string format_number(double value, int significant = 6);
// Like format_number, but never below `value` (adds digits until the text reads back ≥ value).
std::string format_number_at_least(double value, int significant = 6);
// `value` rounded up at `significant` digits (13.333 → "13.4" at 3): a bound that must
// not be undercut, written the way a person would.
std::string format_number_rounded_up(double value, int significant);
// Like format_number, but never above `value`.
std::string format_number_at_most(double value, int significant = 6);

// Half a unit in the last digit of the shortest text that reads back as `value` ("0.001437"
// → 5e-7, "3.781e-07" → 5e-11, "44" → 0.5): how far rounding to the written digits can have
// moved a number typed by hand. 0 for 0.
double half_unit_in_last_digit(double value);

// Width on screen: code points, not bytes ("N·m", "μ").
std::size_t columns(std::string_view text);

}  // namespace assetlint
