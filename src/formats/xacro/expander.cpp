#include "formats/xacro/expander.h"

#include <fmt/format.h>
#include <fnmatch.h>

#include <algorithm>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <regex>
#include <set>

#include "formats/xacro/expression.h"
#include "formats/xacro/packages.h"
#include "formats/xacro/yaml_data.h"

namespace assetlint::xacro {

OutAttribute* OutNode::attribute(std::string_view attr) {
  for (auto& a : attributes)
    if (a.name == attr) return &a;
  return nullptr;
}

namespace {

namespace fs = std::filesystem;

// Thrown inside the expander; becomes the ExpandError at the top.
struct Failure {
  Span span;
  std::string message;
  std::vector<Note> notes;
};

struct Tracked {
  Value value;
  Origin origin;
};

struct Table;

struct Entry {
  enum class Kind { Value, Lazy, SourceBlock, OutBlock, Namespace };
  Kind kind = Kind::Value;
  Tracked tracked;                        // Value
  std::string text;                       // Lazy: the definition, evaluated at first use
  Span span;                              // Lazy: where the definition's value is written
  CallChain chain;                        // Lazy: the macro calls it was defined in
  const XNode* block = nullptr;           // SourceBlock: the xacro:property holding the block
  std::shared_ptr<const OutNode> output;  // OutBlock: a macro's block parameter, expanded
  Table* ns = nullptr;                    // Namespace
};

struct Table {
  Table* parent = nullptr;
  bool is_namespace = false;
  std::map<std::string, Entry, std::less<>> entries;
  std::vector<std::string> resolving;  // lazy properties being evaluated, to name a cycle

  Table* top() {
    Table* t = this;
    while (t->parent) t = t->parent;
    return t;
  }
  std::pair<Table*, Entry*> find(std::string_view name) {
    for (Table* t = this; t; t = t->parent)
      if (auto it = t->entries.find(name); it != t->entries.end()) return {t, &it->second};
    return {nullptr, nullptr};
  }
};

struct Macro {
  std::string name;
  std::vector<std::string> params;
  struct Default {
    std::optional<std::string> forward;  // ^: the caller's property of the same name
    std::optional<std::string> text;
    Span span;
  };
  std::map<std::string, Default> defaults;
  const XNode* body = nullptr;
};

struct MacroTable {
  MacroTable* parent = nullptr;
  std::map<std::string, std::shared_ptr<const Macro>, std::less<>> macros;
  std::map<std::string, MacroTable*, std::less<>> namespaces;

  const Macro* find(std::string_view name) const {
    for (const MacroTable* t = this; t; t = t->parent)
      if (auto it = t->macros.find(name); it != t->macros.end()) return it->second.get();
    return nullptr;
  }
  MacroTable* find_namespace(std::string_view name) const {
    for (const MacroTable* t = this; t; t = t->parent)
      if (auto it = t->namespaces.find(name); it != t->namespaces.end()) return it->second;
    return nullptr;
  }
};

// An element as the expander handles it: xacro:element and xacro:call rename it and drop
// the attribute that named it.
struct ElementView {
  const XNode* node;
  std::string name;
  std::vector<const XAttribute*> attributes;
};

ElementView view_of(const XNode& node) {
  ElementView v{&node, node.name, {}};
  for (const auto& a : node.attributes) v.attributes.push_back(&a);
  return v;
}

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  return std::string(s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1));
}

bool is_identifier(std::string_view name) {
  static const std::set<std::string, std::less<>> kKeywords = {
      "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class", "continue", "def", "del", "elif",
      "else", "except", "finally", "for", "from", "global", "if", "import", "in", "is", "lambda", "nonlocal", "not", "or",
      "pass", "raise", "return", "try", "while", "with", "yield"};
  if (name.empty() || kKeywords.count(name)) return false;
  if (!(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_' || static_cast<unsigned char>(name[0]) >= 0x80))
    return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || static_cast<unsigned char>(c) >= 0x80;
  });
}

// Table._eval_literal: a property's text that reads as a number or a boolean is one.
Value eval_literal(Value value) {
  if (!value.is_string()) return value;
  const std::string& s = value.string();
  if (s.size() >= 2 && s.front() == '\'' && s.back() == '\'') return Value(s.substr(1, s.size() - 2));
  if (s.find('_') != std::string::npos) return value;
  if (auto i = python_int_literal(s)) return Value(*i);
  if (auto f = python_float_literal(s)) return Value(*f);
  if (s == "true" || s == "True") return Value(true);
  if (s == "false" || s == "False") return Value(false);
  return value;
}

std::string location(const Span& span, const std::vector<std::shared_ptr<const SourceFile>>& files, FileId first) {
  const std::string path = span.file >= first && span.file - first < files.size()
                               ? fs::path(files[span.file - first]->path()).filename().string()
                               : std::string("?");
  return fmt::format("{}:{}:{}", path, span.line, span.column);
}

class Expander;

// The names a ${…} expression sees: the properties in scope, recorded as used.
class NameScope : public ExpressionScope {
 public:
  NameScope(Expander& expander, Table* table) : expander_(expander), table_(table) {}
  std::optional<Value> lookup(std::string_view name) override;
  std::optional<Value> lookup_in(const NamespaceRef& ns, std::string_view name) override;
  Value load_yaml(const std::string& filename) override;
  Value arg(const std::string& name) override;
  std::string abs_filename(const std::string& filename) override;

  std::vector<std::pair<std::string, Origin>> used;
  std::set<std::string> arguments;

 private:
  Expander& expander_;
  Table* table_;
};

// The names $(eval …) sees: the arguments, and roslaunch's functions.
class EvalScope : public ExpressionScope {
 public:
  explicit EvalScope(Expander& expander) : expander_(expander) {}
  std::optional<Value> lookup(std::string_view name) override;
  std::optional<Value> lookup_in(const NamespaceRef&, std::string_view) override { return std::nullopt; }
  Value load_yaml(const std::string&) override { throw EvalError("unsupported in $(eval …): xacro.load_yaml"); }
  Value arg(const std::string& name) override;
  std::string abs_filename(const std::string&) override { throw EvalError("unsupported in $(eval …): xacro.abs_filename"); }
  std::optional<Value> call(std::string_view name, const std::vector<Value>& args) override;

  std::set<std::string> arguments;

