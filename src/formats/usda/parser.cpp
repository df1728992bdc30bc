#include "formats/usda/parser.h"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <new>
#include <unordered_map>
#include <utility>

#include "formats/usda/array_scan.h"
#include "formats/usda/lexer.h"
#include "util/binary_data.h"

namespace assetlint::usda {

namespace {

bool is_list_op_keyword(std::string_view s) {
  return s == "add" || s == "append" || s == "prepend" || s == "delete" || s == "reorder";
}

ListOp list_op_from(std::string_view s) {
  if (s == "add") return ListOp::Add;
  if (s == "append") return ListOp::Append;
  if (s == "prepend") return ListOp::Prepend;
  if (s == "delete") return ListOp::Delete;
  if (s == "reorder") return ListOp::Reorder;
  return ListOp::Explicit;
}

// Attribute types whose arrays are never numeric (kept materialized).
bool is_non_numeric_type(std::string_view t) {
  return t == "string" || t == "token" || t == "asset" || t == "pathExpression" || t == "opaque" ||
         t == "dictionary";
}

// Keys whose values are reference-style lists (`@a@</p> (offset = 1)`).
bool is_arc_key(std::string_view k) {
  return k == "references" || k == "payload" || k == "subLayers" || k == "inherits" || k == "specializes";
}

struct Failure {
  ParseError error;
};

// Turns byte offsets into Spans. Requests come mostly in increasing order, so it keeps
// the current line and column and moves forward from there: the line by stepping through
// the file's line index, the column by counting code points since the last request on
// that line. (A 1 MB file can be a single line; nothing here rescans it.)
class SpanMaker {
 public:
  SpanMaker(const SourceFile& file, FileId id, std::size_t start = 0) : file_(file), id_(id), text_(file.view()) {
    if (text_.size() >= 3 && text_.compare(0, 3, "\xEF\xBB\xBF") == 0) off_ = bom_ = 3;
    if (start > off_ && start <= text_.size()) {
      // A parse that starts inside the text (one value) starts at that line.
      line_ = file.position(start).line;
      off_ = std::max(bom_, file.line_start(line_));
    }
  }

  Span span(std::size_t offset, std::size_t length) {
    if (offset > text_.size()) offset = text_.size();
    if (offset < off_ || offset < bom_) return file_.span(id_, offset, length);
    const std::uint32_t lines = file_.line_count();
    bool moved = false;
    while (line_ < lines && file_.line_start(line_ + 1) <= offset) {
      ++line_;
      moved = true;
    }
    if (moved) {
      off_ = file_.line_start(line_);
      col_ = 1;
    }
    const char* s = text_.data();
    std::uint32_t col = col_;
    for (std::size_t i = off_; i < offset; ++i) col += (static_cast<unsigned char>(s[i]) & 0xC0) != 0x80;
    col_ = col;
    off_ = offset;
    return Span{id_, offset, length, line_, col_};
  }

 private:
  const SourceFile& file_;
  FileId id_;
  std::string_view text_;
  std::size_t bom_ = 0;
  std::size_t off_ = 0;      // last offset asked for
  std::uint32_t line_ = 1;   // its line
  std::uint32_t col_ = 1;    // its column
};

std::string quote_for_message(std::string_view s) {
  constexpr std::size_t kMax = 40;
  std::string out;
  out.reserve(std::min(s.size(), kMax) + 5);
  for (std::size_t i = 0; i < s.size() && i < kMax; ++i) {
    const char c = s[i];
    if (c == '\n' || c == '\r') {
      out += ' ';
    } else {
      out += c;
    }
  }
  if (s.size() > kMax) out += "...";
  return out;
}

class Parser {
 public:
  // Reads the text from `start` up to `end`.
  Parser(const SourceFile& file, FileId id, const ParseOptions& options, std::size_t start = 0,
         std::size_t end = std::string_view::npos)
      : file_(file), id_(id), text_(file.view().substr(0, end)), lex_(text_, start), spans_(file, id, start),
        options_(options) {}

  Layer parse_layer();
  Value parse_standalone_value();
  Value parse_whole_value(std::string_view metadata_key, std::string_view attribute_type);

 private:
  // --- tokens ------------------------------------------------------------------
  void advance() {
    tok_ = lex_.next();
    if (tok_.kind == TokenKind::Error) {
      throw Failure{ParseError{lex_.error_message(), file_.span(id_, tok_.offset, tok_.length)}};
    }
  }
  Token peek() {
    Lexer copy = lex_;
    return copy.next();
  }
  std::string_view text(const Token& t) const { return text_.substr(t.offset, t.length); }
  bool is(TokenKind k) const { return tok_.kind == k; }
  bool is_word(std::string_view w) const { return tok_.kind == TokenKind::Identifier && text(tok_) == w; }
  Span span_of(const Token& t) { return spans_.span(t.offset, t.length); }
  // Span from `start` to the end of the previously consumed token.
  void close(Span& s) const { s.length = prev_end_ - s.offset; }
  void consume() {
    prev_end_ = tok_.end();
    advance();
  }

