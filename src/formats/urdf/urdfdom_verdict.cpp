#include "formats/urdf/urdfdom_verdict.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <unordered_set>

namespace assetlint::urdf {
namespace {

using xml::Element;

bool xml_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// `<?xml version = "1.0" encoding="UTF-8" standalone="yes" ?>` with attributes among these
// three, double-quoted, whitespace around '=' and between attributes: the declarations both
// parsers agree on (tinyxml 1 reads each attribute as it reads an element's).
bool plain_declaration(std::string_view text) {
  if (!text.starts_with("<?xml")) return false;
  std::size_t i = 5;
  auto skip_space = [&] {
    const std::size_t start = i;
    while (i < text.size() && xml_space(text[i])) ++i;
    return i > start;
  };
  for (;;) {
    const bool spaced = skip_space();
    if (text.compare(i, 2, "?>") == 0) return true;
    if (!spaced) return false;
    std::size_t name_end = i;
    while (name_end < text.size() && std::isalpha(static_cast<unsigned char>(text[name_end]))) ++name_end;
    const std::string_view name = text.substr(i, name_end - i);
    if (name != "version" && name != "encoding" && name != "standalone") return false;
    i = name_end;
    skip_space();
    if (i >= text.size() || text[i] != '=') return false;
    ++i;
    skip_space();
    if (i >= text.size() || text[i] != '"') return false;
    const std::size_t close = text.find('"', i + 1);
    if (close == std::string_view::npos) return false;
    for (std::size_t k = i + 1; k < close; ++k) {
      const char c = text[k];
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') return false;
    }
    i = close + 1;
  }
}

// Whether `text` is well-formed UTF-8 (complete sequences, no overlong lead bytes).
bool valid_utf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    const std::size_t length = c < 0x80 ? 1 : c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3
                               : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    if (length == 0 || i + length > text.size()) return false;
    for (std::size_t k = 1; k < length; ++k)
      if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return false;
    i += length;
  }
  return true;
}

// Bytes both XML parsers read the same way: printable ASCII and line breaks, no entity
// references, no DOCTYPE or CDATA, no processing instruction but a leading declaration.
// Comments may hold anything in UTF-8 ('&', '©'): both parsers skip them to the first "-->"
// byte by byte.
bool plain_markup(std::string_view document) {
  // 0: ordinary, 1: never plain, 2: '<' (look at what follows).
  static const auto kinds = [] {
    std::array<unsigned char, 256> k{};
    for (int c = 0; c < 256; ++c) k[c] = (c >= 0x80 || c == '&' || (c < 0x20 && c != '\t' && c != '\n' && c != '\r')) ? 1 : 0;
    k['<'] = 2;
    return k;
  }();
  const std::size_t first = document.find_first_not_of(" \t\r\n");
  for (std::size_t i = 0; i < document.size(); ++i) {
    const unsigned char kind = kinds[static_cast<unsigned char>(document[i])];
    if (kind == 0) continue;
    if (kind == 1) return false;
    if (i + 1 >= document.size()) continue;
    if (document.compare(i, 4, "<!--") == 0) {
      const std::size_t end = document.find("-->", i + 4);
      if (end == std::string_view::npos || !valid_utf8(document.substr(i + 4, end - (i + 4)))) return false;
      for (std::size_t k = i + 4; k < end; ++k)
        if (static_cast<unsigned char>(document[k]) < 0x20 && !xml_space(document[k])) return false;
      i = end + 2;
      continue;
    }
    if (document[i + 1] == '!') return false;
    if (document[i + 1] == '?' && !(i == first && plain_declaration(document.substr(i)))) return false;
  }
  return true;
}

// plain_markup from what the scanner saw on its way: without '&' or non-ASCII bytes
// anywhere, only the processing instructions and DOCTYPE/CDATA sections need a look.
bool plain_markup(const xml::ScannedDocument& doc) {
  const xml::XmlScan& scan = doc.scan();
  // tinyxml 1 starts a name with a letter or '_'; tinyxml2 (and so the scanner) also with ':'.
  for (const xml::Element& tag : scan.tags) {
    if (tag.name.starts_with(':')) return false;
    for (const auto& attribute : tag.attributes)
      if (attribute.name.starts_with(':')) return false;
  }
  if (scan.non_ascii || scan.ampersand) return plain_markup(doc.document());
  if (scan.doctype_or_cdata) return false;
  const std::string_view text = doc.file().view();
  const std::size_t first = text.find_first_not_of(" \t\r\n", scan.document_begin);
  for (std::size_t offset : scan.instructions)
    if (offset != first || !plain_declaration(text.substr(offset))) return false;
  return true;
}

bool has_control(std::string_view value) {
  for (char c : value)
    if (static_cast<unsigned char>(c) < 0x20) return true;
  return false;
}

// urdfdom's strToDouble reads with a classic-locale stringstream and needs all of it
// consumed: this accepts the plain decimal subset of that, finite and not denormal.
bool plain_number(std::string_view text) {
  std::size_t i = 0;
  auto digits = [&] {
    const std::size_t start = i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
    return i - start;
  };
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  std::size_t mantissa = digits();
  if (i < text.size() && text[i] == '.') {
    ++i;
    mantissa += digits();  // "1." reads as 1
  }
  if (mantissa == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  if (i != text.size()) return false;
  // from_chars takes no leading '+'; overflow and underflow come back as out of range.
  const std::size_t skip = text[0] == '+' ? 1 : 0;
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data() + skip, text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && std::isfinite(value) &&
         (value == 0 || std::fabs(value) >= 1e-300);
}

// urdfdom's Vector3::init: pieces split at spaces, empty ones skipped, exactly three.
bool plain_vector(std::string_view text) {
  int count = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find(' ', pos), text.size());
    const std::string_view piece = text.substr(pos, end - pos);
    if (!piece.empty()) {
      if (!plain_number(piece)) return false;
      ++count;
    }
    pos = end + 1;
  }
  return count == 3;
}

