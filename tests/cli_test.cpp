// The command line as users and CI run it: exit codes, output, formats.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "test_support.h"

using assetlint::test::run_cli;

namespace {
const std::string kClean = "fixtures/robotiq_2f85/robotiq_2f85.urdf";

std::string bad_urdf() {
  return R"(<?xml version="1.0"?>
<robot name="bad">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="finger"><inertial><mass value="0.1"/><inertia ixx="1e-5" ixy="0" ixz="0" iyy="1e-5" iyz="0" izz="1e-5"/></inertial></link>
  <joint name="j" type="revolute">
    <parent link="base"/><child link="finger"/>
    <limit lower="0" upper="47" effort="10" velocity="2"/>
  </joint>
</robot>
)";
}
}  // namespace

TEST_CASE("cli: a clean file exits 0 with a summary", "[cli]") {
  // The fixture's own asset-lint.toml tells the guide's story; without it the gripper is clean.
  assetlint::test::TempDir dir;
  assetlint::test::write_file(dir.path() / "gripper.urdf",
                              assetlint::test::read_file(assetlint::test::source_dir() / kClean));
  auto r = run_cli({"gripper.urdf"}, dir.path());
  CHECK(r.exit_code == 0);
  CHECK(r.out == "No problems found in 1 file.\n");
  CHECK(r.err.empty());
  auto with_check = run_cli({"check", "gripper.urdf"}, dir.path());
  CHECK(with_check.exit_code == 0);
}

TEST_CASE("cli: findings exit 1, one compiler-style line each", "[cli]") {
  assetlint::test::TempDir dir;
  assetlint::test::write_file(dir.path() / "bad.urdf", bad_urdf());
  auto r = run_cli({"bad.urdf"}, dir.path());
  CHECK(r.exit_code == 1);
  CHECK(r.out ==
        "bad.urdf:7:29: error: limits [0, 47] of revolute joint 'j' look like degrees [units-angle-degrees] (unsafe fix)\n"
        "  note: URDF limits are radians: 47 rad is 7.48 turns, beyond the 12.57 rad threshold (option min_magnitude_rad)\n"
        "  help: unsafe fix: read the limits as degrees and write them in radians: [0, 0.820305]\n"
        "Found 1 problem (1 error, 0 warnings, 0 infos) in 1 file. 0 fixable with --fix (1 more with --unsafe-fixes).\n");
  // No colour codes when stdout is not a terminal, unless asked.
  CHECK(r.out.find('\033') == std::string::npos);
  auto colored = run_cli({"--color", "always", "bad.urdf"}, dir.path());
  CHECK(colored.out.find("\033[1m\033[31merror:\033[0m") != std::string::npos);
}

TEST_CASE("cli: usage and I/O errors exit 2", "[cli]") {
  auto missing = run_cli({"no/such/file.urdf"});
  CHECK(missing.exit_code == 2);
  CHECK(missing.err == "asset-lint: error: no such file or directory: 'no/such/file.urdf'\n");
  auto unknown_rule = run_cli({"--select", "no-such-rule", kClean});
  CHECK(unknown_rule.exit_code == 2);
  CHECK(unknown_rule.err.find("--select 'no-such-rule' matches no rule") != std::string::npos);
  CHECK(run_cli({"--output-format", "yaml", kClean}).exit_code == 2);
  CHECK(run_cli({"--no-such-flag", kClean}).exit_code == 2);
  auto rule = run_cli({"rule", "no-such-rule"});
  CHECK(rule.exit_code == 2);
}

TEST_CASE("cli: --select and --ignore take globs", "[cli]") {
  assetlint::test::TempDir dir;
  assetlint::test::write_file(dir.path() / "bad.urdf", bad_urdf());
  CHECK(run_cli({"--ignore", "units-*", "bad.urdf"}, dir.path()).exit_code == 0);
  CHECK(run_cli({"--select", "mimic-*,inertia-invalid", "bad.urdf"}, dir.path()).exit_code == 0);
  CHECK(run_cli({"--select", "units-angle-degrees", "bad.urdf"}, dir.path()).exit_code == 1);
}

TEST_CASE("cli: --list-rules and rule ID document every rule", "[cli]") {
  auto list = run_cli({"--list-rules"});
  CHECK(list.exit_code == 0);
  for (const char* id : {"parse-error", "urdf-invalid", "structure-undefined-link", "structure-mimic-reference",
                         "limits-inverted", "units-angle-degrees", "units-velocity-implausible", "mimic-max-velocity",
                         "mimic-limit-conflict", "inertia-invalid", "drive-max-force"}) {
    INFO(id);
    CHECK(list.out.find(id) != std::string::npos);
    auto page = run_cli({"rule", id});
    CHECK(page.exit_code == 0);
    CHECK(page.out.rfind(std::string("# ") + id, 0) == 0);
  }
  auto page = run_cli({"rule", "units-angle-degrees"});
  CHECK(page.out.find("min_magnitude_rad = 12.5664") != std::string::npos);
}

