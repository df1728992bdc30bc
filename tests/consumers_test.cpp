// The consumers a file is judged for: the names --target and [targets] accept, each format's
// usual consumers, and the reports naming the consumers a finding concerns.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "engine/consumers.h"
#include "test_support.h"

using namespace assetlint;
using assetlint::test::fixtures_dir;
using assetlint::test::run_cli;

TEST_CASE("consumers: names with versions and engines, and what is refused", "[consumers]") {
  std::string error;
  auto mujoco = parse_consumer("mujoco@3.12", error);
  REQUIRE(mujoco);
  CHECK(mujoco->label() == "MuJoCo 3.12");
  CHECK(mujoco->name() == "mujoco@3.12");
  CHECK_FALSE(couples_urdf_mimic(*mujoco));
  auto later = parse_consumer("mujoco@3.13.1", error);
  REQUIRE(later);
  CHECK(couples_urdf_mimic(*later));
  auto unnamed = parse_consumer("gazebo", error);
  REQUIRE(unnamed);
  CHECK(unnamed->label() == "Gazebo");
  CHECK(couples_urdf_mimic(*unnamed));  // no engine named: no engine's quirk claimed
  auto dart = parse_consumer("gazebo@dart", error);
  REQUIRE(dart);
  CHECK(dart->label() == "Gazebo (DART)");
  CHECK_FALSE(couples_urdf_mimic(*dart));
  auto featherstone = parse_consumer("gazebo@bullet-featherstone", error);
  REQUIRE(featherstone);
  CHECK(couples_urdf_mimic(*featherstone));
  auto isaac61 = parse_consumer("isaac-sim@6.1", error);
  REQUIRE(isaac61);
  CHECK_FALSE(keeps_urdf_dynamics(*isaac61));
  CHECK(keeps_urdf_dynamics(*parse_consumer("isaac-sim@6.0", error)));
  CHECK(keeps_urdf_dynamics(*parse_consumer("isaac-sim", error)));  // no release named: no release's quirk claimed

  CHECK_FALSE(parse_consumer("bullet", error));
  CHECK(error.find("unknown consumer 'bullet'") != std::string::npos);
  CHECK_FALSE(parse_consumer("newton@1.0", error));
  CHECK(error.find("takes no version") != std::string::npos);
  CHECK_FALSE(parse_consumer("mujoco@2.3", error));
  CHECK(error.find("3.3 and later") != std::string::npos);
  CHECK_FALSE(parse_consumer("gazebo@ode", error));
  CHECK_FALSE(parse_consumer("isaac-sim@six", error));
}

TEST_CASE("consumers: each format's usual consumers, replaced by the configured ones", "[consumers]") {
  Settings settings;
  const auto urdf = consumer_profile(SourceFormat::Urdf, settings);
  CHECK_FALSE(urdf.configured);
  CHECK(urdf.consumers.size() == 6);
  REQUIRE(urdf.find(ConsumerKind::Mujoco));
  CHECK(urdf.find(ConsumerKind::Mujoco)->label() == "MuJoCo 3.15");  // [mujoco] version's default
  CHECK(consumer_profile(SourceFormat::Usda, settings).consumers.size() == 3);
  const auto mjcf = consumer_profile(SourceFormat::Mjcf, settings);
  CHECK(mjcf.consumers.size() == 2);
  // MJCF has no max joint velocity, so none of its consumers reads one.
  CHECK_FALSE(mjcf.any([](const Consumer& c) { return reads_max_joint_velocity(c, SourceFormat::Mjcf); }));
  CHECK(urdf.any([](const Consumer& c) { return reads_max_joint_velocity(c, SourceFormat::Urdf); }));

  settings.mujoco.version = {"3.10", "asset-lint.toml:2"};
  CHECK(consumer_profile(SourceFormat::Urdf, settings).find(ConsumerKind::Mujoco)->label() == "MuJoCo 3.10");
  settings.targets.consumers = {{"mujoco", "--target"}, {"gazebo@bullet-featherstone", "--target"}};
  const auto targeted = consumer_profile(SourceFormat::Urdf, settings);
  CHECK(targeted.configured);
  REQUIRE(targeted.consumers.size() == 2);
  CHECK(targeted.consumers[0].label() == "MuJoCo 3.10");
  CHECK(targeted.consumers[1].origin == "--target");
  // Only MuJoCo, which reads no velocity limit: the velocity rules judge nothing.
  settings.targets.consumers = {{"mujoco", "--target"}};
  CHECK_FALSE(consumer_profile(SourceFormat::Urdf, settings).any(
      [](const Consumer& c) { return reads_max_joint_velocity(c, SourceFormat::Urdf); }));
}

TEST_CASE("consumers: --target replaces [targets], names the consumers in JSON, and --show-settings says so",
          "[consumers]") {
  const std::string control = "rules/consumer-drops-value/mujoco-3.13/mimic.urdf";
  // The fixture's own asset-lint.toml names MuJoCo 3.13, which couples the mimic: clean.
  CHECK(run_cli({control}, fixtures_dir()).exit_code == 0);
  const auto json = run_cli({"--target", "mujoco@3.12", "--target", "gazebo@dart", "--output-format", "json", control},
                            fixtures_dir());
  CHECK(json.exit_code == 1);
  const auto doc = nlohmann::json::parse(json.out);
  REQUIRE(doc["diagnostics"].size() == 1);
  const auto& d = doc["diagnostics"][0];
  CHECK(d["rule"] == "consumer-drops-value");
  CHECK(d["severity"] == "warning");
  CHECK(d["consumers"] == nlohmann::json::array({"MuJoCo 3.12", "Gazebo (DART)"}));
  const auto sarif = nlohmann::json::parse(
      run_cli({"--target", "mujoco@3.12", "--output-format", "sarif", control}, fixtures_dir()).out);
  CHECK(sarif["runs"][0]["results"][0]["properties"]["consumers"] == nlohmann::json::array({"MuJoCo 3.12"}));

  const auto shown = run_cli({"--target", "gazebo@dart", "--show-settings", control}, fixtures_dir());
  CHECK(shown.out.find("consumers = [\"gazebo@dart\"]") != std::string::npos);
  CHECK(shown.out.find("# --target") != std::string::npos);
  CHECK(shown.out.find("findings that concern none of these consumers are not reported") != std::string::npos);
  const auto defaults = run_cli({"--show-settings", "rules/limits-inverted/lower_above_upper.urdf"}, fixtures_dir());
  CHECK(defaults.out.find("# consumers is not set") != std::string::npos);
  CHECK(defaults.out.find("isaac-sim, isaac-lab, mujoco, newton, gazebo, ros2_control") != std::string::npos);

  const auto bad = run_cli({"--target", "bullet", control}, fixtures_dir());
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("unknown consumer 'bullet'") != std::string::npos);
}
