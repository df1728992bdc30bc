#include "formats/xacro/xacro_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "formats/urdf/urdf_reader.h"
#include "formats/xacro/urdf_writer.h"
#include "rules/reader_rules.h"

namespace assetlint::xacro {
namespace {

// The expanded text is FileId 0 while the URDF reader and the rules look at it; the .xacro
// files follow from 1 and move down to 0 once every finding is relocated.
constexpr FileId kExpanded = 0;
constexpr FileId kFirstXacro = 1;

Diagnostic expansion_error(const ExpandError& error) {
  Diagnostic d{std::string(rules::kParseError.id), rules::kParseError.default_severity, error.span,
               fmt::format("xacro: {}", error.message), std::nullopt, error.notes, {}, {}};
  return d;
}

void shift_down(Span& span) {
  if (span.file != kNoFile && span.file >= kFirstXacro) span.file -= kFirstXacro;
}

class Relocator {
 public:
  Relocator(Expansion expansion, std::shared_ptr<const SourceFile> top) : expansion_(std::move(expansion)), top_(std::move(top)) {}

  // Writes the expanded text once the expansion has its final address (placements point into it).
  std::shared_ptr<const SourceFile> write() {
    std::vector<Placement> placements;
    std::string text = write_urdf(expansion_, std::filesystem::path(top_->path()).filename().string(), &placements);
    for (const Placement& p : placements) (p.attribute ? attributes_ : elements_).push_back(p);
    const auto by_offset = [](const Placement& a, const Placement& b) { return a.offset < b.offset; };
    std::sort(attributes_.begin(), attributes_.end(), by_offset);
    std::sort(elements_.begin(), elements_.end(), by_offset);
    for (const Placement& p : attributes_) {
      const Origin& o = p.attribute->origin;
      if (o.kind == Origin::Kind::Literal || o.kind == Origin::Kind::Property) ++uses_[{o.span.file, o.span.offset}];
    }
    return std::make_shared<const SourceFile>(top_->path(), std::move(text));
  }

  std::vector<std::shared_ptr<const SourceFile>> relocate(std::vector<Diagnostic>& diagnostics) {
    std::map<std::pair<FileId, std::size_t>, std::size_t> fixed_by;  // a rewritten literal → the finding that rewrites it
    std::vector<Edit> unmoved;  // every fix's edits on the expanded text, before any is moved
    for (const Diagnostic& d : diagnostics)
      if (d.fix) unmoved.insert(unmoved.end(), d.fix->edits.begin(), d.fix->edits.end());
    for (std::size_t i = 0; i < diagnostics.size(); ++i) {
      Diagnostic& d = diagnostics[i];
      const Placement* attribute = d.span.file == kExpanded ? attribute_at(d.span.offset, d.span.length) : nullptr;
      if (d.fix) relocate_fix(d, diagnostics, unmoved, fixed_by, i);
      relocate_primary(d, attribute);
    }
    for (Diagnostic& d : diagnostics) {
      shift_down(d.span);
      for (Note& n : d.notes) shift_down(n.span);
      if (d.fix)
        for (Edit& e : d.fix->edits) e.file -= kFirstXacro;
    }
    return expansion_.files;
  }

  Span written_at(const Span& span) const { return moved(span); }

 private:
  const Placement* attribute_at(std::size_t offset, std::size_t length) const {
    auto it = std::upper_bound(attributes_.begin(), attributes_.end(), offset,
                               [](std::size_t o, const Placement& p) { return o < p.offset; });
    if (it == attributes_.begin()) return nullptr;
    --it;
    return offset + length <= it->offset + it->length ? &*it : nullptr;
  }

  const OutNode* element_at(std::size_t offset) const {
    auto it = std::upper_bound(elements_.begin(), elements_.end(), offset,
                               [](std::size_t o, const Placement& p) { return o < p.offset; });
    if (it == elements_.begin()) return &expansion_.root;
    return std::prev(it)->element;
  }

  bool in_sources(const Span& span) const {
    return span.file != kNoFile && span.file >= kFirstXacro && span.file - kFirstXacro < expansion_.files.size();
  }