 private:
  Expander& expander_;
};

// No names at all: a YAML unit tag's expression sees only xacro's globals.
class GlobalScope : public ExpressionScope {
 public:
  std::optional<Value> lookup(std::string_view) override { return std::nullopt; }
  std::optional<Value> lookup_in(const NamespaceRef&, std::string_view) override { return std::nullopt; }
  Value load_yaml(const std::string&) override { throw EvalError("unsupported here: xacro.load_yaml"); }
  Value arg(const std::string&) override { throw EvalError("unsupported here: xacro.arg"); }
  std::string abs_filename(const std::string&) override { throw EvalError("unsupported here: xacro.abs_filename"); }
};

// roslaunch resolves $(anon name) to the name followed by the host name, the process id and a
// random number, the same for one name throughout a run; a fixed suffix keeps that contract
// and makes the expansion reproducible.
std::string anonymous_name(const std::string& name) { return name + "_anon"; }

// roslaunch's convert_value(…, 'auto'): what $(eval …) makes of an argument's text.
Value auto_convert(const std::string& text) {
  if (text.find('.') != std::string::npos) {
    if (auto f = python_float_literal(text)) return Value(*f);
  } else if (auto i = python_int_literal(text)) {
    return Value(*i);
  }
  std::string lower = text;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "true") return Value(true);
  if (lower == "false") return Value(false);
  return Value(text);
}

class Expander {
 public:
  Expander(const FileSystem& files, const ExpandOptions& options) : files_(files), options_(options) {
    for (const auto& [name, value] : options.arguments) arguments_[name] = value;
  }

  ExpandResult run(std::shared_ptr<const SourceFile> top) {
    ExpandResult result;
    try {
      const SourceTree& tree = add_tree(std::move(top), Span{});
      Table& globals = tables_.emplace_back();
      MacroTable& macros = macro_tables_.emplace_back();
      file_stack_.push_back({tree.file->path(), Span{}});
      Expansion expansion;
      OutNode& root = expansion.root;
      root.kind = XNode::Kind::Element;
      root.name = tree.root.name;
      root.span = tree.root.span;
      root.chain = chain_;
      for (const XAttribute& a : tree.root.attributes) {
        if (a.name == "xacro:targetNamespace") {
          root.attributes.push_back({"xmlns", a.value, literal(a)});
          continue;
        }
        if (a.name.starts_with("xacro:") || a.name == "xmlns:xacro") continue;
        root.attributes.push_back(attribute(a, &globals));
      }
      process_children(tree.root, &globals, &macros, root);
      remove_comment_stops(root);
      expansion.files = files_read_;
      expansion.arguments = arguments_;
      result.expansion = std::move(expansion);
    } catch (const Failure& f) {
      result.error = ExpandError{f.span, f.message, f.notes};
    }
    result.files = files_read_;
    return result;
  }

  // ---- names -------------------------------------------------------------------------

  std::optional<Value> lookup(Table* table, std::string_view name, NameScope& scope) {
    auto [owner, entry] = table->find(name);
    if (!entry) return std::nullopt;
    switch (entry->kind) {
      case Entry::Kind::Lazy: resolve(owner, std::string(name), *entry); [[fallthrough]];
      case Entry::Kind::Value:
        scope.used.emplace_back(std::string(name), entry->tracked.origin);
        if (entry->tracked.origin.kind == Origin::Kind::Argument) {
          for (auto& a : split_names(entry->tracked.origin.name)) scope.arguments.insert(a);
        }
        return entry->tracked.value;
      case Entry::Kind::Namespace: return Value::ns(entry->ns);
      case Entry::Kind::SourceBlock:
      case Entry::Kind::OutBlock: throw EvalError(fmt::format("the block '{}' is not a value", name));
    }
    return std::nullopt;
  }

  Value argument(const std::string& name, std::set<std::string>& used) {
    auto it = arguments_.find(name);
    if (it == arguments_.end()) throw EvalError(fmt::format("Undefined substitution argument {}", name));
    used.insert(name);
    return Value(it->second.value);
  }

  std::string current_file() const { return file_stack_.back().path; }
  std::string current_dir() const {
    std::error_code ec;
    return fs::absolute(fs::path(current_file()), ec).parent_path().string();
  }

  std::string abs_filename(const std::string& spec) const {
    if (fs::path(spec).is_absolute()) return spec;
    const fs::path base = fs::path(current_file()).parent_path();
    return (base.empty() ? fs::path(spec) : base / spec).string();
  }

  Value load_yaml(const std::string& spec) {
    const std::string path = abs_filename(spec);
    std::string error;
    std::optional<std::string> text = files_.read(path, error);
    if (!text) throw EvalError(fmt::format("cannot read YAML file '{}': {}", path, error));
    GlobalScope globals;
    return parse_yaml(*text, [&](const std::string& expression) { return evaluate_expression(expression, globals); });
  }

  std::optional<std::string> find_package(const std::string& name) const {
    return find_ros_package(name, current_file(), options_.root);
  }

 private:
  struct FileFrame {
    std::string path;
    Span include;  // the xacro:include that brought the file in
  };

  static std::vector<std::string> split_names(const std::string& names) {
    std::vector<std::string> out;
    std::size_t at = 0;
    while (at <= names.size()) {
      const std::size_t end = std::min(names.find(", ", at), names.size());
      if (end > at) out.push_back(names.substr(at, end - at));
      at = end + 2;
    }
    return out;
  }

  // ---- errors ------------------------------------------------------------------------

  [[noreturn]] void fail(const Span& span, std::string message) {
    Failure f{span, std::move(message), {}};
    for (auto it = macro_stack_.rbegin(); it != macro_stack_.rend(); ++it)
      f.notes.push_back({fmt::format("in macro '{}' called at {}", it->macro, where(it->call)), it->call});
    for (std::size_t i = file_stack_.size(); i-- > 1;)
      f.notes.push_back({fmt::format("in '{}' included at {}", fs::path(file_stack_[i].path).filename().string(),
                                     where(file_stack_[i].include)),
                         file_stack_[i].include});
    throw f;
  }

  std::string where(const Span& span) const { return location(span, files_read_, options_.first_id); }

  // ---- files -------------------------------------------------------------------------

