#include "formats/xml/xml_scanner.h"

#include <fmt/format.h>

namespace assetlint::xml {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
bool is_name_char(char c) {
  return !is_space(c) && c != '>' && c != '/' && c != '=' && c != '<' && c != '"' && c != '\'' && c != '\0';
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
    std::size_t pos = 0;
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos = 3;
    scan_.document_begin = pos;
    // XML 1.0 allows no C0 control character but tab, LF and CR, not even in attribute
    // values (libxml2, and so ROS, reject the file). NUL bytes have their own messages below.
    for (std::size_t i = pos; i < text_.size(); ++i) {
      const auto c = static_cast<unsigned char>(text_[i]);
      if (c != 0 && c < 0x20 && c != '\t' && c != '\n' && c != '\r') {
        problem(i, 1, fmt::format("control character U+{:04X} is not allowed in XML 1.0", c), false);
        return std::move(scan_);
      }
    }
    scan_prolog(pos);
    if (!scan_.recoverable) return std::move(scan_);
    if (pos >= text_.size()) {
      problem(text_.size(), 0, "no root element: the file holds no XML element", false);
      return std::move(scan_);
    }
    scan_element_tree(pos);
    if (scan_.recoverable) scan_epilog(pos);
    return std::move(scan_);
  }

 private:
  void problem(std::size_t offset, std::size_t length, std::string message, bool recoverable) {
    scan_.problems.push_back({offset, length == 0 ? 1 : length, std::move(message)});
    if (!recoverable) scan_.recoverable = false;
  }

  // Skips whitespace, comments, processing instructions and DOCTYPE before the root.
  void scan_prolog(std::size_t& pos) {
    const std::size_t start = pos;
    while (pos < text_.size()) {
      if (is_space(text_[pos])) { ++pos; continue; }
      if (text_[pos] != '<') {
        // Text before the document: e.g. a log prefix captured with the file.
        std::size_t next = text_.find('<', pos);
        if (next == std::string_view::npos) next = text_.size();
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
      }
      if (text_.compare(pos, 2, "<?") == 0) {
        if (!skip_to(pos, "?>", "unterminated processing instruction '<?'")) return;
        continue;
      }
      if (text_.compare(pos, 4, "<!--") == 0) {
        if (!skip_to(pos, "-->", "unterminated comment '<!--'")) return;
        continue;
      }
      if (text_.compare(pos, 2, "<!") == 0) {
        if (!skip_doctype(pos)) return;
        continue;
      }
      return;  // the root element
    }
  }

  bool skip_to(std::size_t& pos, std::string_view terminator, std::string_view message) {
    const std::size_t end = text_.find(terminator, pos);
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

  void scan_element_tree(std::size_t& pos) {
    std::vector<std::pair<std::string_view, std::size_t>> open;  // name, offset of '<'
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
      if (text_.compare(pos, 4, "<!--") == 0) {
        if (!skip_to(pos, "-->", "unterminated comment '<!--'")) return;
        continue;
      }
      if (text_.compare(pos, 9, "<![CDATA[") == 0) {
        if (!skip_to(pos, "]]>", "unterminated CDATA section")) return;
        continue;
      }
      if (text_.compare(pos, 2, "<?") == 0) {
        if (!skip_to(pos, "?>", "unterminated processing instruction '<?'")) return;
        continue;
      }
      if (text_.compare(pos, 2, "</") == 0) {
        std::size_t name_begin = pos + 2, i = name_begin;
        while (i < text_.size() && is_name_char(text_[i])) ++i;
        std::string_view name = text_.substr(name_begin, i - name_begin);
        while (i < text_.size() && is_space(text_[i])) ++i;
        if (i >= text_.size() || text_[i] != '>') {
          problem(pos, i - pos, fmt::format("malformed end tag '</{}': expected '>'", name), false);
          return;
        }
        if (open.empty() || open.back().first != name) {
          problem(pos, i + 1 - pos,
                  open.empty() ? fmt::format("end tag '</{}>' without a start tag", name)
                               : fmt::format("end tag '</{}>' does not match the open element '<{}>'", name,
                                             open.back().first),
                  false);
          return;
        }
        open.pop_back();
        pos = i + 1;
        continue;
      }
      bool self_closing = false;
      if (!scan_start_tag(pos, self_closing)) return;
      if (!self_closing) open.emplace_back(scan_.tags.back().name, scan_.tags.back().offset);
    } while (!open.empty());
    if (!open.empty()) {
      problem(open.back().second, open.back().first.size() + 1,
              fmt::format("element '<{}>' is never closed (end of file reached)", open.back().first), false);
    }
  }

  bool scan_start_tag(std::size_t& pos, bool& self_closing) {
    XmlStartTag tag;
    tag.offset = pos;
    std::size_t i = pos + 1;
    const std::size_t name_begin = i;
    while (i < text_.size() && is_name_char(text_[i])) ++i;
    tag.name = text_.substr(name_begin, i - name_begin);
    if (tag.name.empty()) {
      problem(pos, 1, "'<' not followed by an element name", false);
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
      const std::size_t lt = text_.find('<', i + 1);
      if (close == std::string_view::npos || lt < close) {
        problem(i, 1, fmt::format("unterminated value of attribute '{}'", attr.name), false);
        return false;
      }
      attr.value_offset = i + 1;
      attr.value_length = close - (i + 1);
      for (const auto& existing : tag.attributes) {
        if (existing.name == attr.name) {
          problem(attr.name_offset, attr.name.size(),
                  fmt::format("attribute '{}' appears twice in '<{}>'", attr.name, tag.name), false);
          return false;
        }
      }
      tag.attributes.push_back(attr);
      i = close + 1;
    }
    tag.end = i;
    scan_.tags.push_back(std::move(tag));
    pos = i;
    return true;
  }

  void scan_epilog(std::size_t& pos) {
    scan_.document_end = pos;
    while (pos < text_.size()) {
      if (is_space(text_[pos])) { ++pos; continue; }
      if (text_.compare(pos, 4, "<!--") == 0) {
        if (!skip_to(pos, "-->", "unterminated comment '<!--'")) return;
        scan_.document_end = pos;
        continue;
      }
      if (text_.compare(pos, 2, "<?") == 0 && text_.compare(pos, 5, "<?xml") != 0) {
        if (!skip_to(pos, "?>", "unterminated processing instruction '<?'")) return;
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

}  // namespace assetlint::xml
