#pragma once
// The values of xacro's `${…}` expressions: the few Python types xacro's expressions produce
// (None, bool, int, float, str, list, tuple, dict), printed as Python's str() prints them,
// since that text is what lands in the expanded URDF.
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace assetlint::xacro {

struct Value;
struct ListValue {
  std::vector<Value> items;
  bool tuple = false;
};
struct DictValue {
  std::vector<std::pair<Value, Value>> items;  // insertion order, as Python keeps it
  bool dotted = false;                          // keys readable as attributes (YAML data, xacro.dotify)
};
// A namespace of properties (an include with `ns`), reached as `ns.name` in expressions.
struct NamespaceRef {
  const void* table = nullptr;
  bool operator==(const NamespaceRef&) const = default;
};

struct Value {
  using None = std::monostate;
  std::variant<None, bool, std::int64_t, double, std::string, std::shared_ptr<const ListValue>,
               std::shared_ptr<const DictValue>, NamespaceRef>
      data;

  Value() = default;
  Value(bool b) : data(b) {}
  Value(std::int64_t i) : data(i) {}
  Value(int i) : data(static_cast<std::int64_t>(i)) {}
  Value(double d) : data(d) {}
  Value(std::string s) : data(std::move(s)) {}
  Value(const char* s) : data(std::string(s)) {}
  static Value list(std::vector<Value> items, bool tuple = false);
  static Value dict(std::vector<std::pair<Value, Value>> items, bool dotted = false);
  static Value ns(const void* table) {
    Value v;
    v.data = NamespaceRef{table};
    return v;
  }

  bool is_none() const { return std::holds_alternative<None>(data); }
  bool is_bool() const { return std::holds_alternative<bool>(data); }
  bool is_int() const { return std::holds_alternative<std::int64_t>(data); }
  bool is_float() const { return std::holds_alternative<double>(data); }
  bool is_number() const { return is_bool() || is_int() || is_float(); }
  bool is_string() const { return std::holds_alternative<std::string>(data); }
  bool is_list() const { return std::holds_alternative<std::shared_ptr<const ListValue>>(data); }
  bool is_dict() const { return std::holds_alternative<std::shared_ptr<const DictValue>>(data); }
  bool is_namespace() const { return std::holds_alternative<NamespaceRef>(data); }

  const std::string& string() const { return std::get<std::string>(data); }
  const ListValue& as_list() const { return *std::get<std::shared_ptr<const ListValue>>(data); }
  const DictValue& as_dict() const { return *std::get<std::shared_ptr<const DictValue>>(data); }
  // bool and int as int (Python's bool is an int).
  std::int64_t integer() const { return is_bool() ? (std::get<bool>(data) ? 1 : 0) : std::get<std::int64_t>(data); }
  double number() const { return is_float() ? std::get<double>(data) : static_cast<double>(integer()); }

  // Python's type name, for messages ("str", "float", …).
  std::string type_name() const;
  bool truthy() const;
};

// An error in an expression, with Python's wording where xacro shows Python's.
struct EvalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

bool python_equal(const Value& a, const Value& b);
// Python's str(value) and repr(value).
std::string python_str(const Value& value);
std::string python_repr(const Value& value);
// Python's repr of a float: the shortest text that reads back to the same double.
std::string python_float(double value);

// What Python's int() and float() accept from a string (surrounding whitespace allowed);
// nullopt otherwise.
std::optional<std::int64_t> python_int_literal(std::string_view text);
std::optional<double> python_float_literal(std::string_view text);

}  // namespace assetlint::xacro