  const SourceTree& add_tree(std::shared_ptr<const SourceFile> file, const Span& included_at) {
    const FileId id = options_.first_id + static_cast<FileId>(files_read_.size());
    files_read_.push_back(file);
    TreeError error;
    std::optional<SourceTree> tree = parse_tree(file, id, error);
    if (!tree) fail(error.span.valid() ? error.span : included_at, std::move(error.message));
    return trees_.emplace_back(std::move(*tree));
  }

  // ---- text evaluation ---------------------------------------------------------------

  Origin literal(const XAttribute& a) const { return Origin{Origin::Kind::Literal, a.value_span, a.value_span, {}, chain_}; }

  // eval_text: the pieces of `text` (plain text, ${…}, $(…), $${ and $$( escapes); a single
  // piece keeps its type, several are joined as strings.
  Tracked eval_text(const std::string& text, Table* table, const Span& span) {
    std::vector<Value> results;
    std::vector<std::pair<std::string, Origin>> used;
    std::set<std::string> arguments;
    bool computed = false;
    std::string single_name;  // the piece is `${name}`
    std::size_t pos = 0;
    while (pos < text.size()) {
      if (text[pos] != '$') {
        const std::size_t end = std::min(text.find('$', pos), text.size());
        results.emplace_back(text.substr(pos, end - pos));
        pos = end;
        continue;
      }
      std::size_t dollars = pos;
      while (dollars < text.size() && text[dollars] == '$') ++dollars;
      const char next = dollars < text.size() ? text[dollars] : '\0';
      if (dollars - pos >= 2 && (next == '{' || next == '(')) {
        results.emplace_back(text.substr(pos + 1, dollars - pos));  // one $ fewer, and the bracket
        pos = dollars + 1;
        continue;
      }
      if (next == '{' || next == '(') {
        const char close = next == '{' ? '}' : ')';
        const std::size_t end = text.find(close, dollars + 1);
        if (end == std::string::npos) fail(span, fmt::format("invalid expression: {}", text.substr(pos)));
        const std::string inner = text.substr(dollars + 1, end - dollars - 1);
        computed = true;
        if (next == '{') {
          Tracked source = eval_text(inner, table, span);
          merge(source.origin, used, arguments);
          const std::string expression = python_str(source.value);
          NameScope scope(*this, table);
          try {
            results.push_back(evaluate_expression(trim(expression), scope));
          } catch (const EvalError& e) {
            fail(span, fmt::format("{} when evaluating expression '{}'", e.what(), inner));
          }
          used.insert(used.end(), scope.used.begin(), scope.used.end());
          arguments.insert(scope.arguments.begin(), scope.arguments.end());
          if (scope.used.size() == 1 && scope.used[0].first == trim(expression)) single_name = scope.used[0].first;
        } else {
          results.emplace_back(extension(inner, table, span, used, arguments));
        }
        pos = end + 1;
        continue;
      }
      // A `$` not starting an expression: `$` followed by other text, or a lone `$` at the end.
      if (dollars - pos >= 2 || (dollars - pos == 1 && dollars < text.size() && false))
        fail(span, fmt::format("invalid expression: {}", text.substr(pos)));
      std::size_t end = pos + 1;
      while (end < text.size() && text[end] != '$' && text[end] != '{' && text[end] != '(') ++end;
      if (end == pos + 1 && end < text.size()) fail(span, fmt::format("invalid expression: {}", text.substr(pos)));
      results.emplace_back(text.substr(pos, end - pos));
      pos = end;
    }
    Tracked out;
    if (results.size() == 1) out.value = results[0];
    else {
      std::string joined;
      for (const Value& v : results) {
        joined += python_str(v);
        if (joined.size() > kMaxExpressionResult) fail(span, "text longer than an expression may build");
      }
      out.value = Value(std::move(joined));
    }
    out.origin = Origin{Origin::Kind::Literal, span, span, {}, chain_};
    if (!computed) return out;
    if (results.size() == 1 && !single_name.empty() && used.size() == 1) {
      // `${name}`: the value is the property's, written where the property got it.
      out.origin = used[0].second;
      if (out.origin.kind == Origin::Kind::Literal) {
        out.origin.kind = Origin::Kind::Property;
        out.origin.name = single_name;
      }
      out.origin.use = span;
      out.origin.chain = chain_;
      return out;
    }
    if (!arguments.empty()) {
      std::string names;
      for (const auto& a : arguments) names += (names.empty() ? "" : ", ") + a;
      out.origin.kind = Origin::Kind::Argument;
      out.origin.name = names;
      return out;
    }
    out.origin.kind = Origin::Kind::Expression;
    out.origin.name = text;
    return out;
  }

  static void merge(const Origin& origin, std::vector<std::pair<std::string, Origin>>& used, std::set<std::string>& arguments) {
    if (origin.kind == Origin::Kind::Argument)
      for (const auto& a : split_names(origin.name)) arguments.insert(a);
    (void)used;
  }

