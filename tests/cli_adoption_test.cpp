// Exit status and CI reports for adopting asset-lint on an existing repository:
// --fail-on, no path = the working directory, --diff usage, escaping of asset names,
// GitLab Code Quality.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <regex>

#include "report/gitlab_reporter.h"
#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::replace_once;
using assetlint::test::report_dir;
using assetlint::test::run_cli;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace {

// A joint name holding a line break and a GitHub workflow command.
const char* kInjectingUrdf =
    "<robot name=\"r\">\n  <link name=\"a\"/>\n  <link name=\"b\"/>\n"
    "  <joint name=\"j&#10;::warning file=x::pwned\" type=\"revolute\">\n    <parent link=\"a\"/>\n"
    "    <child link=\"b\"/>\n    <limit lower=\"1\" upper=\"0\" effort=\"1\" velocity=\"1\"/>\n  </joint>\n</robot>\n";

}  // namespace

TEST_CASE("adoption: infos never fail the run unless --fail-on info, --fail-on error", "[adoption]") {
  const std::vector<std::string> infos_only = {"--select", "stale-schema-attribute", "joints.usda"};
  auto r = run_cli(infos_only, report_dir());
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("2 infos") != std::string::npos);
  std::vector<std::string> strict = {"--fail-on", "info"};
  strict.insert(strict.end(), infos_only.begin(), infos_only.end());
  CHECK(run_cli(strict, report_dir()).exit_code == 1);
  CHECK(run_cli({"--select", "mimic-max-velocity", "gripper.urdf"}, report_dir()).exit_code == 1);
  CHECK(run_cli({"--fail-on", "error", "--select", "mimic-max-velocity", "gripper.urdf"}, report_dir()).exit_code == 0);
  CHECK(run_cli({"--fail-on", "error", "--select", "limits-inverted", "gripper.urdf"}, report_dir()).exit_code == 1);
  CHECK(run_cli({"--fail-on", "fatal", "gripper.urdf"}, report_dir()).exit_code == 2);
}

TEST_CASE("adoption: no path checks the working directory", "[adoption]") {
  TempDir dir;
  write_file(dir.path() / "gripper.urdf", read_file(report_dir() / "gripper.urdf"));
  auto r = run_cli({"--select", "limits-inverted", "--output-format", "concise"}, dir.path());
  CHECK(r.exit_code == 1);
  CHECK(r.out.rfind("gripper.urdf:9:19: limits-inverted ", 0) == 0);
}

TEST_CASE("adoption: --diff with a structured format is a usage error, a clean --diff says so", "[adoption]") {
  auto r = run_cli({"--diff", "--output-format", "json", "gripper.urdf"}, report_dir());
  CHECK(r.exit_code == 2);
  CHECK(r.out.empty());
  CHECK(r.err == "asset-lint: error: --diff prints a unified diff; it cannot be combined with --output-format json\n");
  auto clean = run_cli({"--diff", "--select", "stale-schema-attribute", "joints.usda"}, report_dir());
  CHECK(clean.exit_code == 0);
  CHECK(clean.out.empty());
  CHECK(clean.err == "asset-lint: no fix applies; nothing to change\n");
}

TEST_CASE("adoption: control characters in asset names are escaped in text, concise and github", "[adoption]") {
  TempDir dir;
  write_file(dir.path() / "inj.urdf", kInjectingUrdf);
  for (const char* format : {"text", "concise", "github"}) {
    INFO(format);
    auto r = run_cli({"--select", "limits-inverted", "--output-format", format, "inj.urdf"}, dir.path());
    CHECK(r.exit_code == 1);
    // No line of the output starts a workflow command other than the finding's own.
    CHECK(r.out.find("\n::warning") == std::string::npos);
    CHECK(r.out.find("j\n") == std::string::npos);
  }
  auto text = run_cli({"--select", "limits-inverted", "--output-format", "concise", "inj.urdf"}, dir.path());
  CHECK(text.out.find("'j\\n::warning file=x::pwned'") != std::string::npos);
}

