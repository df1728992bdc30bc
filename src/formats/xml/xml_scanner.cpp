#include "formats/xml/xml_scanner.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>

#include "util/binary_data.h"

namespace assetlint::xml {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
// Byte classes for names: kToken ends at what delimits a name in a tag; an XML name (as
// tinyxml2 reads it) starts with a letter, '_', ':' or a byte of a multi-byte UTF-8
// character and goes on with those, digits, '.' and '-'.
enum : unsigned char { kToken = 1, kNameStart = 2, kNameChar = 4 };
constexpr std::array<unsigned char, 256> kNameClasses = [] {
  std::array<unsigned char, 256> k{};
  for (int c = 0; c < 256; ++c) {
    const bool token = !(c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '>' || c == '/' || c == '=' ||
                         c == '<' || c == '"' || c == '\'' || c == '\0');
    const bool start = c >= 0x80 || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':';
    const bool name = start || (c >= '0' && c <= '9') || c == '.' || c == '-';
    k[c] = static_cast<unsigned char>((token ? kToken : 0) | (start ? kNameStart : 0) | (name ? kNameChar : 0));
  }
  return k;
}();
unsigned char name_class(char c) { return kNameClasses[static_cast<unsigned char>(c)]; }
bool is_name_char(char c) { return name_class(c) & kToken; }
bool is_xml_name(std::string_view name) {
  if (name.empty() || !(name_class(name[0]) & kNameStart)) return false;
  for (char c : name.substr(1))
    if (!(name_class(c) & kNameChar)) return false;
  return true;
}

// Which bytes `text` holds, 16 at a time (vectorised by the compiler on every target).
struct ByteSummary {
  bool control = false;  // a C0 control character other than NUL, tab, LF and CR
  bool non_ascii = false;
  bool ampersand = false;
  bool carriage_return = false;
  bool nul = false;
};
ByteSummary summarise_bytes(std::string_view text) {
  using Bytes = unsigned char __attribute__((vector_size(16)));
  Bytes control{}, high{}, amp{}, cr{}, nul{};
  std::size_t i = 0;
  for (; i + 16 <= text.size(); i += 16) {
    Bytes v;
    std::memcpy(&v, text.data() + i, 16);
    high |= v;
    amp |= (Bytes)(v == '&');
    cr |= (Bytes)(v == '\r');
    nul |= (Bytes)(v == 0);
    control |= (Bytes)((v < 0x20) & (v != 0) & (v != '\t') & (v != '\n') & (v != '\r'));
  }
  ByteSummary summary;
  for (int k = 0; k < 16; ++k) {
    summary.control |= control[k] != 0;
    summary.non_ascii |= (high[k] & 0x80) != 0;
    summary.ampersand |= amp[k] != 0;
    summary.carriage_return |= cr[k] != 0;
    summary.nul |= nul[k] != 0;
  }
  for (; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    summary.control |= c != 0 && c < 0x20 && c != '\t' && c != '\n' && c != '\r';
    summary.non_ascii |= c >= 0x80;
    summary.ampersand |= c == '&';
    summary.carriage_return |= c == '\r';
    summary.nul |= c == 0;
  }
  return summary;
}

std::string printable(std::string_view text, std::size_t max = 24) {
  std::string out;
  for (char c : text.substr(0, max)) {
    if (c == '\0') out += "\\0";
    else if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else out += c;
  }
  if (text.size() > max) out += "…";
  return out;
}

class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  XmlScan run() {
    scan();
    // The storage no longer grows: the tags may point into it.
    for (std::size_t t = 0; t < scan_.tags.size(); ++t) {
      const auto [first, count] = attribute_ranges_[t];
      scan_.tags[t].attributes = std::span<const XmlAttributeSpan>(scan_.attribute_storage).subspan(first, count);
    }
    return std::move(scan_);
  }

