// asset-lint --fix / --unsafe-fixes / --diff from the command line: exit codes,
// stdout, stderr, and what is (not) written.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include <filesystem>

#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::run_cli;
using assetlint::test::TempDir;
using assetlint::test::write_file;
namespace fs = std::filesystem;

namespace {

fs::path fixture(const std::string& rule, const std::string& name) {
  return assetlint::test::fixtures_dir() / "fix" / rule / name;
}

// Copies a fixtures/fix case into `dir` under `name`.
fs::path copy_case(const fs::path& dir, const std::string& rule, const std::string& file, const std::string& name) {
  fs::create_directories((dir / name).parent_path());
  fs::copy_file(fixture(rule, file), dir / name);
  return dir / name;
}

std::int64_t mtime_ns(const fs::path& path) {
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  return static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec;
}

}  // namespace

TEST_CASE("cli: --fix --unsafe-fixes fixes everything and exits 0", "[fix][cli]") {
  TempDir dir;
  const fs::path file = copy_case(dir.path(), "units-angle-degrees", "guide_upper_47.urdf", "robot.urdf");
  auto r = run_cli({"--fix", "--unsafe-fixes", "robot.urdf"}, dir.path());
  CHECK(r.exit_code == 0);
  CHECK(r.out == "No problems found in 1 file.\n");
  CHECK(r.err == "asset-lint: fixed 1 problem in robot.urdf\n");
  CHECK(read_file(file) == read_file(fixture("units-angle-degrees", "guide_upper_47.urdf.fixed")));
}

TEST_CASE("cli: --fix alone leaves unsafe fixes and reports them (exit 1)", "[fix][cli]") {
  TempDir dir;
  const fs::path file = copy_case(dir.path(), "units-angle-degrees", "guide_upper_47.urdf", "robot.urdf");
  const std::string original = read_file(file);
  const auto mtime = mtime_ns(file);
  auto r = run_cli({"--fix", "robot.urdf"}, dir.path());
  CHECK(r.exit_code == 1);
  CHECK(r.err.empty());
  CHECK(r.out ==
        "robot.urdf:30:29: error: limits [0, 47] of revolute joint 'finger_joint' look like degrees [units-angle-degrees] "
        "(unsafe fix)\n"
        "  note: URDF limits are radians: 47 rad is 7.48 turns, beyond the 12.57 rad threshold (option min_magnitude_rad)\n"
        "  help: unsafe fix: read the limits as degrees and write them in radians: [0, 0.820305]\n"
        "Found 1 problem (1 error, 0 warnings, 0 infos) in 1 file. 0 fixable with --fix (1 more with "
        "--unsafe-fixes).\n");
  CHECK(read_file(file) == original);
  CHECK(mtime_ns(file) == mtime);
}

TEST_CASE("cli: --fix applies safe fixes without --unsafe-fixes", "[fix][cli]") {
  TempDir dir;
  // Raising a velocity limit is unsafe (issue 15); stale suppressions are the safe fixes left.
  const fs::path file = copy_case(dir.path(), "unused-suppression", "stale_directives.urdf", "gripper.urdf");
  auto r = run_cli({"--fix", "gripper.urdf"}, dir.path());
  CHECK(r.exit_code == 0);
  CHECK(r.err == "asset-lint: fixed 3 problems in gripper.urdf\n");
  CHECK(read_file(file) == read_file(fixture("unused-suppression", "stale_directives.urdf.fixed")));
}

TEST_CASE("cli: --fix exits 1 when unfixable findings remain and prints them", "[fix][cli]") {
  TempDir dir;
  std::string text = read_file(fixture("units-angle-degrees", "guide_upper_47.urdf"));
  const std::string mass = "<mass value=\"0.0127\"/>";
  text.replace(text.find(mass), mass.size(), "<mass value=\"-1\"/>");  // inertia-invalid, no fix
  write_file(dir.path() / "robot.urdf", text);
  auto r = run_cli({"--fix", "--unsafe-fixes", "robot.urdf"}, dir.path());
  CHECK(r.exit_code == 1);
  CHECK(r.err == "asset-lint: fixed 1 problem in robot.urdf\n");
  CHECK(r.out.find("[inertia-invalid]") != std::string::npos);
  CHECK(r.out.find("[units-angle-degrees]") == std::string::npos);
  CHECK(r.out.find("Found 1 problem") != std::string::npos);
  CHECK(read_file(dir.path() / "robot.urdf").find("upper=\"0.820305\"") != std::string::npos);
}

TEST_CASE("cli: --diff prints a unified diff, writes nothing, exits 1", "[fix][cli]") {
  TempDir dir;
  const fs::path file = copy_case(dir.path(), "units-angle-degrees", "guide_upper_47.urdf", "robot.urdf");
  const std::string original = read_file(file);
  const auto mtime = mtime_ns(file);
  auto r = run_cli({"--diff", "--unsafe-fixes", "robot.urdf"}, dir.path());
  CHECK(r.exit_code == 1);
  CHECK(r.out ==
        "--- a/robot.urdf\n"
        "+++ b/robot.urdf\n"
        "@@ -27,7 +27,7 @@\n"
        "     <parent link=\"base_link\"/>\n"
        "     <child link=\"left_outer_knuckle\"/>\n"
        "     <axis xyz=\"1 0 0\"/>\n"
        "-    <limit lower=\"0\" upper=\"47\" effort=\"24\" velocity=\"2.9\"/>\n"
        "+    <limit lower=\"0\" upper=\"0.820305\" effort=\"24\" velocity=\"2.9\"/>\n"
        "   </joint>\n"
        "   <joint name=\"left_inner_finger_joint\" type=\"fixed\">\n"
        "     <origin xyz=\"0 0.0376 0.043\" rpy=\"0 0 0\"/>\n");
  CHECK(r.err == "asset-lint: would fix 1 problem in robot.urdf\n");
  CHECK(read_file(file) == original);
  CHECK(mtime_ns(file) == mtime);
  // --diff wins over --fix: still nothing written.
  auto both = run_cli({"--fix", "--diff", "--unsafe-fixes", "robot.urdf"}, dir.path());
  CHECK(both.exit_code == 1);
  CHECK(both.out == r.out);
  CHECK(read_file(file) == original);
}