class Verdict {
 public:
  explicit Verdict(const xml::ScannedDocument& doc) : doc_(doc) {}

  bool accepts(const Element* robot) {
    if (!robot || robot->name != "robot") return false;
    if (!value(robot, "name")) return false;
    if (auto version = value(robot, "version"); version && *version != "1.0") return false;

    std::size_t elements = 0;  // sizes the name sets once: rehashing 100 000 names costs more than the lookups
    for (const Element* e = doc_.first_child(robot); e; e = doc_.next_sibling(e)) ++elements;

    std::unordered_set<std::string_view> materials;
    for (const Element* m = doc_.first_child(robot, "material"); m; m = doc_.next_sibling(m, "material"))
      if (!materials.insert(value(m, "name").value_or("")).second) return false;

    std::unordered_set<std::string_view> links(elements);
    for (const Element* l = doc_.first_child(robot, "link"); l; l = doc_.next_sibling(l, "link"))
      if (!links.insert(value(l, "name").value_or("")).second) return false;
    if (links.empty()) return false;

    std::unordered_set<std::string_view> joints(elements), children(elements);
    for (const Element* j = doc_.first_child(robot, "joint"); j; j = doc_.next_sibling(j, "joint")) {
      auto name = value(j, "name");
      if (!name || !joints.insert(*name).second || !joint_parses(j)) return false;
      const auto parent = link_of(j, "parent"), child = link_of(j, "child");
      if (parent.empty() || child.empty() || !links.count(parent) || !links.count(child)) return false;
      children.insert(child);
    }
    // initRoot: exactly one link that is no joint's child.
    std::size_t roots = 0;
    for (std::string_view link : links) roots += children.count(link) ? 0 : 1;
    return roots == 1 && clean_;
  }

 private:
  std::optional<std::string_view> value(const Element* el, std::string_view attr) {
    auto v = doc_.raw_value(el, attr);
    if (v && has_control(*v)) clean_ = false;
    return v;
  }
  bool number_if_present(const Element* el, std::string_view attr) {
    auto v = value(el, attr);
    return !v || plain_number(*v);
  }
  bool number(const Element* el, std::string_view attr) {
    auto v = value(el, attr);
    return v && plain_number(*v);
  }
  bool vector_if_present(const Element* el, std::string_view attr) {
    auto v = value(el, attr);
    return !v || plain_vector(*v);
  }
  std::string_view link_of(const Element* joint, const char* tag) {
    const Element* el = doc_.first_child(joint, tag);
    return el ? value(el, "link").value_or("") : std::string_view();
  }

  // urdfdom's parseJoint returns true.
  bool joint_parses(const Element* j) {
    if (const Element* origin = doc_.first_child(j, "origin"))
      if (!vector_if_present(origin, "xyz") || !vector_if_present(origin, "rpy")) return false;
    auto type = value(j, "type");
    if (!type) return false;
    const bool moving = *type == "revolute" || *type == "continuous" || *type == "prismatic" || *type == "planar";
    if (!moving && *type != "fixed" && *type != "floating") return false;
    if (const Element* axis = doc_.first_child(j, "axis"); axis && moving)
      if (!vector_if_present(axis, "xyz")) return false;
    if (const Element* limit = doc_.first_child(j, "limit")) {
      if (!number_if_present(limit, "lower") || !number_if_present(limit, "upper") || !number(limit, "effort") ||
          !number(limit, "velocity"))
        return false;
    } else if (*type == "revolute" || *type == "prismatic") {
      return false;
    }
    if (const Element* safety = doc_.first_child(j, "safety_controller"))
      if (!number_if_present(safety, "soft_lower_limit") || !number_if_present(safety, "soft_upper_limit") ||
          !number_if_present(safety, "k_position") || !number(safety, "k_velocity"))
        return false;
    if (const Element* calibration = doc_.first_child(j, "calibration"))
      if (!number_if_present(calibration, "rising") || !number_if_present(calibration, "falling")) return false;
    if (const Element* mimic = doc_.first_child(j, "mimic"))
      if (!value(mimic, "joint") || !number_if_present(mimic, "multiplier") || !number_if_present(mimic, "offset"))
        return false;
    if (const Element* dynamics = doc_.first_child(j, "dynamics")) {
      if (!number_if_present(dynamics, "damping") || !number_if_present(dynamics, "friction")) return false;
      if (!value(dynamics, "damping") && !value(dynamics, "friction")) return false;
    }
    return true;
  }

  const xml::ScannedDocument& doc_;
  bool clean_ = true;  // every attribute value read is free of control characters
};

}  // namespace

bool urdfdom_certainly_accepts(const xml::ScannedDocument& doc) {
  if (!doc.errors().empty() || !plain_markup(doc)) return false;
  return Verdict(doc).accepts(doc.root());
}

}  // namespace assetlint::urdf
