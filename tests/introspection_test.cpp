// --show-settings, --show-files, --list-rules --output-format json, rule --all / --help.
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "rules/registry.h"
#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::run_cli;
using assetlint::test::TempDir;
using assetlint::test::write_file;

TEST_CASE("introspection: --show-settings names where every value came from", "[introspection]") {
  TempDir dir;
  write_file(dir.path() / "asset-lint.toml",
             "extend-ignore = [\"units-*\"]\nextend-exclude = [\"vendor\"]\n\n[simulation]\ntimesteps_per_second = 250\n\n"
             "[rules.joint-max-velocity]\nseverity = \"error\"\n\n[rules.drive-damping-ratio]\nmax_ratio = 20\n");
  write_file(dir.path() / "gripper.urdf", read_file(assetlint::test::fixtures_dir() / "report" / "gripper.urdf"));
  auto r = run_cli({"--show-settings", "gripper.urdf", "--extend-exclude", "old", "--position-iterations", "64",
                    "--extend-ignore", "mimic-limit-conflict"},
                   dir.path());
  CHECK(r.exit_code == 0);
  CHECK(r.err.empty());
  std::vector<std::string> units;
  for (const auto* rule : assetlint::rules::catalog())
    if (rule->id.starts_with("units-") || rule->id == "mimic-limit-conflict") units.emplace_back(rule->id);
  CHECK(r.out ==
        "# Settings for gripper.urdf\n"
        "# configuration: asset-lint.toml\n"
        "# looked for asset-lint.toml in " + dir.path().string() + "\n"
        "# checked tree (USD composition reads inside it): " + dir.path().string() + "\n"
        "\n"
        "select = []                              # default: every rule\n"
        "ignore = [\"units-*\", \"mimic-limit-conflict\"] # asset-lint.toml:1, --extend-ignore\n"
        "# rules that run: " + std::to_string(assetlint::rules::catalog().size() - units.size()) + " of " +
        std::to_string(assetlint::rules::catalog().size()) + " (not: " + fmt::format("{}", fmt::join(units, ", ")) +
        ")\n"
        "exclude = [\".*\", \"vendor\", \"old\"]        # default, asset-lint.toml:2, --extend-exclude\n"
        "respect-gitignore = true                 # default\n"
        "\n"
        "[simulation]\n"
        "timesteps_per_second = 250               # asset-lint.toml:5\n"
        "position_iterations = 64                 # --position-iterations\n"
        "# velocity_iterations is not set: PhysX's 1\n"
        "# solver is not set: the stage's physxScene:solverType, else TGS\n"
        "\n"
        "[targets]\n"
        "# consumers is not set: a URDF file's usual ones, isaac-sim, isaac-lab, mujoco, newton, gazebo, ros2_control; "
        "a quirk only some of them have is an info\n"
        "\n"
        "[mujoco]\n"
        "version = \"3.15\"                         # default; dampratio derives kv as MuJoCo 3.15 and later\n"
        "\n"
        "[gripper]\n"
        "# payload_kg is not set: no force derivation\n"
        "# friction is not set: no force derivation\n"
        "# lever_arm_m is not set: no force derivation\n"
        "gravity = 9.81                           # default\n"
        "# finger_speed_m_s is not set: no velocity derivation\n"
        "# stroke_m is not set: no velocity derivation\n"
        "target_delta_deg = 5                     # default\n"
        "# torque_margin is not set: no rounding\n"
        "# driven_joint is not set: the joint the mimics follow\n"
        "\n"
        "[rules.drive-damping-ratio]\n"
        "max_ratio = 20                           # asset-lint.toml:11\n"
        "\n"
        "[rules.joint-max-velocity]\n"
        "severity = \"error\"                       # asset-lint.toml:8\n");
  write_file(dir.path() / "asset-lint.toml", "select = 3\n");
  auto bad = run_cli({"--show-settings", "gripper.urdf"}, dir.path());
  CHECK(bad.exit_code == 2);
  CHECK(bad.err == "asset-lint: error: asset-lint.toml:1:10: 'select' must be an array of rule ids or globs\n");
}

TEST_CASE("introspection: --show-settings gives each rule pattern the file line or flag it came from",
          "[introspection]") {
  TempDir dir;
  write_file(dir.path() / "gripper.urdf", read_file(assetlint::test::fixtures_dir() / "report" / "gripper.urdf"));
  auto line_of = [&](const std::vector<std::string>& args, const std::string& key) {
    std::vector<std::string> all = {"--show-settings", "gripper.urdf"};
    all.insert(all.end(), args.begin(), args.end());
    const auto r = run_cli(all, dir.path());
    REQUIRE(r.exit_code == 0);
    const auto at = r.out.find("\n" + key);
    REQUIRE(at != std::string::npos);
    return r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1);
  };
  write_file(dir.path() / "asset-lint.toml",
             "select = [\"mimic-*\",\n  \"limits-*\"]\n\n[per-file-ignores]\n\"old/**\" = [\"limits-*\"]\n");
  CHECK(line_of({"--extend-select", "structure-*"}, "select = ") ==
        "select = [\"mimic-*\", \"limits-*\", \"structure-*\"] # asset-lint.toml:1, asset-lint.toml:2, --extend-select");
  CHECK(line_of({"--select", "limits-inverted"}, "select = ") == "select = [\"limits-inverted\"]             # --select");
  CHECK(line_of({}, "\"old/**\"") == "\"old/**\" = [\"limits-*\"]                  # asset-lint.toml:5");
  write_file(dir.path() / "asset-lint.toml", "extend-select = [\"structure-*\"]\n");
  CHECK(line_of({"--ignore", "mimic-*"}, "select = ") ==
        "select = [\"*\", \"structure-*\"]            # default (every rule), extended, asset-lint.toml:1");
  CHECK(line_of({"--ignore", "mimic-*"}, "ignore = ") == "ignore = [\"mimic-*\"]                     # --ignore");
}

