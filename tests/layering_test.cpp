// The layers of cmake/layers.txt hold in the code: no file includes a header of a
// layer above its own, and every source directory belongs to a layer.
#include <catch2/catch.hpp>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

namespace fs = std::filesystem;
using assetlint::test::read_file;
using assetlint::test::source_dir;

namespace {

struct Layer {
  std::string name;
  std::vector<std::string> dirs;  // relative to the source dir, '/'-separated
};

std::vector<Layer> read_layers(const std::string& text) {
  std::vector<Layer> layers;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    Layer layer;
    words >> layer.name;
    for (std::string dir; words >> dir;) layer.dirs.push_back(dir);
    layers.push_back(std::move(layer));
  }
  return layers;
}

// The index of the layer holding `path` (relative, '/'-separated); -1 when none does.
int layer_of(const std::vector<Layer>& layers, const std::string& path) {
  int best = -1;
  std::size_t best_length = 0;
  for (std::size_t i = 0; i < layers.size(); ++i)
    for (const auto& dir : layers[i].dirs)
      if (path.starts_with(dir + "/") && dir.size() > best_length) {
        best = static_cast<int>(i);
        best_length = dir.size();
      }
  return best;
}

// Where a project include such as "engine/rule.h" or "rules/registry.h" resolves.
std::string resolve_include(const std::string& include) {
  return fs::exists(source_dir() / "src" / include) ? "src/" + include : include;
}

// The layering problems of one file's text: each upward include, named.
std::vector<std::string> upward_includes(const std::vector<Layer>& layers, const std::string& file,
                                         const std::string& text) {
  std::vector<std::string> problems;
  const int own = layer_of(layers, file);
  static const std::regex include_line(R"re(^\s*#\s*include\s*"([^"]+)")re");
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::smatch match;
    if (!std::regex_search(line, match, include_line)) continue;
    const std::string target = resolve_include(match[1]);
    const int other = layer_of(layers, target);
    if (other > own)
      problems.push_back(file + " (" + layers[own].name + ") includes " + std::string(match[1]) + " (" +
                         layers[other].name + ")");
  }
  return problems;
}

std::vector<Layer> project_layers() { return read_layers(read_file(source_dir() / "cmake" / "layers.txt")); }

}  // namespace

TEST_CASE("the layer check names an upward include", "[layering]") {
  const auto layers = read_layers("low a\nhigh b\n# comment\n");
  REQUIRE(layers.size() == 2);
  CHECK(upward_includes(layers, "a/x.cpp", "#include \"b/y.h\"\n") ==
        std::vector<std::string>{"a/x.cpp (low) includes b/y.h (high)"});
  CHECK(upward_includes(layers, "b/y.cpp", "#include \"a/x.h\"\n#include <vector>\n").empty());
}

TEST_CASE("every source directory belongs to a layer", "[layering]") {
  const auto layers = project_layers();
  REQUIRE(layers.size() >= 5);
  for (const char* top : {"src", "rules"}) {
    for (const auto& entry : fs::recursive_directory_iterator(source_dir() / top)) {
      if (!entry.is_regular_file()) continue;
      const std::string path = fs::relative(entry.path(), source_dir()).generic_string();
      INFO(path);
      CHECK(layer_of(layers, path) >= 0);
    }
  }
}

TEST_CASE("no file includes a header of a higher layer", "[layering]") {
  const auto layers = project_layers();
  std::vector<std::string> problems;
  for (const char* top : {"src", "rules"}) {
    for (const auto& entry : fs::recursive_directory_iterator(source_dir() / top)) {
      if (!entry.is_regular_file()) continue;
      const std::string path = fs::relative(entry.path(), source_dir()).generic_string();
      if (layer_of(layers, path) < 0) continue;  // reported by the test above
      for (auto& problem : upward_includes(layers, path, read_file(entry.path()))) problems.push_back(problem);
    }
  }
  std::string all;
  for (const auto& p : problems) all += p + "\n";
  INFO(all);
  CHECK(problems.empty());
}
