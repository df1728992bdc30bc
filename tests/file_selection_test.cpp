// Which files a walk checks: exclude / extend-exclude (asset-lint.toml and command line),
// .gitignore respected by default, --force-exclude for named paths.
#include <catch2/catch.hpp>

#include "test_support.h"

using assetlint::test::run_cli;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace {

// One limits-inverted finding per file, so the concise report lists the files checked.
const char* kInverted =
    "<robot name=\"r\">\n  <link name=\"a\"/>\n  <link name=\"b\"/>\n  <joint name=\"j\" type=\"revolute\">\n"
    "    <parent link=\"a\"/>\n    <child link=\"b\"/>\n"
    "    <limit lower=\"1\" upper=\"0\" effort=\"1\" velocity=\"1\"/>\n  </joint>\n</robot>\n";

void add(const std::filesystem::path& dir, const std::string& relative) {
  std::filesystem::create_directories((dir / relative).parent_path());
  write_file(dir / relative, kInverted);
}

// The files a run reports, one per line.
std::string checked(const std::filesystem::path& dir, std::vector<std::string> args) {
  std::vector<std::string> all = {"--select", "limits-inverted", "--output-format", "concise"};
  all.insert(all.end(), args.begin(), args.end());
  auto r = run_cli(all, dir);
  std::string files;
  for (std::size_t at = 0; at < r.out.size();) {
    const std::size_t colon = r.out.find(':', at);
    const std::size_t end = r.out.find('\n', at);
    files += r.out.substr(at, colon - at) + "\n";
    at = end + 1;
  }
  return files;
}

}  // namespace

TEST_CASE("file selection: exclude and extend-exclude in asset-lint.toml", "[file-selection]") {
  TempDir dir;
  for (const char* f : {"robots/a.urdf", "robots/old/b.urdf", "vendor/c.urdf", ".hidden/d.urdf", "robots/e.urdf"})
    add(dir.path(), f);
  write_file(dir.path() / "asset-lint.toml", "extend-exclude = [\"vendor\", \"robots/old/**\", \"e.urdf\"]\n");
  CHECK(checked(dir.path(), {}) == "robots/a.urdf\n");
  // exclude replaces the default '.*': the hidden directory is walked.
  write_file(dir.path() / "asset-lint.toml", "exclude = [\"vendor\"]\n");
  CHECK(checked(dir.path(), {}) == ".hidden/d.urdf\nrobots/a.urdf\nrobots/e.urdf\nrobots/old/b.urdf\n");
  // The command line replaces (--exclude) or extends (--extend-exclude) the configuration.
  CHECK(checked(dir.path(), {"--exclude", "robots"}) == ".hidden/d.urdf\nvendor/c.urdf\n");
  CHECK(checked(dir.path(), {"--extend-exclude", "old,.hidden"}) == "robots/a.urdf\nrobots/e.urdf\n");
  write_file(dir.path() / "asset-lint.toml", "exclude = \"vendor\"\n");
  auto bad = run_cli({"robots/a.urdf"}, dir.path());
  CHECK(bad.exit_code == 2);
  CHECK(bad.err == "asset-lint: error: asset-lint.toml:1:11: 'exclude' must be an array of path globs\n");
}

TEST_CASE("file selection: named files are checked unless --force-exclude", "[file-selection]") {
  TempDir dir;
  add(dir.path(), "vendor/c.urdf");
  add(dir.path(), "a.urdf");
  write_file(dir.path() / "asset-lint.toml", "extend-exclude = [\"vendor/**\"]\n");
  CHECK(checked(dir.path(), {"vendor/c.urdf", "a.urdf"}) == "vendor/c.urdf\na.urdf\n");
  CHECK(checked(dir.path(), {"--force-exclude", "vendor/c.urdf", "a.urdf"}) == "a.urdf\n");
}

TEST_CASE("file selection: .gitignore is respected inside a git work tree", "[file-selection]") {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / ".git" / "info");
  write_file(dir.path() / ".git" / "info" / "exclude", "scratch.urdf\n");
  write_file(dir.path() / ".gitignore", "# build output\ngenerated/\n*.tmp.urdf\n!keep.tmp.urdf\n");
  std::filesystem::create_directories(dir.path() / "sub");
  write_file(dir.path() / "sub" / ".gitignore", "/local.urdf\n");
  for (const char* f : {"a.urdf", "generated/x.urdf", "y.tmp.urdf", "keep.tmp.urdf", "scratch.urdf", "sub/local.urdf",
                        "sub/deeper/local.urdf"})
    add(dir.path(), f);
  CHECK(checked(dir.path(), {}) == "a.urdf\nkeep.tmp.urdf\nsub/deeper/local.urdf\n");
  CHECK(checked(dir.path(), {"sub"}) == "sub/deeper/local.urdf\n");
  CHECK(checked(dir.path(), {"--no-respect-gitignore"}) ==
        "a.urdf\ngenerated/x.urdf\nkeep.tmp.urdf\nscratch.urdf\nsub/deeper/local.urdf\nsub/local.urdf\ny.tmp.urdf\n");
  write_file(dir.path() / "asset-lint.toml", "respect-gitignore = false\n");
  CHECK(checked(dir.path(), {}) ==
        "a.urdf\ngenerated/x.urdf\nkeep.tmp.urdf\nscratch.urdf\nsub/deeper/local.urdf\nsub/local.urdf\ny.tmp.urdf\n");
}

TEST_CASE("file selection: outside a git work tree .gitignore files mean nothing", "[file-selection]") {
  TempDir dir;
  write_file(dir.path() / ".gitignore", "*.urdf\n");
  add(dir.path(), "a.urdf");
  // The temporary directory is not inside a git work tree (no .git above it).
  CHECK(checked(dir.path(), {}) == "a.urdf\n");
}