  // A $(…) substitution argument.
  std::string extension(const std::string& raw, Table* table, const Span& span, std::vector<std::pair<std::string, Origin>>& used,
                        std::set<std::string>& arguments) {
    Tracked inner = eval_text(raw, table, span);
    merge(inner.origin, used, arguments);
    const std::string content = python_str(inner.value);
    if (content == "cwd") {
      std::error_code ec;
      return fs::current_path(ec).string();
    }
    if (content.starts_with("eval ")) {
      const std::string expression = content.substr(5);
      if (expression.find("__") != std::string::npos) fail(span, "$(eval ...) may not contain double underscore expressions");
      EvalScope scope(*this);
      try {
        const Value v = evaluate_expression(trim(expression), scope);
        arguments.insert(scope.arguments.begin(), scope.arguments.end());
        return python_str(v);
      } catch (const EvalError& e) {
        fail(span, fmt::format("{} when evaluating $(eval {})", e.what(), expression));
      }
    }
    std::vector<std::string> words;
    for (std::size_t at = 0; at < content.size();) {
      const std::size_t end = std::min(content.find(' ', at), content.size());
      if (end > at) words.push_back(content.substr(at, end - at));
      at = end + 1;
    }
    if (words.empty()) fail(span, "empty substitution argument $()");
    const std::string& command = words[0];
    const auto exactly_one = [&](const char* usage) {
      if (words.size() != 2) fail(span, fmt::format("{} accepts exactly one argument [{}]", usage, content));
    };
    if (command == "find") {
      exactly_one("$(find pkg)");
      if (auto dir = find_package(words[1])) return *dir;
      fail(span, fmt::format("resource not found: package '{}' (no package.xml with <name>{}</name> in the checked tree "
                             "or ROS_PACKAGE_PATH)",
                             words[1], words[1]));
    }
    if (command == "arg") {
      exactly_one("$(arg var)");
      try {
        return argument(words[1], arguments).string();
      } catch (const EvalError& e) {
        fail(span, fmt::format("{} (give it with --xacro-arg {}:=VALUE or in [xacro] args)", e.what(), words[1]));
      }
    }
    if (command == "env") {
      exactly_one("$(env var)");
      if (const char* v = std::getenv(words[1].c_str())) return v;
      fail(span, fmt::format("environment variable {} is not set", words[1]));
    }
    if (command == "optenv") {
      if (words.size() < 2) fail(span, "$(optenv var) must specify an environment variable");
      if (const char* v = std::getenv(words[1].c_str())) return v;
      std::string fallback;
      for (std::size_t i = 2; i < words.size(); ++i) fallback += (i > 2 ? " " : "") + words[i];
      return fallback;
    }
    if (command == "dirname") return current_dir();
    if (command == "anon") {
      if (words.size() < 2) fail(span, fmt::format("$(anon var) must specify a name [{}]", content));
      if (words.size() > 2) fail(span, fmt::format("$(anon var) may only specify one name [{}]", content));
      return anonymous_name(words[1]);
    }
    fail(span, fmt::format("Unknown substitution command [{}]. Valid commands are ['find', 'env', 'optenv', 'dirname', "
                           "'anon', 'arg', 'eval']",
                           content));
  }

  void resolve(Table* owner, const std::string& name, Entry& entry) {
    if (std::find(owner->resolving.begin(), owner->resolving.end(), name) != owner->resolving.end()) {
      std::string cycle;
      for (const auto& r : owner->resolving) cycle += r + " -> ";
      throw EvalError(fmt::format("circular variable definition: {}{} (a property that uses its own earlier value "
                                  "needs lazy_eval=\"false\")",
                                  cycle, name));
    }
    owner->resolving.push_back(name);
    const CallChain saved = chain_;
    chain_ = entry.chain;
    Tracked t;
    try {
      t = eval_text(entry.text, owner, entry.span);
    } catch (...) {
      chain_ = saved;
      owner->resolving.pop_back();
      throw;
    }
    chain_ = saved;
    owner->resolving.pop_back();
    t.value = eval_literal(std::move(t.value));
    entry.kind = Entry::Kind::Value;
    entry.tracked = std::move(t);
  }

  bool boolean(const Value& v, const std::string& condition, const Span& span) {
    if (v.is_string()) {
      const std::string& s = v.string();
      if (s == "true" || s == "True") return true;
      if (s == "false" || s == "False") return false;
      if (auto i = python_int_literal(s)) return *i != 0;
      fail(span, fmt::format("Xacro conditional \"{}\" evaluated to \"{}\", which is not a boolean expression.", condition, s));
    }
    return v.truthy();
  }

  // ---- output ------------------------------------------------------------------------

  // The clock is read every 4096 steps: often enough to stop within milliseconds of the
  // budget, rarely enough to cost nothing.
  void count_step(const Span& span) {
    if (++steps_ > options_.max_steps)
      fail(span, fmt::format("the expansion visited more than {} elements and macro calls; a macro calls itself "
                             "more often than any robot needs",
                             options_.max_steps));
    if (steps_ % 4096 == 0 && options_.deadline.passed())
      fail(span, fmt::format("the expansion ran out of the file's time budget of {:g} s (--time-budget)",
                             options_.deadline.budget_seconds()));
  }

  void spend(std::size_t bytes, const Span& span) {
    output_bytes_ += bytes;
    if (output_bytes_ > options_.max_output_bytes)
      fail(span, fmt::format("the expansion exceeds {} MiB; a macro or include repeats without end",
                             options_.max_output_bytes >> 20));
  }

  OutAttribute attribute(const XAttribute& a, Table* table) {
    Tracked t = eval_text(a.value, table, a.value_span);
    OutAttribute out{a.name, python_str(t.value), std::move(t.origin)};
    spend(sizeof(OutAttribute) + out.name.size() + out.value.size(), a.value_span);
    return out;
  }

  // ---- the walk ----------------------------------------------------------------------

  struct Depth {
    Depth(Expander& e, const Span& span) : e_(e) {
      if (++e_.depth_ > kMaxWalkDepth) e_.fail(span, fmt::format("expansion nested deeper than {} levels", kMaxWalkDepth));
      e_.count_step(span);
    }
    ~Depth() { --e_.depth_; }
    Expander& e_;
  };
  static constexpr std::size_t kMaxWalkDepth = 400;

  void process_children(const XNode& parent, Table* symbols, MacroTable* macros, OutNode& out) {
    bool eval_comments = false;
    for (const XNode& child : parent.children) {
      switch (child.kind) {
        case XNode::Kind::Element: {
          eval_comments = false;
          const ElementView view = view_of(child);
          const bool last = &child == &parent.children.back();
          if (!drops_previous_comments(view.name)) {
            process_element(view, symbols, macros, out);
            break;
          }
          drop_previous_comments(out);
          // xacro marks the stop after a conditional before its content is expanded (an
          // element inside moves the mark), after a macro call or include once it is.
          const bool mark_after = view.name == "xacro:include" || !xacro_construct(view.name);
          const std::uint64_t mark = mark_after ? 0 : ++comment_stop_;
          process_element(view, symbols, macros, out);
          if (last) break;
          if (mark_after) place_comment_stop(out, ++comment_stop_);
          else if (mark == comment_stop_) place_comment_stop(out, mark);
          break;
        }
        case XNode::Kind::Text: {
          Tracked t = eval_text(child.name, symbols, child.span);
          std::string text = python_str(t.value);
          if (!trim(text).empty()) eval_comments = false;
          spend(text.size(), child.span);
          out.children.push_back(OutNode{XNode::Kind::Text, std::move(text), {}, {}, child.span, chain_});
          break;
        }
        case XNode::Kind::Comment:
          if (child.name.find("xacro:eval-comments") != std::string::npos) {
            eval_comments = child.name.find("xacro:eval-comments:off") == std::string::npos;
            break;
          }
          out.children.push_back(OutNode{XNode::Kind::Comment,
                                         eval_comments ? python_str(eval_text(child.name, symbols, child.span).value) : child.name,
                                         {}, {}, child.span, chain_});
          spend(out.children.back().name.size(), child.span);
          break;
      }
    }
  }

