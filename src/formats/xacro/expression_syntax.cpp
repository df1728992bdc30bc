#include "formats/xacro/expression_syntax.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>

namespace assetlint::xacro {

void unsupported(std::string_view what) { throw EvalError(fmt::format("unsupported in ${{…}}: {}", what)); }
void fail(std::string message) { throw EvalError(std::move(message)); }

namespace {

// ---------------------------------------------------------------------------------------
// Tokens

enum class Tok { Name, Int, Float, String, Op, End };

struct Token {
  Tok kind = Tok::End;
  std::string text;  // the name, the operator, the decoded string
  std::int64_t integer = 0;
  double real = 0;
  std::size_t at = 0;
};

bool name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || static_cast<unsigned char>(c) >= 0x80; }
bool name_char(char c) { return name_start(c) || std::isdigit(static_cast<unsigned char>(c)); }

class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    for (;;) {
      while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      if (pos_ >= text_.size()) break;
      tokens.push_back(next());
    }
    Token end;
    end.at = text_.size();
    tokens.push_back(end);
    return tokens;
  }

 private:
  Token next() {
    Token t;
    t.at = pos_;
    const char c = text_[pos_];
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && pos_ + 1 < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_ + 1]))))
      return number();
    if (name_start(c)) {
      std::size_t end = pos_;
      while (end < text_.size() && name_char(text_[end])) ++end;
      std::string word(text_.substr(pos_, end - pos_));
      // String prefixes: u'' is a plain string, r'' a raw one; f'' and b'' are not supported.
      if (end < text_.size() && (text_[end] == '\'' || text_[end] == '"')) {
        std::string lower = word;
        for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        if (lower == "u" || lower == "r") {
          pos_ = end;
          return string(lower == "r", t.at);
        }
        if (lower.find('f') != std::string::npos) unsupported("f-string");
        if (lower.find('b') != std::string::npos) unsupported("bytes literal");
      }
      pos_ = end;
      t.kind = Tok::Name;
      t.text = std::move(word);
      return t;
    }
    if (c == '\'' || c == '"') return string(false, t.at);
    static const char* const kOps[] = {"**", "//", "==", "!=", "<=", ">=", "<<", ">>", ":=", "->", "+", "-", "*", "/",
                                       "%",  "<",  ">",  "(",  ")",  "[",  "]",  "{",  "}",  ",",  ":", ".", "~", "&",
                                       "|",  "^",  "@",  "=",  ";"};
    for (const char* op : kOps) {
      const std::string_view o(op);
      if (text_.substr(pos_, o.size()) == o) {
        pos_ += o.size();
        t.kind = Tok::Op;
        t.text = std::string(o);
        return t;
      }
    }
    fail(fmt::format("invalid syntax: unexpected character '{}'", c));
  }

  Token number() {
    Token t;
    t.at = pos_;
    std::size_t end = pos_;
    if (text_.substr(pos_, 2) == "0x" || text_.substr(pos_, 2) == "0X" || text_.substr(pos_, 2) == "0o" ||
        text_.substr(pos_, 2) == "0O" || text_.substr(pos_, 2) == "0b" || text_.substr(pos_, 2) == "0B") {
      const int base = std::tolower(static_cast<unsigned char>(text_[pos_ + 1])) == 'x' ? 16
                       : std::tolower(static_cast<unsigned char>(text_[pos_ + 1])) == 'o' ? 8 : 2;
      end += 2;
      std::string digits;
      while (end < text_.size() && (std::isxdigit(static_cast<unsigned char>(text_[end])) || text_[end] == '_')) {
        if (text_[end] != '_') digits += text_[end];
        ++end;
      }
      errno = 0;
      char* stop = nullptr;
      const long long v = std::strtoll(digits.c_str(), &stop, base);
      if (digits.empty() || *stop != '\0' || errno == ERANGE) fail(fmt::format("invalid number '{}'", text_.substr(pos_, end - pos_)));
      t.kind = Tok::Int;
      t.integer = v;
      pos_ = end;
      return t;
    }
    bool real = false;
    while (end < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[end])) || text_[end] == '_')) ++end;
    if (end < text_.size() && text_[end] == '.') {
      real = true;
      ++end;
      while (end < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[end])) || text_[end] == '_')) ++end;
    }
    if (end < text_.size() && (text_[end] == 'e' || text_[end] == 'E')) {
      std::size_t e = end + 1;
      if (e < text_.size() && (text_[e] == '+' || text_[e] == '-')) ++e;
      if (e < text_.size() && std::isdigit(static_cast<unsigned char>(text_[e]))) {
        real = true;
        end = e;
        while (end < text_.size() && std::isdigit(static_cast<unsigned char>(text_[end]))) ++end;
      }
    }
    if (end < text_.size() && (text_[end] == 'j' || text_[end] == 'J')) unsupported("complex number");
    std::string literal;
    for (char ch : text_.substr(pos_, end - pos_))
      if (ch != '_') literal += ch;
    pos_ = end;
    if (real) {
      t.kind = Tok::Float;
      t.real = std::strtod(literal.c_str(), nullptr);
    } else {
      t.kind = Tok::Int;
      errno = 0;
      t.integer = std::strtoll(literal.c_str(), nullptr, 10);
      if (errno == ERANGE) fail(fmt::format("integer {} is beyond 64 bits", literal));
    }
    return t;
  }

  Token string(bool raw, std::size_t start) {
    Token t;
    t.at = start;
    t.kind = Tok::String;
    const char quote = text_[pos_];
    const bool triple = text_.substr(pos_, 3) == std::string(3, quote);
    pos_ += triple ? 3 : 1;
    for (;;) {
      if (pos_ >= text_.size()) fail("invalid syntax: unterminated string literal");
      const char c = text_[pos_];
      if (triple ? text_.substr(pos_, 3) == std::string(3, quote) : c == quote) {
        pos_ += triple ? 3 : 1;
        return t;
      }
      if (c == '\\' && pos_ + 1 < text_.size()) {
        const char e = text_[pos_ + 1];
        pos_ += 2;
        if (raw) {
          t.text += '\\';
          t.text += e;
          continue;
        }
        switch (e) {
          case 'n': t.text += '\n'; break;
          case 't': t.text += '\t'; break;
          case 'r': t.text += '\r'; break;
          case '\\': t.text += '\\'; break;
          case '\'': t.text += '\''; break;
          case '"': t.text += '"'; break;
          case '\n': break;
          default: t.text += '\\'; t.text += e; break;
        }
        continue;
      }
      t.text += c;
      ++pos_;
    }
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

NodePtr make(Kind kind) {
  auto n = std::make_unique<Node>();
  n->kind = kind;
  return n;
}

constexpr std::size_t kMaxNesting = 100;

class Parser {
 public:
  explicit Parser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

  NodePtr parse() {
    if (peek().kind == Tok::End) fail("invalid syntax: empty expression");
    NodePtr n = expression_list();
    if (peek().kind != Tok::End) syntax_error();
    return n;
  }

 private:
  const Token& peek(std::size_t ahead = 0) const { return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)]; }
  bool is_op(std::string_view op, std::size_t ahead = 0) const { return peek(ahead).kind == Tok::Op && peek(ahead).text == op; }
  bool is_word(std::string_view word, std::size_t ahead = 0) const { return peek(ahead).kind == Tok::Name && peek(ahead).text == word; }
  bool accept_op(std::string_view op) {
    if (!is_op(op)) return false;
    ++pos_;
    return true;
  }
  bool accept_word(std::string_view word) {
    if (!is_word(word)) return false;
    ++pos_;
    return true;
  }
  void expect_op(std::string_view op) {
    if (!accept_op(op)) syntax_error();
  }
  [[noreturn]] void syntax_error() const {
    const Token& t = peek();
    if (t.kind == Tok::End) fail("invalid syntax: unexpected end of expression");
    fail(fmt::format("invalid syntax at '{}'", t.kind == Tok::String ? "'" + t.text + "'" : t.text.empty() ? "number" : t.text));
  }

  struct Depth {
    explicit Depth(std::size_t& d) : d_(d) {
      if (++d_ > kMaxNesting) fail("expression nested too deeply");
    }
    ~Depth() { --d_; }
    std::size_t& d_;
  };

  // `a, b` at the top level is a tuple, as in Python.
  NodePtr expression_list() {
    NodePtr first = expression();
    if (!is_op(",")) return first;
    NodePtr tuple = make(Kind::Tuple);
    tuple->children.push_back(std::move(first));
    while (accept_op(",")) {
      if (peek().kind == Tok::End || is_op(")")) break;
      tuple->children.push_back(expression());
    }
    return tuple;
  }

  NodePtr expression() {
    Depth depth(depth_);
    if (is_word("lambda")) unsupported("lambda");
    if (is_word("yield")) unsupported("yield");
    if (is_word("await")) unsupported("await");
    NodePtr body = or_test();
    if (is_op(":=")) unsupported("assignment expression (:=)");
    if (!accept_word("if")) return body;
    NodePtr condition = or_test();
    if (!accept_word("else")) syntax_error();
    NodePtr otherwise = expression();
    NodePtr n = make(Kind::IfElse);
    n->children.push_back(std::move(condition));
    n->children.push_back(std::move(body));
    n->children.push_back(std::move(otherwise));
    return n;
  }

  NodePtr or_test() {
    NodePtr left = and_test();
    while (accept_word("or")) {
      NodePtr n = make(Kind::Or);
      n->children.push_back(std::move(left));
      n->children.push_back(and_test());
      left = std::move(n);
    }
    return left;
  }

  NodePtr and_test() {
    NodePtr left = not_test();
    while (accept_word("and")) {
      NodePtr n = make(Kind::And);
      n->children.push_back(std::move(left));
      n->children.push_back(not_test());
      left = std::move(n);
    }
    return left;
  }

  NodePtr not_test() {
    if (accept_word("not")) {
      Depth depth(depth_);
      NodePtr n = make(Kind::Not);
      n->children.push_back(not_test());
      return n;
    }
    return comparison();
  }

  std::optional<std::string> comparison_op() {
    for (const char* op : {"==", "!=", "<=", ">=", "<", ">"})
      if (accept_op(op)) return std::string(op);
    if (accept_word("in")) return std::string("in");
    if (is_word("not") && is_word("in", 1)) {
      pos_ += 2;
      return std::string("not in");
    }
    if (accept_word("is")) return std::string(accept_word("not") ? "is not" : "is");
    return std::nullopt;
  }

  NodePtr comparison() {
    NodePtr first = bitwise();
    std::optional<std::string> op = comparison_op();
    if (!op) return first;
    NodePtr n = make(Kind::Compare);
    n->children.push_back(std::move(first));
    while (op) {
      n->ops.push_back(*op);
      n->children.push_back(bitwise());
      op = comparison_op();
    }
    return n;
  }

  NodePtr bitwise() {
    NodePtr n = arith();
    for (const char* op : {"|", "^", "&", "<<", ">>"})
      if (is_op(op)) unsupported(fmt::format("bitwise operator '{}'", op));
    return n;
  }

  NodePtr arith() {
    NodePtr left = term();
    while (is_op("+") || is_op("-")) {
      NodePtr n = make(Kind::Binary);
      n->text = peek().text;
      ++pos_;
      n->children.push_back(std::move(left));
      n->children.push_back(term());
      left = std::move(n);
    }
    return left;
  }

  NodePtr term() {
    NodePtr left = factor();
    while (is_op("*") || is_op("/") || is_op("//") || is_op("%") || is_op("@")) {
      if (is_op("@")) unsupported("matrix multiplication '@'");
      NodePtr n = make(Kind::Binary);
      n->text = peek().text;
      ++pos_;
      n->children.push_back(std::move(left));
      n->children.push_back(factor());
      left = std::move(n);
    }
    return left;
  }

  NodePtr factor() {
    Depth depth(depth_);
    if (is_op("~")) unsupported("bitwise operator '~'");
    if (is_op("+") || is_op("-")) {
      NodePtr n = make(Kind::Unary);
      n->text = peek().text;
      ++pos_;
      n->children.push_back(factor());
      return n;
    }
    NodePtr base = primary();
    if (!accept_op("**")) return base;
    NodePtr n = make(Kind::Binary);
    n->text = "**";
    n->children.push_back(std::move(base));
    n->children.push_back(factor());
    return n;
  }

  NodePtr primary() {
    NodePtr n = atom();
    for (;;) {
      if (accept_op(".")) {
        if (peek().kind != Tok::Name) syntax_error();
        NodePtr a = make(Kind::Attribute);
        a->text = peek().text;
        ++pos_;
        a->children.push_back(std::move(n));
        n = std::move(a);
      } else if (accept_op("(")) {
        NodePtr call = make(Kind::Call);
        call->children.push_back(std::move(n));
        while (!accept_op(")")) {
          if (is_op("*") || is_op("**")) unsupported("argument unpacking");
          if (peek().kind == Tok::Name && is_op("=", 1)) {
            call->ops.push_back(peek().text);
            pos_ += 2;
          } else {
            call->ops.push_back("");
          }
          call->children.push_back(expression());
          if (is_word("for")) unsupported("generator expression");
          if (!accept_op(",")) {
            expect_op(")");
            break;
          }
        }
        n = std::move(call);
      } else if (accept_op("[")) {
        NodePtr index = make(Kind::Subscript);
        index->children.push_back(std::move(n));
        NodePtr lower = is_op(":") ? nullptr : expression();
        if (accept_op(":")) {
          NodePtr slice = make(Kind::Slice);
          slice->children.push_back(std::move(lower));
          slice->children.push_back(is_op("]") || is_op(":") ? nullptr : expression());
          if (accept_op(":")) unsupported("slice step");
          index->children.push_back(std::move(slice));
        } else {
          index->children.push_back(std::move(lower));
        }
        if (is_op(",")) unsupported("multi-dimensional subscript");
        expect_op("]");
        n = std::move(index);
      } else {
        return n;
      }
    }
  }

  NodePtr atom() {
    Depth depth(depth_);
    const Token& t = peek();
    switch (t.kind) {
      case Tok::Int: {
        NodePtr n = make(Kind::Constant);
        n->constant = Value(t.integer);
        ++pos_;
        return n;
      }
      case Tok::Float: {
        NodePtr n = make(Kind::Constant);
        n->constant = Value(t.real);
        ++pos_;
        return n;
      }
      case Tok::String: {
        std::string text;
        while (peek().kind == Tok::String) text += tokens_[pos_++].text;  // adjacent literals concatenate
        NodePtr n = make(Kind::Constant);
        n->constant = Value(std::move(text));
        return n;
      }
      case Tok::Name: {
        static const char* const kKeywords[] = {"import", "from", "def", "class", "for", "while", "return", "del",
                                                "global", "nonlocal", "assert", "with", "try", "except", "raise",
                                                "pass", "break", "continue", "async", "elif", "as", "finally"};
        for (const char* k : kKeywords)
          if (t.text == k) unsupported(fmt::format("'{}'", k));
        for (const char* k : {"and", "or", "not", "in", "is", "if", "else"})
          if (t.text == k) syntax_error();
        if (t.text.find("__") == 0) fail(fmt::format("Use of invalid name(s): {}", t.text));
        NodePtr n = make(Kind::Name);
        n->text = t.text;
        ++pos_;
        return n;
      }
      case Tok::Op:
        if (accept_op("(")) {
          if (accept_op(")")) return make(Kind::Tuple);
          NodePtr inner = expression();
          if (is_word("for")) unsupported("generator expression");
          if (!is_op(",")) {
            expect_op(")");
            return inner;
          }
          NodePtr tuple = make(Kind::Tuple);
          tuple->children.push_back(std::move(inner));
          while (accept_op(",")) {
            if (is_op(")")) break;
            tuple->children.push_back(expression());
          }
          expect_op(")");
          return tuple;
        }
        if (accept_op("[")) {
          NodePtr list = make(Kind::List);
          while (!accept_op("]")) {
            list->children.push_back(expression());
            if (list->children.size() == 1 && is_word("for")) return comprehension(std::move(list->children[0]));
            if (!accept_op(",")) {
              expect_op("]");
              break;
            }
          }
          return list;
        }
        if (accept_op("{")) {
          NodePtr dict = make(Kind::Dict);
          while (!accept_op("}")) {
            if (is_op("**")) unsupported("dictionary unpacking");
            dict->children.push_back(expression());
            if (!accept_op(":")) unsupported("set literal");
            dict->children.push_back(expression());
            if (is_word("for")) unsupported("dictionary comprehension");
            if (!accept_op(",")) {
              expect_op("}");
              break;
            }
          }
          return dict;
        }
        syntax_error();
      case Tok::End: syntax_error();
    }
    syntax_error();
  }

  NodePtr comprehension(NodePtr element) {
    NodePtr n = make(Kind::ListComp);
    n->children.push_back(std::move(element));
    while (accept_word("for")) {
      n->ops.push_back("for");
      n->children.push_back(target_list());
      if (!accept_word("in")) syntax_error();
      n->children.push_back(or_test());
      while (accept_word("if")) {
        n->ops.push_back("if");
        n->children.push_back(or_test());
      }
    }
    if (is_word("async")) unsupported("'async'");
    expect_op("]");
    return n;
  }

  // What a `for` clause assigns to: a name, or names in a tuple (`for k, v in d.items()`).
  NodePtr target_list(std::string_view close = "in") {
    NodePtr first = target();
    if (!is_op(",")) return first;
    NodePtr tuple = make(Kind::Tuple);
    tuple->children.push_back(std::move(first));
    while (accept_op(",")) {
      if (close == "in" ? is_word("in") : is_op(close)) break;
      tuple->children.push_back(target());
    }
    return tuple;
  }

  NodePtr target() {
    Depth depth(depth_);
    if (accept_op("(")) {  // `(a)` is `a`, `(a,)` unpacks one item
      NodePtr inner = target_list(")");
      expect_op(")");
      return inner;
    }
    if (accept_op("[")) {  // `[a]` unpacks one item
      NodePtr inner = target_list("]");
      expect_op("]");
      if (inner->kind == Kind::Tuple) return inner;
      NodePtr one = make(Kind::Tuple);
      one->children.push_back(std::move(inner));
      return one;
    }
    if (peek().kind != Tok::Name || !is_name(peek().text)) syntax_error();
    if (peek().text.find("__") == 0) fail(fmt::format("Use of invalid name(s): {}", peek().text));
    NodePtr n = make(Kind::Name);
    n->text = peek().text;
    ++pos_;
    return n;
  }

  static bool is_name(std::string_view text) {
    static const char* const kReserved[] = {"and", "or", "not", "in", "is", "if", "else", "for", "lambda", "True",
                                            "False", "None", "import", "from", "def", "class", "while", "return",
                                            "del", "global", "nonlocal", "assert", "with", "try", "except", "raise",
                                            "pass", "break", "continue", "async", "await", "yield", "elif", "as", "finally"};
    return std::none_of(std::begin(kReserved), std::end(kReserved), [&](const char* k) { return text == k; });
  }

  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  std::size_t depth_ = 0;
};

}  // namespace

NodePtr parse_expression(std::string_view expression) { return Parser(Lexer(expression).run()).parse(); }

}  // namespace assetlint::xacro
