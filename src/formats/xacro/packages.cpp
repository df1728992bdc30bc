#include "formats/xacro/packages.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <vector>

#include "util/ros_package_path.h"

namespace assetlint::xacro {
namespace {

namespace fs = std::filesystem;

// Directories deeper than this below a search root are not searched (a workspace's
// src/<repo>/<group>/<package> is four).
constexpr int kMaxSearchDepth = 5;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void collect(const fs::path& dir, int depth, std::map<std::string, std::string>& found) {
  std::error_code ec;
  if (fs::exists(dir / "package.xml", ec)) {
    const std::string name = package_name(read_text(dir / "package.xml"));
    if (!name.empty()) found.emplace(name, dir.string());
    // A package does not hold other packages (catkin and colcon stop here too).
    return;
  }
  if (depth >= kMaxSearchDepth) return;
  std::vector<fs::path> subdirectories;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string leaf = it->path().filename().string();
    if (leaf.empty() || leaf[0] == '.' || leaf == "build" || leaf == "install" || leaf == "log" || leaf == "node_modules")
      continue;
    std::error_code type_ec;
    if (it->is_directory(type_ec) && !it->is_symlink(type_ec)) subdirectories.push_back(it->path());
  }
  for (const auto& sub : subdirectories) collect(sub, depth + 1, found);
}

// Each searched root's packages, found once per run (lint runs check files in parallel).
const std::map<std::string, std::string>& packages_below(const fs::path& root) {
  static std::mutex mutex;
  static std::map<std::string, std::map<std::string, std::string>> cache;
  std::lock_guard lock(mutex);
  auto it = cache.find(root.string());
  if (it != cache.end()) return it->second;
  std::map<std::string, std::string> found;
  collect(root, 0, found);
  return cache.emplace(root.string(), std::move(found)).first->second;
}

}  // namespace

std::string package_name(const std::string& package_xml) {
  const auto open = package_xml.find("<name>");
  if (open == std::string::npos) return {};
  const auto close = package_xml.find("</name>", open);
  if (close == std::string::npos) return {};
  std::string name = package_xml.substr(open + 6, close - open - 6);
  const auto b = name.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  return name.substr(b, name.find_last_not_of(" \t\r\n") - b + 1);
}

std::optional<std::string> find_ros_package(const std::string& name, const std::string& from_file, const std::string& root) {
  std::error_code ec;
  std::vector<fs::path> roots;
  // The package holding the file, and the directory holding that package (its siblings).
  for (fs::path dir = fs::absolute(from_file, ec).parent_path(); !dir.empty(); dir = dir.parent_path()) {
    if (fs::exists(dir / "package.xml", ec)) {
      if (package_name(read_text(dir / "package.xml")) == name) return dir.string();
      roots.push_back(dir.parent_path());
      break;
    }
    if (dir == dir.parent_path()) break;
  }
  if (!root.empty()) roots.push_back(fs::absolute(root, ec));
  for (const std::string& entry : ros_package_search_path()) roots.emplace_back(entry);
  for (const auto& r : roots) {
    const auto& packages = packages_below(r.lexically_normal());
    if (auto it = packages.find(name); it != packages.end()) return it->second;
  }
  return std::nullopt;
}

}  // namespace assetlint::xacro
