#include "formats/xacro/expression.h"

#include "formats/xacro/expression_syntax.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>

namespace assetlint::xacro {
namespace {

// ---------------------------------------------------------------------------------------
// Evaluation

[[noreturn]] void type_error(std::string message) { fail("TypeError: " + std::move(message)); }

std::int64_t checked(long double exact, const char* what) {
  if (exact > static_cast<long double>(std::numeric_limits<std::int64_t>::max()) ||
      exact < static_cast<long double>(std::numeric_limits<std::int64_t>::min()))
    fail(fmt::format("{}: integer result beyond 64 bits", what));
  return static_cast<std::int64_t>(exact);
}

double python_mod(double a, double b) {
  double r = std::fmod(a, b);
  if (r != 0 && ((r < 0) != (b < 0))) r += b;
  return r;
}

Value repeat(const Value& sequence, std::int64_t times) {
  times = std::max<std::int64_t>(times, 0);
  if (sequence.is_string()) {
    const std::string& s = sequence.string();
    if (!s.empty() && static_cast<std::size_t>(times) > kMaxExpressionResult / s.size())
      fail(fmt::format("string of {} × {} characters exceeds the {} MiB an expression may build", s.size(), times,
                       kMaxExpressionResult >> 20));
    std::string out;
    out.reserve(s.size() * static_cast<std::size_t>(times));
    for (std::int64_t i = 0; i < times; ++i) out += s;
    return Value(std::move(out));
  }
  const ListValue& l = sequence.as_list();
  if (!l.items.empty() && static_cast<std::size_t>(times) > kMaxExpressionResult / l.items.size() / 16)
    fail("list repetition exceeds what an expression may build");
  std::vector<Value> out;
  for (std::int64_t i = 0; i < times; ++i) out.insert(out.end(), l.items.begin(), l.items.end());
  return Value::list(std::move(out), l.tuple);
}

Value binary(const std::string& op, const Value& a, const Value& b) {
  if (op == "+") {
    if (a.is_number() && b.is_number()) {
      if (a.is_float() || b.is_float()) return Value(a.number() + b.number());
      return Value(checked(static_cast<long double>(a.integer()) + b.integer(), "+"));
    }
    if (a.is_string() && b.is_string()) {
      if (a.string().size() + b.string().size() > kMaxExpressionResult)
        fail(fmt::format("string longer than the {} MiB an expression may build", kMaxExpressionResult >> 20));
      return Value(a.string() + b.string());
    }
    if (a.is_list() && b.is_list() && a.as_list().tuple == b.as_list().tuple) {
      if (a.as_list().items.size() + b.as_list().items.size() > kMaxExpressionResult / 16)
        fail("list longer than an expression may build");
      std::vector<Value> items = a.as_list().items;
      items.insert(items.end(), b.as_list().items.begin(), b.as_list().items.end());
      return Value::list(std::move(items), a.as_list().tuple);
    }
    type_error(fmt::format("unsupported operand type(s) for +: '{}' and '{}'", a.type_name(), b.type_name()));
  }
  if (op == "*") {
    if (a.is_number() && b.is_number()) {
      if (a.is_float() || b.is_float()) return Value(a.number() * b.number());
      return Value(checked(static_cast<long double>(a.integer()) * b.integer(), "*"));
    }
    if ((a.is_string() || a.is_list()) && (b.is_int() || b.is_bool())) return repeat(a, b.integer());
    if ((b.is_string() || b.is_list()) && (a.is_int() || a.is_bool())) return repeat(b, a.integer());
    if (a.is_string() || b.is_string())
      type_error(fmt::format("can't multiply sequence by non-int of type '{}'", (a.is_string() ? b : a).type_name()));
    type_error(fmt::format("unsupported operand type(s) for *: '{}' and '{}'", a.type_name(), b.type_name()));
  }
  if (!a.is_number() || !b.is_number()) {
    if (op == "%" && a.is_string()) unsupported("string formatting with %");
    type_error(fmt::format("unsupported operand type(s) for {}: '{}' and '{}'", op, a.type_name(), b.type_name()));
  }
  const bool ints = !a.is_float() && !b.is_float();
  if (op == "-") {
    if (ints) return Value(checked(static_cast<long double>(a.integer()) - b.integer(), "-"));
    return Value(a.number() - b.number());
  }
  if (op == "/") {
    if (b.number() == 0) fail("ZeroDivisionError: division by zero");
    return Value(a.number() / b.number());
  }
  if (op == "//" || op == "%") {
    if (b.number() == 0) fail(op == "//" ? "ZeroDivisionError: integer division or modulo by zero" : "ZeroDivisionError: modulo by zero");
    if (ints) {
      const std::int64_t x = a.integer(), y = b.integer();
      if (x == std::numeric_limits<std::int64_t>::min() && y == -1) fail("integer result beyond 64 bits");
      std::int64_t q = x / y, r = x % y;
      if (r != 0 && ((r < 0) != (y < 0))) {
        --q;
        r += y;
      }
      return op == "//" ? Value(q) : Value(r);
    }
    const double r = python_mod(a.number(), b.number());
    if (op == "%") return Value(r);
    // Python's float floor division: from the remainder, so that a == b·q + r holds.
    const double div = (a.number() - r) / b.number();
    double q = std::floor(div);
    if (div - q > 0.5) q += 1.0;
    return Value(q);
  }
  if (op == "**") {
    if (ints && b.integer() >= 0) {
      long double result = 1;
      const long double base = static_cast<long double>(a.integer());
      for (std::int64_t i = 0; i < b.integer(); ++i) {
        result *= base;
        if (std::fabs(result) > 9.3e18L) fail("**: integer result beyond 64 bits");
        if (result == 0 || result == 1) break;
      }
      if (result == 1 && a.integer() == -1) result = b.integer() % 2 ? -1 : 1;
      return Value(checked(result, "**"));
    }
    if (a.number() == 0 && b.number() < 0) fail("ZeroDivisionError: 0.0 cannot be raised to a negative power");
    const double r = std::pow(a.number(), b.number());
    if (std::isnan(r) && !std::isnan(a.number()) && !std::isnan(b.number())) unsupported("complex result of **");
    if (std::isinf(r) && std::isfinite(a.number()) && std::isfinite(b.number())) fail("OverflowError: (34, 'Numerical result out of range')");
    return Value(r);
  }
  fail(fmt::format("unknown operator {}", op));
}

int compare_order(const Value& a, const Value& b, const std::string& op) {
  if (a.is_number() && b.is_number()) {
    if (a.is_float() || b.is_float()) {
      const double x = a.number(), y = b.number();
      return x < y ? -1 : x > y ? 1 : (x == y ? 0 : 2);  // 2: unordered (nan)
    }
    return a.integer() < b.integer() ? -1 : a.integer() > b.integer() ? 1 : 0;
  }
  if (a.is_string() && b.is_string()) return a.string() < b.string() ? -1 : a.string() > b.string() ? 1 : 0;
  if (a.is_list() && b.is_list()) {
    const auto &x = a.as_list().items, &y = b.as_list().items;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i)
      if (!python_equal(x[i], y[i])) return compare_order(x[i], y[i], op);
    return x.size() < y.size() ? -1 : x.size() > y.size() ? 1 : 0;
  }
  type_error(fmt::format("'{}' not supported between instances of '{}' and '{}'", op, a.type_name(), b.type_name()));
}

bool contains(const Value& container, const Value& item) {
  if (container.is_string()) {
    if (!item.is_string()) type_error(fmt::format("'in <string>' requires string as left operand, not {}", item.type_name()));
    return container.string().find(item.string()) != std::string::npos;
  }
  if (container.is_list()) {
    for (const Value& v : container.as_list().items)
      if (python_equal(v, item)) return true;
    return false;
  }
  if (container.is_dict()) {
    for (const auto& [k, v] : container.as_dict().items)
      if (python_equal(k, item)) return true;
    return false;
  }
  type_error(fmt::format("argument of type '{}' is not iterable", container.type_name()));
}

bool compare(const std::string& op, const Value& a, const Value& b) {
  if (op == "==") return python_equal(a, b);
  if (op == "!=") return !python_equal(a, b);
  if (op == "in") return contains(b, a);
  if (op == "not in") return !contains(b, a);
  if (op == "is" || op == "is not") {
    // Identity is only meaningful here for None, True and False.
    const bool singleton = a.is_none() || a.is_bool() || b.is_none() || b.is_bool();
    if (!singleton) unsupported("'is' between values other than None, True and False");
    const bool same = a.data.index() == b.data.index() && python_equal(a, b);
    return op == "is" ? same : !same;
  }
  const int order = compare_order(a, b, op);
  if (order == 2) return false;
  if (op == "<") return order < 0;
  if (op == "<=") return order <= 0;
  if (op == ">") return order > 0;
  return order >= 0;
}

std::int64_t normalize_index(std::int64_t index, std::size_t size, bool clamp) {
  const auto n = static_cast<std::int64_t>(size);
  if (index < 0) index += n;
  if (clamp) return std::clamp<std::int64_t>(index, 0, n);
  if (index < 0 || index >= n) fail("IndexError: index out of range");
  return index;
}

const Value* dict_find(const DictValue& dict, const Value& key) {
  for (const auto& [k, v] : dict.items)
    if (python_equal(k, key)) return &v;
  return nullptr;
}

// A str's characters as Python counts them: the code points of its UTF-8 text (a byte that
// starts no valid sequence counts as one).
std::vector<std::string> characters(const std::string& s) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < s.size();) {
    const auto lead = static_cast<unsigned char>(s[i]);
    std::size_t n = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 1;
    if (i + n > s.size()) n = 1;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) n = 1;
    out.push_back(s.substr(i, n));
    i += n;
  }
  return out;
}