 private:
  void scan() {
    // Room for a tag every 32 bytes and an attribute every 16: a generated URDF has about
    // half that, and pages never touched cost nothing, where growing by doubling copies and
    // faults in every page twice. Capped (a 100 MB file's worth) so that a file near the
    // size limit asks for no more address space than it may end up needing.
    const std::size_t room = std::min<std::size_t>(text_.size(), std::size_t{100} << 20);
    scan_.tags.reserve(room / 32 + 4);
    scan_.attribute_storage.reserve(room / 16 + 4);
    attribute_ranges_.reserve(room / 32 + 4);
    std::size_t pos = 0;
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos = 3;
    scan_.document_begin = pos;
    const ByteSummary bytes = summarise_bytes(text_.substr(pos));
    scan_.non_ascii = bytes.non_ascii;
    scan_.ampersand = bytes.ampersand;
    scan_.carriage_return = bytes.carriage_return;
    // XML 1.0 allows no C0 control character but tab, LF and CR, not even in attribute
    // values (libxml2, and so ROS, reject the file). NUL bytes have their own messages below.
    // A file with such a byte before its first '<' is binary data, not XML with a stray byte:
    // it is described, not quoted.
    if (const auto binary = first_binary_byte(text_.substr(pos), text_.find('<', pos) - pos)) {
      problem(pos + *binary, 1,
              fmt::format("binary data, not XML: byte {} is U+{:04X}, a control character no text file holds",
                          pos + *binary, static_cast<unsigned char>(text_[pos + *binary])),
              false);
      return;
    }
    for (std::size_t i = pos; bytes.control && i < text_.size(); ++i) {
      const auto c = static_cast<unsigned char>(text_[i]);
      if (c != 0 && c < 0x20 && c != '\t' && c != '\n' && c != '\r') {
        problem(i, 1, fmt::format("control character U+{:04X} is not allowed in XML 1.0", c), false);
        return;
      }
    }
    scan_prolog(pos);
    if (!scan_.recoverable) return;
    if (pos >= text_.size()) {
      problem(text_.size(), 0, "no root element: the file holds no XML element", false);
      return;
    }
    scan_element_tree(pos);
    if (scan_.recoverable) scan_epilog(pos);
    // tinyxml2 and urdfdom's tinyxml stop reading at a NUL byte, wherever it is: in a comment,
    // an attribute value or a processing instruction it cuts the document short.
    if (bytes.nul && scan_.recoverable) {
      const std::string_view document = text_.substr(scan_.document_begin, scan_.document_end - scan_.document_begin);
      if (const std::size_t nul = document.find('\0'); nul != std::string_view::npos)
        problem(scan_.document_begin + nul, 1, "NUL byte inside the XML document", false);
    }
  }

 private:
  void problem(std::size_t offset, std::size_t length, std::string message, bool recoverable) {
    scan_.problems.push_back({offset, length == 0 ? 1 : length, std::move(message)});
    if (!recoverable) scan_.recoverable = false;
  }

  // tinyxml2 (MuJoCo's parser, and the one asset-lint used to build URDF models with)
  // accepts '<?' only before anything else; XML would allow more, but a file it rejects is
  // rejected by those tools.
  void misplaced_instruction(std::size_t pos, std::string_view where) {
    std::size_t name_end = pos + 2;
    while (name_end < text_.size() && is_name_char(text_[name_end])) ++name_end;
    problem(pos, name_end - pos,
            fmt::format("processing instruction '{}' {}: tinyxml2-based parsers accept '<?' only at the start "
                        "of the file", printable(text_.substr(pos, name_end - pos)), where),
            false);
  }

  // Skips whitespace, comments, processing instructions and DOCTYPE before the root.
  void scan_prolog(std::size_t& pos) {
    const std::size_t start = pos;
    bool markup_seen = false;  // a comment or DOCTYPE since the document began
    while (pos < text_.size()) {
      if (is_space(text_[pos])) { ++pos; continue; }
      if (text_[pos] != '<') {
        // Text before the document: e.g. a log prefix captured with the file.
        std::size_t next = text_.find('<', pos);
        if (next == std::string_view::npos) {
          // No markup at all: not an XML file. Its text is described, not quoted.
          problem(pos, 0, "not XML: the file holds text and no element; an XML file starts with '<?xml' or an element",
                  false);
          pos = text_.size();
          return;
        }
        std::size_t junk_end = next;
        while (junk_end > pos && is_space(text_[junk_end - 1])) --junk_end;
        problem(pos, junk_end - pos,
                fmt::format("text before the XML document: '{}'; an XML file must start with '<?xml' or an element",
                            printable(text_.substr(pos, junk_end - pos))),
                true);
        pos = next;
        scan_.document_begin = next;
        continue;
      }
      if (text_.compare(pos, 5, "<?xml") == 0) {
        if (pos != start && scan_.document_begin != pos) {
          // Whitespace or other markup before the declaration: strict parsers reject it.
          problem(pos, 5, "the XML declaration '<?xml' must be the first thing in the file", true);
        }
        scan_.document_begin = pos;
        markup_seen = false;
      }
      if (text_.compare(pos, 2, "<?") == 0) {
        if (markup_seen) {
          misplaced_instruction(pos, "after a comment or DOCTYPE");
          return;
        }
        scan_.instructions.push_back(pos);
        if (!skip_to(pos, "<?", "?>", "unterminated processing instruction '<?'")) return;
        continue;
      }
      markup_seen = true;
      if (text_.compare(pos, 4, "<!--") == 0) {
        if (!skip_to(pos, "<!--", "-->", "unterminated comment '<!--'")) return;
        continue;
      }
      if (text_.compare(pos, 2, "<!") == 0) {
        scan_.doctype_or_cdata = true;
        if (!skip_doctype(pos)) return;
        continue;
      }
      return;  // the root element
    }
  }