TEST_CASE("cli: JSON output is the documented version-1 object", "[cli]") {
  assetlint::test::TempDir dir;
  assetlint::test::write_file(dir.path() / "bad.urdf", bad_urdf());
  auto r = run_cli({"--output-format", "json", "bad.urdf"}, dir.path());
  CHECK(r.exit_code == 1);
  const auto doc = nlohmann::json::parse(r.out);
  CHECK(doc["version"] == 1);
  CHECK(doc["tool"]["name"] == "asset-lint");
  REQUIRE(doc["diagnostics"].size() == 1);
  const auto& d = doc["diagnostics"][0];
  CHECK(d["file"] == "bad.urdf");
  CHECK(d["line"] == 7);
  CHECK(d["column"] == 29);
  CHECK(d["end_line"] == 7);
  CHECK(d["end_column"] == 31);
  CHECK(d["rule"] == "units-angle-degrees");
  CHECK(d["severity"] == "error");
  CHECK(d["fix"]["applicability"] == "unsafe");
  REQUIRE(d["fix"]["edits"].size() == 1);
  CHECK(d["fix"]["edits"][0]["replacement"] == "0.820305");
  CHECK(d["fix"]["edits"][0]["length"] == 2);
  CHECK(d["fix"]["edits"][0]["line"] == 7);
  CHECK(d["fix"]["edits"][0]["column"] == 29);
  CHECK(doc["summary"]["files"] == 1);
  CHECK(doc["summary"]["errors"] == 1);
}

TEST_CASE("cli: directories are searched recursively in a stable order", "[cli]") {
  assetlint::test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "b" / "deep");
  std::filesystem::create_directories(dir.path() / ".hidden");
  for (const char* name : {"b/deep/z.urdf", "a.urdf", "b/c.urdf", ".hidden/skip.urdf"})
    assetlint::test::write_file(dir.path() / name, bad_urdf());
  assetlint::test::write_file(dir.path() / "notes.txt", "not an asset");
  auto r = run_cli({"--jobs", "2", "."}, dir.path());
  CHECK(r.exit_code == 1);
  // Paths are spelled without the "./" of the directory named.
  CHECK(r.out.rfind("a.urdf:7:29", 0) == 0);
  CHECK(r.out.find("a.urdf:7:29") < r.out.find("\nb/c.urdf:7:29"));
  CHECK(r.out.find("\nb/c.urdf:7:29") < r.out.find("\nb/deep/z.urdf:7:29"));
  CHECK(r.out.find("./") == std::string::npos);
  CHECK(r.out.find("skip.urdf") == std::string::npos);
  CHECK(r.out.find("in 3 files.") != std::string::npos);
}

TEST_CASE("cli: asset-lint.toml is found above the file, flags override it, bad keys exit 2", "[cli]") {
  assetlint::test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "robots");
  const std::string gripper = assetlint::test::read_file(assetlint::test::source_dir() / kClean);
  assetlint::test::write_file(dir.path() / "robots" / "gripper.urdf", gripper);
  assetlint::test::write_file(dir.path() / "asset-lint.toml",
                              "select = [\"drive-natural-frequency\"]\n\n[drives.finger_joint]\nstiffness = 5700\n"
                              "damping = 0.1\n");
  auto flags = run_cli({"--timesteps-per-second", "250", "--position-iterations", "64", "robots/gripper.urdf"},
                       dir.path());
  CHECK(flags.exit_code == 1);
  CHECK(flags.out.find("h = dt/64 = 1/16000 s (250 Hz (--timesteps-per-second) / 64 position iterations "
                       "(--position-iterations))") != std::string::npos);
  CHECK(flags.out.find("The guide's stiffness is 275 N·m/rad") != std::string::npos);
  // Without flags: PhysX's defaults, 60 Hz × 32.
  auto defaults = run_cli({"robots/gripper.urdf"}, dir.path());
  CHECK(defaults.out.find("h = dt/32 = 1/1920 s (60 Hz (PhysX default) / 32 position iterations (PhysX default))") !=
        std::string::npos);
  CHECK(run_cli({"--position-iterations", "32.5", "robots/gripper.urdf"}, dir.path()).exit_code == 2);

  assetlint::test::write_file(dir.path() / "asset-lint.toml", "[simulation]\ntimestep = 250\n");
  auto bad = run_cli({"robots/gripper.urdf"}, dir.path());
  CHECK(bad.exit_code == 2);
  CHECK(bad.err == "asset-lint: error: asset-lint.toml:2:1: unknown key 'timestep' in [simulation]\n");
}
