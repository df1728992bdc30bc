// docs/ci.md's recipes, run as written in a throwaway git repository of assets: every
// asset-lint command of the GitHub, baseline, --fail-on and GitLab recipes in the order the
// page gives them, and the pre-commit commands with a local repository standing in for the
// download. The build steps are not re-run (the suite already built the binary); the
// packages they install are checked against the Debian archive's names instead.
// Without git the test skips; without pre-commit or xmllint those parts are skipped.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

using assetlint::test::on_path;
using assetlint::test::read_file;
using assetlint::test::run_shell;
using assetlint::test::shell_quote;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace {

struct Block {
  std::string language;
  std::vector<std::string> lines;
};

std::vector<Block> fenced_blocks(const std::string& markdown) {
  std::vector<Block> blocks;
  std::istringstream in(markdown);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind("```", 0) == 0) {
      if (!inside) blocks.push_back({line.substr(3), {}});
      inside = !inside;
    } else if (inside) {
      blocks.back().lines.push_back(line);
    }
  }
  return blocks;
}

std::string trim(std::string s) {
  s.erase(0, s.find_first_not_of(" \t"));
  s.erase(s.find_last_not_of(" \t") + 1);
  return s;
}

// The shell commands of the page that run asset-lint or pre-commit: `run:` steps and list
// items of the YAML recipes, lines of the sh blocks (without their trailing comments).
std::vector<std::string> documented_commands(const std::vector<Block>& blocks) {
  static const std::regex yaml_step(R"(^\s*(?:-\s+)?(?:run:\s+)?((?:asset-lint|pre-commit) .*)$)");
  std::vector<std::string> commands;
  for (const Block& block : blocks) {
    for (const std::string& line : block.lines) {
      std::smatch m;
      if (block.language == "sh" && (line.rfind("asset-lint ", 0) == 0 || line.rfind("pre-commit ", 0) == 0))
        commands.push_back(trim(line.substr(0, line.find(" #"))));
      else if (block.language == "yaml" && std::regex_match(line, m, yaml_step))
        commands.push_back(trim(m[1]));
    }
  }
  return commands;
}

// The Debian packages each recipe's `apt-get install` names, one list per recipe.
std::vector<std::vector<std::string>> recipe_packages(const std::vector<Block>& blocks) {
  std::vector<std::vector<std::string>> recipes;
  for (const Block& block : blocks) {
    std::string text;
    for (const auto& line : block.lines) text += line + "\n";
    const auto at = text.find("--no-install-recommends");
    if (at == std::string::npos) continue;
    std::istringstream words(text.substr(at + std::string("--no-install-recommends").size()));
    std::string word;
    recipes.emplace_back();
    while (words >> word && word[0] != '-' && word.back() != ':')
      if (word != "\\") recipes.back().push_back(word);
  }
  return recipes;
}

std::vector<std::string> installed_packages(const std::vector<Block>& blocks) {
  std::vector<std::string> packages;
  for (const auto& recipe : recipe_packages(blocks)) packages.insert(packages.end(), recipe.begin(), recipe.end());
  return packages;
}

// The words of bash array `name=( … )` in `script`, comments left out.
std::vector<std::string> bash_array(const std::string& script, const std::string& name) {
  std::vector<std::string> words;
  const auto start = script.find("\n" + name + "=(");
  if (start == std::string::npos) return words;
  std::istringstream in(script.substr(start + name.size() + 3));
  std::string line;
  while (std::getline(in, line)) {
    const std::string code = line.substr(0, line.find('#'));
    std::istringstream tokens(code);
    std::string word;
    bool closed = false;
    while (tokens >> word) {
      if (word == ")") {
        closed = true;
        break;
      }
      words.push_back(word);
    }
    if (closed || trim(code) == ")") break;
  }
  return words;
}

// The assets (fixtures/ci): hand.urdf, whose mimic follower is limited below its gearing (a
// warning), arm.urdf with nothing to report, and wrist.urdf, whose limits are inverted (an
// error), added later as a new asset.
std::string fixture(const char* name) { return read_file(assetlint::test::fixtures_dir() / "ci" / name); }


const std::string kGit = "git -c user.name=test -c user.email=test@example.invalid -c init.defaultBranch=main "
                         "-c commit.gpgsign=false ";