  const XAttribute* attr(const ElementView& v, std::string_view name) const {
    for (const XAttribute* a : v.attributes)
      if (a->name == name) return a;
    return nullptr;
  }

  const XAttribute& required(const ElementView& v, std::string_view name) {
    if (const XAttribute* a = attr(v, name)) return *a;
    fail(v.node->span, fmt::format("{}: missing required attribute '{}'", v.name, name));
  }

  static bool xacro_construct(std::string_view name) {
    for (const char* n : {"xacro:if", "xacro:unless", "xacro:property", "xacro:macro", "xacro:arg", "xacro:include"})
      if (name == n) return true;
    return false;
  }
  static bool drops_previous_comments(std::string_view name) {
    return name.starts_with("xacro:") && name != "xacro:insert_block" && name != "xacro:element" && name != "xacro:attribute";
  }

  // remove_previous_comments: xacro drops the comments right before a macro, property,
  // include, argument, conditional or macro call (they documented the xacro construct), walking
  // back over single line breaks. It stops at a blank line, at anything else, and at the mark it
  // leaves after the xacro construct it handled last (one mark, moved each time).
  void drop_previous_comments(OutNode& out) const {
    auto& c = out.children;
    const auto previous = [&](std::size_t k) -> std::optional<std::size_t> {
      while (k > 0) {
        --k;
        if (c[k].comment_stop == 0 || c[k].comment_stop == comment_stop_) return k;  // a moved mark is gone
      }
      return std::nullopt;
    };
    std::optional<std::size_t> j = previous(c.size());
    while (j) {
      const OutNode& n = c[*j];
      if (n.kind == XNode::Kind::Text && n.comment_stop == 0 && trim(n.name).empty() && std::count(n.name.begin(), n.name.end(), '\n') <= 1)
        j = previous(*j);
      if (!j || c[*j].kind != XNode::Kind::Comment) return;
      c.erase(c.begin() + static_cast<std::ptrdiff_t>(*j));
      j = previous(*j);
    }
  }

  void place_comment_stop(OutNode& out, std::uint64_t mark) const {
    OutNode stop;
    stop.kind = XNode::Kind::Text;
    stop.comment_stop = mark;
    out.children.push_back(std::move(stop));
  }

  static void remove_comment_stops(OutNode& node) {
    std::erase_if(node.children, [](const OutNode& c) { return c.comment_stop != 0; });
    for (OutNode& c : node.children) remove_comment_stops(c);
  }

  void process_element(const ElementView& v, Table* symbols, MacroTable* macros, OutNode& out) {
    Depth depth(*this, v.node->span);
    const std::string& name = v.name;
    if (name == "xacro:insert_block") return insert_block(v, symbols, macros, out);
    if (name == "xacro:include") return include(v, symbols, macros, out);
    if (name == "xacro:property") return property(v, symbols);
    if (name == "xacro:macro") return define_macro(v, macros);
    if (name == "xacro:arg") {
      const std::string arg_name = required(v, "name").value;
      const XAttribute& def = required(v, "default");
      if (!arguments_.count(arg_name)) {
        Tracked t = eval_text(def.value, symbols, def.value_span);
        arguments_[arg_name] = ArgumentValue{python_str(t.value), "", def.value_span};
      }
      return;
    }
    if (name == "xacro:element") {
      const XAttribute& tag = required(v, "xacro:name");
      const std::string new_name = python_str(eval_text(tag.value, symbols, tag.value_span).value);
      if (new_name.empty()) fail(v.node->span, "xacro:element: empty name");
      ElementView renamed{v.node, new_name, {}};
      for (const XAttribute* a : v.attributes)
        if (a->name != "xacro:name") renamed.attributes.push_back(a);
      return process_element(renamed, symbols, macros, out);
    }
    if (name == "xacro:attribute") {
      const XAttribute& n = required(v, "name");
      const XAttribute& value = required(v, "value");
      const std::string attr_name = python_str(eval_text(n.value, symbols, n.value_span).value);
      if (attr_name.empty()) fail(v.node->span, "xacro:attribute: empty name");
      OutAttribute a = attribute(value, symbols);
      a.name = attr_name;
      if (OutAttribute* existing = out.attribute(attr_name)) *existing = std::move(a);
      else out.attributes.push_back(std::move(a));
      return;
    }
    if (name == "xacro:if" || name == "xacro:unless") {
      const XAttribute& cond = required(v, "value");
      const Tracked t = eval_text(cond.value, symbols, cond.value_span);
      bool keep = boolean(t.value, cond.value, cond.value_span);
      if (name == "xacro:unless") keep = !keep;
      if (keep) process_children(*v.node, symbols, macros, out);
      return;
    }
    if (name == "xacro:call") {
      const XAttribute& m = required(v, "macro");
      const std::string macro = python_str(eval_text(m.value, symbols, m.value_span).value);
      if (macro.empty()) fail(v.node->span, "xacro:call is missing the 'macro' attribute");
      ElementView call{v.node, "xacro:" + macro, {}};
      for (const XAttribute* a : v.attributes)
        if (a->name != "macro") call.attributes.push_back(a);
      return call_macro(call, symbols, macros, out);
    }
    if (name.starts_with("xacro:")) return call_macro(v, symbols, macros, out);

    OutNode element;
    element.kind = XNode::Kind::Element;
    element.name = name;
    element.span = v.node->span;
    element.chain = chain_;
    spend(sizeof(OutNode) + name.size(), v.node->span);
    for (const XAttribute* a : v.attributes) {
      if (a->name.starts_with("xacro:") || a->name == "xmlns:xacro") continue;
      element.attributes.push_back(attribute(*a, symbols));
    }
    process_children(*v.node, symbols, macros, element);
    out.children.push_back(std::move(element));
  }

