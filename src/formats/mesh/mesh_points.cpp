#include "formats/mesh/mesh_points.h"

#include <assimp/cimport.h>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "util/ros_package_path.h"

namespace assetlint::mesh {
namespace {

namespace fs = std::filesystem;

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Binary STL: an 80-byte header, a triangle count, 50 bytes per triangle. A file whose size
// matches that layout is binary even when its header starts with "solid".
std::optional<std::vector<Eigen::Vector3d>> binary_stl(const std::string& bytes) {
  if (bytes.size() < 84) return std::nullopt;
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  if (bytes.size() != 84 + 50ull * count) return std::nullopt;
  std::vector<Eigen::Vector3d> points;
  points.reserve(3ull * count);
  for (std::uint32_t t = 0; t < count; ++t)
    for (int v = 0; v < 3; ++v) {
      float xyz[3];
      std::memcpy(xyz, bytes.data() + 84 + 50ull * t + 12 + 12 * v, 12);
      points.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
  return points;
}

// ASCII STL and OBJ: the numbers after each `vertex` (STL) or `v` (OBJ) keyword.
std::vector<Eigen::Vector3d> keyword_points(const std::string& bytes, const std::string& keyword) {
  std::vector<Eigen::Vector3d> points;
  std::istringstream lines(bytes);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string first;
    if (!(words >> first) || first != keyword) continue;
    double x, y, z;
    if (words >> x >> y >> z) points.emplace_back(x, y, z);
  }
  return points;
}

std::optional<std::vector<Eigen::Vector3d>> assimp_points(const std::string& path, std::string& error) {
  aiPropertyStore* store = aiCreatePropertyStore();
  const aiScene* scene = aiImportFileExWithProperties(path.c_str(), aiProcess_PreTransformVertices, nullptr, store);
  aiReleasePropertyStore(store);
  if (!scene) {
    error = fmt::format("cannot read '{}': {}", path, aiGetErrorString());
    return std::nullopt;
  }
  std::vector<Eigen::Vector3d> points;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)
    for (unsigned v = 0; v < scene->mMeshes[m]->mNumVertices; ++v) {
      const aiVector3D& p = scene->mMeshes[m]->mVertices[v];
      points.emplace_back(p.x, p.y, p.z);
    }
  aiReleaseImport(scene);
  return points;
}

}  // namespace

std::optional<std::vector<Eigen::Vector3d>> read_points(const std::string& path, std::string& error) {
  const std::string ext = lower_extension(path);
  std::optional<std::vector<Eigen::Vector3d>> points;
  if (ext == ".dae") {
    points = assimp_points(path, error);
    if (!points) return std::nullopt;
  } else if (ext == ".stl" || ext == ".obj") {
    std::ifstream file(path, std::ios::binary);
    std::stringstream buffer;
    buffer << file.rdbuf();
    if (!file) {
      error = fmt::format("cannot read mesh '{}'", path);
      return std::nullopt;
    }
    const std::string bytes = buffer.str();
    if (ext == ".obj") points = keyword_points(bytes, "v");
    else if (!(points = binary_stl(bytes))) points = keyword_points(bytes, "vertex");
  } else {
    error = fmt::format("mesh '{}': verify reads STL (binary and ASCII), OBJ and Collada (.dae) meshes", path);
    return std::nullopt;
  }
  if (points->size() < 4) {
    error = fmt::format("mesh '{}' has {} vertices: too few to collide with", path, points->size());
    return std::nullopt;
  }
  return points;
}

std::optional<std::string> resolve_mesh(const std::string& filename, const std::string& base_dir,
                                        const std::string& root, std::string& error) {
  if (filename.starts_with("file://")) return filename.substr(7);
  if (!filename.starts_with("package://")) {
    const fs::path path(filename);
    return (path.is_absolute() ? path : fs::path(base_dir) / path).lexically_normal().string();
  }
  const std::string rest = filename.substr(10);
  const std::string package = rest.substr(0, rest.find('/'));
  const std::string inside = rest.find('/') == std::string::npos ? "" : rest.substr(rest.find('/') + 1);
  const std::regex name_element("<name>\\s*([^<\\s]+)\\s*</name>");
  std::vector<fs::path> found;
  // The checked tree first, then the runner's package path (ROS_PACKAGE_PATH, --package-path).
  std::vector<std::string> search{root};
  for (std::string& entry : ros_package_search_path()) search.push_back(std::move(entry));
  for (const std::string& top : search) {
    if (!found.empty()) break;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(top, fs::directory_options::skip_permission_denied, ec), end;
         !ec && it != end; it.increment(ec)) {
      if (it->is_directory(ec) && it->path().filename().string().starts_with(".")) {
        it.disable_recursion_pending();
        continue;
      }
      if (it->path().filename() != "package.xml") continue;
      std::ifstream file(it->path());
      std::stringstream text;
      text << file.rdbuf();
      const std::string xml = text.str();
      std::smatch match;
      if (std::regex_search(xml, match, name_element) && match[1] == package) found.push_back(it->path().parent_path());
    }
  }
  if (found.empty()) {
    error = fmt::format("mesh '{}': no package.xml named '{}' under '{}' (pass --package-path or --root with the "
                        "directory that holds the package)",
                        filename, package, root);
    return std::nullopt;
  }
  std::sort(found.begin(), found.end());
  return (found.front() / inside).lexically_normal().string();
}

}  // namespace assetlint::mesh