TEST_CASE("adoption: GitLab Code Quality report with stable fingerprints", "[adoption][report]") {
  auto r = run_cli({"--output-format", "gitlab", "--select", "limits-inverted,mimic-max-velocity", "gripper.urdf"},
                   report_dir());
  CHECK(r.exit_code == 1);
  const auto issues = nlohmann::json::parse(r.out);
  REQUIRE(issues.is_array());
  REQUIRE(issues.size() == 2);
  const auto& first = issues[0];
  CHECK(first["check_name"] == "limits-inverted");
  CHECK(first["severity"] == "major");
  CHECK(first["location"]["path"] == "gripper.urdf");
  CHECK(first["location"]["lines"]["begin"] == 9);
  CHECK(first["description"].get<std::string>().rfind("revolute joint 'finger_joint' has lower limit", 0) == 0);
  CHECK(issues[1]["severity"] == "minor");
  CHECK(first["fingerprint"].get<std::string>().size() == 32);
  CHECK(first["fingerprint"] != issues[1]["fingerprint"]);
  // The same finding gets the same fingerprint in another run and from another directory.
  auto again = run_cli({"--output-format", "gitlab", "--select", "limits-inverted", "./gripper.urdf"}, report_dir());
  CHECK(nlohmann::json::parse(again.out)[0]["fingerprint"] == first["fingerprint"]);
  // No line number in it: a finding that moves keeps its fingerprint; occurrences differ.
  CHECK(assetlint::gitlab_fingerprint("r", "p", "m", 0) == assetlint::gitlab_fingerprint("r", "p", "m", 0));
  CHECK(assetlint::gitlab_fingerprint("r", "p", "m", 0) != assetlint::gitlab_fingerprint("r", "p", "m", 1));
}

TEST_CASE("adoption: standard input is linted as the file --stdin-filename names", "[adoption][stdin]") {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "robots");
  // The file's own configuration applies: per-file-ignores relative to it.
  write_file(dir.path() / "asset-lint.toml", "[per-file-ignores]\n\"legacy/*.urdf\" = [\"limits-inverted\"]\n");
  const std::string gripper = read_file(report_dir() / "gripper.urdf");
  auto r = assetlint::test::run_cli_with_input(
      {"check", "-", "--stdin-filename", "robots/gripper.urdf", "--select", "limits-inverted", "--output-format",
       "concise"},
      dir.path(), gripper);
  CHECK(r.exit_code == 1);
  CHECK(r.out.rfind("robots/gripper.urdf:9:19: limits-inverted ", 0) == 0);
  auto ignored = assetlint::test::run_cli_with_input(
      {"-", "--stdin-filename", "legacy/gripper.urdf", "--select", "limits-inverted"}, dir.path(), gripper);
  CHECK(ignored.exit_code == 0);
  CHECK(!std::filesystem::exists(dir.path() / "robots" / "gripper.urdf"));  // nothing written

  // With --fix the fixed text goes to standard output; only the bytes that change differ.
  auto fixed = assetlint::test::run_cli_with_input(
      {"-", "--stdin-filename", "robots/gripper.urdf", "--select", "limits-inverted", "--fix", "--unsafe-fixes"},
      dir.path(), gripper);
  CHECK(fixed.exit_code == 0);
  std::string expected = gripper;
  const std::string before = "lower=\"0.82\" upper=\"0\"";
  REQUIRE(expected.find(before) != std::string::npos);
  expected.replace(expected.find(before), before.size(), "lower=\"0\" upper=\"0.82\"");
  CHECK(fixed.out == expected);

  auto usage = run_cli({"-"}, dir.path());
  CHECK(usage.exit_code == 2);
  CHECK(usage.err == "asset-lint: error: '-' (standard input) must be the only path, with --stdin-filename PATH\n");
}