  void insert_block(const ElementView& v, Table* symbols, MacroTable* macros, OutNode& out) {
    const std::string name = required(v, "name").value;
    auto [owner, entry] = symbols->find("**" + name);
    bool content_only = true;
    if (!entry) {
      std::tie(owner, entry) = symbols->find("*" + name);
      content_only = false;
    }
    if (!entry) fail(v.node->span, fmt::format("Undefined block \"{}\"", name));
    if (entry->kind == Entry::Kind::SourceBlock) {
      // A block property: evaluated where it is inserted.
      process_children(*entry->block, symbols, macros, out);
      return;
    }
    const OutNode& block = *entry->output;
    if (content_only) {
      for (const OutNode& c : block.children) copy_into(c, out, v.node->span);
    } else {
      copy_into(block, out, v.node->span);
    }
  }

  void copy_into(const OutNode& node, OutNode& out, const Span& span) {
    spend(approximate_size(node), span);
    out.children.push_back(node);
  }

  static std::size_t approximate_size(const OutNode& node) {
    std::size_t n = sizeof(OutNode) + node.name.size();
    for (const auto& a : node.attributes) n += sizeof(OutAttribute) + a.name.size() + a.value.size();
    for (const auto& c : node.children) n += approximate_size(c);
    return n;
  }

  void property(const ElementView& v, Table* table) {
    const XAttribute& name_attr = required(v, "name");
    const std::string name = python_str(eval_text(name_attr.value, table, name_attr.value_span).value);
    if (!is_identifier(name)) fail(name_attr.value_span, "Property names must be valid python identifiers: " + name);
    if (name.starts_with("__")) fail(name_attr.value_span, "Property names must not start with double underscore:" + name);
    const XAttribute* value = attr(v, "value");
    const XAttribute* def = attr(v, "default");
    const XAttribute* remove_attr = attr(v, "remove");
    const XAttribute* scope = attr(v, "scope");
    const XAttribute* lazy_attr = attr(v, "lazy_eval");
    const bool remove = remove_attr && boolean(eval_text(remove_attr->value, table, remove_attr->value_span).value,
                                               remove_attr->value, remove_attr->value_span);
    if ((value != nullptr) + (def != nullptr) + remove > 1)
      fail(v.node->span, "Property attributes default, value, and remove are mutually exclusive: " + name);
    if (remove) {
      for (Table* t = table; t; t = t->parent) t->entries.erase(name);
      return;
    }
    if (def) {
      if (table->find(name).second) return;
      value = def;
    }
    bool lazy = !lazy_attr || boolean(eval_text(lazy_attr->value, table, lazy_attr->value_span).value, lazy_attr->value,
                                      lazy_attr->value_span);
    Table* target = table;
    if (scope && scope->value == "global") {
      target = table->top();
      lazy = false;
    } else if (scope && scope->value == "parent") {
      if (!table->parent) return;  // xacro warns: no parent scope at global scope
      target = table->parent;
      lazy = false;
      if (!table->is_namespace)
        while (target->is_namespace && target->parent) target = target->parent;
    }
    Entry entry;
    if (!value) {
      entry.kind = Entry::Kind::SourceBlock;
      entry.block = v.node;
      target->entries["**" + name] = std::move(entry);
      return;
    }
    const Value literal_value = eval_literal(Value(value->value));
    if (!literal_value.is_string()) {
      entry.tracked = Tracked{literal_value, literal(*value)};
    } else if (lazy) {
      entry.kind = Entry::Kind::Lazy;
      entry.text = value->value;
      entry.span = value->value_span;
      entry.chain = chain_;
    } else {
      Tracked t = eval_text(value->value, table, value->value_span);
      t.value = eval_literal(std::move(t.value));
      entry.tracked = std::move(t);
    }
    target->entries[name] = std::move(entry);
  }

  void define_macro(const ElementView& v, MacroTable* macros) {
    std::string name = required(v, "name").value;
    if (name == "call") fail(v.node->span, "Invalid use of macro name 'call'");
    if (name.find('.') != std::string::npos)
      fail(v.node->span, "macro names must not contain '.' (reserved for namespaces): " + name);
    if (name.starts_with("xacro:")) name = name.substr(6);
    auto macro = std::make_shared<Macro>();
    macro->name = name;
    macro->body = v.node;
    if (const XAttribute* params = attr(v, "params")) parse_params(*params, *macro);
    macros->macros[name] = std::move(macro);
  }

