// The pieces around the binary: the pre-commit hooks and `cmake --install` (the .deb is
// tests/package_test.cpp).
// Tools that are not installed make these tests warn and skip.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>

#include "test_support.h"

using assetlint::test::on_path;
using assetlint::test::read_file;
using assetlint::test::run_shell;
using assetlint::test::shell_quote;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace {

std::filesystem::path binary_dir() { return assetlint::test::asset_lint_binary().parent_path(); }

}  // namespace

TEST_CASE("report: the pre-commit hooks run asset-lint on staged assets", "[report][pre-commit]") {
  if (!on_path("pre-commit") || !on_path("git")) {
    WARN("pre-commit or git not installed (apt-get install pre-commit); skipping the hooks test");
    return;
  }
  TempDir dir;
  const auto hooks = dir.path() / "hooks", assets = dir.path() / "assets";
  std::filesystem::create_directories(hooks);
  std::filesystem::create_directories(assets);
  // A repository holding only the hooks file, as a user's `repo:` would.
  write_file(hooks / ".pre-commit-hooks.yaml", read_file(assetlint::test::source_dir() / ".pre-commit-hooks.yaml"));
  const std::string git = "git -c user.name=test -c user.email=test@example.invalid -c init.defaultBranch=main "
                          "-c commit.gpgsign=false";
  std::string out;
  REQUIRE(run_shell("cd " + shell_quote(hooks.string()) + " && " + git + " init -q && " + git + " add . && " + git +
                    " commit -q -m hooks",
                dir.path() / "git.log", out) == 0);
  const std::string gripper = read_file(assetlint::test::fixtures_dir() / "report" / "gripper.urdf");
  write_file(assets / "gripper.urdf", gripper);
  write_file(assets / "notes.txt", "not an asset\n");
  // A text USD layer with an upper-case extension: the hooks' pattern is case-insensitive.
  write_file(assets / "Joints.USD", read_file(assetlint::test::fixtures_dir() / "report" / "joints.usda"));
  REQUIRE(run_shell("cd " + shell_quote(assets.string()) + " && " + git + " init -q && " + git + " add .", dir.path() / "git.log",
                out) == 0);

  // language: system needs no network; everything runs offline, bounded by a timeout.
  const std::string env = "PATH=" + shell_quote(binary_dir().string()) + ":\"$PATH\" PRE_COMMIT_HOME=" +
                          shell_quote((dir.path() / "cache").string()) + " PRE_COMMIT_COLOR=never ";
  auto try_repo = [&](const std::string& hook, std::string& output) {
    return run_shell("cd " + shell_quote(assets.string()) + " && " + env + "timeout 180 pre-commit try-repo " +
                     shell_quote(hooks.string()) + " " + hook + " --all-files",
                 dir.path() / (hook + ".log"), output);
  };
  CHECK(try_repo("asset-lint", out) == 1);
  INFO(out);
  CHECK(out.find("Failed") != std::string::npos);
  CHECK(out.find("gripper.urdf:9:19: error:") != std::string::npos);
  CHECK(out.find("notes.txt") == std::string::npos);
  CHECK(out.find("Joints.USD:40:15: info:") != std::string::npos);
  // require_serial: one run, one summary for both files.
  CHECK(out.find("in 2 files.") != std::string::npos);

  // The fix hook applies only safe fixes: raising a mimic's velocity limit changes the robot
  // (unsafe since issue 15), so the file is left as it is and the hook still fails.
  CHECK(try_repo("asset-lint-fix", out) == 1);
  CHECK(read_file(assets / "gripper.urdf") == gripper);
  CHECK(out.find("--unsafe-fixes") != std::string::npos);

  // Clean assets pass.
  write_file(assets / "gripper.urdf",
             read_file(assetlint::test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf"));
  CHECK(try_repo("asset-lint", out) == 0);
}

TEST_CASE("report: cmake --install puts the binary and its man page under the prefix", "[report][install]") {
  const auto cache = binary_dir() / "CMakeCache.txt";
  if (!std::filesystem::exists(cache) || !std::filesystem::exists(binary_dir() / "asset-lint.1")) {
    WARN("no configured build directory with asset-lint.1 beside the binary; skipping the install test");
    return;
  }
  TempDir prefix;
  std::string out;
  REQUIRE(run_shell("timeout 120 cmake --install " + shell_quote(binary_dir().string()) + " --prefix " +
                    shell_quote(prefix.path().string()),
                prefix.path() / "install.log", out) == 0);
  INFO(out);
  const auto bin = prefix.path() / "bin" / "asset-lint";
  const auto man = prefix.path() / "share" / "man" / "man1" / "asset-lint.1.gz";
  const auto doc = prefix.path() / "share" / "doc" / "asset-lint";
  REQUIRE(std::filesystem::exists(bin));
  REQUIRE(std::filesystem::exists(man));
  std::string page;
  REQUIRE(run_shell("gzip -dc " + shell_quote(man.string()), prefix.path() / "man.log", page) == 0);
  CHECK(page.rfind(".TH ASSET-LINT 1", 0) == 0);
  CHECK(page.find("--output-format") != std::string::npos);
  CHECK(page.find("--exit-zero") != std::string::npos);
  CHECK(read_file(prefix.path() / "share" / "asset-lint" / ".pre-commit-hooks.yaml") ==
        read_file(assetlint::test::source_dir() / ".pre-commit-hooks.yaml"));
  CHECK(std::filesystem::exists(doc / "README.md"));
  CHECK(std::filesystem::exists(doc / "docs" / "ci.md"));
  CHECK(std::filesystem::exists(doc / "docs" / "rules" / "mimic-max-velocity.md"));
  CHECK(read_file(doc / "copyright").find("License: Apache-2.0") != std::string::npos);
  CHECK(std::filesystem::exists(doc / "changelog.gz"));
  CHECK(run_shell(shell_quote(bin.string()) + " --version", prefix.path() / "version.log", out) == 0);
  CHECK(out == std::string("asset-lint ") + ASSET_LINT_VERSION + "\n");
}
