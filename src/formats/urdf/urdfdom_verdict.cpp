#include "formats/urdf/urdfdom_verdict.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

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
// consumed: this accepts the plain decimal subset of that, finite and not denormal, and
// gives its value.
std::optional<double> plain_value(std::string_view text) {
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
  if (mantissa == 0) return std::nullopt;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (digits() == 0) return std::nullopt;
  }
  if (i != text.size()) return std::nullopt;
  // from_chars takes no leading '+'; overflow and underflow come back as out of range.
  const std::size_t skip = text[0] == '+' ? 1 : 0;
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data() + skip, text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
      (value != 0 && std::fabs(value) < 1e-300))
    return std::nullopt;
  return value;
}

bool plain_number(std::string_view text) { return plain_value(text).has_value(); }

// urdfdom's split_string at ' ' with the empty pieces skipped: how many pieces there are,
// or -1 when one is not a plain number in [low, high].
int plain_numbers(std::string_view text, double low = -HUGE_VAL, double high = HUGE_VAL) {
  int count = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find(' ', pos), text.size());
    const std::string_view piece = text.substr(pos, end - pos);
    if (!piece.empty()) {
      const auto value = plain_value(piece);
      if (!value || *value < low || *value > high) return -1;
      ++count;
    }
    pos = end + 1;
  }
  return count;
}

// urdfdom's Vector3::init: exactly three numbers.
bool plain_vector(std::string_view text) { return plain_numbers(text) == 3; }

// A vector urdfdom reads without complaint, when present.
bool plain_vector_or_absent(const std::optional<std::string_view>& text) { return !text || plain_vector(*text); }

// urdfdom's Color::init: every piece a number in [0, 1] (a wrong count is not an error).
bool plain_color(std::string_view text) { return plain_numbers(text, 0, 1) >= 0; }

class Verdict {
 public:
  explicit Verdict(const xml::ScannedDocument& doc) : doc_(doc) {}

  std::optional<std::vector<std::string>> predict(const Element* robot) {
    if (!robot || robot->name != "robot") return std::nullopt;
    if (!value(robot, "name")) return std::nullopt;
    if (auto version = value(robot, "version"); version && *version != "1.0") return std::nullopt;

    std::size_t elements = 0;  // sizes the name sets once: rehashing 100 000 names costs more than the lookups
    for (const Element* e = doc_.first_child(robot); e; e = doc_.next_sibling(e)) ++elements;

    std::unordered_set<std::string_view> materials;
    for (const Element* m = doc_.first_child(robot, "material"); m; m = doc_.next_sibling(m, "material"))
      if (!materials.insert(value(m, "name").value_or("")).second) return std::nullopt;

    std::unordered_set<std::string_view> links(elements);
    for (const Element* l = doc_.first_child(robot, "link"); l; l = doc_.next_sibling(l, "link"))
      if (!links.insert(value(l, "name").value_or("")).second) return std::nullopt;
    if (links.empty()) return std::nullopt;

    // urdfdom parses every joint before it builds the tree, so a joint it cannot parse is
    // the refusal even when an earlier joint names an undefined link.
    bool tree_links_defined = true;
    std::unordered_set<std::string_view> joints(elements), children(elements);
    for (const Element* j = doc_.first_child(robot, "joint"); j; j = doc_.next_sibling(j, "joint")) {
      auto name = value(j, "name");
      if (!name) return std::nullopt;
      switch (parse_joint(j)) {
        case JointParse::Other: return std::nullopt;
        case JointParse::MissingLimit: return missing_limit(robot, j, *name);
        case JointParse::Parses: break;
      }
      if (!joints.insert(*name).second) return std::nullopt;
      const auto parent = link_of(j, "parent"), child = link_of(j, "child");
      if (parent.empty() || child.empty() || !links.count(parent) || !links.count(child)) tree_links_defined = false;
      children.insert(child);
    }
    if (!tree_links_defined) return std::nullopt;
    // initRoot: exactly one link that is no joint's child.
    std::size_t roots = 0;
    for (std::string_view link : links) roots += children.count(link) ? 0 : 1;
    if (roots != 1 || !clean_) return std::nullopt;
    return std::vector<std::string>{};
  }

 private:
  enum class JointParse { Parses, MissingLimit, Other };

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
  bool vector_if_present(const Element* el, std::string_view attr) { return plain_vector_or_absent(value(el, attr)); }
  std::string_view link_of(const Element* joint, const char* tag) {
    const Element* el = doc_.first_child(joint, tag);
    return el ? value(el, "link").value_or("") : std::string_view();
  }

  // The joint urdfdom's parseJoint rejects for a missing <limit> (its first complaint, so
  // its message is known) when nothing urdfdom reads before it logs an error.
  std::optional<std::vector<std::string>> missing_limit(const Element* robot, const Element* joint,
                                                        std::string_view name) {
    for (const Element* m = doc_.first_child(robot, "material"); m; m = doc_.next_sibling(m, "material"))
      if (!material_quiet(m, false)) return std::nullopt;
    for (const Element* l = doc_.first_child(robot, "link"); l; l = doc_.next_sibling(l, "link"))
      if (!link_quiet(l)) return std::nullopt;
    if (!clean_) return std::nullopt;
    const bool revolute = value(joint, "type") == "revolute";
    std::string message = revolute ? "Joint [" + std::string(name) + "] is of type REVOLUTE but it does not specify limits"
                                   : "Joint [" + std::string(name) + "] is of type PRISMATIC without limits";
    return std::vector<std::string>{std::move(message), "joint xml is not initialized correctly"};
  }

