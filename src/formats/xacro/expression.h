#pragma once
// xacro's `${…}` expressions: the safe subset of Python that xacro evaluates (arithmetic
// with ** and //, comparisons, and/or/not, conditional expressions, strings, lists, tuples,
// dicts, indexing and slices, attribute access on YAML data and namespaces, the math
// functions and the few builtins xacro exposes). Anything else is an EvalError that names
// the construct ("unsupported in ${…}: lambda"), never a guess.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/xacro/python_value.h"

namespace assetlint::xacro {

// What the names of an expression resolve to.
class ExpressionScope {
 public:
  virtual ~ExpressionScope() = default;
  // A property (or argument, in $(eval …)) by name; nullopt: not defined here, try the globals.
  virtual std::optional<Value> lookup(std::string_view name) = 0;
  // A property of a namespace an include with `ns` made.
  virtual std::optional<Value> lookup_in(const NamespaceRef& ns, std::string_view name) = 0;
  // xacro.load_yaml(file), xacro.arg(name), xacro.abs_filename(file).
  virtual Value load_yaml(const std::string& filename) = 0;
  virtual Value arg(const std::string& name) = 0;
  virtual std::string abs_filename(const std::string& filename) = 0;
  // A function of this scope called by name (the $(eval …) functions arg(), env(), find()…);
  // nullopt: not one of them.
  virtual std::optional<Value> call(std::string_view name, const std::vector<Value>& args) {
    (void)name;
    (void)args;
    return std::nullopt;
  }
};

// Bounds on what one expression may build (a string repeated 10**9 times).
inline constexpr std::size_t kMaxExpressionResult = std::size_t{16} << 20;

Value evaluate_expression(std::string_view expression, ExpressionScope& scope);

}  // namespace assetlint::xacro
