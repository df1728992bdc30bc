// xacro's ${…} expression language: the Python subset, its printing, and the clear errors for
// what is outside it.
#include <catch2/catch.hpp>

#include <map>

#include "formats/xacro/expression.h"

using namespace assetlint::xacro;

namespace {

class Scope : public ExpressionScope {
 public:
  std::map<std::string, Value, std::less<>> names;
  std::optional<Value> lookup(std::string_view name) override {
    auto it = names.find(name);
    if (it == names.end()) return std::nullopt;
    return it->second;
  }
  std::optional<Value> lookup_in(const NamespaceRef&, std::string_view) override { return std::nullopt; }
  Value load_yaml(const std::string&) override { throw EvalError("no YAML here"); }
  Value arg(const std::string& name) override { return Value("arg:" + name); }
  std::string abs_filename(const std::string& f) override { return "/abs/" + f; }
};

std::string eval(const std::string& expression) {
  Scope scope;
  scope.names["a"] = Value(2);
  scope.names["x"] = Value(0.5);
  scope.names["s"] = Value("Hello");
  scope.names["l"] = Value::list({Value(1), Value(2.5), Value("z")});
  scope.names["d"] = Value::dict({{Value("k"), Value(7)}}, true);
  return python_str(evaluate_expression(expression, scope));
}

std::string error_of(const std::string& expression) {
  try {
    eval(expression);
  } catch (const EvalError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("xacro expressions: arithmetic as Python computes it", "[xacro]") {
  CHECK(eval("1+2*3") == "7");
  CHECK(eval("7/2") == "3.5");
  CHECK(eval("7//2") == "3");
  CHECK(eval("-7//2") == "-4");
  CHECK(eval("-7%3") == "2");
  CHECK(eval("7.5//2") == "3.0");
  CHECK(eval("2**10") == "1024");
  CHECK(eval("2**-1") == "0.5");
  CHECK(eval("-2**2") == "-4");
  CHECK(eval("a*x") == "1.0");
  CHECK(eval("3*0.1") == "0.30000000000000004");
  CHECK(eval("0.9 / 2 - 0.2") == "0.25");
  CHECK(eval("1e-5") == "1e-05");
  CHECK(eval("1e16") == "1e+16");
  CHECK(eval("123456789.0*10") == "1234567890.0");
  CHECK(eval("0.0001") == "0.0001");
  CHECK(eval("pi/2") == "1.5707963267948966");
  CHECK(eval("1. + sin(pi)") == "1.0000000000000002");
}

TEST_CASE("xacro expressions: math functions and builtins", "[xacro]") {
  CHECK(eval("radians(180)") == "3.141592653589793");
  CHECK(eval("degrees(pi)") == "180.0");
  CHECK(eval("math.cos(0)") == "1.0");
  CHECK(eval("atan2(1, 1)") == "0.7853981633974483");
  CHECK(eval("sqrt(16)") == "4.0");
  CHECK(eval("pow(2, 3)") == "8.0");
  CHECK(eval("fabs(-3)") == "3.0");
  CHECK(eval("floor(2.7)") == "2");
  CHECK(eval("ceil(2.1)") == "3");
  CHECK(eval("log(exp(2))") == "2.0");
  CHECK(eval("math.pi") == "3.141592653589793");
  CHECK(eval("len(l)") == "3");
  CHECK(eval("int('42') + float('0.5')") == "42.5");
  CHECK(eval("str(1.0) + 'x'") == "1.0x");
  CHECK(eval("bool(0)") == "False");
  CHECK(eval("abs(-2)") == "2");
  CHECK(eval("min(3, 1, 2)") == "1");
  CHECK(eval("max([1, 5, 2])") == "5");
  CHECK(eval("round(2.5)") == "2");
  CHECK(eval("round(3.5)") == "4");
  CHECK(eval("round(0.125, 2)") == "0.12");
  CHECK(eval("True and None") == "None");
  CHECK(eval("xacro.arg('foo')") == "arg:foo");
}

TEST_CASE("xacro expressions: logic, comparisons, conditionals, strings", "[xacro]") {
  CHECK(eval("1 < a <= 2") == "True");
  CHECK(eval("1 < a < 2") == "False");
  CHECK(eval("a == 2.0") == "True");
  CHECK(eval("not a") == "False");
  CHECK(eval("0 or 'x'") == "x");
  CHECK(eval("'yes' if a > 1 else 'no'") == "yes");
  CHECK(eval("'ell' in s") == "True");
  CHECK(eval("3 not in l") == "True");
  CHECK(eval("s + ' ' + \"world\"") == "Hello world");
  CHECK(eval("'ab' * 3") == "ababab");
  CHECK(eval("s.lower()") == "hello");
  CHECK(eval("'a' 'b'") == "ab");
  CHECK(eval("u'x'") == "x");
  // Characters, not bytes, as Python 3 counts them.
  CHECK(eval("len('\u00b5m')") == "2");
  CHECK(eval("'\u00b5m'[0]") == "\u00b5");
  CHECK(eval("'a\u00b5m'[1:]") == "\u00b5m");
  CHECK(eval("[c for c in '\u00b5m']") == "['\u00b5', 'm']");
}

TEST_CASE("xacro expressions: str.find, rfind, index, rindex and count as Python answers them", "[xacro]") {
  // Each expected value is what Python 3 prints for the same expression.
  CHECK(eval("'right_arm'.find('right_') != -1") == "True");
  CHECK(eval("'left_arm'.find('right_')") == "-1");
  CHECK(eval("'abcabc'.find('c', 3)") == "5");
  CHECK(eval("'abcabc'.find('c', 3, 5)") == "-1");
  CHECK(eval("'abcabc'.find('a', -3)") == "3");
  CHECK(eval("'abcabc'.rfind('b')") == "4");
  CHECK(eval("'abcabc'.rfind('b', 0, 4)") == "1");
  CHECK(eval("'abc'.find('')") == "0");
  CHECK(eval("'abc'.find('', 3)") == "3");
  CHECK(eval("'abc'.find('', 4)") == "-1");
  CHECK(eval("'abc'.rfind('')") == "3");
  CHECK(eval("'aaaa'.count('aa')") == "2");
  CHECK(eval("'abc'.count('')") == "4");
  CHECK(eval("'abc'.count('', 4)") == "0");
  CHECK(eval("s.index('l')") == "2");
  CHECK(eval("s.rindex('l')") == "3");
  CHECK(error_of("s.index('z')") == "ValueError: substring not found");
  CHECK(error_of("s.find(1)") == "TypeError: must be str, not int");
  // Code points, not bytes.
  CHECK(eval("'\u00b5m_\u00b5m'.find('m', 2)") == "4");
}

TEST_CASE("xacro expressions: lists, tuples, dicts and indexing", "[xacro]") {
  CHECK(eval("[0, 1+1, 2]") == "[0, 2, 2]");
  CHECK(eval("(0,1+1,2)") == "(0, 2, 2)");
  CHECK(eval("l[-1]") == "z");
  CHECK(eval("l[0:2]") == "[1, 2.5]");
  CHECK(eval("s[1]") == "e");
  CHECK(eval("d['k'] + d.k") == "14");
  CHECK(eval("dict(a=0, b=1+1)") == "{'a': 0, 'b': 2}");
  CHECK(eval("dict(a=1)['a']") == "1");
  CHECK(eval("[1, 'a']") == "[1, 'a']");
}

TEST_CASE("xacro expressions: list comprehensions", "[xacro]") {
  CHECK(eval("[i * a for i in range(3)]") == "[0, 2, 4]");
  CHECK(eval("[i for i in range(6) if i % 2 if i > 1]") == "[3, 5]");
  CHECK(eval("[c.upper() for c in 'ab']") == "['A', 'B']");
  CHECK(eval("[k for k in d]") == "['k']");
  CHECK(eval("[v + 1 for k, v in d.items()]") == "[8]");
  CHECK(eval("[x * y for x in (1, 2) for y in [10, 100]]") == "[10, 100, 20, 200]");
  CHECK(eval("[(a, b) for [a, (b)] in [[1, 2]]]") == "[(1, 2)]");
  CHECK(eval("[[j for j in range(i)] for i in range(3)]") == "[[], [0], [0, 1]]");
  CHECK(eval("[l[i] for i in [2, 0]]") == "['z', 1]");
  // The loop variable hides the property `a` inside, and only inside.
  CHECK(eval("([a for a in 'xy'], a)") == "(['x', 'y'], 2)");
  CHECK(eval("sum([x for x in [0.5, 0.25]])") == "0.75");
  CHECK(error_of("[i for i in 3]") == "TypeError: 'int' object is not iterable");
  CHECK(error_of("[p for p, q in [1]]").find("TypeError") == 0);
  CHECK(error_of("[p for p, q in ['abc']]") == "ValueError: too many values to unpack (expected 2)");
  CHECK(error_of("[i for i in]") == "invalid syntax at ']'");
  CHECK(error_of("[i for 1 in l]") == "invalid syntax at 'number'");
  CHECK(error_of("[i for i in range(2000) for j in range(2000)]").find("steps") != std::string::npos);
}

TEST_CASE("xacro expressions: what is outside the subset is named, never guessed", "[xacro]") {
  CHECK(error_of("lambda x: x") == "unsupported in ${…}: lambda");
  CHECK(error_of("{k: 1 for k in d}") == "unsupported in ${…}: dictionary comprehension");
  CHECK(error_of("sum(i for i in l)") == "unsupported in ${…}: generator expression");
  CHECK(error_of("f'{a}'") == "unsupported in ${…}: f-string");
  CHECK(error_of("a | 1") == "unsupported in ${…}: bitwise operator '|'");
  CHECK(error_of("__import__('os')").find("invalid name") != std::string::npos);
  CHECK(error_of("open('x')") == "unsupported in ${…}: open()");
  CHECK(error_of("undefined_name") == "NameError: name 'undefined_name' is not defined");
  CHECK(error_of("1/0") == "ZeroDivisionError: division by zero");
  CHECK(error_of("'a' + 1").find("TypeError") == 0);
  CHECK(error_of("l[5]") == "IndexError: index out of range");
  CHECK(error_of("1 +") == "invalid syntax: unexpected end of expression");
  CHECK(error_of("2**2**2**2**2").find("beyond 64 bits") != std::string::npos);
  CHECK(error_of("'a' * 10**9").find("MiB") != std::string::npos);
  CHECK(error_of(std::string(500, '(') + "1" + std::string(500, ')')) == "expression nested too deeply");
}

TEST_CASE("python floats print as Python's repr", "[xacro]") {
  CHECK(python_float(0.1) == "0.1");
  CHECK(python_float(1.0) == "1.0");
  CHECK(python_float(-0.0) == "-0.0");
  CHECK(python_float(1e22) == "1e+22");
  CHECK(python_float(1.5e-7) == "1.5e-07");
  CHECK(python_float(123.456) == "123.456");
  CHECK(python_float(1e15) == "1000000000000000.0");
  CHECK(python_float(0.00012) == "0.00012");
  CHECK(python_float(8.625e-08) == "8.625e-08");
}