  // Past `opener` at pos, to the end of the first `terminator` after it ("<!-->" and "<?>"
  // are not closed).
  bool skip_to(std::size_t& pos, std::string_view opener, std::string_view terminator, std::string_view message) {
    const std::size_t end = text_.find(terminator, pos + opener.size());
    if (end == std::string_view::npos) {
      problem(pos, 2, std::string(message), false);
      pos = text_.size();
      return false;
    }
    pos = end + terminator.size();
    return true;
  }

  bool skip_doctype(std::size_t& pos) {
    int depth = 0;
    for (std::size_t i = pos; i < text_.size(); ++i) {
      if (text_[i] == '[') ++depth;
      else if (text_[i] == ']') --depth;
      else if (text_[i] == '>' && depth <= 0) { pos = i + 1; return true; }
    }
    problem(pos, 2, "unterminated '<!' declaration", false);
    pos = text_.size();
    return false;
  }

  struct OpenElement {
    std::uint32_t tag;
    std::uint32_t last_child = XmlStartTag::kNone;
  };

  void scan_element_tree(std::size_t& pos) {
    std::vector<OpenElement> open;
    do {
      if (pos >= text_.size()) break;
      if (text_[pos] != '<') {
        const std::size_t next = std::min(text_.find('<', pos), text_.size());
        // Only the text up to the next markup: searching the rest of the file would
        // make the scan quadratic.
        const std::size_t nul = text_.substr(pos, next - pos).find('\0');
        if (nul != std::string_view::npos) {
          problem(pos + nul, 1, "NUL byte inside the XML document", false);
          return;
        }
        pos = next;
        continue;
      }
      // Most markup is a start tag: the other kinds only when the byte after '<' says so.
      const char kind = pos + 1 < text_.size() ? text_[pos + 1] : '\0';
      if (kind == '!' && text_.compare(pos, 4, "<!--") == 0) {
        if (!skip_to(pos, "<!--", "-->", "unterminated comment '<!--'")) return;
        continue;
      }
      if (kind == '!' && text_.compare(pos, 9, "<![CDATA[") == 0) {
        scan_.doctype_or_cdata = true;
        if (!skip_to(pos, "<![CDATA[", "]]>", "unterminated CDATA section")) return;
        continue;
      }
      if (kind == '?') {
        misplaced_instruction(pos, "inside the root element");
        return;
      }
      if (kind == '/') {
        std::size_t name_begin = pos + 2, i = name_begin;
        while (i < text_.size() && is_name_char(text_[i])) ++i;
        std::string_view name = text_.substr(name_begin, i - name_begin);
        while (i < text_.size() && is_space(text_[i])) ++i;
        if (i >= text_.size() || text_[i] != '>') {
          problem(pos, i - pos, fmt::format("malformed end tag '</{}': expected '>'", name), false);
          return;
        }
        if (open.empty() || scan_.tags[open.back().tag].name != name) {
          problem(pos, i + 1 - pos,
                  open.empty() ? fmt::format("end tag '</{}>' without a start tag", name)
                               : fmt::format("end tag '</{}>' does not match the open element '<{}>'", name,
                                             scan_.tags[open.back().tag].name),
                  false);
          return;
        }
        open.pop_back();
        pos = i + 1;
        continue;
      }
      bool self_closing = false;
      if (!scan_start_tag(pos, self_closing)) return;
      const auto index = static_cast<std::uint32_t>(scan_.tags.size() - 1);
      if (!open.empty()) {
        OpenElement& parent = open.back();
        if (parent.last_child == XmlStartTag::kNone) scan_.tags[parent.tag].first_child = index;
        else scan_.tags[parent.last_child].next_sibling = index;
        parent.last_child = index;
      }
      if (self_closing) continue;
      if (open.size() + 1 > kMaxXmlDepth) {
        const XmlStartTag& tag = scan_.tags.back();
        problem(tag.offset, tag.end - tag.offset,
                fmt::format("elements nested deeper than {} levels ('<{}>')", kMaxXmlDepth, tag.name), false);
        return;
      }
      open.push_back({index});
    } while (!open.empty());
    if (!open.empty()) {
      const XmlStartTag& tag = scan_.tags[open.back().tag];
      problem(tag.offset, tag.name.size() + 1,
              fmt::format("element '<{}>' is never closed (end of file reached)", tag.name), false);
    }
  }