  std::string describe(const Token& t) const {
    switch (t.kind) {
      case TokenKind::End: return "end of file";
      case TokenKind::Identifier: return "'" + quote_for_message(text(t)) + "'";
      case TokenKind::Number: return "number " + quote_for_message(text(t));
      case TokenKind::String: return "string " + quote_for_message(text(t));
      case TokenKind::AssetPath: return "asset path " + quote_for_message(text(t));
      case TokenKind::PathRef: return "path " + quote_for_message(text(t));
      default: return token_kind_name(t.kind);
    }
  }

  [[noreturn]] void fail_here(const std::string& what) {
    throw Failure{ParseError{what + ", found " + describe(tok_), file_.span(id_, tok_.offset, tok_.length)}};
  }
  [[noreturn]] void fail_at(const std::string& message, std::size_t offset, std::size_t length) {
    throw Failure{ParseError{message, file_.span(id_, offset, length)}};
  }
  Token expect(TokenKind k, const char* context_fmt_before, std::string_view context_name = {}) {
    if (tok_.kind != k) {
      std::string msg = std::string("expected ") + token_kind_name(k) + " " + context_fmt_before;
      if (!context_name.empty()) msg += " '" + quote_for_message(context_name) + "'";
      fail_here(msg);
    }
    Token t = tok_;
    consume();
    return t;
  }

  // A statement (metadata item, property, dictionary entry) ends at a line break, a ';',
  // or the bracket closing its block.
  void end_statement(TokenKind closer, const std::string& what) {
    if (is(TokenKind::Semicolon) || is(closer) || is(TokenKind::End) || (tok_.flags & kTokenNewlineBefore) != 0) return;
    fail_here("expected a line break or ';' after " + what);
  }

  struct DepthGuard {
    Parser& p;
    explicit DepthGuard(Parser& parser) : p(parser) {
      if (++p.depth_ > p.options_.max_depth) {
        p.fail_at("nesting deeper than " + std::to_string(p.options_.max_depth) + " levels", p.tok_.offset,
                  p.tok_.length);
      }
    }
    ~DepthGuard() { --p.depth_; }
  };

  // --- grammar -----------------------------------------------------------------
  void parse_metadata_block(std::vector<Metadata>& out, const char* owner);
  Metadata parse_metadata_item();
  Value parse_arc_list();
  Value parse_arc_item();
  void parse_arc_parameters(Value& item);
  Value parse_value(bool numeric_array_hint);
  Value parse_atomic();
  Value parse_sequence(TokenKind open, TokenKind close, ValueKind kind);
  bool try_skip_numeric_list(Value& out);
  Value parse_dictionary();
  void parse_prim(std::vector<Prim>& siblings);
  void parse_prim_body(Prim& prim);
  void parse_variant_set(Prim& prim);
  void parse_reorder(std::vector<ReorderStatement>& out);
  void parse_property(Prim& prim, struct NameIndex& index);
  void parse_relationship(Prim& prim, NameIndex& index, ListOp op, Span start, Span op_span, bool custom,
                          bool varying);
  PathList parse_path_list(const char* context, std::string_view name);
  TimeSamples parse_time_samples(bool numeric_array_hint);
  Value skip_braced_block();

  const SourceFile& file_;
  FileId id_;
  std::string_view text_;
  Lexer lex_;
  SpanMaker spans_;
  const ParseOptions& options_;
  Token tok_;
  std::size_t prev_end_ = 0;
  std::size_t depth_ = 0;
};

// Finds a prim's attribute or relationship by name while the prim is being parsed.
// Keys are views of the source text, which outlives the parse.
struct NameIndex {
  std::unordered_map<std::string_view, std::uint32_t> attrs;
  std::unordered_map<std::string_view, std::uint32_t> rels;