TEST_CASE("adoption: mimic-max-velocity and units-velocity-implausible agree on a mimic's limit", "[adoption][fix]") {
  TempDir dir;
  // A continuous leader at 166 rad/s: mimic-max-velocity raises the follower to 166, which
  // units-velocity-implausible used to read as deg/s on a joint over 0..0.8757 rad and convert
  // back to 2.897, forever (fix_engine_test checks how a real cycle is reported). It now
  // leaves a mimic's demanded value to mimic-max-velocity: one run converges.
  const std::string urdf =
      "<robot name=\"r\">\n  <link name=\"a\"/>\n"
      "  <link name=\"b\"><inertial><mass value=\"0.1\"/><inertia ixx=\"1e-4\" ixy=\"0\" ixz=\"0\" iyy=\"1e-4\" iyz=\"0\" "
      "izz=\"1e-4\"/></inertial></link>\n"
      "  <link name=\"c\"><inertial><mass value=\"0.1\"/><inertia ixx=\"1e-4\" ixy=\"0\" ixz=\"0\" iyy=\"1e-4\" iyz=\"0\" "
      "izz=\"1e-4\"/></inertial></link>\n"
      "  <joint name=\"leader\" type=\"continuous\">\n    <parent link=\"a\"/>\n    <child link=\"b\"/>\n"
      "    <axis xyz=\"0 0 1\"/>\n    <limit effort=\"10\" velocity=\"166\"/>\n  </joint>\n"
      "  <joint name=\"follower\" type=\"revolute\">\n    <parent link=\"b\"/>\n    <child link=\"c\"/>\n"
      "    <axis xyz=\"0 0 1\"/>\n    <limit lower=\"0\" upper=\"0.8757\" effort=\"10\" velocity=\"2\"/>\n"
      "    <mimic joint=\"leader\" multiplier=\"1\"/>\n  </joint>\n</robot>\n";
  write_file(dir.path() / "cycle.urdf", urdf);
  auto r = run_cli({"--fix", "--unsafe-fixes", "cycle.urdf"}, dir.path());
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out == "No problems found in 1 file.\n");
  CHECK(r.err == "asset-lint: fixed 1 problem in cycle.urdf\n");
  const std::string fixed = replace_once(urdf, "effort=\"10\" velocity=\"2\"", "effort=\"10\" velocity=\"166\"");
  CHECK(read_file(dir.path() / "cycle.urdf") == fixed);
  // And a second run has nothing left to do.
  r = run_cli({"--fix", "--unsafe-fixes", "cycle.urdf"}, dir.path());
  CHECK(r.exit_code == 0);
  CHECK(read_file(dir.path() / "cycle.urdf") == fixed);
}

TEST_CASE("adoption: --help lists every command, one line each", "[adoption][cli-commands]") {
  const auto help = run_cli({"--help"});
  CHECK(help.exit_code == 0);
  for (const char* command : {"check", "compare", "expand", "tune", "simulate", "verify", "rule", "cat", "completion"}) {
    INFO(command);
    const std::regex line(std::string("\\n  asset-lint (\\[)?") + command + "\\b[^\\n]*  [a-z][^\\n]+\\n");
    CHECK(std::regex_search(help.out, line));
  }
}

TEST_CASE("adoption: a mistyped command or rule id is answered with the nearest one", "[adoption][cli-commands]") {
  const auto verb = run_cli({"verfy", "gripper.urdf"}, report_dir());
  CHECK(verb.exit_code == 2);
  CHECK(verb.out.empty());
  CHECK(verb.err == "asset-lint: error: unknown command 'verfy'; did you mean 'verify'?\n");
  const auto far = run_cli({"robots"}, report_dir());
  CHECK(far.exit_code == 2);
  CHECK(far.err.find("'robots' is neither a command nor a file or directory") != std::string::npos);
  // A file of that name is checked, command or not.
  TempDir dir;
  write_file(dir.path() / "verfy", "");
  CHECK(run_cli({"verfy"}, dir.path()).err.find("unknown command") == std::string::npos);
  const auto rule = run_cli({"rule", "limts-inverted"});
  CHECK(rule.exit_code == 2);
  CHECK(rule.err == "asset-lint: error: unknown rule 'limts-inverted'; did you mean 'limits-inverted'?\n");
}