class AssetRepository {
 public:
  AssetRepository() {
    std::filesystem::create_directories(root() / "assets");
    write_file(root() / "assets" / "hand.urdf", fixture("hand.urdf"));
    write_file(root() / "assets" / "arm.urdf", fixture("arm.urdf"));
    REQUIRE(run(kGit + "init -q && " + kGit + "add . && " + kGit + "commit -q -m assets") == 0);
  }
  const std::filesystem::path& root() const { return root_; }
  // Runs `command` in the repository with the built asset-lint first on PATH.
  int run(const std::string& command) {
    const std::string env = "PATH=" + shell_quote(assetlint::test::asset_lint_binary().parent_path().string()) +
                            ":\"$PATH\" NO_COLOR=1 PRE_COMMIT_COLOR=never PRE_COMMIT_HOME=" +
                            shell_quote((dir_.path() / "pre-commit-cache").string()) + " ";
    return run_shell("cd " + shell_quote(root_.string()) + " && " + env + command, dir_.path() / "log", output);
  }
  const TempDir& dir() const { return dir_; }
  std::string output;

 private:
  TempDir dir_;
  std::filesystem::path root_ = dir_.path() / "robot-assets";
};

}  // namespace

TEST_CASE("docs/ci.md: the recipes' commands run as written in an asset repository", "[ci-recipe]") {
  if (!on_path("git")) {
    WARN("git not installed; skipping the CI recipe test");
    return;
  }
  const auto blocks = fenced_blocks(read_file(assetlint::test::source_dir() / "docs" / "ci.md"));
  const auto commands = documented_commands(blocks);
  // The page's commands, in its order. A changed recipe must be changed here too, with
  // what it is expected to do below.
  const std::vector<std::string> expected = {
      "asset-lint --output-format sarif --output-file asset-lint.sarif --exit-zero assets/",
      "asset-lint --output-format github assets/",
      "asset-lint --write-baseline asset-lint-baseline.json assets/",
      "asset-lint --baseline asset-lint-baseline.json --output-format github assets/",
      "asset-lint --fail-on error --output-format github assets/",
      "asset-lint --output-format junit --output-file asset-lint.xml --exit-zero assets/",
      "asset-lint --output-format gitlab --output-file gl-code-quality.json --exit-zero assets/",
      "asset-lint --output-format concise assets/",
      "pre-commit try-repo /path/to/asset-lint asset-lint --all-files",
  };
  REQUIRE(commands == expected);

  AssetRepository repo;
  const auto& out = repo.output;

  SECTION("GitHub Actions: SARIF for code scanning, then the gate's annotations") {
    CHECK(repo.run(commands[0]) == 0);
    INFO(out);
    const auto sarif = nlohmann::json::parse(read_file(repo.root() / "asset-lint.sarif"));
    CHECK(sarif["version"] == "2.1.0");
    const auto& results = sarif["runs"][0]["results"];
    REQUIRE(results.size() == 1);
    CHECK(results[0]["ruleId"] == "mimic-max-velocity");
    const auto& location = results[0]["locations"][0]["physicalLocation"];
    CHECK(location["artifactLocation"]["uri"] == "assets/hand.urdf");
    CHECK(location["artifactLocation"]["uriBaseId"] == "%SRCROOT%");
    CHECK(location["region"]["startLine"] == 14);
    CHECK(sarif["runs"][0]["invocations"][0]["executionSuccessful"] == true);

    CHECK(repo.run(commands[1]) == 1);
    CHECK(out.rfind("::warning file=assets/hand.urdf,line=14,", 0) == 0);
    CHECK(out.find("arm.urdf") == std::string::npos);
  }

  SECTION("a baseline gates only new findings") {
    CHECK(repo.run(commands[2]) == 0);
    INFO(out);
    CHECK(out.find("wrote 1 finding") != std::string::npos);
    const auto baseline = nlohmann::json::parse(read_file(repo.root() / "asset-lint-baseline.json"));
    REQUIRE(baseline["findings"].size() == 1);
    CHECK(baseline["findings"][0]["path"] == "assets/hand.urdf");
    CHECK(baseline["findings"][0]["element"] == "joint 'follow'");

    CHECK(repo.run(commands[3]) == 0);
    CHECK(out.find("::") == std::string::npos);

    // Lines added above the recorded finding keep it matched; a new asset with an error fails.
    std::string hand = fixture("hand.urdf");
    hand.insert(hand.find("  <link name=\"palm\"/>"), "  <!-- reviewed -->\n  <!-- twice -->\n");
    write_file(repo.root() / "assets" / "hand.urdf", hand);
    std::filesystem::create_directories(repo.root() / "assets" / "wrist");
    write_file(repo.root() / "assets" / "wrist" / "wrist.urdf", fixture("wrist.urdf"));
    CHECK(repo.run(commands[3]) == 1);
    CHECK(out.find("::error file=assets/wrist/wrist.urdf,line=8,") != std::string::npos);
    CHECK(out.find("hand.urdf,") == std::string::npos);

    // Fixing the recorded finding names the stale entry without failing the job.
    std::filesystem::remove_all(repo.root() / "assets" / "wrist");
    write_file(repo.root() / "assets" / "hand.urdf", assetlint::test::replace_once(fixture("hand.urdf"), "velocity=\"1.5\"", "velocity=\"3.0\""));
    CHECK(repo.run(commands[3]) == 0);
    CHECK(out.find("1 baseline entry no longer occurs") != std::string::npos);
    CHECK(out.find("assets/hand.urdf: joint 'follow' limit.velocity [mimic-max-velocity]") != std::string::npos);
  }

  SECTION("--fail-on error lets warnings through and fails on errors") {
    CHECK(repo.run(commands[4]) == 0);
    INFO(out);
    CHECK(out.rfind("::warning file=assets/hand.urdf,line=14,", 0) == 0);
    write_file(repo.root() / "assets" / "wrist.urdf", fixture("wrist.urdf"));
    CHECK(repo.run(commands[4]) == 1);
    CHECK(out.find("::error file=assets/wrist.urdf,line=8,") != std::string::npos);
  }

  SECTION("GitLab CI: JUnit and Code Quality reports, then a concise log") {
    write_file(repo.root() / "assets" / "wrist.urdf", fixture("wrist.urdf"));
    CHECK(repo.run(commands[5]) == 0);
    INFO(out);
    const std::string junit = read_file(repo.root() / "asset-lint.xml");
    CHECK(junit.find("<testsuites name=\"asset-lint\"") != std::string::npos);
    CHECK(junit.find("file=\"assets/hand.urdf\" line=\"14\"") != std::string::npos);
    CHECK(junit.find("file=\"assets/wrist.urdf\" line=\"8\"") != std::string::npos);
    if (on_path("xmllint")) {
      const auto schema = assetlint::test::source_dir() / "tests" / "schemas" / "junit.xsd";
      CHECK(repo.run("xmllint --noout --schema " + shell_quote(schema.string()) + " asset-lint.xml") == 0);
    } else {
      WARN("xmllint not installed (apt-get install libxml2-utils); the JUnit file is not validated");
    }

    CHECK(repo.run(commands[6]) == 0);
    const auto quality = nlohmann::json::parse(read_file(repo.root() / "gl-code-quality.json"));
    REQUIRE(quality.size() == 2);
    for (const auto& issue : quality) {
      for (const char* field : {"description", "check_name", "fingerprint", "severity"}) CHECK(issue.contains(field));
      CHECK(issue["location"]["path"].get<std::string>().rfind("assets/", 0) == 0);
      CHECK(issue["location"]["lines"]["begin"].get<int>() > 0);
    }

    CHECK(repo.run(commands[7]) == 1);
    CHECK(out.find("assets/hand.urdf:14:") != std::string::npos);
    CHECK(out.find("assets/wrist.urdf:8:") != std::string::npos);
  }

  SECTION("pre-commit: try-repo and the .pre-commit-config.yaml example") {
    if (!on_path("pre-commit")) {
      WARN("pre-commit not installed (apt-get install pre-commit); skipping the pre-commit recipe");
      return;
    }
    // A local repository holding the hooks file stands in for the asset-lint repository.
    const auto hooks = repo.dir().path() / "asset-lint";
    std::filesystem::create_directories(hooks);
    write_file(hooks / ".pre-commit-hooks.yaml",
               read_file(assetlint::test::source_dir() / ".pre-commit-hooks.yaml"));
    REQUIRE(repo.run("cd " + shell_quote(hooks.string()) + " && " + kGit + "init -q && " + kGit + "add . && " + kGit +
                     "commit -q -m hooks") == 0);
    const std::string try_repo =
        assetlint::test::replace_once(commands[8], "/path/to/asset-lint", shell_quote(hooks.string()));
    CHECK(repo.run("timeout 180 " + try_repo) == 1);
    INFO(out);
    CHECK(out.find("assets/hand.urdf:14:") != std::string::npos);
    CHECK(out.find("in 2 files.") != std::string::npos);

    // The config example, with the placeholders filled in.
    std::string config;
    for (const Block& block : blocks)
      if (block.language == "yaml" && !block.lines.empty() && block.lines[0] == "repos:")
        for (const auto& line : block.lines) config += line + "\n";
    REQUIRE_FALSE(config.empty());
    REQUIRE(repo.run("cd " + shell_quote(hooks.string()) + " && git rev-parse HEAD") == 0);
    const std::string rev = trim(out.substr(0, out.find('\n')));
    config = assetlint::test::replace_once(config, "<URL or path of the asset-lint repository>", hooks.string());
    config = assetlint::test::replace_once(config, "<a tag or commit of it>", rev);
    write_file(repo.root() / ".pre-commit-config.yaml", config);
    REQUIRE(repo.run(kGit + "add .pre-commit-config.yaml") == 0);
    CHECK(repo.run("timeout 180 pre-commit run --all-files") == 1);
    CHECK(out.find("asset-lint (fix)") != std::string::npos);
    CHECK(out.find("assets/hand.urdf:14:") != std::string::npos);
    // With the finding fixed, both hooks pass.
    write_file(repo.root() / "assets" / "hand.urdf",
               assetlint::test::replace_once(fixture("hand.urdf"), "velocity=\"1.5\"", "velocity=\"3.0\""));
    CHECK(repo.run("timeout 180 pre-commit run --all-files") == 0);
  }
}