std::vector<Value> iterate(const Value& v) {
  if (v.is_list()) return v.as_list().items;
  if (v.is_string()) {
    std::vector<Value> chars;
    for (std::string& c : characters(v.string())) chars.emplace_back(std::move(c));
    return chars;
  }
  if (v.is_dict()) {
    std::vector<Value> keys;
    for (const auto& [k, _] : v.as_dict().items) keys.push_back(k);
    return keys;
  }
  type_error(fmt::format("'{}' object is not iterable", v.type_name()));
}

Value to_float(const Value& v) {
  if (v.is_number()) return Value(v.number());
  if (v.is_string()) {
    if (auto f = python_float_literal(v.string())) return Value(*f);
    fail(fmt::format("ValueError: could not convert string to float: {}", python_repr(v)));
  }
  type_error(fmt::format("float() argument must be a string or a number, not '{}'", v.type_name()));
}

Value to_int(const Value& v) {
  if (v.is_bool() || v.is_int()) return Value(v.integer());
  if (v.is_float()) {
    const double d = v.number();
    if (!std::isfinite(d)) fail("ValueError: cannot convert float NaN or infinity to integer");
    return Value(checked(std::trunc(static_cast<long double>(d)), "int()"));
  }
  if (v.is_string()) {
    if (auto i = python_int_literal(v.string())) return Value(*i);
    fail(fmt::format("ValueError: invalid literal for int() with base 10: {}", python_repr(v)));
  }
  type_error(fmt::format("int() argument must be a string or a number, not '{}'", v.type_name()));
}