  std::string where(const Span& span) const {
    const FileId index = span.file - kFirstXacro;
    const std::string path =
        index < expansion_.files.size() ? std::filesystem::path(expansion_.files[index]->path()).filename().string() : "?";
    return fmt::format("{}:{}:{}", path, span.line, span.column);
  }

  Span moved(const Span& span) const {
    if (span.file != kExpanded) return span;
    if (const Placement* a = attribute_at(span.offset, span.length); a && in_sources(a->attribute->origin.span))
      return a->attribute->origin.span;
    return element_at(span.offset)->span;
  }

  void relocate_primary(Diagnostic& d, const Placement* attribute) {
    for (Note& n : d.notes) n.span = moved(n.span);
    if (d.span.file != kExpanded) return;
    CallChain chain;
    if (attribute && in_sources(attribute->attribute->origin.span)) {
      const Origin& o = attribute->attribute->origin;
      d.span = o.span;
      chain = o.chain;
      switch (o.kind) {
        case Origin::Kind::Literal: break;
        case Origin::Kind::Property:
          d.note(o.use, fmt::format("the value of property '{}', defined at {}, is used here", o.name, where(o.span)));
          break;
        case Origin::Kind::Expression: d.note(fmt::format("the value is computed by '{}' in the xacro source", o.name)); break;
        case Origin::Kind::Argument: d.note(argument_note(o)); break;
      }
    } else {
      const OutNode* element = element_at(d.span.offset);
      d.span = element->span;
      chain = element->chain;
    }
    if (chain)
      for (auto it = chain->rbegin(); it != chain->rend(); ++it)
        d.note(it->call, fmt::format("in macro '{}' called at {}", it->macro, where(it->call)));
  }

  std::string argument_note(const Origin& o) const {
    std::string text = fmt::format("the value depends on the xacro argument{} ", o.name.find(", ") == std::string::npos ? "" : "s");
    std::size_t at = 0;
    bool first = true;
    while (at <= o.name.size()) {
      const std::size_t end = std::min(o.name.find(", ", at), o.name.size());
      const std::string name = o.name.substr(at, end - at);
      at = end + 2;
      if (name.empty()) continue;
      text += first ? "" : ", ";
      first = false;
      auto it = expansion_.arguments.find(name);
      if (it == expansion_.arguments.end()) {
        text += fmt::format("'{}'", name);
      } else if (!it->second.origin.empty()) {
        text += fmt::format("'{}' = '{}' (from {})", name, it->second.value, it->second.origin);
      } else {
        text += fmt::format("'{}' = '{}' (its default, at {})", name, it->second.value, where(it->second.span));
      }
    }
    return text;
  }

  // A fix moves to the .xacro only where the output value is a literal written there byte for
  // byte, and only when every use of that literal gets the same fix (a literal in a macro is
  // used once per call; a property's value once per substitution).
  void relocate_fix(Diagnostic& d, std::vector<Diagnostic>& all, const std::vector<Edit>& unmoved,
                    std::map<std::pair<FileId, std::size_t>, std::size_t>& fixed_by, std::size_t index) {
    std::vector<Edit> edits;
    std::string why;
    for (const Edit& e : d.fix->edits) {
      const Placement* p = e.file == kExpanded ? attribute_at(e.offset, e.length) : nullptr;
      if (!p || !in_sources(p->attribute->origin.span)) {
        why = "the fix would add text the xacro source produces elsewhere";
        break;
      }
      const Origin& o = p->attribute->origin;
      if (o.kind == Origin::Kind::Expression) {
        why = fmt::format("the value is computed by '{}'; asset-lint does not rewrite expressions", o.name);
        break;
      }
      if (o.kind == Origin::Kind::Argument) {
        why = fmt::format("the value depends on the xacro argument {}; asset-lint does not rewrite arguments", o.name);
        break;
      }
      const FileId index_of = o.span.file - kFirstXacro;
      const std::string_view source = expansion_.files[index_of]->view().substr(o.span.offset, o.span.length);
      if (source != p->attribute->value || p->length != source.size()) {
        why = fmt::format("the xacro source writes this value as '{}', not as the URDF shows it", source);
        break;
      }
      const std::size_t uses = uses_.count({o.span.file, o.span.offset}) ? uses_.at({o.span.file, o.span.offset}) : 1;
      if (uses > 1 && !all_uses_fixed_alike(o, e.offset - p->offset, e, unmoved)) {
        why = o.kind == Origin::Kind::Property
                  ? fmt::format("property '{}' is used {} times and not every use gets this fix", o.name, uses)
                  : fmt::format("this literal is expanded {} times (it sits in a macro) and not every expansion gets this fix", uses);
        break;
      }
      edits.push_back(Edit{o.span.file, o.span.offset + (e.offset - p->offset), e.length, e.replacement});
    }
    if (!why.empty()) {
      d.fix.reset();
      d.note(fmt::format("No fix through xacro: {}.", why));
      return;
    }
    // Several findings fixing the same literal alike: the first carries the edit.
    for (const Edit& e : edits) {
      auto [it, inserted] = fixed_by.emplace(std::pair{e.file, e.offset}, index);
      if (!inserted) {
        d.fix.reset();
        d.note(all[it->second].span, "The fix of this finding rewrites the same xacro literal.");
        return;
      }
    }
    d.fix->edits = std::move(edits);
  }