// The shipped hooks pass every format asset-lint reads: xacro, binary crate USD (.usdc) and MJCF
// (.xml with a <mujoco> root), and leave other XML (a launch file) out without a word.
TEST_CASE("pre-commit hooks: xacro, .usdc and MJCF are checked, other XML is passed over", "[ci-recipe][hooks]") {
  if (!on_path("git") || !on_path("pre-commit")) {
    WARN("git or pre-commit not installed; skipping the hooks test");
    return;
  }
  AssetRepository repo;
  namespace fs = std::filesystem;
  const fs::path assets = repo.root() / "assets";
  fs::copy(assetlint::test::fixtures_dir() / "xacro" / "demo_gripper_description", assets / "demo_gripper_description",
           fs::copy_options::recursive);
  fs::copy_file(assetlint::test::fixtures_dir() / "usdc" / "angular_near_miss.usd", assets / "near_miss.usdc");
  fs::copy_file(assetlint::test::fixtures_dir() / "mjcf" / "robotiq_2f85" / "robotiq_2f85.xml", assets / "gripper.xml");
  write_file(assets / "bringup.launch.xml", "<launch>\n  <node pkg=\"demo\" exec=\"demo\"/>\n</launch>\n");
  const auto hooks = repo.dir().path() / "asset-lint";
  fs::create_directories(hooks);
  write_file(hooks / ".pre-commit-hooks.yaml", read_file(assetlint::test::source_dir() / ".pre-commit-hooks.yaml"));
  REQUIRE(repo.run("cd " + shell_quote(hooks.string()) + " && " + kGit + "init -q && " + kGit + "add . && " + kGit +
                   "commit -q -m hooks") == 0);
  REQUIRE(repo.run(kGit + "add . && " + kGit + "commit -q -m formats") == 0);
  CHECK(repo.run("timeout 180 pre-commit try-repo " + shell_quote(hooks.string()) + " asset-lint --all-files") == 1);
  const std::string& out = repo.output;
  INFO(out);
  CHECK(out.find("assets/demo_gripper_description/urdf/demo_gripper_macro.xacro:19:31: error:") != std::string::npos);
  CHECK(out.find("assets/gripper.xml:61:55: error:") != std::string::npos);
  CHECK(out.find("assets/near_miss.usdc </gripper/finger_joint>: info:") != std::string::npos);
  CHECK(out.find("assets/hand.urdf:14:") != std::string::npos);
  CHECK(out.find("bringup.launch.xml") == std::string::npos);
  // The macro file the hook names is checked through the file that includes it.
  CHECK(out.find("urdf-invalid") == std::string::npos);
  CHECK(out.find("could not be read") == std::string::npos);
}