  // urdfdom's parseMaterial logs nothing. A material inside a visual may hold only a name.
  bool material_quiet(const Element* material, bool only_name_is_ok) {
    if (!value(material, "name")) return false;
    bool has_rgb = false, has_filename = false;
    if (const Element* texture = doc_.first_child(material, "texture")) has_filename = value(texture, "filename").has_value();
    if (const Element* color = doc_.first_child(material, "color"))
      if (auto rgba = value(color, "rgba")) {
        if (!plain_color(*rgba)) return false;
        has_rgb = true;
      }
    return only_name_is_ok || has_rgb || has_filename;
  }
  bool pose_quiet(const Element* parent) {
    const Element* origin = doc_.first_child(parent, "origin");
    return !origin || (vector_if_present(origin, "xyz") && vector_if_present(origin, "rpy"));
  }
  bool geometry_quiet(const Element* holder) {
    const Element* geometry = doc_.first_child(holder, "geometry");
    const Element* shape = geometry ? doc_.first_child(geometry) : nullptr;
    if (!shape) return false;
    if (shape->name == "sphere") return number(shape, "radius");
    if (shape->name == "box") {
      const auto size = value(shape, "size");
      return size && plain_vector(*size);
    }
    if (shape->name == "cylinder") return number(shape, "length") && number(shape, "radius");
    if (shape->name == "mesh") return value(shape, "filename") && vector_if_present(shape, "scale");
    return false;
  }
  // urdfdom's parseLink logs nothing (its failures are logged, then ignored by parseURDF).
  bool link_quiet(const Element* link) {
    if (!value(link, "name")) return false;
    if (const Element* inertial = doc_.first_child(link, "inertial")) {
      if (!pose_quiet(inertial)) return false;
      const Element* mass = doc_.first_child(inertial, "mass");
      const Element* inertia = doc_.first_child(inertial, "inertia");
      if (!mass || !number(mass, "value") || !inertia) return false;
      for (const char* moment : {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"})
        if (!number(inertia, moment)) return false;
    }
    for (const Element* visual = doc_.first_child(link, "visual"); visual; visual = doc_.next_sibling(visual, "visual")) {
      if (!pose_quiet(visual) || !geometry_quiet(visual)) return false;
      if (const Element* material = doc_.first_child(visual, "material"))
        if (!material_quiet(material, true)) return false;
    }
    for (const Element* collision = doc_.first_child(link, "collision"); collision;
         collision = doc_.next_sibling(collision, "collision"))
      if (!pose_quiet(collision) || !geometry_quiet(collision)) return false;
    return true;
  }

  // urdfdom's parseJoint: returns true, or fails first on a missing <limit>, or otherwise.
  JointParse parse_joint(const Element* j) {
    if (const Element* origin = doc_.first_child(j, "origin"))
      if (!vector_if_present(origin, "xyz") || !vector_if_present(origin, "rpy")) return JointParse::Other;
    auto type = value(j, "type");
    if (!type) return JointParse::Other;
    const bool moving = *type == "revolute" || *type == "continuous" || *type == "prismatic" || *type == "planar";
    if (!moving && *type != "fixed" && *type != "floating") return JointParse::Other;
    if (const Element* axis = doc_.first_child(j, "axis"); axis && moving)
      if (!vector_if_present(axis, "xyz")) return JointParse::Other;
    if (const Element* limit = doc_.first_child(j, "limit")) {
      if (!number_if_present(limit, "lower") || !number_if_present(limit, "upper") || !number(limit, "effort") ||
          !number(limit, "velocity"))
        return JointParse::Other;
    } else if (*type == "revolute" || *type == "prismatic") {
      return JointParse::MissingLimit;
    }
    if (const Element* safety = doc_.first_child(j, "safety_controller"))
      if (!number_if_present(safety, "soft_lower_limit") || !number_if_present(safety, "soft_upper_limit") ||
          !number_if_present(safety, "k_position") || !number(safety, "k_velocity"))
        return JointParse::Other;
    if (const Element* calibration = doc_.first_child(j, "calibration"))
      if (!number_if_present(calibration, "rising") || !number_if_present(calibration, "falling"))
        return JointParse::Other;
    if (const Element* mimic = doc_.first_child(j, "mimic"))
      if (!value(mimic, "joint") || !number_if_present(mimic, "multiplier") || !number_if_present(mimic, "offset"))
        return JointParse::Other;
    if (const Element* dynamics = doc_.first_child(j, "dynamics")) {
      if (!number_if_present(dynamics, "damping") || !number_if_present(dynamics, "friction")) return JointParse::Other;
      if (!value(dynamics, "damping") && !value(dynamics, "friction")) return JointParse::Other;
    }
    return JointParse::Parses;
  }

  const xml::ScannedDocument& doc_;
  bool clean_ = true;  // every attribute value read is free of control characters
};

}  // namespace

std::optional<std::vector<std::string>> predicted_urdfdom_errors(const xml::ScannedDocument& doc) {
  if (!doc.errors().empty() || !plain_markup(doc)) return std::nullopt;
  return Verdict(doc).predict(doc.root());
}

}  // namespace assetlint::urdf
