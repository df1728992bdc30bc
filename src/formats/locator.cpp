#include "formats/locator.h"

#include <fmt/format.h>

#include "formats/suppressions.h"
#include "formats/xml/xml_scanner.h"
#include "formats/usda/parser.h"

namespace assetlint {

// A piece of the file's structure: an element, a prim, a statement or an XML attribute.
struct SourceLocator::Unit {
  std::size_t begin = 0;
  std::size_t end = 0;
  std::string element;    // set on named elements and prims
  std::string attribute;  // set on statements, attributes and unnamed elements
  bool placeable = true;  // a suppression comment may stand before it
};

namespace {

using Unit = SourceLocator::Unit;

bool starts_at(std::string_view text, std::size_t at, std::string_view prefix) {
  return text.substr(at, prefix.size()) == prefix;
}

// Elements with their whole range (start tag through end tag) and attribute values, from
// the scanner's start tags and the end tags between them.
void xml_units(std::string_view text, std::vector<Unit>& units) {
  const xml::XmlScan scan = xml::scan_xml(text);
  struct Open {
    std::string_view name;
    std::size_t unit;
  };
  std::vector<Open> open;
  auto close_in = [&](std::size_t from, std::size_t to) {
    for (std::size_t p = text.find('<', from); p < to; p = text.find('<', p + 1)) {
      if (starts_at(text, p, "<!--")) {
        p = text.find("-->", p);
      } else if (starts_at(text, p, "<![CDATA[")) {
        p = text.find("]]>", p);
      } else if (starts_at(text, p, "</")) {
        std::size_t q = p + 2;
        while (q < to && text[q] != '>' && text[q] != ' ' && text[q] != '\t' && text[q] != '\n' && text[q] != '\r') ++q;
        const std::string_view name = text.substr(p + 2, q - p - 2);
        const std::size_t gt = text.find('>', q);
        const std::size_t end = gt == std::string_view::npos ? text.size() : gt + 1;
        for (std::size_t k = open.size(); k-- > 0;) {
          if (open[k].name != name) continue;
          for (std::size_t j = k; j < open.size(); ++j) units[open[j].unit].end = end;
          open.resize(k);
          break;
        }
      }
      if (p == std::string_view::npos) return;
    }
  };
  std::size_t previous_end = 0;
  for (const auto& tag : scan.tags) {
    close_in(previous_end, tag.offset);
    const bool self_closing = tag.end >= 2 && text[tag.end - 2] == '/';
    Unit element{tag.offset, self_closing ? tag.end : text.size(), "", std::string(tag.name), true};
    const xml::XmlAttributeSpan* name = tag.attribute("name");
    if (!name) name = tag.attribute("reference");                           // <gazebo reference="link">
    if (!name && tag.name == "default") name = tag.attribute("class");     // MJCF <default class="x">
    if (name) {
      element.element = fmt::format("{} '{}'", tag.name, text.substr(name->value_offset, name->value_length));
      element.attribute.clear();
    }
    units.push_back(std::move(element));
    if (!self_closing) open.push_back({tag.name, units.size() - 1});
    for (const auto& attribute : tag.attributes)
      units.push_back(Unit{attribute.name_offset, attribute.value_offset + attribute.value_length + 1, "",
                           fmt::format("{}.{}", tag.name, attribute.name), false});
    previous_end = tag.end;
  }
  close_in(previous_end, text.size());
}

void metadata_units(const std::vector<usda::Metadata>& metadata, std::vector<Unit>& units) {
  for (const auto& item : metadata) units.push_back(Unit{item.span.offset, item.span.end(), "", item.key, true});
}

void prim_units(const std::vector<usda::Prim>& prims, const std::string& parent, std::vector<Unit>& units) {
  for (const auto& prim : prims) {
    const std::string path = parent + "/" + prim.name;
    units.push_back(Unit{prim.span.offset, prim.span.end(), path, "", true});
    metadata_units(prim.metadata, units);
    for (const auto& attribute : prim.attributes) {
      units.push_back(Unit{attribute.span.offset, attribute.span.end(), "", attribute.name, true});
      if (attribute.time_samples) {
        const Span& s = attribute.time_samples->declaration_span;
        units.push_back(Unit{s.offset, s.end(), "", attribute.name, true});
      }
    }
    for (const auto& relationship : prim.relationships)
      units.push_back(Unit{relationship.span.offset, relationship.span.end(), "", relationship.name, true});
    prim_units(prim.children, path, units);
  }
}

// The smallest unit holding `offset` that passes `wanted`.
template <class Wanted>
const Unit* innermost(const std::vector<Unit>& units, std::size_t offset, Wanted wanted) {
  const Unit* best = nullptr;
  for (const auto& unit : units) {
    const bool holds = unit.begin <= offset && (offset < unit.end || (unit.begin == unit.end && offset == unit.begin));
    if (!holds || !wanted(unit)) continue;
    if (!best || unit.end - unit.begin <= best->end - best->begin) best = &unit;
  }
  return best;
}

bool is_blank(char c) { return c == ' ' || c == '\t'; }

}  // namespace

SourceLocator::SourceLocator(const SourceFile& file) : file_(file) {
  xml_ = comment_syntax_for(file.path()) == CommentSyntax::Xml;
  if (xml_) {
    xml_units(file.view(), units_);
    return;
  }
  usda::ParseResult parsed = usda::parse_layer(file, 0);
  if (!parsed) return;  // a layer that does not parse has no structure to name
  metadata_units(parsed.layer().metadata, units_);
  prim_units(parsed.layer().prims, "", units_);
}

SourceLocator::~SourceLocator() = default;

ElementKey SourceLocator::key_at(std::size_t offset) const {
  ElementKey key;
  const Unit* element = innermost(units_, offset, [](const Unit& u) { return !u.element.empty(); });
  if (element) key.element = element->element;
  const Unit* detail = innermost(units_, offset, [&](const Unit& u) {
    return !u.attribute.empty() && (!element || (u.begin >= element->begin && u.end <= element->end));
  });
  if (detail) key.attribute = detail->attribute;
  return key;
}

std::optional<SuppressionSite> SourceLocator::site_at(std::size_t offset) const {
  const std::string_view text = file_.view();
  SuppressionSite site;
  const Unit* unit = innermost(units_, offset, [](const Unit& u) { return u.placeable; });
  std::size_t at = 0;
  if (unit) {
    at = unit->begin;
  } else if (xml_) {
    // An XML comment may not precede the declaration: ignore-file goes before the root.
    const Unit* root = nullptr;
    for (const auto& u : units_)
      if (u.placeable && (!root || u.begin < root->begin)) root = &u;
    if (!root) return std::nullopt;
    site.file_level = true;
    at = root->begin;
  } else {
    // USDA: on the line after the `#usda 1.0` header.
    site.file_level = true;
    const std::size_t newline = text.find('\n');
    site.offset = newline == std::string_view::npos ? text.size() : newline + 1;
    site.line_end = newline != std::string_view::npos && newline > 0 && text[newline - 1] == '\r' ? "\r\n" : "\n";
    if (newline == std::string_view::npos) site.indent = site.line_end;  // a header without a line break
    return site;
  }
  std::size_t line_begin = at;
  while (line_begin > 0 && text[line_begin - 1] != '\n' && text[line_begin - 1] != '\r') --line_begin;
  std::size_t indent_end = line_begin;
  while (indent_end < at && is_blank(text[indent_end])) ++indent_end;
  const std::size_t line_end = text.find('\n', at);
  site.line_end = line_end != std::string_view::npos && line_end > 0 && text[line_end - 1] == '\r' ? "\r\n" : "\n";
  site.indent = std::string(text.substr(line_begin, indent_end - line_begin));
  site.own_line = indent_end == at;
  site.offset = site.own_line ? line_begin : at;
  return site;
}

std::string SourceLocator::suppression_text(const SuppressionSite& site, const std::vector<std::string>& rules) const {
  const std::string comment =
      suppression_comment(xml_ ? CommentSyntax::Xml : CommentSyntax::Usda, site.file_level, rules);
  if (site.file_level && !xml_) return site.indent + comment + site.line_end;
  if (site.own_line) return site.indent + comment + site.line_end;
  // Inside a line: XML comments close themselves; a USDA `#` comment runs to the end of
  // its line, so the statement moves to the next one.
  if (xml_) return comment + " ";
  return site.line_end + site.indent + comment + site.line_end + site.indent;
}

}  // namespace assetlint
