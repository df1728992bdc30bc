#pragma once
// The syntax of xacro's `${…}` expressions: a small subset of Python's expression grammar,
// parsed into a tree the evaluator (expression.cpp) walks. A construct outside the subset is
// an EvalError naming it ("unsupported in ${…}: lambda") at parse time, before anything runs.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "formats/xacro/python_value.h"

namespace assetlint::xacro {

[[noreturn]] void unsupported(std::string_view what);
[[noreturn]] void fail(std::string message);

struct Node;
using NodePtr = std::unique_ptr<Node>;

enum class Kind { Constant, Name, Attribute, Subscript, Slice, Call, Unary, Binary, And, Or, Not, Compare, IfElse, List, Tuple, Dict, ListComp };

struct Node {
  Kind kind;
  Value constant;
  std::string text;                       // name, attribute, operator
  std::vector<NodePtr> children;          // operands, elements, arguments
  std::vector<std::string> ops;           // comparison operators; keyword argument names ("" for positional)
};
// A list comprehension `[element for target in iterable if condition …]`: children are the
// element, then per clause its target and iterable ("for") or its condition ("if"); ops holds
// "for" or "if" for each clause, in order.

NodePtr parse_expression(std::string_view expression);

}  // namespace assetlint::xacro