// Python's round(): half to even, to an int without digits.
Value round_value(const Value& v, std::optional<std::int64_t> digits) {
  if (!v.is_number()) type_error(fmt::format("type {} doesn't define __round__ method", v.type_name()));
  if (!digits) {
    if (!v.is_float()) return Value(v.integer());
    const double d = v.number();
    if (!std::isfinite(d)) fail("cannot convert float infinity or NaN to integer");
    return Value(checked(std::nearbyint(d), "round()"));  // FE_TONEAREST: ties to even
  }
  if (!v.is_float()) return Value(v.integer());
  // Python rounds the exact decimal value of the double; printing it to `digits` places
  // with correct rounding does the same.
  const double d = v.number();
  if (!std::isfinite(d) || *digits > 300) return Value(d);
  if (*digits < 0) {
    const double scale = std::pow(10.0, static_cast<double>(-*digits));
    return Value(std::nearbyint(d / scale) * scale);
  }
  const std::string text = fmt::format("{:.{}f}", d, *digits);
  return Value(std::strtod(text.c_str(), nullptr));
}

using Args = std::vector<Value>;

void arity(std::string_view name, const Args& args, std::size_t min, std::size_t max) {
  if (args.size() < min || args.size() > max) {
    if (min == max)
      type_error(fmt::format("{}() takes exactly {} argument{} ({} given)", name, min, min == 1 ? "" : "s", args.size()));
    type_error(fmt::format("{}() takes {} to {} arguments ({} given)", name, min, max, args.size()));
  }
}

double real(std::string_view name, const Value& v) {
  if (!v.is_number()) type_error(fmt::format("{}(): must be real number, not {}", name, v.type_name()));
  return v.number();
}

std::optional<Value> math_constant(std::string_view name) {
  if (name == "pi") return Value(M_PI);
  if (name == "e") return Value(M_E);
  if (name == "tau") return Value(2 * M_PI);
  if (name == "inf") return Value(HUGE_VAL);
  if (name == "nan") return Value(std::nan(""));
  return std::nullopt;
}

Value domain_checked(std::string_view name, double result, double input) {
  if (std::isnan(result) && !std::isnan(input)) fail(fmt::format("ValueError: math domain error (in {})", name));
  return Value(result);
}

std::optional<Value> math_function(std::string_view name, const Args& args) {
  using F = double (*)(double);
  static const std::map<std::string_view, F, std::less<>> unary = {
      {"sin", [](double x) { return std::sin(x); }},     {"cos", [](double x) { return std::cos(x); }},
      {"tan", [](double x) { return std::tan(x); }},     {"asin", [](double x) { return std::asin(x); }},
      {"acos", [](double x) { return std::acos(x); }},   {"atan", [](double x) { return std::atan(x); }},
      {"sinh", [](double x) { return std::sinh(x); }},   {"cosh", [](double x) { return std::cosh(x); }},
      {"tanh", [](double x) { return std::tanh(x); }},   {"asinh", [](double x) { return std::asinh(x); }},
      {"acosh", [](double x) { return std::acosh(x); }}, {"atanh", [](double x) { return std::atanh(x); }},
      {"sqrt", [](double x) { return std::sqrt(x); }},   {"exp", [](double x) { return std::exp(x); }},
      {"fabs", [](double x) { return std::fabs(x); }},   {"log10", [](double x) { return std::log10(x); }},
      {"log2", [](double x) { return std::log2(x); }},   {"log1p", [](double x) { return std::log1p(x); }},
      {"expm1", [](double x) { return std::expm1(x); }},
      {"radians", [](double x) { return x * M_PI / 180.0; }},
      {"degrees", [](double x) { return x * 180.0 / M_PI; }},
  };
  if (auto f = unary.find(name); f != unary.end()) {
    arity(name, args, 1, 1);
    const double x = real(name, args[0]);
    if ((name == "log10" || name == "log2") && x <= 0) fail("ValueError: math domain error");
    return domain_checked(name, f->second(x), x);
  }
  if (name == "floor" || name == "ceil" || name == "trunc") {
    arity(name, args, 1, 1);
    if (!args[0].is_float()) return Value(to_int(args[0]));
    const double x = real(name, args[0]);
    if (!std::isfinite(x)) fail("OverflowError: cannot convert float infinity to integer");
    const long double r = name == "floor" ? std::floor(static_cast<long double>(x))
                          : name == "ceil" ? std::ceil(static_cast<long double>(x))
                                           : std::trunc(static_cast<long double>(x));
    return Value(checked(r, "floor/ceil"));
  }
  if (name == "log") {
    arity(name, args, 1, 2);
    const double x = real(name, args[0]);
    if (x <= 0) fail("ValueError: math domain error");
    if (args.size() == 1) return Value(std::log(x));
    const double base = real(name, args[1]);
    if (base <= 0 || base == 1) fail("ValueError: math domain error");
    return Value(std::log(x) / std::log(base));
  }
  if (name == "atan2" || name == "pow" || name == "hypot" || name == "fmod" || name == "copysign") {
    arity(name, args, 2, 2);
    const double x = real(name, args[0]), y = real(name, args[1]);
    if (name == "atan2") return Value(std::atan2(x, y));
    if (name == "hypot") return Value(std::hypot(x, y));
    if (name == "copysign") return Value(std::copysign(x, y));
    if (name == "fmod") {
      if (y == 0) fail("ValueError: math domain error");
      return Value(std::fmod(x, y));
    }
    if (x == 0 && y < 0) fail("ValueError: math domain error");
    return domain_checked(name, std::pow(x, y), x);
  }
  if (name == "isnan" || name == "isinf" || name == "isfinite") {
    arity(name, args, 1, 1);
    const double x = real(name, args[0]);
    return Value(name == "isnan" ? std::isnan(x) : name == "isinf" ? std::isinf(x) : std::isfinite(x));
  }
  return std::nullopt;
}