TEST_CASE("introspection: --show-files lists what a run would check", "[introspection]") {
  TempDir dir;
  const std::string urdf = read_file(assetlint::test::fixtures_dir() / "report" / "gripper.urdf");
  for (const char* f : {"b.urdf", "a/x.USDA", "vendor/v.urdf", ".cache/c.urdf", "notes.txt"}) {
    std::filesystem::create_directories((dir.path() / f).parent_path());
    write_file(dir.path() / f, urdf);
  }
  auto r = run_cli({"--show-files", "--extend-exclude", "vendor"}, dir.path());
  CHECK(r.exit_code == 0);
  CHECK(r.out == "a/x.USDA\nb.urdf\n");
  auto missing = run_cli({"--show-files", "b.urdf", "nope.urdf"}, dir.path());
  CHECK(missing.exit_code == 2);
  CHECK(missing.out == "b.urdf\n");
  CHECK(missing.err == "asset-lint: error: no such file or directory: 'nope.urdf'\n");
}

TEST_CASE("introspection: --list-rules --output-format json", "[introspection]") {
  auto r = run_cli({"--list-rules", "--output-format", "json"});
  CHECK(r.exit_code == 0);
  const auto rules = nlohmann::json::parse(r.out);
  REQUIRE(rules.size() == assetlint::rules::catalog().size());
  const auto& first = rules.at(0);
  CHECK(first.at("id") == std::string(assetlint::rules::catalog().front()->id));
  for (const auto& rule : rules) {
    CHECK(rule.at("severity").is_string());
    CHECK(rule.at("fixable").is_boolean());
    CHECK(rule.at("summary").is_string());
    CHECK(rule.at("options").is_array());
  }
  auto sarif = run_cli({"--list-rules", "--output-format", "sarif"});
  CHECK(sarif.exit_code == 2);
  CHECK(sarif.err == "asset-lint: error: --list-rules prints text or --output-format json\n");
}

TEST_CASE("introspection: rule --all prints every page, rule --help is help", "[introspection]") {
  auto all = run_cli({"rule", "--all"});
  CHECK(all.exit_code == 0);
  for (const auto* rule : assetlint::rules::catalog())
    CHECK(all.out.find("# " + std::string(rule->id) + "\n") != std::string::npos);
  auto help = run_cli({"rule", "--help"});
  CHECK(help.exit_code == 0);
  CHECK(help.out.rfind("usage: asset-lint rule RULE-ID", 0) == 0);
  CHECK(help.err.empty());
  auto bare = run_cli({"rule"});
  CHECK(bare.exit_code == 2);
  CHECK(bare.err.rfind("asset-lint: error: usage: asset-lint rule RULE-ID", 0) == 0);
}

TEST_CASE("introspection: [mujoco] version selects MuJoCo's dampratio rule, shown with where it was set", "[introspection][mjcf]") {
  TempDir dir;
  write_file(dir.path() / "asset-lint.toml", "[mujoco]\nversion = \"3.14\"\n");
  write_file(dir.path() / "arm.xml", read_file(assetlint::test::fixtures_dir() / "mjcf" / "dampratio" / "two_link_arm.xml"));
  auto shown = run_cli({"--show-settings", "arm.xml"}, dir.path());
  CHECK(shown.exit_code == 0);
  CHECK(shown.out.find("[mujoco]\nversion = \"3.14\"                         # asset-lint.toml:2; dampratio derives kv as "
                       "MuJoCo 3.3 to 3.14\n") != std::string::npos);
  // The servos of the arm are critically damped on M₀ under 3.14's rule, at 0.553 under 3.15's.
  write_file(dir.path() / "asset-lint.toml",
             "select = [\"drive-damping-ratio\"]\n[rules.drive-damping-ratio]\nmin_ratio = 0.9\n[mujoco]\nversion = \"3.14\"\n");
  CHECK(run_cli({"arm.xml"}, dir.path()).exit_code == 0);
  write_file(dir.path() / "asset-lint.toml",
             "select = [\"drive-damping-ratio\"]\n[rules.drive-damping-ratio]\nmin_ratio = 0.9\n[mujoco]\nversion = \"3.16.1\"\n");
  auto later = run_cli({"arm.xml"}, dir.path());
  CHECK(later.exit_code == 1);
  CHECK(later.out.find("damping ratio 0.553 is below 0.9") != std::string::npos);
  for (const auto& [value, message] : std::vector<std::pair<std::string, std::string>>{
           {"3.15", "[mujoco] version must be a string such as \"3.15\" (a number cannot tell 3.1 from 3.10)"},
           {"\"3.2\"", "[mujoco] version '3.2': asset-lint models MuJoCo 3.3 and later"},
           {"\"latest\"", "[mujoco] version 'latest' is not a MuJoCo release such as \"3.15\""}}) {
    write_file(dir.path() / "asset-lint.toml", "[mujoco]\nversion = " + value + "\n");
    auto bad = run_cli({"arm.xml"}, dir.path());
    INFO(bad.err);
    CHECK(bad.exit_code == 2);
    CHECK(bad.err.find(message) != std::string::npos);
  }
}
