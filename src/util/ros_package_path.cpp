#include "util/ros_package_path.h"

#include <cstdlib>
#include <filesystem>
#include <mutex>

namespace assetlint {
namespace {

std::mutex given_mutex;
std::vector<std::string>& given() {
  static std::vector<std::string> directories;
  return directories;
}

}  // namespace

std::vector<std::string> ros_package_search_path() {
  std::vector<std::string> entries;
  if (const char* variable = std::getenv("ROS_PACKAGE_PATH")) {
    const std::string text(variable);
    for (std::size_t at = 0; at <= text.size();) {
      const std::size_t end = std::min(text.find(':', at), text.size());
      if (end > at) entries.push_back(text.substr(at, end - at));
      at = end + 1;
    }
  }
  const std::lock_guard lock(given_mutex);
  entries.insert(entries.end(), given().begin(), given().end());
  return entries;
}

void add_package_paths(const std::vector<std::string>& directories) {
  const std::lock_guard lock(given_mutex);
  std::error_code ec;
  for (const auto& directory : directories)
    given().push_back(std::filesystem::absolute(directory, ec).lexically_normal().string());
}

}  // namespace assetlint