// Roughly the bytes a value holds, to bound what a comprehension builds.
std::size_t footprint(const Value& v) {
  if (v.is_string()) return v.string().size() + 16;
  if (v.is_list()) {
    std::size_t total = 16;
    for (const Value& item : v.as_list().items) total += footprint(item);
    return total;
  }
  if (v.is_dict()) {
    std::size_t total = 16;
    for (const auto& [key, value] : v.as_dict().items) total += footprint(key) + footprint(value);
    return total;
  }
  return 16;
}

// Iterations all comprehensions of one expression may run (nested loops multiply).
constexpr std::size_t kMaxComprehensionSteps = std::size_t{1} << 18;

class Evaluator {
 public:
  explicit Evaluator(ExpressionScope& scope) : scope_(scope) {}

  Value eval(const Node& n) {
    switch (n.kind) {
      case Kind::Constant: return n.constant;
      case Kind::Name: return name(n.text);
      case Kind::Attribute: return attribute(n);
      case Kind::Subscript: return subscript(n);
      case Kind::Slice: fail("invalid slice");
      case Kind::Call: return call(n);
      case Kind::Unary: {
        const Value v = eval(*n.children[0]);
        if (!v.is_number()) type_error(fmt::format("bad operand type for unary {}: '{}'", n.text, v.type_name()));
        if (n.text == "+") return v.is_float() ? v : Value(v.integer());
        if (v.is_float()) return Value(-v.number());
        return Value(checked(-static_cast<long double>(v.integer()), "-"));
      }
      case Kind::Binary: return binary(n.text, eval(*n.children[0]), eval(*n.children[1]));
      case Kind::And: {
        Value left = eval(*n.children[0]);
        return left.truthy() ? eval(*n.children[1]) : left;
      }
      case Kind::Or: {
        Value left = eval(*n.children[0]);
        return left.truthy() ? left : eval(*n.children[1]);
      }
      case Kind::Not: return Value(!eval(*n.children[0]).truthy());
      case Kind::Compare: {
        Value left = eval(*n.children[0]);
        for (std::size_t i = 0; i < n.ops.size(); ++i) {
          Value right = eval(*n.children[i + 1]);
          if (!compare(n.ops[i], left, right)) return Value(false);
          left = std::move(right);
        }
        return Value(true);
      }
      case Kind::IfElse: return eval(*n.children[0]).truthy() ? eval(*n.children[1]) : eval(*n.children[2]);
      case Kind::List:
      case Kind::Tuple: {
        std::vector<Value> items;
        for (const auto& c : n.children) items.push_back(eval(*c));
        return Value::list(std::move(items), n.kind == Kind::Tuple);
      }
      case Kind::ListComp: return comprehension(n);
      case Kind::Dict: {
        std::vector<std::pair<Value, Value>> items;
        for (std::size_t i = 0; i + 1 < n.children.size(); i += 2) {
          Value key = eval(*n.children[i]);
          Value value = eval(*n.children[i + 1]);
          if (key.is_list() && !key.as_list().tuple) type_error("unhashable type: 'list'");
          auto same = std::find_if(items.begin(), items.end(), [&](const auto& kv) { return python_equal(kv.first, key); });
          if (same != items.end()) same->second = std::move(value);
          else items.emplace_back(std::move(key), std::move(value));
        }
        return Value::dict(std::move(items));
      }
    }
    fail("invalid expression");
  }

 private:
  // Comprehension variables hide properties and builtins, as Python's local scope does.
  std::optional<Value> lookup(std::string_view name) {
    for (auto it = locals_.rbegin(); it != locals_.rend(); ++it)
      if (it->first == name) return it->second;
    return scope_.lookup(name);
  }

  Value comprehension(const Node& n) {
    std::vector<Value> out;
    std::size_t size = 0;
    const std::size_t outer = locals_.size();
    comprehend(n, 1, 0, out, size);
    locals_.resize(outer);
    return Value::list(std::move(out));
  }

