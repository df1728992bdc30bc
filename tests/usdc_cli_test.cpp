// Binary USD (crate) layers on the command line: read like text layers, located by object
// path in every report format, never written by --fix, printed as USDA by `cat`.
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "test_support.h"

using assetlint::test::fixtures_dir;
using assetlint::test::read_file;
using assetlint::test::run_cli;
using assetlint::test::TempDir;

namespace {

// The crate fixture with a fixable drive (written by OpenUSD from
// fixtures/usda/rules/drive-instance-ignored/angular_near_miss.usda).
const std::string kCrate = "fixtures/usdc/angular_near_miss.usd";
const std::string kStiffness = "/gripper/finger_joint.drive:angular:physics:stiffness";

}  // namespace

TEST_CASE("crate: findings name the layer and the object path in every format", "[usdc][cli]") {
  const auto text = run_cli({kCrate});
  CHECK(text.exit_code == 1);
  CHECK(text.out.find(kCrate + " <" + kStiffness + ">: error: drive of 'finger_joint': natural frequency") !=
        std::string::npos);
  CHECK(text.out.find(".usd:") == std::string::npos);  // no line numbers of a text the file does not have

  const auto json = nlohmann::json::parse(run_cli({"--output-format", "json", kCrate}).out);
  bool found = false;
  for (const auto& d : json["diagnostics"]) {
    CHECK(d["file"] == kCrate);
    CHECK_FALSE(d.contains("line"));
    if (d["rule"] == "drive-natural-frequency") {
      found = true;
      CHECK(d["object_path"] == kStiffness);
      CHECK_FALSE(d.contains("fix"));
    }
  }
  CHECK(found);

  const auto sarif = nlohmann::json::parse(run_cli({"--output-format", "sarif", kCrate}).out);
  for (const auto& r : sarif["runs"][0]["results"]) {
    if (r["ruleId"] != "drive-natural-frequency") continue;
    const auto& where = r["locations"][0];
    CHECK_FALSE(where["physicalLocation"].contains("region"));
    CHECK(where["logicalLocations"][0]["fullyQualifiedName"] == kStiffness);
  }

  const auto github = run_cli({"--output-format", "github", kCrate}).out;
  CHECK(github.find("::error file=" + kCrate + ",line=1,title=asset-lint (drive-natural-frequency)::<" + kStiffness +
                    "> drive of") != std::string::npos);
  const auto junit = run_cli({"--output-format", "junit", kCrate}).out;
  CHECK(junit.find("name=\"drive-natural-frequency (&lt;" + kStiffness + "&gt;)\"") != std::string::npos);
  const auto gitlab = nlohmann::json::parse(run_cli({"--output-format", "gitlab", kCrate}).out);
  for (const auto& issue : gitlab) CHECK(issue["location"]["lines"]["begin"] == 1);
}

TEST_CASE("crate: --fix never writes a binary layer; the note gives the value", "[usdc][cli]") {
  TempDir dir;
  std::filesystem::copy_file(fixtures_dir() / "usdc" / "angular_near_miss.usd", dir.path() / "gripper.usd");
  const std::string before = read_file(dir.path() / "gripper.usd");
  const auto r = run_cli({"--fix", "--unsafe-fixes", "gripper.usd"}, dir.path());
  CHECK(read_file(dir.path() / "gripper.usd") == before);
  CHECK(r.out.find("the value lives in the binary layer 'gripper.usd' (<" + kStiffness +
                   ">), which asset-lint does not write; the fix would write `0.8499797` there") != std::string::npos);
}

TEST_CASE("crate: a directory run reads crate layers instead of skipping them", "[usdc][cli]") {
  const auto r = run_cli({"fixtures/usdc"});
  CHECK(r.out.find("Skipped") == std::string::npos);
  std::size_t layers = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(fixtures_dir() / "usdc"))
    layers += e.path().extension() == ".usd" || e.path().extension() == ".usda";
  CHECK(layers >= 12);
  CHECK(r.out.find(fmt::format("in {} files", layers)) != std::string::npos);
}

TEST_CASE("crate: `asset-lint cat` prints the layer as USDA", "[usdc][cli]") {
  const auto r = run_cli({"cat", kCrate});
  CHECK(r.exit_code == 0);
  CHECK(r.out.rfind("#usda 1.0\n", 0) == 0);
  CHECK(r.out.find("float drive:angular:physics:stiffness = 5700") != std::string::npos);
  const auto text = run_cli({"cat", "fixtures/usda/crate_stack/gripper_over.usda"});
  CHECK(text.out == read_file(fixtures_dir() / "usda" / "crate_stack" / "gripper_over.usda"));
  const auto missing = run_cli({"cat", "missing.usd"});
  CHECK(missing.exit_code == 2);
  CHECK(missing.err.rfind("asset-lint: error: cannot read 'missing.usd'", 0) == 0);
}