  template <class T>
  static T* find(std::vector<T>& items, std::unordered_map<std::string_view, std::uint32_t>& map,
                 std::string_view name) {
    auto it = map.find(name);
    return it == map.end() ? nullptr : &items[it->second];
  }
};

// ---------------------------------------------------------------------------------
Layer Parser::parse_layer() {
  Layer layer;
  layer.file = id_;
  const Header h = lex_.read_header();
  if (!h.ok) {
    const std::size_t start = text_.size() >= 3 && text_.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    if (text_.compare(start, 5, "#usda") != 0 || text_.size() < start + 5) {
      // Binary data is described, not quoted.
      if (const auto binary = first_binary_byte(text_.substr(start)))
        fail_at(fmt::format("binary data, not a USD layer: byte {} is U+{:04X}; a layer is '#usda 1.0' text or a "
                            "'PXR-USDC' crate",
                            start + *binary, static_cast<unsigned char>(text_[start + *binary])),
                start + *binary, 1);
      fail_at("missing '#usda 1.0' header on the first line", start, 0);
    }
    fail_at("malformed header: expected '#usda <version>' on the first line", start, h.body_offset - start);
  }
  layer.version = std::string(h.version);
  {
    const std::size_t start = text_.size() >= 3 && text_.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    layer.header_span = spans_.span(start, h.version_offset + h.version.size() - start);
  }
  advance();
  if (is(TokenKind::LParen)) parse_metadata_block(layer.metadata, "layer");
  for (;;) {
    if (is(TokenKind::End)) break;
    if (is(TokenKind::Semicolon)) {
      consume();
      continue;
    }
    if (is_word("def") || is_word("over") || is_word("class")) {
      parse_prim(layer.prims);
    } else if (is_word("reorder")) {
      parse_reorder(layer.reorders);
    } else {
      fail_here("expected 'def', 'over' or 'class' to start a prim");
    }
  }
  return layer;
}

Value Parser::parse_standalone_value() {
  advance();
  return parse_value(false);
}

Value Parser::parse_whole_value(std::string_view metadata_key, std::string_view attribute_type) {
  advance();
  Value v;
  if (metadata_key.empty()) {
    const bool is_array = attribute_type.ends_with("[]");
    v = parse_value(is_array && !is_non_numeric_type(attribute_type.substr(0, attribute_type.size() - 2)));
  } else if (metadata_key == "symmetryFunction") {
    fail_here("a symmetryFunction value is read with its statement only");
  } else if (is_word("None")) {
    v.kind = ValueKind::None;
    v.span = span_of(tok_);
    consume();
  } else if (is_arc_key(metadata_key)) {
    v = parse_arc_list();
  } else {
    v = parse_value(false);
  }
  if (!is(TokenKind::End)) fail_here("expected the end of the value");
  return v;
}

void Parser::parse_metadata_block(std::vector<Metadata>& out, const char* owner) {
  DepthGuard guard(*this);
  const Token open = tok_;
  consume();  // (
  for (;;) {
    if (is(TokenKind::Semicolon)) {
      consume();
      continue;
    }
    if (is(TokenKind::RParen)) {
      consume();
      return;
    }
    if (is(TokenKind::End)) {
      fail_at(std::string("unterminated ") + owner + " metadata: missing ')' for the '(' here", open.offset, 1);
    }
    out.push_back(parse_metadata_item());
    end_statement(TokenKind::RParen, "metadata '" + out.back().key + "'");
  }
}

Metadata Parser::parse_metadata_item() {
  Metadata m;
  m.span = span_of(tok_);
  if (is(TokenKind::String)) {
    m.key = "doc";
    m.is_doc_shorthand = true;
    m.key_span = m.span;
    m.value = parse_atomic();
    close(m.span);
    return m;
  }
  if (!is(TokenKind::Identifier)) fail_here("expected a metadata key or ')'");
  if (is_list_op_keyword(text(tok_)) && peek().kind == TokenKind::Identifier) {
    m.op = list_op_from(text(tok_));
    m.op_span = m.span;
    consume();
  }
  if (!is(TokenKind::Identifier)) fail_here("expected a metadata key");
  m.key = std::string(text(tok_));
  m.key_span = span_of(tok_);
  consume();
  if (!is(TokenKind::Equals)) fail_here("expected '=' after metadata key '" + m.key + "'");
  const Token eq = tok_;
  consume();
  if (m.key == "symmetryFunction" &&
      (!is(TokenKind::Identifier) || (tok_.flags & kTokenNewlineBefore) != 0)) {
    // `symmetryFunction =` may have no value.
    m.value.kind = ValueKind::None;
    m.value.span = spans_.span(eq.end(), 0);
  } else if (is_word("None")) {
    m.value.kind = ValueKind::None;
    m.value.span = span_of(tok_);
    consume();
  } else if (is_arc_key(m.key)) {
    m.value = parse_arc_list();
  } else {
    if (is(TokenKind::RParen) || is(TokenKind::End) || is(TokenKind::Semicolon)) {
      fail_here("expected a value after '" + m.key + " ='");
    }
    m.value = parse_value(false);
  }
  close(m.span);
  return m;
}

Value Parser::parse_arc_list() {
  if (!is(TokenKind::LBracket)) return parse_arc_item();
  DepthGuard guard(*this);
  Value list;
  list.kind = ValueKind::List;
  list.span = span_of(tok_);
  consume();
  for (;;) {
    if (is(TokenKind::RBracket)) break;
    list.elements.push_back(parse_arc_item());
    if (is(TokenKind::Comma)) {
      consume();
      continue;
    }
    if (!is(TokenKind::RBracket)) fail_here("expected ',' or ']' in list");
  }
  consume();
  list.count = list.elements.size();
  close(list.span);
  return list;
}

Value Parser::parse_arc_item() {
  Value item;
  if (is(TokenKind::PathRef)) {
    item = parse_atomic();
  } else if (is(TokenKind::AssetPath)) {
    item = parse_atomic();
    if (is(TokenKind::PathRef)) {
      const std::string_view t = text(tok_);
      item.prim_path = std::string(t.substr(1, t.size() - 2));
      item.prim_path_span = span_of(tok_);
      consume();
    }
  } else {
    fail_here("expected an asset path @...@ or a prim path <...>");
  }
  if (is(TokenKind::LParen)) parse_arc_parameters(item);
  close(item.span);
  return item;
}

void Parser::parse_arc_parameters(Value& item) {
  DepthGuard guard(*this);
  const Token open = tok_;
  consume();
  for (;;) {
    if (is(TokenKind::Semicolon)) {
      consume();
      continue;
    }
    if (is(TokenKind::RParen)) {
      consume();
      return;
    }
    if (is(TokenKind::End)) fail_at("missing ')' for the '(' here", open.offset, 1);
    if (!is(TokenKind::Identifier)) fail_here("expected 'offset', 'scale' or 'customData'");
    DictEntry e;
    e.key = std::string(text(tok_));
    e.span = e.key_span = span_of(tok_);
    consume();
    if (!is(TokenKind::Equals)) fail_here("expected '=' after '" + e.key + "'");
    consume();
    e.value = parse_value(false);
    close(e.span);
    item.entries.push_back(std::move(e));
  }
}

Value Parser::parse_atomic() {
  Value v;
  v.span = span_of(tok_);
  const std::string_view t = text(tok_);
  switch (tok_.kind) {
    case TokenKind::Number:
      v.kind = ValueKind::Number;
      v.number = parse_number(t);
      v.is_integer = (tok_.flags & kTokenFloat) == 0;
      break;
    case TokenKind::Identifier:
      if (t == "None") {
        v.kind = ValueKind::None;
      } else if (t == "inf" || t == "nan") {
        v.kind = ValueKind::Number;
        v.number = parse_number(t);
      } else {
        v.kind = ValueKind::Identifier;
        v.text = std::string(t);
      }
      break;
    case TokenKind::String:
      v.kind = ValueKind::String;
      v.text = decode_string(t);
      break;
    case TokenKind::AssetPath:
      v.kind = ValueKind::AssetPath;
      v.text = decode_asset_path(t);
      break;
    case TokenKind::PathRef:
      v.kind = ValueKind::Path;
      v.text = std::string(t.substr(1, t.size() - 2));
      break;
    default:
      fail_here("expected a value");
  }
  consume();
  return v;
}

Value Parser::parse_value(bool numeric_array_hint) {
  switch (tok_.kind) {
    case TokenKind::LParen: return parse_sequence(TokenKind::LParen, TokenKind::RParen, ValueKind::Tuple);
    case TokenKind::LBracket: {
      if (numeric_array_hint && options_.lazy_arrays) {
        Value v;
        if (try_skip_numeric_list(v)) return v;
      }
      return parse_sequence(TokenKind::LBracket, TokenKind::RBracket, ValueKind::List);
    }
    case TokenKind::LBrace: return parse_dictionary();
    case TokenKind::Number:
    case TokenKind::Identifier:
    case TokenKind::String:
    case TokenKind::AssetPath:
    case TokenKind::PathRef: return parse_atomic();
    default: fail_here("expected a value");
  }
}

Value Parser::parse_sequence(TokenKind open, TokenKind close_kind, ValueKind kind) {
  DepthGuard guard(*this);
  Value v;
  v.kind = kind;
  v.span = span_of(tok_);
  const Token open_tok = tok_;
  consume();
  (void)open;
  const char* closer = close_kind == TokenKind::RParen ? "')'" : "']'";
  const char* what = kind == ValueKind::Tuple ? "tuple" : "list";
  for (;;) {
    if (is(close_kind)) {
      if (kind == ValueKind::Tuple && v.elements.empty()) fail_here("expected a value in tuple");
      break;
    }
    if (is(TokenKind::End)) {
      fail_at(std::string("unterminated ") + what + ": missing " + closer + " for the one here", open_tok.offset, 1);
    }
    if (is(TokenKind::LBrace)) fail_here(std::string("expected a value in ") + what);
    v.elements.push_back(parse_value(false));
    if (is(TokenKind::Comma)) {
      consume();
      continue;
    }
    if (!is(close_kind)) {
      if (is(TokenKind::End)) {
        fail_at(std::string("unterminated ") + what + ": missing " + closer + " for the one here", open_tok.offset,
                1);
      }
      fail_here(std::string("expected ',' or ") + closer + " in " + what);
    }
  }
  consume();
  v.count = v.elements.size();
  close(v.span);
  return v;
}

// Skips over a large list of numbers / nested tuples of numbers without building nodes,
// keeping only its span and item count. Returns false (nothing consumed) if the list is
// small or is not a well-formed numeric list; the caller then parses it normally, which
// also produces the precise error for malformed input.
bool Parser::try_skip_numeric_list(Value& out) {
  const auto scan = scan_numeric_array(text_, tok_.offset, options_.max_depth);
  if (!scan || scan->count <= options_.eager_array_limit) return false;
  out.kind = ValueKind::List;
  out.lazy = true;
  out.count = scan->count;
  out.span = spans_.span(tok_.offset, scan->end - tok_.offset);
  prev_end_ = scan->end;
  lex_.reset(scan->end);
  advance();
  return true;
}

Value Parser::parse_dictionary() {
  DepthGuard guard(*this);
  Value v;
  v.kind = ValueKind::Dictionary;
  v.span = span_of(tok_);
  const Token open = tok_;
  consume();
  for (;;) {
    if (is(TokenKind::Semicolon) || is(TokenKind::Comma)) {
      consume();
      continue;
    }
    if (is(TokenKind::RBrace)) break;
    if (is(TokenKind::End)) fail_at("unterminated dictionary: missing '}' for the '{' here", open.offset, 1);
    DictEntry e;
    e.span = span_of(tok_);
    if ((is(TokenKind::String) || is(TokenKind::PathRef)) && peek().kind == TokenKind::Colon) {
      // {"from": "to"} (prefix/suffix substitutions) or {</a>: </b>} (relocates)
      e.key_span = e.span;
      e.key_value = parse_atomic();
      e.key = e.key_value.text;
      consume();  // :
      e.value = parse_value(false);
    } else {
      if (!is(TokenKind::Identifier)) fail_here("expected a type name, a key or '}' in dictionary");
      e.type_name = std::string(text(tok_));
      consume();
      if (is(TokenKind::LBracket)) {
        consume();
        if (!is(TokenKind::RBracket)) fail_here("expected ']' after '[' in type name '" + e.type_name + "[]'");
        consume();
        e.type_is_array = true;
      }
      if (!is(TokenKind::Identifier) && !is(TokenKind::String)) {
        fail_here("expected a key after type '" + e.type_name + "' in dictionary");
      }
      e.key_span = span_of(tok_);
      e.key_value = parse_atomic();
      e.key = e.key_value.text;
      if (!is(TokenKind::Equals)) fail_here("expected '=' after dictionary key '" + e.key + "'");
      consume();
      if (e.type_name == "dictionary") {
        if (!is(TokenKind::LBrace)) fail_here("expected '{' after 'dictionary " + e.key + " ='");
        e.value = parse_dictionary();
      } else {
        e.value = parse_value(false);
      }
    }
    close(e.span);
    v.entries.push_back(std::move(e));
    if (!is(TokenKind::Comma)) end_statement(TokenKind::RBrace, "dictionary entry '" + v.entries.back().key + "'");
  }
  consume();
  v.count = v.entries.size();
  close(v.span);
  return v;
}

void Parser::parse_reorder(std::vector<ReorderStatement>& out) {
  ReorderStatement r;
  r.span = span_of(tok_);
  consume();  // reorder
  if (!is(TokenKind::Identifier)) fail_here("expected 'nameChildren', 'properties' or 'rootPrims' after 'reorder'");
  r.what = std::string(text(tok_));
  consume();
  if (!is(TokenKind::Equals)) fail_here("expected '=' after 'reorder " + r.what + "'");
  consume();
  if (!is(TokenKind::LBracket) && !is(TokenKind::String)) fail_here("expected a list of names");
  r.names = parse_value(false);
  close(r.span);
  out.push_back(std::move(r));
}

void Parser::parse_prim(std::vector<Prim>& siblings) {
  DepthGuard guard(*this);
  Prim prim;
  prim.span = span_of(tok_);
  prim.specifier_span = prim.span;
  const std::string_view spec = text(tok_);
  prim.specifier = spec == "def" ? Specifier::Def : spec == "over" ? Specifier::Over : Specifier::Class;
  consume();
  if (is(TokenKind::Identifier)) {
    prim.type_name = std::string(text(tok_));
    prim.type_span = span_of(tok_);
    consume();
  }
  if (!is(TokenKind::String)) fail_here(std::string("expected a quoted prim name after '") + specifier_name(prim.specifier) + "'");
  prim.name_span = span_of(tok_);
  prim.name = decode_string(text(tok_));
  consume();
  if (is(TokenKind::LParen)) parse_metadata_block(prim.metadata, "prim");
  if (!is(TokenKind::LBrace)) fail_here("expected '{' to open prim '" + prim.name + "'");
  prim.open_brace_span = span_of(tok_);
  consume();
  parse_prim_body(prim);
  close(prim.span);
  siblings.push_back(std::move(prim));
}

void Parser::parse_prim_body(Prim& prim) {
  const std::size_t open = prev_end_ - 1;
  NameIndex index;
  for (;;) {
    if (is(TokenKind::RBrace)) {
      consume();
      return;
    }
    if (is(TokenKind::Semicolon)) {
      consume();
      continue;
    }
    if (is(TokenKind::End)) {
      fail_at("unterminated prim '" + prim.name + "': missing '}' for the '{' here", open, 1);
    }
    if (!is(TokenKind::Identifier)) fail_here("expected a property, a prim or '}' in prim '" + prim.name + "'");
    const std::string_view w = text(tok_);
    if (w == "def" || w == "over" || w == "class") {
      parse_prim(prim.children);
    } else if (w == "variantSet") {
      parse_variant_set(prim);
    } else if (w == "reorder") {
      const Token next = peek();
      const std::string_view nw = next.kind == TokenKind::Identifier ? lex_.token_text(next) : std::string_view{};
      if (nw == "nameChildren" || nw == "properties") {
        parse_reorder(prim.reorders);
      } else {
        parse_property(prim, index);
      }
    } else {
      parse_property(prim, index);
    }
  }
}

void Parser::parse_variant_set(Prim& prim) {
  DepthGuard guard(*this);
  VariantSet set;
  set.span = span_of(tok_);
  consume();  // variantSet
  if (!is(TokenKind::String)) fail_here("expected a quoted variant set name after 'variantSet'");
  set.name_span = span_of(tok_);
  set.name = decode_string(text(tok_));
  consume();
  if (!is(TokenKind::Equals)) fail_here("expected '=' after variantSet \"" + set.name + "\"");
  consume();
  if (!is(TokenKind::LBrace)) fail_here("expected '{' to open variantSet \"" + set.name + "\"");
  const Token open = tok_;
  consume();
  for (;;) {
    if (is(TokenKind::RBrace)) break;
    if (is(TokenKind::End)) fail_at("unterminated variantSet: missing '}' for the '{' here", open.offset, 1);
    if (!is(TokenKind::String)) fail_here("expected a quoted variant name or '}' in variantSet \"" + set.name + "\"");
    DepthGuard inner(*this);
    Variant var;
    var.span = span_of(tok_);
    var.name_span = var.span;
    var.name = decode_string(text(tok_));
    var.body.specifier = Specifier::Over;
    var.body.name = var.name;
    var.body.name_span = var.name_span;
    consume();
    if (is(TokenKind::LParen)) parse_metadata_block(var.body.metadata, "variant");
    if (!is(TokenKind::LBrace)) fail_here("expected '{' to open variant \"" + var.name + "\"");
    var.body.open_brace_span = span_of(tok_);
    consume();
    parse_prim_body(var.body);
    close(var.span);
    var.body.span = var.span;
    set.variants.push_back(std::move(var));
  }
  consume();
  close(set.span);
  prim.variant_sets.push_back(std::move(set));
}

PathList Parser::parse_path_list(const char* context, std::string_view name) {
  PathList list;
  list.span = span_of(tok_);
  if (is_word("None")) {
    list.none = true;
    consume();
  } else if (is(TokenKind::PathRef)) {
    list.paths.push_back(parse_atomic());
  } else if (is(TokenKind::LBracket)) {
    const Token open = tok_;
    consume();
    for (;;) {
      if (is(TokenKind::RBracket)) break;
      if (is(TokenKind::End)) fail_at("unterminated list: missing ']' for the '[' here", open.offset, 1);
      if (!is(TokenKind::PathRef)) fail_here(std::string("expected a path <...> in ") + context + " '" + std::string(name) + "'");
      list.paths.push_back(parse_atomic());
      if (is(TokenKind::Comma)) {
        consume();
        continue;
      }
      if (!is(TokenKind::RBracket)) fail_here("expected ',' or ']' in list");
    }
    consume();
  } else {
    fail_here(std::string("expected a path <...>, a list of paths or None for ") + context + " '" + std::string(name) + "'");
  }
  close(list.span);
  return list;
}

TimeSamples Parser::parse_time_samples(bool numeric_array_hint) {
  DepthGuard guard(*this);
  TimeSamples ts;
  ts.span = span_of(tok_);
  const Token open = tok_;
  consume();  // {
  for (;;) {
    if (is(TokenKind::RBrace)) break;
    if (is(TokenKind::End)) fail_at("unterminated timeSamples: missing '}' for the '{' here", open.offset, 1);
    TimeSample s;
    if (!(is(TokenKind::Number) || is_word("inf") || is_word("nan"))) fail_here("expected a time code number in timeSamples");
    s.time_span = span_of(tok_);
    s.time = parse_number(text(tok_));
    consume();
    if (!is(TokenKind::Colon)) fail_here("expected ':' after time code in timeSamples");
    consume();
    if (is(TokenKind::Comma) || is(TokenKind::RBrace)) fail_here("expected a value after ':' in timeSamples");
    s.value = parse_value(numeric_array_hint);
    ts.samples.push_back(std::move(s));
    if (is(TokenKind::Comma)) {
      consume();
      continue;
    }
    if (!is(TokenKind::RBrace)) fail_here("expected ',' or '}' in timeSamples");
  }
  consume();
  close(ts.span);
  return ts;
}

Value Parser::skip_braced_block() {
  // Splines: kept as their span only. Any tokens are accepted inside balanced braces.
  Value v;
  v.kind = ValueKind::None;
  v.span = span_of(tok_);
  const Token open = tok_;
  std::size_t depth = 0;
  for (;;) {
    if (is(TokenKind::LBrace) || is(TokenKind::LParen) || is(TokenKind::LBracket)) {
      if (++depth > options_.max_depth) fail_here("nesting too deep");
    } else if (is(TokenKind::RBrace) || is(TokenKind::RParen) || is(TokenKind::RBracket)) {
      if (depth == 0) fail_here("unbalanced bracket in spline");
      --depth;
      if (depth == 0) {
        consume();
        break;
      }
    } else if (is(TokenKind::End)) {
      fail_at("unterminated spline: missing '}' for the '{' here", open.offset, 1);
    }
    consume();
  }
  close(v.span);
  return v;
}

void Parser::parse_property(Prim& prim, NameIndex& index) {
  Span start = span_of(tok_);
  Span op_span;
  ListOp op = ListOp::Explicit;
  if (is_list_op_keyword(text(tok_))) {
    op = list_op_from(text(tok_));
    op_span = start;
    consume();
  }
  bool custom = false;
  if (is_word("custom")) {
    custom = true;
    consume();
  }
  Variability variability = Variability::Varying;
  bool varying_kw = false;
  if (is_word("uniform")) {
    variability = Variability::Uniform;
    consume();
  } else if (is_word("config")) {
    variability = Variability::Config;
    consume();
  } else if (is_word("varying")) {
    varying_kw = true;
    consume();
  }
  if (is_word("rel")) {
    if (variability != Variability::Varying) fail_here("a relationship cannot be 'uniform' or 'config'; expected a type name");
    parse_relationship(prim, index, op, start, op_span, custom, varying_kw);
    return;
  }
  if (!is(TokenKind::Identifier)) fail_here("expected an attribute type name or 'rel'");
  const Token type_tok = tok_;
  const std::string_view type_name = text(tok_);
  if (type_name.find('.') != std::string_view::npos) fail_here("expected an attribute type name");
  consume();
  bool is_array = false;
  if (is(TokenKind::LBracket)) {
    consume();
    if (!is(TokenKind::RBracket)) fail_here("expected ']' after '[' in type '" + std::string(type_name) + "[]'");
    consume();
    is_array = true;
  }
  if (!is(TokenKind::Identifier)) {
    fail_here("expected an attribute name after type '" + std::string(type_name) + (is_array ? "[]'" : "'"));
  }
  const Token name_tok = tok_;
  std::string_view full = text(tok_);
  std::string_view suffix;
  std::string_view name = full;
  if (const auto dot = full.rfind('.'); dot != std::string_view::npos) {
    name = full.substr(0, dot);
    suffix = full.substr(dot + 1);
    if (suffix != "timeSamples" && suffix != "connect" && suffix != "spline" && suffix != "default") {
      fail_at("unknown property field '." + std::string(suffix) + "' (expected .timeSamples, .connect or .spline)",
              name_tok.offset + dot, suffix.size() + 1);
    }
    if (suffix == "default") fail_at("'.default' is only allowed on relationships", name_tok.offset + dot, suffix.size() + 1);
  }
  if (op != ListOp::Explicit && suffix != "connect") {
    fail_at(std::string("list-op '") + list_op_name(op) + "' is only allowed on relationships and attribute connections",
            op_span.offset, op_span.length);
  }
  consume();

  Attribute* attr = NameIndex::find(prim.attributes, index.attrs, name);
  if (attr == nullptr) {
    prim.attributes.emplace_back();
    attr = &prim.attributes.back();
    attr->custom = custom;
    attr->variability = variability;
    attr->type_name = std::string(type_name);
    attr->is_array = is_array;
    attr->name = std::string(name);
    attr->span = start;
    attr->type_span = spans_.span(type_tok.offset, type_tok.length);
    attr->name_span = spans_.span(name_tok.offset, name.size());
    const auto idx = static_cast<std::uint32_t>(prim.attributes.size() - 1);
    index.attrs.emplace(name, idx);
    prim.property_order.push_back(PropertyRef{false, idx});
  }
  const bool numeric_array = is_array && !is_non_numeric_type(type_name);
  Span decl = start;
  if (!suffix.empty()) {
    if (!is(TokenKind::Equals)) fail_here("expected '=' after '" + std::string(full) + "'");
    consume();
    if (suffix == "timeSamples") {
      if (!is(TokenKind::LBrace)) fail_here("expected '{' to open timeSamples of '" + std::string(name) + "'");
      TimeSamples ts = parse_time_samples(numeric_array);
      close(decl);
      ts.declaration_span = decl;
      attr->time_samples = std::move(ts);
    } else if (suffix == "connect") {
      PathList list = parse_path_list("connection of attribute", name);
      list.op = op;
      close(decl);
      list.declaration_span = decl;
      attr->connections.push_back(std::move(list));
    } else {  // spline
      if (!is(TokenKind::LBrace)) fail_here("expected '{' to open spline of '" + std::string(name) + "'");
      attr->spline = skip_braced_block();
    }
  } else {
    if (!is(TokenKind::Equals) && !is(TokenKind::LParen) && !is(TokenKind::Semicolon) && !is(TokenKind::RBrace) &&
        (tok_.flags & kTokenNewlineBefore) == 0) {
      fail_here("expected '=' after attribute name '" + std::string(name) + "'");
    }
    if (is(TokenKind::Equals)) {
      consume();
      if (is(TokenKind::RParen) || is(TokenKind::RBrace) || is(TokenKind::End) || is(TokenKind::Semicolon) ||
          is(TokenKind::Comma) || is(TokenKind::RBracket)) {
        fail_here("expected a value after '" + std::string(name) + " ='");
      }
      Value v = parse_value(numeric_array);
      attr->default_value = std::move(v);
    }
    if (is(TokenKind::LParen)) parse_metadata_block(attr->metadata, "attribute");
    end_statement(TokenKind::RBrace, "attribute '" + std::string(name) + "'");
    close(decl);
    if (attr->default_value) attr->default_declaration_span = decl;
  }
  if (attr->span.offset == start.offset) close(attr->span);
}

void Parser::parse_relationship(Prim& prim, NameIndex& index, ListOp op, Span start, Span op_span, bool custom,
                                bool varying) {
  (void)op_span;
  consume();  // rel
  if (!is(TokenKind::Identifier)) fail_here("expected a relationship name after 'rel'");
  const Token name_tok = tok_;
  const std::string_view full = text(tok_);
  std::string_view name = full;
  std::string_view suffix;
  if (const auto dot = full.rfind('.'); dot != std::string_view::npos) {
    name = full.substr(0, dot);
    suffix = full.substr(dot + 1);
    if (suffix != "default" && suffix != "timeSamples") {
      fail_at("unknown relationship field '." + std::string(suffix) + "' (expected .default)", name_tok.offset + dot,
              suffix.size() + 1);
    }
  }
  consume();
  Relationship* rel = NameIndex::find(prim.relationships, index.rels, name);
  if (rel == nullptr) {
    prim.relationships.emplace_back();
    rel = &prim.relationships.back();
    rel->custom = custom;
    rel->varying = varying;
    rel->name = std::string(name);
    rel->span = start;
    rel->name_span = spans_.span(name_tok.offset, name.size());
    const auto idx = static_cast<std::uint32_t>(prim.relationships.size() - 1);
    index.rels.emplace(name, idx);
    prim.property_order.push_back(PropertyRef{true, idx});
  }
  Span decl = start;
  if (suffix == "default") {
    if (!is(TokenKind::Equals)) fail_here("expected '=' after '" + std::string(full) + "'");
    consume();
    if (!is(TokenKind::PathRef)) fail_here("expected a path <...> for '" + std::string(full) + "'");
    rel->default_target = parse_atomic();
  } else if (suffix == "timeSamples") {
    if (!is(TokenKind::Equals)) fail_here("expected '=' after '" + std::string(full) + "'");
    consume();
    if (!is(TokenKind::LBrace)) fail_here("expected '{' to open timeSamples of '" + std::string(name) + "'");
    (void)parse_time_samples(false);
  } else {
    if (is(TokenKind::LBracket) && peek().kind == TokenKind::PathRef && op == ListOp::Explicit) {
      // Legacy `rel x[</target>]` form: a single target without '='.
      consume();
      PathList list;
      list.span = span_of(tok_);
      list.paths.push_back(parse_atomic());
      if (!is(TokenKind::RBracket)) fail_here("expected ']' after target path");
      consume();
      close(list.span);
      close(decl);
      list.declaration_span = decl;
      rel->targets.push_back(std::move(list));
    } else if (is(TokenKind::Equals)) {
      consume();
      PathList list = parse_path_list("relationship", name);
      list.op = op;
      if (is(TokenKind::LParen)) parse_metadata_block(rel->metadata, "relationship");
      close(decl);
      list.declaration_span = decl;
      rel->targets.push_back(std::move(list));
    } else {
      if (op != ListOp::Explicit) fail_here("expected '=' after 'rel " + std::string(name) + "'");
      if (is(TokenKind::LParen)) parse_metadata_block(rel->metadata, "relationship");
    }
  }
  end_statement(TokenKind::RBrace, "relationship '" + std::string(name) + "'");
  if (rel->span.offset == start.offset) close(rel->span);
}

}  // namespace

// ---------------------------------------------------------------------------------
ParseResult parse_layer(const SourceFile& file, FileId id, const ParseOptions& options) {
  try {
    Parser parser(file, id, options);
    return ParseResult(parser.parse_layer());
  } catch (Failure& f) {
    return ParseResult(std::move(f.error));
  }
}

std::variant<Value, ParseError> parse_value_at(const SourceFile& file, FileId id, std::size_t begin, std::size_t end,
                                               std::string_view metadata_key, std::string_view attribute_type) {
  try {
    const ParseOptions options;
    Parser parser(file, id, options, begin, end);
    return parser.parse_whole_value(metadata_key, attribute_type);
  } catch (Failure& f) {
    return std::move(f.error);
  }
}

std::variant<std::vector<Value>, ParseError> parse_elements(const Value& list, const SourceFile& file, FileId id) {
  if (!list.lazy) return list.elements;
  if (list.held) return list.held->elements();
  ParseOptions options;
  options.lazy_arrays = false;
  try {
    Parser parser(file, id, options, list.span.offset);
    Value v = parser.parse_standalone_value();
    return std::move(v.elements);
  } catch (Failure& f) {
    return std::move(f.error);
  }
}

std::optional<ParseError> materialize(Value& list, const SourceFile& file, FileId id) {
  if (!list.lazy) return std::nullopt;
  auto r = parse_elements(list, file, id);
  if (auto* err = std::get_if<ParseError>(&r)) return *err;
  list.elements = std::move(std::get<std::vector<Value>>(r));
  list.count = list.elements.size();
  list.lazy = false;
  return std::nullopt;
}

bool read_numbers(const Value& value, std::string_view text, std::vector<double>& out) {
  switch (value.kind) {
    case ValueKind::Number: out.push_back(value.number); return true;
    case ValueKind::Tuple:
    case ValueKind::List:
      if (!value.lazy) {
        for (const Value& e : value.elements)
          if (!read_numbers(e, text, out)) return false;
        return true;
      } else if (value.held) {
        value.held->append_numbers(out);
        return true;
      } else {
        if (value.span.end() > text.size()) return false;
        Lexer lex(text.substr(0, value.span.end()), value.span.offset);
        for (Token t = lex.next(); t.kind != TokenKind::End; t = lex.next()) {
          switch (t.kind) {
            case TokenKind::Number:
            case TokenKind::Identifier: {
              const std::string_view w = lex.token_text(t);
              if (t.kind == TokenKind::Identifier && w != "inf" && w != "nan") return false;
              out.push_back(parse_number(w));
              break;
            }
            case TokenKind::LBracket:
            case TokenKind::RBracket:
            case TokenKind::LParen:
            case TokenKind::RParen:
            case TokenKind::Comma: break;
            default: return false;
          }
        }
        return true;
      }
    default: return false;
  }
}

}  // namespace assetlint::usda