  bool scan_start_tag(std::size_t& pos, bool& self_closing) {
    XmlStartTag tag;
    tag.offset = pos;
    const std::size_t first_attribute = scan_.attribute_storage.size();
    // Where the attributes will be, as (offset, count) until the scan ends: the storage moves as it grows.
    attribute_ranges_.emplace_back(first_attribute, 0);
    std::size_t i = pos + 1;
    const std::size_t name_begin = i;
    while (i < text_.size() && is_name_char(text_[i])) ++i;
    tag.name = text_.substr(name_begin, i - name_begin);
    if (tag.name.empty()) {
      problem(pos, 1, "'<' not followed by an element name", false);
      return false;
    }
    if (!is_xml_name(tag.name)) {
      problem(name_begin, tag.name.size(), fmt::format("'{}' is not an XML element name", printable(tag.name)), false);
      return false;
    }
    for (;;) {
      const std::size_t before_space = i;
      while (i < text_.size() && is_space(text_[i])) ++i;
      if (i >= text_.size()) {
        problem(pos, i - pos, fmt::format("start tag '<{}' is not closed with '>'", tag.name), false);
        return false;
      }
      if (text_[i] == '>') { ++i; break; }
      if (text_[i] == '/' && i + 1 < text_.size() && text_[i + 1] == '>') {
        self_closing = true;
        i += 2;
        break;
      }
      if (i == before_space) {
        problem(i, 1, fmt::format("expected whitespace, '>' or '/>' in '<{}', found '{}'", tag.name,
                                  printable(text_.substr(i, 1))), false);
        return false;
      }
      XmlAttributeSpan attr;
      attr.name_offset = i;
      while (i < text_.size() && is_name_char(text_[i])) ++i;
      attr.name = text_.substr(attr.name_offset, i - attr.name_offset);
      if (attr.name.empty()) {
        problem(i, 1, fmt::format("expected an attribute name in '<{}', found '{}'", tag.name,
                                  printable(text_.substr(i, 1))), false);
        return false;
      }
      if (!is_xml_name(attr.name)) {
        problem(attr.name_offset, attr.name.size(),
                fmt::format("'{}' in '<{}' is not an XML attribute name", printable(attr.name), tag.name), false);
        return false;
      }
      while (i < text_.size() && is_space(text_[i])) ++i;
      if (i >= text_.size() || text_[i] != '=') {
        problem(i, 1, fmt::format("expected '=' after attribute '{}'", attr.name), false);
        return false;
      }
      ++i;
      while (i < text_.size() && is_space(text_[i])) ++i;
      if (i >= text_.size() || (text_[i] != '"' && text_[i] != '\'')) {
        problem(i, 1, fmt::format("attribute '{}' value must be quoted", attr.name), false);
        return false;
      }
      const char quote = text_[i];
      const std::size_t close = text_.find(quote, i + 1);
      if (close == std::string_view::npos || text_.substr(i + 1, close - i - 1).find('<') != std::string_view::npos) {
        problem(i, 1, fmt::format("unterminated value of attribute '{}'", attr.name), false);
        return false;
      }
      attr.value_offset = i + 1;
      attr.value_length = close - (i + 1);
      for (std::size_t k = first_attribute; k < scan_.attribute_storage.size(); ++k) {
        if (scan_.attribute_storage[k].name == attr.name) {
          problem(attr.name_offset, attr.name.size(),
                  fmt::format("attribute '{}' appears twice in '<{}>'", attr.name, tag.name), false);
          return false;
        }
      }
      scan_.attribute_storage.push_back(attr);
      i = close + 1;
    }
    tag.end = i;
    attribute_ranges_.back().second = scan_.attribute_storage.size() - first_attribute;
    scan_.tags.push_back(std::move(tag));
    pos = i;
    return true;
  }