  // Runs the clauses from `clause` on (their nodes from `child` on) under the bindings the
  // clauses before it made, appending an element each time all of them pass.
  void comprehend(const Node& n, std::size_t child, std::size_t clause, std::vector<Value>& out, std::size_t& size) {
    if (clause == n.ops.size()) {
      out.push_back(eval(*n.children[0]));
      size += footprint(out.back());
      if (size > kMaxExpressionResult) fail("list comprehension too large for an expression");
      return;
    }
    if (n.ops[clause] == "if") {
      if (eval(*n.children[child]).truthy()) comprehend(n, child + 1, clause + 1, out, size);
      return;
    }
    const std::vector<Value> items = iterate(eval(*n.children[child + 1]));
    const std::size_t mark = locals_.size();
    for (const Value& item : items) {
      if (++comprehension_steps_ > kMaxComprehensionSteps)
        fail(fmt::format("list comprehensions of one expression run more than {} steps", kMaxComprehensionSteps));
      locals_.resize(mark);
      bind(*n.children[child], item);
      comprehend(n, child + 2, clause + 1, out, size);
    }
    locals_.resize(mark);
  }

  void bind(const Node& target, const Value& item) {
    if (target.kind == Kind::Name) {
      locals_.emplace_back(target.text, item);
      return;
    }
    const std::vector<Value> parts = iterate(item);
    const std::size_t want = target.children.size();
    if (parts.size() < want) fail(fmt::format("ValueError: not enough values to unpack (expected {}, got {})", want, parts.size()));
    if (parts.size() > want) fail(fmt::format("ValueError: too many values to unpack (expected {})", want));
    for (std::size_t i = 0; i < want; ++i) bind(*target.children[i], parts[i]);
  }

  static bool is_builtin(std::string_view name) {
    static const char* const kBuiltins[] = {"len", "int", "float", "str", "bool", "abs", "min", "max", "round", "list",
                                            "dict", "sum", "sorted", "range", "any", "all", "tuple", "load_yaml"};
    return std::any_of(std::begin(kBuiltins), std::end(kBuiltins), [&](const char* b) { return name == b; });
  }

  Value name(const std::string& n) {
    if (auto v = lookup(n)) return *v;
    if (n == "True") return Value(true);
    if (n == "False") return Value(false);
    if (n == "None") return Value();
    if (auto c = math_constant(n)) return *c;
    if (n == "math" || n == "xacro" || n == "python") fail(fmt::format("module '{}' used as a value", n));
    if (is_builtin(n) || math_function(n, {Value(0.5)}).has_value())
      unsupported(fmt::format("the function '{}' used as a value", n));
    fail(fmt::format("NameError: name '{}' is not defined", n));
  }

  Value attribute(const Node& n) {
    const Node& object = *n.children[0];
    if (object.kind == Kind::Name && !lookup(object.text)) {
      if (object.text == "math")
        if (auto c = math_constant(n.text)) return *c;
    }
    const Value base = eval(object);
    if (base.is_namespace()) {
      if (auto v = scope_.lookup_in(std::get<NamespaceRef>(base.data), n.text)) return *v;
      fail(fmt::format("NameError: name '{}' is not defined", n.text));
    }
    if (base.is_dict() && base.as_dict().dotted) {
      if (const Value* v = dict_find(base.as_dict(), Value(n.text))) return *v;
      fail(fmt::format("The yaml dictionary has no key '{}'", n.text));
    }
    unsupported(fmt::format("attribute '.{}' of a {}", n.text, base.type_name()));
  }

  Value subscript(const Node& n) {
    const Value base = eval(*n.children[0]);
    const Node& index = *n.children[1];
    if (index.kind == Kind::Slice) {
      const auto bound = [&](const NodePtr& b, std::int64_t fallback, std::size_t size) {
        if (!b) return fallback;
        const Value v = eval(*b);
        if (!v.is_int() && !v.is_bool()) type_error("slice indices must be integers");
        return normalize_index(v.integer(), size, true);
      };
      if (base.is_string()) {
        const std::vector<std::string> chars = characters(base.string());
        const std::int64_t lo = bound(index.children[0], 0, chars.size()), hi = bound(index.children[1], static_cast<std::int64_t>(chars.size()), chars.size());
        std::string out;
        for (std::int64_t i = lo; i < hi; ++i) out += chars[static_cast<std::size_t>(i)];
        return Value(std::move(out));
      }
      if (base.is_list()) {
        const auto& items = base.as_list().items;
        const std::int64_t lo = bound(index.children[0], 0, items.size()), hi = bound(index.children[1], static_cast<std::int64_t>(items.size()), items.size());
        std::vector<Value> out;
        for (std::int64_t i = lo; i < hi; ++i) out.push_back(items[static_cast<std::size_t>(i)]);
        return Value::list(std::move(out), base.as_list().tuple);
      }
      type_error(fmt::format("'{}' object is not subscriptable", base.type_name()));
    }
    const Value key = eval(index);
    if (base.is_dict()) {
      if (const Value* v = dict_find(base.as_dict(), key)) return *v;
      fail(fmt::format("KeyError: {}", python_repr(key)));
    }
    if (base.is_list() || base.is_string()) {
      if (!key.is_int() && !key.is_bool())
        type_error(fmt::format("{} indices must be integers, not {}", base.type_name(), key.type_name()));
      if (base.is_string()) {
        const std::vector<std::string> chars = characters(base.string());
        return Value(chars[static_cast<std::size_t>(normalize_index(key.integer(), chars.size(), false))]);
      }
      return base.as_list().items[static_cast<std::size_t>(normalize_index(key.integer(), base.as_list().items.size(), false))];
    }
    type_error(fmt::format("'{}' object is not subscriptable", base.type_name()));
  }