TEST_CASE("docs/ci.md: the recipes install packages the Debian archive has", "[ci-recipe]") {
  if (!on_path("apt-cache")) {
    WARN("apt-cache not available; skipping the check of the recipes' package names");
    return;
  }
  const auto packages = installed_packages(fenced_blocks(read_file(assetlint::test::source_dir() / "docs" / "ci.md")));
  CHECK(packages.size() >= 2 * 12);  // both recipes, each with the build dependencies
  // One query for all: apt-cache names each package it does not know.
  std::string names;
  for (const auto& package : packages) names += " " + shell_quote(package);
  TempDir dir;
  std::string out;
  CHECK(run_shell("apt-cache show --no-all-versions" + names + " 2>/dev/null | grep -c '^Package: '", dir.path() / "apt.log", out) ==
        0);
  INFO("packages:" + names);
  CHECK(std::stoul(out) == packages.size());
}

TEST_CASE("docs/ci.md: the recipes install what scripts/bootstrap.sh builds with", "[ci-recipe]") {
  const auto build = bash_array(read_file(assetlint::test::source_dir() / "scripts" / "bootstrap.sh"), "build_packages");
  REQUIRE(build.size() >= 15);
  CHECK(std::find(build.begin(), build.end(), "libmujoco-dev") != build.end());
  const auto recipes = recipe_packages(fenced_blocks(read_file(assetlint::test::source_dir() / "docs" / "ci.md")));
  REQUIRE(recipes.size() == 2);
  for (const auto& recipe : recipes) {
    for (const auto& package : build) {
      INFO("bootstrap.sh builds with " << package);
      CHECK(std::find(recipe.begin(), recipe.end(), package) != recipe.end());
    }
    // Beyond the build: only what a bare container needs to check the repository out.
    for (const auto& package : recipe) {
      INFO("a recipe installs " << package);
      CHECK((std::find(build.begin(), build.end(), package) != build.end() || package == "git" ||
             package == "ca-certificates"));
    }
  }
}