TEST_CASE("adoption: completion scripts for bash, zsh and fish", "[adoption][cli-commands]") {
  for (const char* shell : {"bash", "zsh", "fish"}) {
    INFO(shell);
    const auto script = run_cli({"completion", shell});
    CHECK(script.exit_code == 0);
    for (const char* word : {"verify", "simulate", "select", "output-format", "limits-inverted", "sarif"})
      CHECK(script.out.find(word) != std::string::npos);
  }
  CHECK(run_cli({"completion", "tcsh"}).exit_code == 2);
  if (!assetlint::test::on_path("bash")) return;
  TempDir dir;
  write_file(dir.path() / "asset-lint.bash", run_cli({"completion", "bash"}).out);
  std::string out;
  CHECK(assetlint::test::run_shell("bash -n " + assetlint::test::shell_quote((dir.path() / "asset-lint.bash").string()),
                                   dir.path() / "log", out) == 0);
  // Completing as bash does: the command word, a rule id after `rule`, an option and its value.
  const auto complete = [&](const std::string& words, int index) {
    const std::string script = "source asset-lint.bash; COMP_WORDS=(" + words + "); COMP_CWORD=" +
                               std::to_string(index) + "; _asset_lint; printf '%s\\n' \"${COMPREPLY[@]}\"";
    std::string reply;
    CHECK(assetlint::test::run_shell("cd " + assetlint::test::shell_quote(dir.path().string()) + " && bash -c " +
                                         assetlint::test::shell_quote(script),
                                     dir.path() / "log", reply) == 0);
    return reply;
  };
  CHECK(complete("asset-lint ver", 1) == "verify\n");
  CHECK(complete("asset-lint rule limits-inv", 2) == "limits-inverted\n");
  CHECK(complete("asset-lint --output-fo", 1) == "--output-format\n");
  CHECK(complete("asset-lint --output-format sa", 2) == "sarif\n");
}

TEST_CASE("adoption: an asset-lint.toml above the git work tree is not used", "[adoption][config-lookup]") {
  // A folder of clones with a gripper's configuration, and a quadruped's repository inside it.
  TempDir dir;
  write_file(dir.path() / "asset-lint.toml", "[simulation]\ntimesteps_per_second = 250\n");
  const auto repo = dir.path() / "quadruped";
  std::filesystem::create_directories(repo / ".git");
  std::filesystem::create_directories(repo / "urdf");
  write_file(repo / "urdf" / "gripper.urdf", read_file(report_dir() / "gripper.urdf"));
  const auto shown = run_cli({"--show-settings", "urdf/gripper.urdf"}, repo);
  CHECK(shown.exit_code == 0);
  CHECK(shown.out.find("# configuration: none (defaults)\n") != std::string::npos);
  CHECK(shown.out.find("# looked for asset-lint.toml in " + (repo / "urdf").string() + " and up to " + repo.string() +
                       ", the git work tree's root (the lookup stops there)\n") != std::string::npos);
  CHECK(shown.out.find("250") == std::string::npos);
  // Inside the repository its own configuration is found as before.
  write_file(repo / "asset-lint.toml", "[simulation]\ntimesteps_per_second = 120\n");
  const auto own = run_cli({"--show-settings", "urdf/gripper.urdf"}, repo);
  CHECK(own.out.find("timesteps_per_second = 120") != std::string::npos);
  // Outside any work tree the walk goes on to the file system's root.
  std::filesystem::remove_all(repo / ".git");
  std::filesystem::remove(repo / "asset-lint.toml");
  CHECK(run_cli({"--show-settings", "urdf/gripper.urdf"}, repo).out.find("timesteps_per_second = 250") !=
        std::string::npos);
}

TEST_CASE("adoption: --diff says how many unsafe fixes wait for --unsafe-fixes", "[adoption][fix-safety]") {
  // gripper.urdf's two fixes (swap inverted limits, raise a mimic's velocity limit) are unsafe.
  const auto only_unsafe = run_cli({"--diff", "gripper.urdf"}, report_dir());
  CHECK(only_unsafe.exit_code == 0);
  CHECK(only_unsafe.out.empty());
  CHECK(only_unsafe.err ==
        "asset-lint: no safe fix applies; 2 unsafe fixes exist, applied with --unsafe-fixes (review with --diff "
        "--unsafe-fixes)\n");
  const auto both = run_cli({"--diff", "--unsafe-fixes", "gripper.urdf"}, report_dir());
  CHECK(both.exit_code == 1);
  CHECK(both.err.find("unsafe fix") == std::string::npos);
  // The summary of --fix says the same.
  TempDir dir;
  write_file(dir.path() / "gripper.urdf", read_file(report_dir() / "gripper.urdf"));
  const auto fixed = run_cli({"--fix", "gripper.urdf"}, dir.path());
  CHECK(fixed.out.find("0 fixable with --fix (2 more with --unsafe-fixes)") != std::string::npos);
}