  // parse_macro_arg, repeatedly: `name`, `name:=default`, `name:=^`, `name:=^|default`, `*block`.
  void parse_params(const XAttribute& params, Macro& macro) {
    static const std::regex kParam(
        R"(^\s*([^\s:=]+?)\s*:?=\s*(\^\|?)?(\$\{.*?\}|\$\(.*?\)|(?:'.*?'|".*?"|[^\s'"]+)+|)(?:\s+|$)([\s\S]*))");
    std::string rest = params.value;
    std::size_t base = 0;  // where `rest` starts in the attribute's value
    const auto span_at = [&](std::size_t offset, std::size_t length) {
      if (!params.verbatim) return params.value_span;
      const SourceFile& file = *files_read_[params.value_span.file - options_.first_id];
      return file.span(params.value_span.file, params.value_span.offset + offset, length);
    };
    while (!trim(rest).empty()) {
      std::smatch m;
      std::string param;
      if (std::regex_search(rest, m, kParam)) {
        param = m[1];
        Macro::Default d;
        if (m[2].matched && m[2].length() > 0) d.forward = param;
        if (m[3].length() > 0) {
          d.text = m[3].str();
          d.span = span_at(base + static_cast<std::size_t>(m.position(3)), static_cast<std::size_t>(m.length(3)));
        }
        macro.defaults[param] = d;
        const std::size_t consumed = static_cast<std::size_t>(m.position(4));
        base += consumed;
        rest = m[4].str();
      } else {
        const std::size_t b = rest.find_first_not_of(" \t\r\n");
        const std::size_t e = std::min(rest.find_first_of(" \t\r\n", b), rest.size());
        param = rest.substr(b, e - b);
        base += e;
        rest = rest.substr(e);
      }
      macro.params.push_back(param);
    }
  }

  // resolve_macro: the macro by its full name, else through its namespaces (`ns.name`).
  std::tuple<const Macro*, Table*, MacroTable*> resolve_macro(const std::string& full, Table* symbols, MacroTable* macros) {
    if (const Macro* m = macros->find(full)) return {m, symbols, macros};
    std::vector<std::string> parts;
    for (std::size_t at = 0; at <= full.size();) {
      const std::size_t end = std::min(full.find('.', at), full.size());
      parts.push_back(full.substr(at, end - at));
      at = end + 1;
    }
    if (parts.size() < 2) return {nullptr, nullptr, nullptr};
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      macros = macros->find_namespace(parts[i]);
      auto [owner, entry] = symbols->find(parts[i]);
      if (!macros || !entry || entry->kind != Entry::Kind::Namespace) return {nullptr, nullptr, nullptr};
      symbols = entry->ns;
    }
    if (const Macro* m = macros->find(parts.back())) return {m, symbols, macros};
    return {nullptr, nullptr, nullptr};
  }

  void call_macro(const ElementView& v, Table* caller_symbols, MacroTable* caller_macros, OutNode& out) {
    const std::string full = v.name.substr(6);
    auto [macro, symbols, macros] = resolve_macro(full, caller_symbols, caller_macros);
    if (!macro) fail(v.node->span, fmt::format("unknown macro name: {}", v.name));
    if (macro_stack_.size() >= options_.max_macro_depth) {
      std::string chain;
      const std::size_t from = macro_stack_.size() > 6 ? macro_stack_.size() - 6 : 0;
      for (std::size_t i = from; i < macro_stack_.size(); ++i) chain += macro_stack_[i].macro + " → ";
      fail(v.node->span, fmt::format("macro calls nested deeper than {} ({}{}{}); a macro calls itself without end",
                                     options_.max_macro_depth, from ? "… → " : "", chain, macro->name));
    }
    Table scoped;
    scoped.parent = symbols;
    MacroTable scoped_macros;
    scoped_macros.parent = macros;
    std::vector<std::string> params = macro->params;

    for (const XAttribute* a : v.attributes) {
      auto it = std::find(params.begin(), params.end(), a->name);
      if (it == params.end()) fail(a->value_span, fmt::format("Invalid parameter \"{}\" of macro '{}'", a->name, macro->name));
      params.erase(it);
      Tracked t = eval_text(a->value, symbols, a->value_span);
      t.value = eval_literal(std::move(t.value));
      scoped.entries[a->name] = Entry{Entry::Kind::Value, std::move(t), {}, {}, {}, nullptr, nullptr, nullptr};
    }

    // Block parameters, in order: the call's child elements, expanded where the call is.
    const bool has_elements = v.node->first_element() != nullptr;
    if (has_elements) {
      auto blocks = std::make_shared<OutNode>();
      process_children(*v.node, symbols, macros, *blocks);
      std::size_t next = 0;
      const auto next_element = [&]() -> const OutNode* {
        while (next < blocks->children.size() && blocks->children[next].kind != XNode::Kind::Element) ++next;
        return next < blocks->children.size() ? &blocks->children[next++] : nullptr;
      };
      for (auto it = params.begin(); it != params.end();) {
        if (it->empty() || (*it)[0] != '*') {
          ++it;
          continue;
        }
        const OutNode* block = next_element();
        if (!block) fail(v.node->span, fmt::format("Not enough blocks for macro '{}'", macro->name));
        Entry e;
        e.kind = Entry::Kind::OutBlock;
        e.output = std::make_shared<const OutNode>(*block);
        scoped.entries[*it] = std::move(e);
        it = params.erase(it);
      }
      if (const OutNode* extra = next_element()) fail(extra->span, fmt::format("Unused block \"{}\"", extra->name));
    } else {
      for (const auto& p : params)
        if (!p.empty() && p[0] == '*') fail(v.node->span, fmt::format("Not enough blocks for macro '{}'", macro->name));
    }

    for (auto it = params.begin(); it != params.end();) {
      auto d = macro->defaults.find(*it);
      if ((*it)[0] == '*' || d == macro->defaults.end()) {
        ++it;
        continue;
      }
      Tracked t;
      bool forwarded = false;
      if (d->second.forward) {
        NameScope scope(*this, symbols);
        try {
          if (auto value = lookup(symbols, *d->second.forward, scope)) {
            t = Tracked{*value, scope.used.empty() ? Origin{} : scope.used[0].second};
            forwarded = true;
          }
        } catch (const EvalError& e) {
          fail(v.node->span, e.what());
        }
        if (!forwarded && !d->second.text)
          fail(v.node->span, fmt::format("Undefined property to forward: {} (macro '{}')", *d->second.forward, macro->name));
      }
      if (!forwarded) {
        t = eval_text(*d->second.text, symbols, d->second.span);
        t.value = eval_literal(std::move(t.value));
      }
      scoped.entries[*it] = Entry{Entry::Kind::Value, std::move(t), {}, {}, {}, nullptr, nullptr, nullptr};
      it = params.erase(it);
    }
    if (!params.empty()) {
      std::string names;
      for (const auto& p : params) names += (names.empty() ? "" : ",") + p;
      fail(v.node->span, fmt::format("Undefined parameters [{}] of macro '{}'", names, macro->name));
    }

    macro_stack_.push_back({macro->name, v.node->span});
    const CallChain saved = chain_;
    chain_ = std::make_shared<const std::vector<CallFrame>>(macro_stack_);
    process_children(*macro->body, &scoped, &scoped_macros, out);
    chain_ = saved;
    macro_stack_.pop_back();
  }

  void include(const ElementView& v, Table* symbols, MacroTable* macros, OutNode& out) {
    const XAttribute& filename = required(v, "filename");
    const XAttribute* ns = attr(v, "ns");
    const XAttribute* optional_attr = attr(v, "optional");
    Table* ns_symbols = symbols;
    MacroTable* ns_macros = macros;
    if (ns) {
      const std::string ns_name = python_str(eval_text(ns->value, symbols, ns->value_span).value);
      ns_macros = &macro_tables_.emplace_back();
      macros->namespaces[ns_name] = ns_macros;
      ns_symbols = &tables_.emplace_back();
      ns_symbols->parent = symbols;
      ns_symbols->is_namespace = true;
      Entry e;
      e.kind = Entry::Kind::Namespace;
      e.ns = ns_symbols;
      symbols->entries[ns_name] = std::move(e);
    }
    const bool optional = optional_attr && boolean(eval_text(optional_attr->value, symbols, optional_attr->value_span).value,
                                                   optional_attr->value, optional_attr->value_span);
    const std::string spec = abs_filename(python_str(eval_text(filename.value, symbols, filename.value_span).value));
    std::vector<std::string> paths;
    if (spec.find_first_of("*?[") != std::string::npos) {
      const fs::path pattern(spec);
      if (pattern.parent_path().string().find_first_of("*?[") != std::string::npos)
        fail(filename.value_span, "unsupported in xacro:include: wildcards in directory names");
      std::error_code ec;
      for (fs::directory_iterator it(pattern.parent_path().empty() ? "." : pattern.parent_path(), ec), end; !ec && it != end;
           it.increment(ec))
        if (fnmatch(pattern.filename().c_str(), it->path().filename().c_str(), FNM_PERIOD) == 0)
          paths.push_back((pattern.parent_path() / it->path().filename()).string());
      std::sort(paths.begin(), paths.end());
    } else {
      paths.push_back(spec);
    }
    for (const std::string& path : paths) {
      const std::string canonical = canonical_path(path);
      for (const FileFrame& frame : file_stack_) {
        if (canonical_path(frame.path) != canonical) continue;
        std::string chain;
        for (const FileFrame& f : file_stack_) chain += fs::path(f.path).filename().string() + " → ";
        fail(v.node->span, fmt::format("include cycle: {}{}", chain, fs::path(path).filename().string()));
      }
      if (file_stack_.size() > options_.max_include_depth)
        fail(v.node->span, fmt::format("includes nested deeper than {}", options_.max_include_depth));
      // Read under the name the file is shown with: the fixer's in-memory edits are keyed by it.
      const std::string name = shown(path);
      std::string error;
      std::optional<std::string> text = files_.read(name, error);
      if (!text) {
        if (optional) continue;
        fail(filename.value_span, fmt::format("cannot include '{}': {}", path, error));
      }
      const SourceTree& tree = add_tree(std::make_shared<const SourceFile>(name, std::move(*text)), v.node->span);
      file_stack_.push_back({path, v.node->span});
      for (const XAttribute& a : tree.root.attributes) {
        if (!a.name.starts_with("xmlns:") || a.name == "xmlns:xacro" || out.attribute(a.name)) continue;
        out.attributes.push_back({a.name, a.value, literal(a)});
      }
      process_children(tree.root, ns_symbols, ns_macros, out);
      file_stack_.pop_back();
    }
  }

  // An included file's path as reports show it: relative to the working directory when inside it
  // ($(find …) gives absolute paths).
  static std::string shown(const std::string& path) {
    std::error_code ec;
    const fs::path p(path);
    if (!p.is_absolute()) return p.lexically_normal().string();
    const fs::path relative = p.lexically_normal().lexically_relative(fs::current_path(ec));
    if (ec || relative.empty() || *relative.begin() == "..") return p.lexically_normal().string();
    return relative.string();
  }

  static std::string canonical_path(const std::string& path) {
    std::error_code ec;
    const fs::path c = fs::weakly_canonical(path, ec);
    return ec ? fs::path(path).lexically_normal().string() : c.string();
  }

  const FileSystem& files_;
  const ExpandOptions& options_;
  std::map<std::string, ArgumentValue> arguments_;
  std::vector<std::shared_ptr<const SourceFile>> files_read_;
  std::deque<SourceTree> trees_;
  std::deque<Table> tables_;
  std::deque<MacroTable> macro_tables_;
  std::vector<FileFrame> file_stack_;
  std::vector<CallFrame> macro_stack_;
  CallChain chain_ = std::make_shared<const std::vector<CallFrame>>();
  std::size_t output_bytes_ = 0;
  std::size_t depth_ = 0;
  std::size_t steps_ = 0;
  std::uint64_t comment_stop_ = 0;  // the mark drop_previous_comments stops at
};