TEST_CASE("docs/ci.md: the git textconv recipe makes crate layers diff as USDA", "[ci-recipe][usdc]") {
  if (!on_path("git")) {
    WARN("git not installed; skipping the CI recipe test");
    return;
  }
  const auto blocks = fenced_blocks(read_file(assetlint::test::source_dir() / "docs" / "ci.md"));
  const auto recipe = std::find_if(blocks.begin(), blocks.end(), [](const Block& b) {
    return b.language == "sh" && std::any_of(b.lines.begin(), b.lines.end(), [](const std::string& l) {
             return l.find("diff.usd.textconv") != std::string::npos;
           });
  });
  REQUIRE(recipe != blocks.end());
  AssetRepository repo;
  const auto crate = [](const char* name) { return read_file(assetlint::test::fixtures_dir() / "usdc" / name); };
  write_file(repo.root() / "assets" / "robot.usd", crate("value_types.usd"));
  REQUIRE(repo.run(kGit + "add . && " + kGit + "commit -q -m crate") == 0);
  for (const std::string& line : recipe->lines) REQUIRE(repo.run(line) == 0);
  write_file(repo.root() / "assets" / "robot.usd", crate("robotiq_2f85.usd"));
  REQUIRE(repo.run(kGit + "diff -- assets/robot.usd") == 0);
  const std::string& out = repo.output;
  INFO(out);
  CHECK(out.find("Binary files") == std::string::npos);
  CHECK(out.find("-    defaultPrim = \"robot\"") != std::string::npos);
  CHECK(out.find("+            float drive:angular:physics:stiffness = 4.8") != std::string::npos);
}