  bool all_uses_fixed_alike(const Origin& origin, std::size_t relative, const Edit& edit, const std::vector<Edit>& unmoved) const {
    std::size_t fixed = 0;
    for (const Placement& p : attributes_) {
      const Origin& o = p.attribute->origin;
      if (o.span.file != origin.span.file || o.span.offset != origin.span.offset) continue;
      if (o.kind != Origin::Kind::Literal && o.kind != Origin::Kind::Property) return false;
      const bool covered = std::any_of(unmoved.begin(), unmoved.end(), [&](const Edit& e) {
        return e.file == kExpanded && e.offset >= p.offset && e.offset + e.length <= p.offset + p.length &&
               e.offset - p.offset == relative && e.replacement == edit.replacement && e.length == edit.length;
      });
      if (!covered) return false;
      ++fixed;
    }
    return fixed > 0;
  }

  Expansion expansion_;
  std::shared_ptr<const SourceFile> top_;
  std::vector<Placement> attributes_, elements_;
  std::map<std::pair<FileId, std::size_t>, std::size_t> uses_;
};

ExpandOptions expand_options(const XacroOptions& options) {
  ExpandOptions expand;
  expand.arguments = options.arguments;
  expand.root = options.root;
  expand.first_id = kFirstXacro;
  expand.deadline = options.deadline;
  return expand;
}

}  // namespace

ReadResult read_xacro(std::shared_ptr<const SourceFile> file, const FileSystem& files, const XacroOptions& options) {
  ExpandResult expanded = expand_xacro(file, files, expand_options(options));
  if (!expanded.expansion) {
    ReadResult failed;
    failed.asset.format = SourceFormat::Urdf;
    failed.asset.sources = expanded.files.empty() ? std::vector<std::shared_ptr<const SourceFile>>{file} : expanded.files;
    Diagnostic d = expansion_error(*expanded.error);
    shift_down(d.span);
    for (Note& n : d.notes) shift_down(n.span);
    failed.diagnostics.push_back(std::move(d));
    failed.usable = false;
    return failed;
  }
  auto relocator = std::make_shared<Relocator>(std::move(*expanded.expansion), file);
  std::shared_ptr<const SourceFile> text = relocator->write();
  ReadResult result = urdf::read_urdf(text);
  for (auto& f : expanded.files) result.asset.sources.push_back(f);
  result.relocate = [relocator](std::vector<Diagnostic>& diagnostics) { return relocator->relocate(diagnostics); };
  result.written_at = [relocator](const Span& span) { return relocator->written_at(span); };
  return result;
}

ExpandedText expand_to_text(std::shared_ptr<const SourceFile> file, const FileSystem& files, const XacroOptions& options) {
  ExpandOptions expand = expand_options(options);
  expand.first_id = 0;
  ExpandResult expanded = expand_xacro(file, files, expand);
  ExpandedText out;
  out.files = expanded.files;
  if (!expanded.expansion) {
    out.error = expanded.error;
    return out;
  }
  out.text = write_urdf(*expanded.expansion, std::filesystem::path(file->path()).filename().string(), nullptr);
  return out;
}

}  // namespace assetlint::xacro