  Value call(const Node& n) {
    const Node& callee = *n.children[0];
    Args args;
    std::vector<std::pair<std::string, Value>> keywords;
    for (std::size_t i = 1; i < n.children.size(); ++i) {
      Value v = eval(*n.children[i]);
      if (n.ops[i - 1].empty()) {
        if (!keywords.empty()) fail("SyntaxError: positional argument follows keyword argument");
        args.push_back(std::move(v));
      } else {
        keywords.emplace_back(n.ops[i - 1], std::move(v));
      }
    }
    const auto no_keywords = [&](std::string_view f) {
      if (!keywords.empty()) type_error(fmt::format("{}() takes no keyword arguments", f));
    };
    if (callee.kind == Kind::Name) {
      if (auto shadow = lookup(callee.text))
        type_error(fmt::format("'{}' object is not callable", shadow->type_name()));
      if (callee.text == "dict") return make_dict(args, keywords);
      no_keywords(callee.text);
      if (auto v = scope_.call(callee.text, args)) return *v;
      return builtin(callee.text, args);
    }
    if (callee.kind == Kind::Attribute) {
      const Node& object = *callee.children[0];
      if (object.kind == Kind::Name && !lookup(object.text)) {
        if (object.text == "math") {
          no_keywords(callee.text);
          if (auto v = math_function(callee.text, args)) return *v;
          unsupported(fmt::format("math.{}", callee.text));
        }
        if (object.text == "xacro") {
          if (callee.text == "dotify") {
            arity("dotify", args, 1, 1);
            if (!args[0].is_dict()) type_error("dotify() needs a dict");
            return Value::dict(args[0].as_dict().items, true);
          }
          no_keywords(callee.text);
          return xacro_function(callee.text, args);
        }
        if (object.text == "python") {
          if (callee.text == "dict") return make_dict(args, keywords);
          no_keywords(callee.text);
          return builtin(callee.text, args);
        }
      }
      no_keywords(callee.text);
      return method(eval(object), callee.text, args);
    }
    unsupported("calling the result of an expression");
  }

  Value make_dict(const Args& args, const std::vector<std::pair<std::string, Value>>& keywords) {
    std::vector<std::pair<Value, Value>> items;
    if (args.size() > 1) type_error("dict expected at most 1 argument");
    if (args.size() == 1) {
      if (args[0].is_dict()) items = args[0].as_dict().items;
      else unsupported("dict() from a sequence of pairs");
    }
    for (const auto& [name, value] : keywords) {
      const Value key(name);
      auto same = std::find_if(items.begin(), items.end(), [&](const auto& kv) { return python_equal(kv.first, key); });
      if (same != items.end()) same->second = value;
      else items.emplace_back(key, value);
    }
    return Value::dict(std::move(items));
  }

  Value xacro_function(const std::string& name, const Args& args) {
    if (name == "load_yaml") {
      arity(name, args, 1, 1);
      if (!args[0].is_string()) type_error("load_yaml() needs a file name");
      return scope_.load_yaml(args[0].string());
    }
    if (name == "arg") {
      arity(name, args, 1, 1);
      return scope_.arg(python_str(args[0]));
    }
    if (name == "abs_filename") {
      arity(name, args, 1, 1);
      return Value(scope_.abs_filename(python_str(args[0])));
    }
    if (name == "fatal") {
      std::string message;
      for (const Value& a : args) message += (message.empty() ? "" : " ") + python_str(a);
      fail(message);
    }
    if (name == "tokenize") {
      arity(name, args, 1, 3);
      const std::string separators = args.size() > 1 ? python_str(args[1]) : ",; ";
      const bool skip_empty = args.size() > 2 ? args[2].truthy() : true;
      std::vector<Value> items;
      std::string current;
      for (char c : python_str(args[0]) + separators.substr(0, 1)) {
        if (separators.find(c) == std::string::npos) {
          current += c;
          continue;
        }
        if (!current.empty() || !skip_empty) items.emplace_back(current);
        current.clear();
      }
      return Value::list(std::move(items));
    }
    if (name == "message" || name == "warning" || name == "error" || name == "print_location") return Value(std::string());
    unsupported(fmt::format("xacro.{}", name));
  }

