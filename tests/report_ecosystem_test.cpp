// The pieces around the binary: the pre-commit hooks and `cmake --install`.
// Tools that are not installed make these tests warn and skip.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>

#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace {

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

bool on_path(const char* tool) {
  return std::system((std::string("command -v ") + tool + " >/dev/null 2>&1").c_str()) == 0;
}

// Runs a shell command; returns its exit status, its output in `output`.
int shell(const std::string& command, const std::filesystem::path& log, std::string& output) {
  const int status = std::system((command + " >" + quote(log.string()) + " 2>&1 </dev/null").c_str());
  output = std::filesystem::exists(log) ? read_file(log) : "";
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::filesystem::path binary_dir() { return std::filesystem::path(ASSET_LINT_BINARY).parent_path(); }

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
  REQUIRE(shell("cd " + quote(hooks.string()) + " && " + git + " init -q && " + git + " add . && " + git +
                    " commit -q -m hooks",
                dir.path() / "git.log", out) == 0);
  const std::string gripper = read_file(assetlint::test::fixtures_dir() / "report" / "gripper.urdf");
  write_file(assets / "gripper.urdf", gripper);
  write_file(assets / "notes.txt", "not an asset\n");
  // A text USD layer with an upper-case extension: the hooks' pattern is case-insensitive.
  write_file(assets / "Joints.USD", read_file(assetlint::test::fixtures_dir() / "report" / "joints.usda"));
  REQUIRE(shell("cd " + quote(assets.string()) + " && " + git + " init -q && " + git + " add .", dir.path() / "git.log",
                out) == 0);

  // language: system needs no network; everything runs offline, bounded by a timeout.
  const std::string env = "PATH=" + quote(binary_dir().string()) + ":\"$PATH\" PRE_COMMIT_HOME=" +
                          quote((dir.path() / "cache").string()) + " PRE_COMMIT_COLOR=never ";
  auto try_repo = [&](const std::string& hook, std::string& output) {
    return shell("cd " + quote(assets.string()) + " && " + env + "timeout 180 pre-commit try-repo " +
                     quote(hooks.string()) + " " + hook + " --all-files",
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
  REQUIRE(shell("timeout 120 cmake --install " + quote(binary_dir().string()) + " --prefix " +
                    quote(prefix.path().string()),
                prefix.path() / "install.log", out) == 0);
  INFO(out);
  const auto bin = prefix.path() / "bin" / "asset-lint";
  const auto man = prefix.path() / "share" / "man" / "man1" / "asset-lint.1";
  REQUIRE(std::filesystem::exists(bin));
  REQUIRE(std::filesystem::exists(man));
  const std::string page = read_file(man);
  CHECK(page.rfind(".TH ASSET-LINT 1", 0) == 0);
  CHECK(page.find("--output-format") != std::string::npos);
  CHECK(page.find("--exit-zero") != std::string::npos);
  CHECK(shell(quote(bin.string()) + " --version", prefix.path() / "version.log", out) == 0);
  CHECK(out == std::string("asset-lint ") + ASSET_LINT_VERSION + "\n");
}