std::optional<Value> NameScope::lookup(std::string_view name) { return expander_.lookup(table_, name, *this); }

std::optional<Value> NameScope::lookup_in(const NamespaceRef& ns, std::string_view name) {
  return expander_.lookup(static_cast<Table*>(const_cast<void*>(ns.table)), name, *this);
}

Value NameScope::load_yaml(const std::string& filename) { return expander_.load_yaml(filename); }
Value NameScope::arg(const std::string& name) { return expander_.argument(name, arguments); }
std::string NameScope::abs_filename(const std::string& filename) { return expander_.abs_filename(filename); }

std::optional<Value> EvalScope::lookup(std::string_view name) {
  try {
    return auto_convert(expander_.argument(std::string(name), arguments).string());
  } catch (const EvalError&) {
  }
  if (name == "true") return Value(true);
  if (name == "false") return Value(false);
  return std::nullopt;
}

Value EvalScope::arg(const std::string& name) { return auto_convert(expander_.argument(name, arguments).string()); }

std::optional<Value> EvalScope::call(std::string_view name, const std::vector<Value>& args) {
  const auto one = [&](std::string_view f) -> std::string {
    if (args.size() != 1) throw EvalError(fmt::format("{}() takes exactly one argument", f));
    return python_str(args[0]);
  };
  if (name == "arg") return arg(one(name));
  if (name == "dirname") return Value(expander_.current_dir());
  if (name == "env") {
    const std::string var = one(name);
    if (const char* v = std::getenv(var.c_str())) return Value(std::string(v));
    throw EvalError(fmt::format("environment variable {} is not set", var));
  }
  if (name == "optenv") {
    if (args.empty() || args.size() > 2) throw EvalError("optenv() takes one or two arguments");
    if (const char* v = std::getenv(python_str(args[0]).c_str())) return Value(std::string(v));
    return Value(args.size() > 1 ? python_str(args[1]) : std::string());
  }
  if (name == "find") {
    const std::string pkg = one(name);
    if (auto dir = expander_.find_package(pkg)) return Value(*dir);
    throw EvalError(fmt::format("resource not found: package '{}'", pkg));
  }
  return std::nullopt;
}

}  // namespace

ExpandResult expand_xacro(std::shared_ptr<const SourceFile> top, const FileSystem& files, const ExpandOptions& options) {
  return Expander(files, options).run(std::move(top));
}

}  // namespace assetlint::xacro