  Value builtin(const std::string& name, const Args& args) {
    if (auto v = math_function(name, args)) return *v;
    if (name == "load_yaml") return xacro_function(name, args);
    if (name == "len") {
      arity(name, args, 1, 1);
      const Value& v = args[0];
      if (v.is_string()) return Value(static_cast<std::int64_t>(characters(v.string()).size()));
      if (v.is_list()) return Value(static_cast<std::int64_t>(v.as_list().items.size()));
      if (v.is_dict()) return Value(static_cast<std::int64_t>(v.as_dict().items.size()));
      type_error(fmt::format("object of type '{}' has no len()", v.type_name()));
    }
    if (name == "int") {
      arity(name, args, 0, 1);
      return args.empty() ? Value(0) : to_int(args[0]);
    }
    if (name == "float") {
      arity(name, args, 0, 1);
      return args.empty() ? Value(0.0) : to_float(args[0]);
    }
    if (name == "str") {
      arity(name, args, 0, 1);
      return Value(args.empty() ? std::string() : python_str(args[0]));
    }
    if (name == "bool") {
      arity(name, args, 0, 1);
      return Value(!args.empty() && args[0].truthy());
    }
    if (name == "abs") {
      arity(name, args, 1, 1);
      const Value& v = args[0];
      if (v.is_float()) return Value(std::fabs(v.number()));
      if (v.is_number()) return Value(checked(std::fabs(static_cast<long double>(v.integer())), "abs"));
      type_error(fmt::format("bad operand type for abs(): '{}'", v.type_name()));
    }
    if (name == "min" || name == "max") {
      if (args.empty()) type_error(fmt::format("{} expected at least 1 argument, got 0", name));
      const std::vector<Value> items = args.size() == 1 ? iterate(args[0]) : args;
      if (items.empty()) fail(fmt::format("ValueError: {}() arg is an empty sequence", name));
      Value best = items[0];
      for (std::size_t i = 1; i < items.size(); ++i)
        if (compare(name == "min" ? "<" : ">", items[i], best)) best = items[i];
      return best;
    }
    if (name == "round") {
      arity(name, args, 1, 2);
      std::optional<std::int64_t> digits;
      if (args.size() == 2 && !args[1].is_none()) digits = to_int(args[1]).integer();
      return round_value(args[0], digits);
    }
    if (name == "list" || name == "tuple") {
      arity(name, args, 0, 1);
      return Value::list(args.empty() ? std::vector<Value>{} : iterate(args[0]), name == "tuple");
    }
    if (name == "sum") {
      arity(name, args, 1, 2);
      Value total = args.size() > 1 ? args[1] : Value(0);
      for (const Value& v : iterate(args[0])) total = binary("+", total, v);
      return total;
    }
    if (name == "sorted") {
      arity(name, args, 1, 1);
      std::vector<Value> items = iterate(args[0]);
      std::stable_sort(items.begin(), items.end(), [](const Value& a, const Value& b) { return compare("<", a, b); });
      return Value::list(std::move(items));
    }
    if (name == "range") {
      arity(name, args, 1, 3);
      for (const Value& a : args)
        if (!a.is_int() && !a.is_bool()) type_error("range() arguments must be integers");
      const std::int64_t start = args.size() > 1 ? args[0].integer() : 0;
      const std::int64_t stop = args.size() > 1 ? args[1].integer() : args[0].integer();
      const std::int64_t step = args.size() > 2 ? args[2].integer() : 1;
      if (step == 0) fail("ValueError: range() arg 3 must not be zero");
      std::vector<Value> items;
      for (std::int64_t i = start; step > 0 ? i < stop : i > stop; i += step) {
        if (items.size() > kMaxExpressionResult / 16) fail("range() too long for an expression");
        items.emplace_back(i);
      }
      return Value::list(std::move(items));
    }
    if (name == "any" || name == "all") {
      arity(name, args, 1, 1);
      for (const Value& v : iterate(args[0]))
        if (v.truthy() == (name == "any")) return Value(name == "any");
      return Value(name == "all");
    }
    if (name == "eval" || name == "exec" || name == "open" || name == "getattr" || name == "setattr" || name == "compile" ||
        name == "globals" || name == "locals" || name == "vars" || name == "type" || name == "map" || name == "filter")
      unsupported(fmt::format("{}()", name));
    fail(fmt::format("NameError: name '{}' is not defined", name));
  }

  // str.find, rfind, index, rindex and count with Python's optional start and end, all in code
  // points as Python counts them.
  Value substring_search(const std::string& s, const std::string& name, const Args& args) {
    arity(name, args, 1, 3);
    if (!args[0].is_string()) type_error(fmt::format("must be str, not {}", args[0].type_name()));
    const std::vector<std::string> chars = characters(s), sub = characters(args[0].string());
    const auto size = static_cast<std::int64_t>(chars.size()), width = static_cast<std::int64_t>(sub.size());
    const auto bound = [&](std::size_t i, std::int64_t fallback) {
      if (args.size() <= i || args[i].is_none()) return fallback;
      if (!args[i].is_int() && !args[i].is_bool()) type_error("slice indices must be integers or None");
      return normalize_index(args[i].integer(), chars.size(), true);
    };
    // A start past the end finds nothing, not even the empty string (Python's rule).
    const bool start_past_end = args.size() > 1 && args[1].is_int() && args[1].integer() > size;
    const std::int64_t lo = bound(1, 0), hi = bound(2, size);
    const auto matches_at = [&](std::int64_t at) {
      return std::equal(sub.begin(), sub.end(), chars.begin() + at);
    };
    if (name == "count") {
      if (start_past_end || hi < lo) return Value(std::int64_t{0});
      if (width == 0) return Value(hi - lo + 1);
      std::int64_t n = 0;
      for (std::int64_t at = lo; at + width <= hi;) {
        if (matches_at(at)) { ++n; at += width; } else ++at;
      }
      return Value(n);
    }
    std::int64_t found = -1;
    if (!start_past_end && hi - lo >= width) {
      if (name == "find" || name == "index") {
        for (std::int64_t at = lo; at + width <= hi && found < 0; ++at)
          if (matches_at(at)) found = at;
      } else {
        for (std::int64_t at = hi - width; at >= lo && found < 0; --at)
          if (matches_at(at)) found = at;
      }
    }
    if (found < 0 && (name == "index" || name == "rindex")) fail("ValueError: substring not found");
    return Value(found);
  }

