// Data-driven test over fixtures/: every asset file has a sibling `<file>.expected`
// holding the exact text diagnostics (paths relative to fixtures/, no summary line).
// ASSET_LINT_UPDATE_EXPECTED=1 rewrites the .expected files (review the diff!).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "config/config.h"
#include "pipeline/lint.h"
#include "formats/file_kind.h"
#include "report/text_reporter.h"
#include "test_support.h"

using namespace assetlint;

namespace {

std::vector<std::filesystem::path> fixture_assets() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(test::fixtures_dir())) {
    // .xacro fixtures are ROS packages ($(find) looks for their package.xml on disk): the xacro
    // tests check them by path.
    const FileKind kind = entry.is_regular_file() ? file_kind(entry.path().string(), test::read_file(entry.path())) : FileKind::Unsupported;
    if (kind != FileKind::Unsupported && kind != FileKind::Xacro) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Reads paths relative to fixtures/, so that layers a .usda fixture composes resolve
// whatever the working directory is.
class FixturesFileSystem final : public FileSystem {
 public:
  std::optional<std::string> read(const std::string& path, std::string& error) const override {
    const std::filesystem::path p(path);
    return disk().read(p.is_absolute() ? path : (test::fixtures_dir() / p).string(), error);
  }
};

FileReport lint_fixture(const std::filesystem::path& file) {
  const std::string relative = std::filesystem::relative(file, test::fixtures_dir()).generic_string();
  // A fixture directory may hold an asset-lint.toml (simulation rate, gripper spec,
  // drive gains for URDF), found as the CLI finds it.
  Settings settings;
  if (const auto config_path = config::discover(file); !config_path.empty()) {
    // Named relative to fixtures/, like the fixture itself, whatever the working directory.
    const auto shown = std::filesystem::relative(std::filesystem::absolute(config_path), test::fixtures_dir());
    const auto error = config::load(config_path.string(), settings, shown.generic_string());
    INFO((error ? error->to_string() : std::string()));
    REQUIRE_FALSE(error);
  }
  // Rules that read files beside the asset (meshes, an SRDF) open them from the disk, relative
  // to the working directory, as the CLI does: run from fixtures/, where the paths are relative to.
  struct InFixtures {
    std::filesystem::path before = std::filesystem::current_path();
    InFixtures() { std::filesystem::current_path(test::fixtures_dir()); }
    ~InFixtures() { std::filesystem::current_path(before); }
  } in_fixtures;
  return lint_text(relative, test::read_file(file), settings, FixturesFileSystem());
}

std::string render(const std::filesystem::path& file) {
  const FileReport report = lint_fixture(file);
  std::ostringstream out;
  write_text(out, {report}, TextOptions{false, false});
  return out.str();
}

}  // namespace

TEST_CASE("every fixture produces exactly its expected diagnostics", "[fixtures]") {
  const auto files = fixture_assets();
  REQUIRE(files.size() >= 10);
  const bool update = std::getenv("ASSET_LINT_UPDATE_EXPECTED") != nullptr;
  for (const auto& file : files) {
    const auto expected_path = std::filesystem::path(file.string() + ".expected");
    const std::string actual = render(file);
    if (update) test::write_file(expected_path, actual);
    INFO("fixture " << file.string());
    REQUIRE(std::filesystem::exists(expected_path));
    CHECK(actual == test::read_file(expected_path));
  }
}

TEST_CASE("the bundled Robotiq 2F-85 tells the guide's story: 5700 N·m/rad is too stiff at 250 Hz × 64", "[fixtures]") {
  // fixtures/robotiq_2f85/asset-lint.toml holds the guide's spec sheet and its original tuning;
  // the README's first command prints this finding.
  const std::string text = render(test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf");
  CHECK(text.find("robotiq_2f85/robotiq_2f85.urdf:56:16: error: ") != std::string::npos);
  CHECK(text.find("[drive-natural-frequency]") != std::string::npos);
  CHECK(text.find("41130 rad/s") != std::string::npos);
  CHECK(text.find("16000") != std::string::npos);
  CHECK(text.find("275 N·m/rad") != std::string::npos);
  CHECK(text.find("0.06089 N·m·s/rad") != std::string::npos);
}

TEST_CASE("every primary message is short, the numbers go in notes", "[fixtures][diagnostics]") {
  std::size_t checked = 0;
  for (const auto& file : fixture_assets()) {
    for (const Diagnostic& d : lint_fixture(file).diagnostics) {
      ++checked;
      INFO(file.string() << ": [" << d.rule << "] " << d.message);
      // A finding of another USD variant selection starts with it ("in variant PhysX=Enabled: "):
      // the rule's own message follows.
      std::string_view message = d.message;
      if (message.starts_with("in variant")) message.remove_prefix(message.find(": ") + 2);
      const auto characters = std::count_if(message.begin(), message.end(),
                                            [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; });
      CHECK(static_cast<std::size_t>(characters) <= kMaxPrimaryMessage);
    }
  }
  CHECK(checked > 50);
}