  void scan_epilog(std::size_t& pos) {
    scan_.document_end = pos;
    while (pos < text_.size()) {
      if (is_space(text_[pos])) { ++pos; continue; }
      if (text_.compare(pos, 4, "<!--") == 0) {
        if (!skip_to(pos, "<!--", "-->", "unterminated comment '<!--'")) return;
        scan_.document_end = pos;
        continue;
      }
      std::size_t end = text_.size();
      while (end > pos && is_space(text_[end - 1])) --end;
      const std::string_view rest = text_.substr(pos, end - pos);
      if (rest.find_first_not_of('\0') == std::string_view::npos) {
        problem(pos, rest.size(),
                fmt::format("{} NUL byte{} after the root element; strict XML parsers reject the file", rest.size(),
                            rest.size() == 1 ? "" : "s"),
                true);
      } else {
        problem(pos, rest.size(),
                fmt::format("content after the root element: '{}'", printable(rest)), true);
      }
      return;
    }
  }

  std::string_view text_;
  XmlScan scan_;
  std::vector<std::pair<std::size_t, std::size_t>> attribute_ranges_;  // per tag: first, count
};

}  // namespace

const XmlAttributeSpan* XmlStartTag::attribute(std::string_view attr_name) const {
  for (const auto& attr : attributes)
    if (attr.name == attr_name) return &attr;
  return nullptr;
}

XmlScan scan_xml(std::string_view text) {
  XmlScan scan = Scanner(text).run();
  if (scan.document_end == 0) scan.document_end = text.size();
  return scan;
}

bool attribute_value_needs_decoding(std::string_view raw) {
  return raw.find_first_of("&\r") != std::string_view::npos || raw.find("\n\r") != std::string_view::npos;
}

namespace {

void append_utf8(std::string& out, std::uint32_t code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x200000) {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

// `&#65;` or `&#x41;` at the start of `text`: its length and code point; 0 when it is not one.
std::size_t character_reference(std::string_view text, std::uint32_t& code) {
  const std::size_t semicolon = text.find(';');
  if (text.size() < 4 || text[1] != '#' || semicolon == std::string_view::npos) return 0;
  const bool hex = text[2] == 'x';
  const std::string_view digits = text.substr(hex ? 3 : 2, semicolon - (hex ? 3 : 2));
  if (digits.empty() || digits.size() > 8) return 0;
  code = 0;
  for (char c : digits) {
    const int digit = c >= '0' && c <= '9' ? c - '0'
                      : hex && c >= 'a' && c <= 'f' ? c - 'a' + 10
                      : hex && c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
    if (digit < 0) return 0;
    code = code * (hex ? 16 : 10) + static_cast<std::uint32_t>(digit);
  }
  return semicolon + 1;
}

}  // namespace

std::string decode_attribute_value(std::string_view raw) {
  static constexpr std::pair<std::string_view, char> kEntities[] = {
      {"&quot;", '"'}, {"&amp;", '&'}, {"&apos;", '\''}, {"&lt;", '<'}, {"&gt;", '>'}};
  std::string out;
  out.reserve(raw.size());
  for (std::size_t i = 0; i < raw.size();) {
    const char c = raw[i];
    if (c == '\r' || c == '\n') {
      const char pair = c == '\r' ? '\n' : '\r';
      i += (i + 1 < raw.size() && raw[i + 1] == pair) ? 2 : 1;
      out += '\n';
      continue;
    }
    if (c == '&') {
      std::uint32_t code = 0;
      if (const std::size_t length = character_reference(raw.substr(i), code)) {
        append_utf8(out, code);
        i += length;
        continue;
      }
      bool named = false;
      for (const auto& [entity, value] : kEntities)
        if (raw.compare(i, entity.size(), entity) == 0) {
          out += value;
          i += entity.size();
          named = true;
          break;
        }
      if (named) continue;
    }
    out += c;
    ++i;
  }
  return out;
}

}  // namespace assetlint::xml
