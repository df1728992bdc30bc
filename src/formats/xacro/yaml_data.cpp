#include "formats/xacro/yaml_data.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <regex>

namespace assetlint::xacro {
namespace {

// PyYAML's implicit resolvers for plain scalars (YAML 1.1).
Value resolve_plain(const std::string& s) {
  static const std::regex kBool("yes|Yes|YES|no|No|NO|true|True|TRUE|false|False|FALSE|on|On|ON|off|Off|OFF");
  static const std::regex kNull("~|null|Null|NULL|");
  static const std::regex kInt("[-+]?0b[0-1_]+|[-+]?0[0-7_]+|[-+]?(?:0|[1-9][0-9_]*)|[-+]?0x[0-9a-fA-F_]+");
  static const std::regex kFloat(
      "[-+]?(?:[0-9][0-9_]*)\\.[0-9_]*(?:[eE][-+][0-9]+)?|\\.[0-9_]+(?:[eE][-+][0-9]+)?|[-+]?\\.(?:inf|Inf|INF)|\\.(?:nan|NaN|NAN)");
  if (std::regex_match(s, kBool)) {
    const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
    return Value(c == 'y' || c == 't' || (c == 'o' && (s[1] == 'n' || s[1] == 'N')));
  }
  if (std::regex_match(s, kNull)) return Value();
  if (std::regex_match(s, kInt)) {
    std::string digits;
    for (char c : s)
      if (c != '_') digits += c;
    bool negative = false;
    std::size_t at = 0;
    if (digits[0] == '+' || digits[0] == '-') {
      negative = digits[0] == '-';
      at = 1;
    }
    int base = 10;
    if (digits.compare(at, 2, "0b") == 0) base = 2, at += 2;
    else if (digits.compare(at, 2, "0x") == 0) base = 16, at += 2;
    else if (digits.size() > at + 1 && digits[at] == '0') base = 8, at += 1;
    errno = 0;
    const long long v = std::strtoll(digits.c_str() + at, nullptr, base);
    if (errno == ERANGE) throw EvalError(fmt::format("YAML integer {} is beyond 64 bits", s));
    return Value(static_cast<std::int64_t>(negative ? -v : v));
  }
  if (std::regex_match(s, kFloat)) {
    std::string digits;
    for (char c : s)
      if (c != '_') digits += c;
    std::string lower = digits;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower.find("inf") != std::string::npos) return Value(lower[0] == '-' ? -HUGE_VAL : HUGE_VAL);
    if (lower.find("nan") != std::string::npos) return Value(std::nan(""));
    return Value(std::strtod(digits.c_str(), nullptr));
  }
  return Value(s);
}

double unit_factor(const std::string& tag) {
  if (tag == "!radians" || tag == "!meters") return 1.0;
  if (tag == "!degrees") return M_PI / 180.0;
  if (tag == "!millimeters") return 0.001;
  if (tag == "!foot") return 0.3048;
  if (tag == "!inches") return 0.0254;
  return 0.0;
}

Value convert(const YAML::Node& node, const std::function<Value(const std::string&)>& evaluate, int depth) {
  if (depth > 200) throw EvalError("YAML nested too deeply");
  switch (node.Type()) {
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined: return Value();
    case YAML::NodeType::Scalar: {
      const std::string& tag = node.Tag();
      if (const double factor = unit_factor(tag); factor != 0.0) {
        const Value v = evaluate(node.Scalar());
        if (!v.is_number()) throw EvalError(fmt::format("invalid expression: {}", node.Scalar()));
        return Value(v.number() * factor);
      }
      if (tag == "?") return resolve_plain(node.Scalar());
      if (tag == "!" || tag == "tag:yaml.org,2002:str") return Value(node.Scalar());
      if (tag == "tag:yaml.org,2002:int" || tag == "tag:yaml.org,2002:float" || tag == "tag:yaml.org,2002:bool" ||
          tag == "tag:yaml.org,2002:null")
        return resolve_plain(node.Scalar());
      throw EvalError(fmt::format("could not determine a constructor for the tag '{}'", tag));
    }
    case YAML::NodeType::Sequence: {
      std::vector<Value> items;
      for (const auto& item : node) items.push_back(convert(item, evaluate, depth + 1));
      return Value::list(std::move(items));
    }
    case YAML::NodeType::Map: {
      std::vector<std::pair<Value, Value>> items;
      for (const auto& kv : node) {
        Value key = convert(kv.first, evaluate, depth + 1);
        Value value = convert(kv.second, evaluate, depth + 1);
        auto same = std::find_if(items.begin(), items.end(), [&](const auto& e) { return python_equal(e.first, key); });
        if (same != items.end()) same->second = std::move(value);
        else items.emplace_back(std::move(key), std::move(value));
      }
      return Value::dict(std::move(items), true);
    }
  }
  return Value();
}

}  // namespace

Value parse_yaml(const std::string& text, const std::function<Value(const std::string&)>& evaluate) {
  try {
    const YAML::Node root = YAML::Load(text);
    return convert(root, evaluate, 0);
  } catch (const YAML::Exception& e) {
    throw EvalError(fmt::format("YAML: {}", e.what()));
  }
}

}  // namespace assetlint::xacro