TEST_CASE("adoption: a fixed value's trailing comment restating the old value is rewritten", "[adoption][fix-safety]") {
  TempDir dir;
  const auto guide = assetlint::test::fixtures_dir() / "fix" / "drive-natural-frequency";
  write_file(dir.path() / "guide.usda", read_file(guide / "guide_99_48_per_deg.usda"));
  write_file(dir.path() / "asset-lint.toml", read_file(guide / "asset-lint.toml"));
  CHECK(run_cli({"--fix", "--unsafe-fixes", "guide.usda"}, dir.path()).exit_code == 0);
  const std::string fixed = read_file(dir.path() / "guide.usda");
  CHECK(fixed.find("stiffness = 4.8   # 275 N*m/rad, per degree as USD writes it\n") != std::string::npos);
  // A URDF comment in degrees after a limit in radians follows the limit.
  write_file(dir.path() / "arm.urdf",
             "<robot name=\"arm\">\n  <link name=\"a\"/>\n  <link name=\"b\"/>\n  <joint name=\"j\" type=\"revolute\">\n"
             "    <parent link=\"a\"/>\n    <child link=\"b\"/>\n"
             "    <limit lower=\"0.82\" upper=\"0\" effort=\"1\" velocity=\"1\"/> <!-- 47 deg -->\n  </joint>\n</robot>\n");
  CHECK(run_cli({"--fix", "--unsafe-fixes", "--select", "limits-inverted", "arm.urdf"}, dir.path()).exit_code == 0);
  CHECK(read_file(dir.path() / "arm.urdf").find("lower=\"0\" upper=\"0.82\" effort=\"1\" velocity=\"1\"/> <!-- 47 deg -->") !=
        std::string::npos);
}

TEST_CASE("adoption: init writes a commented asset-lint.toml and never overwrites one", "[adoption][init]") {
  TempDir dir;
  const auto robot = dir.path() / "robot";
  std::filesystem::create_directories(robot / "urdf");
  write_file(robot / "urdf" / "robotiq_2f85.urdf",
             read_file(assetlint::test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf"));
  const auto init = run_cli({"init", "robot"}, dir.path());
  CHECK(init.exit_code == 0);
  CHECK(init.err == "asset-lint: wrote robot/asset-lint.toml for 1 asset (driven joint 'finger_joint')\n");
  const std::string toml = read_file(robot / "asset-lint.toml");
  CHECK(toml.find("\ndriven_joint = \"finger_joint\"   # its mimics: ") != std::string::npos);
  CHECK(toml.find("\n# payload_kg = ") != std::string::npos);
  CHECK(toml.find("\n# timesteps_per_second = 60 ") != std::string::npos);
  // The file it writes is a configuration the check reads, and the spec is left to the user.
  const auto shown = run_cli({"--show-settings", "urdf/robotiq_2f85.urdf"}, robot);
  CHECK(shown.exit_code == 0);
  CHECK(shown.out.find("# configuration: asset-lint.toml\n") != std::string::npos);
  CHECK(shown.out.find("driven_joint = \"finger_joint\"") != std::string::npos);
  CHECK(shown.out.find("# payload_kg is not set") != std::string::npos);
  const auto again = run_cli({"init", "robot"}, dir.path());
  CHECK(again.exit_code == 2);
  CHECK(again.err.find("'robot/asset-lint.toml' exists; init does not overwrite it") != std::string::npos);
  CHECK(read_file(robot / "asset-lint.toml") == toml);
  // A USD stage's authored rate is taken as it is.
  TempDir usd;
  write_file(usd.path() / "guide.usda",
             read_file(assetlint::test::fixtures_dir() / "fix" / "drive-natural-frequency" / "guide_99_48_per_deg.usda"));
  CHECK(run_cli({"init"}, usd.path()).exit_code == 0);
  CHECK(read_file(usd.path() / "asset-lint.toml").find("\ntimesteps_per_second = ") != std::string::npos);
  TempDir empty;
  CHECK(run_cli({"init"}, empty.path()).exit_code == 2);
}
