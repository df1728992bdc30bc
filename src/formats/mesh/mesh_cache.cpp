#include "formats/mesh/mesh_cache.h"

#include <algorithm>
#include <map>
#include <mutex>

#include "formats/mesh/mesh_points.h"

namespace assetlint::mesh {
namespace {

struct Entry {
  std::shared_ptr<const std::vector<Eigen::Vector3d>> points;
  std::string error;
};

std::vector<Eigen::Vector3d> distinct(std::vector<Eigen::Vector3d> points) {
  const auto less = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(points.begin(), points.end(), less);
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

}  // namespace

std::shared_ptr<const std::vector<Eigen::Vector3d>> cached_points(const std::string& path, std::string& error) {
  static std::mutex mutex;
  static std::map<std::string, Entry, std::less<>> cache;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = cache.find(path); it != cache.end()) {
      error = it->second.error;
      return it->second.points;
    }
  }
  Entry entry;
  if (auto points = read_points(path, entry.error))
    entry.points = std::make_shared<const std::vector<Eigen::Vector3d>>(distinct(std::move(*points)));
  const std::lock_guard<std::mutex> lock(mutex);
  const auto& stored = cache.emplace(path, std::move(entry)).first->second;
  error = stored.error;
  return stored.points;
}

}  // namespace assetlint::mesh
