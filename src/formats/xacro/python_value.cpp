#include "formats/xacro/python_value.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace assetlint::xacro {

Value Value::list(std::vector<Value> items, bool tuple) {
  Value v;
  v.data = std::make_shared<const ListValue>(ListValue{std::move(items), tuple});
  return v;
}

Value Value::dict(std::vector<std::pair<Value, Value>> items, bool dotted) {
  Value v;
  v.data = std::make_shared<const DictValue>(DictValue{std::move(items), dotted});
  return v;
}

std::string Value::type_name() const {
  if (is_none()) return "NoneType";
  if (is_bool()) return "bool";
  if (is_int()) return "int";
  if (is_float()) return "float";
  if (is_string()) return "str";
  if (is_list()) return as_list().tuple ? "tuple" : "list";
  if (is_dict()) return "dict";
  return "namespace";
}

bool Value::truthy() const {
  if (is_none()) return false;
  if (is_bool() || is_int()) return integer() != 0;
  if (is_float()) return number() != 0.0;
  if (is_string()) return !string().empty();
  if (is_list()) return !as_list().items.empty();
  if (is_dict()) return !as_dict().items.empty();
  return true;
}

bool python_equal(const Value& a, const Value& b) {
  if (a.is_number() && b.is_number()) {
    if (a.is_float() || b.is_float()) return a.number() == b.number();
    return a.integer() == b.integer();
  }
  if (a.data.index() != b.data.index()) return false;
  if (a.is_none()) return true;
  if (a.is_string()) return a.string() == b.string();
  if (a.is_list()) {
    const auto &x = a.as_list(), &y = b.as_list();
    if (x.tuple != y.tuple || x.items.size() != y.items.size()) return false;
    for (std::size_t i = 0; i < x.items.size(); ++i)
      if (!python_equal(x.items[i], y.items[i])) return false;
    return true;
  }
  if (a.is_dict()) {
    const auto &x = a.as_dict(), &y = b.as_dict();
    if (x.items.size() != y.items.size()) return false;
    for (const auto& [k, v] : x.items) {
      bool found = false;
      for (const auto& [k2, v2] : y.items)
        if (python_equal(k, k2)) found = python_equal(v, v2);
      if (!found) return false;
    }
    return true;
  }
  return std::get<NamespaceRef>(a.data) == std::get<NamespaceRef>(b.data);
}

std::string python_float(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
  if (value == 0.0) return std::signbit(value) ? "-0.0" : "0.0";
  // The shortest round-trip digits, then Python's layout: positional for 1e-4 <= |x| < 1e16,
  // scientific with a two-digit exponent otherwise.
  char buffer[64];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific);
  std::string text(buffer, end);
  const bool negative = text[0] == '-';
  if (negative) text.erase(0, 1);
  const std::size_t e = text.find('e');
  std::string digits = text.substr(0, e);
  const int exponent = std::atoi(text.c_str() + e + 1);
  digits.erase(std::remove(digits.begin(), digits.end(), '.'), digits.end());
  std::string out;
  if (exponent >= -4 && exponent < 16) {
    if (exponent < 0) {
      out = "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
    } else if (static_cast<std::size_t>(exponent) + 1 >= digits.size()) {
      out = digits + std::string(static_cast<std::size_t>(exponent) + 1 - digits.size(), '0') + ".0";
    } else {
      out = digits.substr(0, static_cast<std::size_t>(exponent) + 1) + "." + digits.substr(static_cast<std::size_t>(exponent) + 1);
    }
  } else {
    out = digits.substr(0, 1);
    if (digits.size() > 1) out += "." + digits.substr(1);
    out += fmt::format("e{}{:02d}", exponent < 0 ? '-' : '+', std::abs(exponent));
  }
  return negative ? "-" + out : out;
}

namespace {

std::string quote(const std::string& s) {
  // Python prefers single quotes, double when the text holds a single quote and no double.
  const bool use_double = s.find('\'') != std::string::npos && s.find('"') == std::string::npos;
  const char q = use_double ? '"' : '\'';
  std::string out(1, q);
  for (char c : s) {
    if (c == '\\') out += "\\\\";
    else if (c == q) out += std::string("\\") + q;
    else if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (c == '\r') out += "\\r";
    else out += c;
  }
  return out + q;
}

}  // namespace

std::string python_repr(const Value& value) {
  if (value.is_string()) return quote(value.string());
  if (value.is_list()) {
    const ListValue& list = value.as_list();
    std::string out = list.tuple ? "(" : "[";
    for (std::size_t i = 0; i < list.items.size(); ++i) out += (i ? ", " : "") + python_repr(list.items[i]);
    if (list.tuple && list.items.size() == 1) out += ",";
    return out + (list.tuple ? ")" : "]");
  }
  if (value.is_dict()) {
    std::string out = "{";
    bool first = true;
    for (const auto& [k, v] : value.as_dict().items) {
      out += (first ? "" : ", ") + python_repr(k) + ": " + python_repr(v);
      first = false;
    }
    return out + "}";
  }
  return python_str(value);
}

std::string python_str(const Value& value) {
  if (value.is_none()) return "None";
  if (value.is_bool()) return std::get<bool>(value.data) ? "True" : "False";
  if (value.is_int()) return std::to_string(value.integer());
  if (value.is_float()) return python_float(value.number());
  if (value.is_string()) return value.string();
  if (value.is_namespace()) return "<namespace>";
  return python_repr(value);
}

namespace {

std::string_view strip(std::string_view text) {
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; };
  while (!text.empty() && space(text.front())) text.remove_prefix(1);
  while (!text.empty() && space(text.back())) text.remove_suffix(1);
  return text;
}

}  // namespace

std::optional<std::int64_t> python_int_literal(std::string_view text) {
  text = strip(text);
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  if (text.empty() || text.find('_') != std::string_view::npos) return std::nullopt;
  std::int64_t value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<double> python_float_literal(std::string_view text) {
  text = strip(text);
  if (text.empty() || text.find('_') != std::string_view::npos) return std::nullopt;
  std::string_view body = text;
  if (body[0] == '+' || body[0] == '-') body.remove_prefix(1);
  std::string lower(body);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool negative = text[0] == '-';
  if (lower == "inf" || lower == "infinity") return negative ? -HUGE_VAL : HUGE_VAL;
  if (lower == "nan") return std::nan("");
  // Digits, at most one point, an optional exponent: what float() reads (no hex, no "1e").
  bool digit = false, point = false;
  std::size_t i = 0;
  for (; i < body.size() && (std::isdigit(static_cast<unsigned char>(body[i])) || (body[i] == '.' && !point)); ++i) {
    if (body[i] == '.') point = true;
    else digit = true;
  }
  if (!digit) return std::nullopt;
  if (i < body.size() && (body[i] == 'e' || body[i] == 'E')) {
    ++i;
    if (i < body.size() && (body[i] == '+' || body[i] == '-')) ++i;
    if (i >= body.size() || !std::isdigit(static_cast<unsigned char>(body[i]))) return std::nullopt;
    while (i < body.size() && std::isdigit(static_cast<unsigned char>(body[i]))) ++i;
  }
  if (i != body.size()) return std::nullopt;
  double value = 0;
  auto [end, ec] = std::from_chars(text.data() + (text[0] == '+' ? 1 : 0), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range) return negative ? -HUGE_VAL : HUGE_VAL;
  if (ec != std::errc()) return std::nullopt;
  return value;
}

}  // namespace assetlint::xacro