TEST_CASE("cli: --diff exits 0 with no diff when there is nothing to change, and says so", "[fix][cli]") {
  TempDir dir;
  copy_case(dir.path(), "units-angle-degrees", "guide_upper_47.urdf", "robot.urdf");
  auto r = run_cli({"--diff", "robot.urdf"}, dir.path());  // the only fix is unsafe
  CHECK(r.exit_code == 0);
  CHECK(r.out.empty());
  CHECK(r.err == "asset-lint: no safe fix applies; 1 unsafe fix exists, applied with --unsafe-fixes (review with "
                 "--diff --unsafe-fixes)\n");
  auto clean = run_cli({"--diff", "fixtures/robotiq_2f85/robotiq_2f85.urdf"});
  CHECK(clean.exit_code == 0);
  CHECK(clean.out.empty());
}

TEST_CASE("cli: --fix over a directory rewrites only the files it changes", "[fix][cli]") {
  TempDir dir;
  const fs::path clean = dir.path() / "assets" / "clean.urdf";
  fs::create_directories(clean.parent_path());
  fs::copy_file(assetlint::test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf", clean);
  const fs::path a = copy_case(dir.path(), "limits-inverted", "lower_above_upper.urdf", "assets/a.urdf");
  const fs::path b = copy_case(dir.path(), "units-velocity-implausible", "cascade_after_degrees.urdf", "assets/sub/b.urdf");
  const auto clean_mtime = mtime_ns(clean);
  struct stat before {};
  REQUIRE(::stat(clean.c_str(), &before) == 0);
  auto r = run_cli({"--fix", "--unsafe-fixes", "assets"}, dir.path());
  CHECK(r.exit_code == 0);
  CHECK(r.err == "asset-lint: fixed 1 problem in assets/a.urdf\nasset-lint: fixed 2 problems in assets/sub/b.urdf\n");
  CHECK(r.out == "No problems found in 3 files.\n");
  CHECK(read_file(a) == read_file(fixture("limits-inverted", "lower_above_upper.urdf.fixed")));
  CHECK(read_file(b) == read_file(fixture("units-velocity-implausible", "cascade_after_degrees.urdf.fixed")));
  struct stat after {};
  REQUIRE(::stat(clean.c_str(), &after) == 0);
  CHECK(mtime_ns(clean) == clean_mtime);
  CHECK(after.st_ino == before.st_ino);
  // Idempotent: a second run changes nothing.
  const std::string a_once = read_file(a), b_once = read_file(b);
  auto again = run_cli({"--fix", "--unsafe-fixes", "assets"}, dir.path());
  CHECK(again.exit_code == 0);
  CHECK(again.err.empty());
  CHECK(read_file(a) == a_once);
  CHECK(read_file(b) == b_once);
}

TEST_CASE("cli: a file named twice is fixed once", "[fix][cli]") {
  TempDir dir;
  const fs::path file = copy_case(dir.path(), "limits-inverted", "lower_above_upper.urdf", "assets/a.urdf");
  auto r = run_cli({"--fix", "--unsafe-fixes", "assets/a.urdf", "assets", "./assets/a.urdf"}, dir.path());
  CHECK(r.exit_code == 0);
  CHECK(r.err == "asset-lint: fixed 1 problem in assets/a.urdf\n");
  CHECK(r.out == "No problems found in 1 file.\n");
  CHECK(read_file(file) == read_file(fixture("limits-inverted", "lower_above_upper.urdf.fixed")));
}

TEST_CASE("cli: --fix with JSON output reports what remains", "[fix][cli]") {
  TempDir dir;
  copy_case(dir.path(), "units-angle-degrees", "guide_upper_47.urdf", "robot.urdf");
  auto r = run_cli({"--fix", "--output-format", "json", "robot.urdf"}, dir.path());
  CHECK(r.exit_code == 1);
  const auto json = nlohmann::json::parse(r.out);
  CHECK(json.dump().find("units-angle-degrees") != std::string::npos);
  auto fixed = run_cli({"--fix", "--unsafe-fixes", "--output-format", "json", "robot.urdf"}, dir.path());
  CHECK(fixed.exit_code == 0);
  CHECK(nlohmann::json::parse(fixed.out).dump().find("units-angle-degrees") == std::string::npos);
}

TEST_CASE("cli: --fix errors exit 2", "[fix][cli]") {
  auto missing = run_cli({"--fix", "no/such/file.urdf"});
  CHECK(missing.exit_code == 2);
  CHECK(missing.err == "asset-lint: error: no such file or directory: 'no/such/file.urdf'\n");
  auto diff_missing = run_cli({"--diff", "no/such/file.urdf"});
  CHECK(diff_missing.exit_code == 2);
  CHECK(run_cli({"--help"}).out.find("--unsafe-fixes") != std::string::npos);
}
