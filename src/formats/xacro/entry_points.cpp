#include "formats/xacro/entry_points.h"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "formats/xacro/packages.h"
#include "formats/xml/xml_scanner.h"

namespace assetlint::xacro {
namespace {

namespace fs = std::filesystem;

std::string canonical_path(const fs::path& path) {
  std::error_code ec;
  const fs::path c = fs::weakly_canonical(path, ec);
  return ec ? path.lexically_normal().string() : c.string();
}

struct Scanned {
  std::vector<std::string> includes;  // filename attributes of xacro:include
  bool library = true;                // only definitions at the top level
};

Scanned scan_text(std::string_view text) {
  Scanned out;
  const xml::XmlScan s = xml::scan_xml(text);
  if (s.tags.empty() || !s.recoverable) {
    out.library = false;  // let the check report what is wrong with it
    return out;
  }
  for (const xml::XmlStartTag& tag : s.tags) {
    if (tag.name != "xacro:include") continue;
    if (const xml::XmlAttributeSpan* a = tag.attribute("filename"))
      out.includes.push_back(xml::decode_attribute_value(text.substr(a->value_offset, a->value_length)));
  }
  for (std::uint32_t i = s.tags[0].first_child; i != xml::XmlStartTag::kNone; i = s.tags[i].next_sibling) {
    const std::string_view name = s.tags[i].name;
    if (name != "xacro:macro" && name != "xacro:property" && name != "xacro:include" && name != "xacro:arg") out.library = false;
  }
  return out;
}

Scanned scan(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return scan_text(buffer.str());
}

// Where an include points, as far as it can be told without expanding: `$(find pkg)` and
// `$(dirname)` resolved, a path relative to the including file. Anything computed (an
// argument, a property) leaves only the text after it, matched as a path suffix.
struct Target {
  std::string path;    // resolved, canonical
  std::string suffix;  // or only this tail is known
};

Target resolve(const std::string& spec, const std::string& from) {
  std::string text = spec;
  const std::string dir = fs::path(from).parent_path().string();
  for (std::size_t at; (at = text.find("$(dirname)")) != std::string::npos;) text.replace(at, 10, dir);
  for (std::size_t at; (at = text.find("$(find ")) != std::string::npos;) {
    const std::size_t end = text.find(')', at);
    if (end == std::string::npos) break;
    const std::string pkg = text.substr(at + 7, end - at - 7);
    const auto found = find_ros_package(pkg, from, "");
    if (!found) break;
    text.replace(at, end - at + 1, *found);
  }
  const std::size_t computed = std::max(text.rfind(')') == std::string::npos ? 0 : text.rfind(')') + 1,
                                        text.rfind('}') == std::string::npos ? 0 : text.rfind('}') + 1);
  if (text.find("$(") != std::string::npos || text.find("${") != std::string::npos) return {{}, text.substr(computed)};
  const fs::path p(text);
  return {canonical_path(p.is_absolute() ? p : fs::path(dir) / p), {}};
}

}  // namespace

bool is_xacro_library(std::string_view text) {
  const xml::XmlScan s = xml::scan_xml(text);
  // A root that names the robot is a top file, whatever it includes.
  return scan_text(text).library && !s.tags.empty() && s.tags[0].attribute("name") == nullptr;
}

bool includes_file(const std::string& top, const std::string& file) {
  const std::string wanted = canonical_path(file);
  std::set<std::string> seen{canonical_path(top)};
  std::vector<std::string> pending{top};
  while (!pending.empty()) {
    const std::string from = pending.back();
    pending.pop_back();
    for (const std::string& spec : scan(from).includes) {
      const Target t = resolve(spec, from);
      if (t.path.empty() ? (t.suffix.size() > 1 && wanted.ends_with(t.suffix)) : t.path == wanted) return true;
      if (!t.path.empty() && seen.insert(t.path).second) pending.push_back(t.path);
    }
  }
  return false;
}

std::vector<std::string> top_level_xacro_files(const std::vector<std::string>& paths) {
  std::set<std::string> included;
  std::vector<std::string> suffixes;
  std::vector<bool> library(paths.size());
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const Scanned s = scan(paths[i]);
    library[i] = s.library;
    for (const std::string& spec : s.includes) {
      const Target t = resolve(spec, paths[i]);
      if (!t.path.empty()) included.insert(t.path);
      else if (!t.suffix.empty()) suffixes.push_back(t.suffix);
    }
  }
  std::vector<std::string> tops;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (library[i]) continue;
    const std::string c = canonical_path(paths[i]);
    if (included.count(c)) continue;
    bool by_suffix = false;
    for (const std::string& suffix : suffixes) by_suffix = by_suffix || (suffix.size() > 1 && c.ends_with(suffix));
    if (!by_suffix) tops.push_back(paths[i]);
  }
  return tops;
}

}  // namespace assetlint::xacro