  Value method(const Value& object, const std::string& name, const Args& args) {
    if (object.is_string()) {
      const std::string& s = object.string();
      if (name == "lower" || name == "upper") {
        arity(name, args, 0, 0);
        std::string out = s;
        for (char& c : out) c = static_cast<char>(name == "lower" ? std::tolower(static_cast<unsigned char>(c)) : std::toupper(static_cast<unsigned char>(c)));
        return Value(std::move(out));
      }
      if (name == "strip") {
        arity(name, args, 0, 0);
        const auto b = s.find_first_not_of(" \t\n\r\f\v");
        if (b == std::string::npos) return Value(std::string());
        return Value(s.substr(b, s.find_last_not_of(" \t\n\r\f\v") - b + 1));
      }
      if (name == "startswith" || name == "endswith") {
        arity(name, args, 1, 1);
        if (!args[0].is_string()) type_error(fmt::format("{} first arg must be str", name));
        return Value(name == "startswith" ? s.starts_with(args[0].string()) : s.ends_with(args[0].string()));
      }
      if (name == "replace") {
        arity(name, args, 2, 2);
        if (!args[0].is_string() || !args[1].is_string()) type_error("replace() arguments must be str");
        const std::string &from = args[0].string(), &to = args[1].string();
        if (from.empty()) unsupported("replace() of an empty string");
        std::string out;
        std::size_t at = 0;
        for (std::size_t hit; (hit = s.find(from, at)) != std::string::npos; at = hit + from.size()) {
          out += s.substr(at, hit - at) + to;
          if (out.size() > kMaxExpressionResult) fail("replace() result too long for an expression");
        }
        return Value(out + s.substr(at));
      }
      if (name == "split") {
        arity(name, args, 0, 1);
        std::vector<Value> parts;
        if (args.empty() || args[0].is_none()) {
          std::size_t at = 0;
          while ((at = s.find_first_not_of(" \t\n\r\f\v", at)) != std::string::npos) {
            const std::size_t end = std::min(s.find_first_of(" \t\n\r\f\v", at), s.size());
            parts.emplace_back(s.substr(at, end - at));
            at = end;
          }
        } else {
          if (!args[0].is_string() || args[0].string().empty()) fail("ValueError: empty separator");
          const std::string& sep = args[0].string();
          std::size_t at = 0;
          for (std::size_t hit; (hit = s.find(sep, at)) != std::string::npos; at = hit + sep.size()) parts.emplace_back(s.substr(at, hit - at));
          parts.emplace_back(s.substr(at));
        }
        return Value::list(std::move(parts));
      }
      if (name == "find" || name == "rfind" || name == "index" || name == "rindex" || name == "count")
        return substring_search(s, name, args);
      if (name == "join") {
        arity(name, args, 1, 1);
        std::string out;
        bool first = true;
        for (const Value& v : iterate(args[0])) {
          if (!v.is_string()) type_error(fmt::format("sequence item: expected str instance, {} found", v.type_name()));
          out += (first ? "" : s) + v.string();
          first = false;
        }
        return Value(std::move(out));
      }
    }
    if (object.is_dict()) {
      const DictValue& d = object.as_dict();
      if (name == "get") {
        arity(name, args, 1, 2);
        if (const Value* v = dict_find(d, args[0])) return *v;
        return args.size() > 1 ? args[1] : Value();
      }
      if (name == "keys" || name == "values" || name == "items") {
        arity(name, args, 0, 0);
        std::vector<Value> out;
        for (const auto& [k, v] : d.items)
          out.push_back(name == "keys" ? k : name == "values" ? v : Value::list({k, v}, true));
        return Value::list(std::move(out));
      }
      if (d.dotted) {
        if (const Value* v = dict_find(d, Value(name))) type_error(fmt::format("'{}' object is not callable", v->type_name()));
      }
    }
    if (object.is_list() && name == "index") {
      arity(name, args, 1, 1);
      const auto& items = object.as_list().items;
      for (std::size_t i = 0; i < items.size(); ++i)
        if (python_equal(items[i], args[0])) return Value(static_cast<std::int64_t>(i));
      fail(fmt::format("ValueError: {} is not in list", python_repr(args[0])));
    }
    if (object.is_list() && name == "count") {
      arity(name, args, 1, 1);
      std::int64_t n = 0;
      for (const Value& v : object.as_list().items) n += python_equal(v, args[0]) ? 1 : 0;
      return Value(n);
    }
    unsupported(fmt::format("method '.{}()' of a {}", name, object.type_name()));
  }

  ExpressionScope& scope_;
  std::vector<std::pair<std::string, Value>> locals_;
  std::size_t comprehension_steps_ = 0;
};

}  // namespace

Value evaluate_expression(std::string_view expression, ExpressionScope& scope) {
  NodePtr tree = parse_expression(expression);
  return Evaluator(scope).eval(*tree);
}

}  // namespace assetlint::xacro
