// Crate (binary USD) layers with variant sets: variant set and variant specs, variant
// selections, variantSetNames, nested sets and physics inside variants and their payloads.
// OpenUSD's stage export flattens, so these crate files are written by the test crate writer
// (tests/support/crate_writer.h) and kept as fixtures under fixtures/usdc/variants; OpenUSD
// 22.11 (WASM, tests/usd_reference) reads them back. usd_crate_test.cpp holds asset-lint's
// reading of every crate fixture, these included, to OpenUSD's USDA export of it, and
// usd_reference_test.cpp the composition of the stage layers that sublayer them; here the
// findings of each variant selection on the crate stack must equal those on the same stack
// with every crate layer replaced by OpenUSD's USDA export of it.
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "test_support.h"

#include "config/config.h"
#include "engine/settings.h"
#include "formats/usda/parser.h"
#include "formats/usdc/crate_usda.h"
#include "pipeline/lint.h"
#include "pipeline/variant_label.h"
#include "support/crate_variant_assets.h"
#include "support/crate_writer.h"
#include "support/openusd_oracle.h"

using assetlint::test::fixtures_dir;
using assetlint::test::read_file;
using assetlint::test::run_cli;

namespace {

namespace fs = std::filesystem;
namespace usda = assetlint::usda;
namespace usdc = assetlint::usdc;

std::size_t occurrences(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

usda::Layer read_crate(const std::string& bytes) {
  auto result = usdc::crate_to_usda(bytes);
  if (auto* e = std::get_if<usdc::CrateError>(&result)) FAIL(usdc::describe(*e, "crate"));
  const auto& crate = std::get<usdc::CrateText>(result);
  CHECK(crate.skipped_fields.empty());
  const assetlint::SourceFile file("crate.usd", crate.text);
  usda::ParseResult r = usda::parse_layer(file, 0, usda::ParseOptions{});
  if (!r.ok()) FAIL(r.error().message << " at line " << r.error().span.line << " of\n" << crate.text);
  return std::move(r.layer());
}

std::vector<std::string> names_of(const std::vector<usda::Variant>& variants) {
  std::vector<std::string> out;
  for (const auto& v : variants) out.push_back(v.name);
  return out;
}

// "prepend [PhysX, Newton]": a list-op metadata item with its string items.
std::string list_metadata(const usda::Prim& prim, const std::string& key) {
  const auto* m = prim.find_metadata(key);
  if (!m) return "";
  const auto items = m->value.as_string_list();
  return items ? fmt::format("{} [{}]", usda::list_op_name(m->op), fmt::join(*items, ", ")) : "not a list";
}

}  // namespace

TEST_CASE("crate variant fixtures are the test crate writer's bytes", "[usdc][variants]") {
  // ASSET_LINT_UPDATE_EXPECTED=1 rewrites them (then the fixture snapshots).
  const bool update = std::getenv("ASSET_LINT_UPDATE_EXPECTED") != nullptr;
  for (const auto& asset : assetlint::test::crate_variant_assets()) {
    const auto path = fixtures_dir() / asset.path;
    INFO(path.string());
    if (update) assetlint::test::write_file(path, asset.bytes);
    REQUIRE(fs::exists(path));
    CHECK(read_file(path) == asset.bytes);
  }
}

TEST_CASE("a crate layer's variant sets, variants, selections and nested sets read as USDA", "[usdc][variants]") {
  const usda::Layer layer = read_crate(read_file(fixtures_dir() / "usdc/variants/simready/gripper.usd"));
  REQUIRE(layer.prims.size() == 1);
  const usda::Prim& gripper = layer.prims[0];
  CHECK(gripper.name == "gripper");
  CHECK(list_metadata(gripper, "variantSets") == "prepend [PhysX, Newton, MuJoCo]");
  const auto* selection = gripper.find_metadata("variants");
  REQUIRE(selection);
  REQUIRE(selection->value.entries.size() == 3);
  CHECK(selection->value.entries[2].key == "PhysX");
  CHECK(selection->value.entries[2].value.text == "Disabled");

  // Variant sets in the order the prim lists them, variants in the order the set lists them.
  REQUIRE(gripper.variant_sets.size() == 3);
  CHECK(gripper.variant_sets[0].name == "PhysX");
  CHECK(gripper.variant_sets[1].name == "Newton");
  CHECK(gripper.variant_sets[2].name == "MuJoCo");
  for (const auto& set : gripper.variant_sets) CHECK(names_of(set.variants) == std::vector<std::string>{"Disabled", "Enabled"});

  const auto* physx = gripper.variant_sets[0].find_variant("Enabled");
  REQUIRE(physx);
  const auto* payload = physx->body.find_metadata("payload", usda::ListOp::Prepend);
  REQUIRE(payload);
  CHECK(payload->value.text == "./runnables/physics/physx.usd");
  const auto* mujoco = gripper.variant_sets[2].find_variant("Enabled");
  REQUIRE(mujoco);
  const auto* mujoco_payload = mujoco->body.find_metadata("payload", usda::ListOp::Prepend);
  REQUIRE(mujoco_payload);
  CHECK(mujoco_payload->value.prim_path == "/gripper");

  // Newton's variant holds prims, properties and a nested variant set with its own selection.
  const auto* newton = gripper.variant_sets[1].find_variant("Enabled");
  REQUIRE(newton);
  CHECK(newton->body.has_api_schema("PhysicsArticulationRootAPI"));
  REQUIRE(newton->body.children.size() == 3);
  const usda::Prim* joint = newton->body.find_child("finger_joint");
  REQUIRE(joint);
  CHECK(joint->type_name == "PhysicsRevoluteJoint");
  CHECK_FALSE(joint->find_attribute("drive:angular:physics:stiffness"));
  REQUIRE(joint->find_relationship("physics:body1"));
  REQUIRE(newton->body.find_metadata("variants"));
  CHECK(list_metadata(newton->body, "variantSets") == "prepend [NewtonSolver]");
  REQUIRE(newton->body.variant_sets.size() == 1);
  const auto& solver = newton->body.variant_sets[0];
  CHECK(solver.name == "NewtonSolver");
  // By name, as OpenUSD writes a set, whatever order the set lists them in.
  CHECK(names_of(solver.variants) == std::vector<std::string>{"Featherstone", "XPBD"});
  const auto* featherstone = solver.find_variant("Featherstone");
  REQUIRE(featherstone);
  const usda::Prim* over = featherstone->body.find_child("finger_joint");
  REQUIRE(over);
  CHECK(over->specifier == usda::Specifier::Over);
  CHECK(over->attribute_double("drive:angular:physics:stiffness") == Approx(60.0));
}

TEST_CASE("a crate layer's variant values: float, double, token and string attributes, uniform tokens", "[usdc][variants]") {
  const usda::Layer layer = read_crate(read_file(fixtures_dir() / "usdc/variants/isaac_arm.usd"));
  REQUIRE(layer.prims.size() == 1);
  REQUIRE(layer.prims[0].variant_sets.size() == 1);  // "Sensors" has no variant: OpenUSD writes no set
  const auto* physx = layer.prims[0].variant_sets[0].find_variant("PhysX");
  REQUIRE(physx);
  const usda::Prim* joint = physx->body.find_child("joint1");
  REQUIRE(joint);
  CHECK(joint->attribute_double("isaac:gainScale") == 0.1);  // a double no float holds, stored out of line
  CHECK(joint->attribute_double("physics:lowerLimit") == -170.0);
  CHECK(joint->attribute_string("isaac:note") == "tuned on the \"real\" arm");
  const auto* axis = joint->find_attribute("physics:axis");
  REQUIRE(axis);
  CHECK(axis->variability == usda::Variability::Uniform);
  CHECK(joint->attribute_string("physics:axis") == "Z");
  CHECK(joint->api_schemas(usda::ListOp::Prepend) == std::vector<std::string_view>{"PhysicsDriveAPI:angular", "PhysxJointAPI"});
}

namespace {

// fixtures/usdc/variants copied twice into a temporary directory: as it is ("crate"), and with
// every crate layer replaced by OpenUSD's USDA export of it under the same name ("text"; a
// .usd file may hold USDA text), so the two stacks differ only in how their layers are stored.
struct Stacks {
  std::string skipped;
  std::unique_ptr<assetlint::test::TempDir> dir;
  fs::path crate, text;
};

const Stacks& stacks() {
  static const Stacks result = [] {
    Stacks s;
    s.skipped = assetlint::test::openusd_missing();
    if (!s.skipped.empty()) return s;
    s.dir = std::make_unique<assetlint::test::TempDir>();
    s.crate = s.dir->path() / "crate";
    s.text = s.dir->path() / "text";
    for (const auto& to : {s.crate, s.text}) fs::copy(fixtures_dir() / "usdc" / "variants", to, fs::copy_options::recursive);
    std::vector<fs::path> crates;
    std::vector<std::string> args;
    for (const auto& asset : assetlint::test::crate_variant_assets()) {
      crates.push_back(s.text / fs::relative(fixtures_dir() / asset.path, fixtures_dir() / "usdc" / "variants"));
      args.push_back(crates.back().string());
    }
    const auto json = assetlint::test::run_openusd("export_layers.mjs", args, s.dir->path());
    REQUIRE(json["layers"].size() == crates.size());
    for (std::size_t i = 0; i < crates.size(); ++i) {
      const auto& layer = json["layers"][i];
      INFO(crates[i].string() << ": " << layer["errors"].dump());
      REQUIRE_FALSE(layer["usda"].is_null());
      assetlint::test::write_file(crates[i], layer["usda"].get<std::string>());
    }
    return s;
  }();
  return result;
}

// Each finding with its layer (relative to the stack's directory), rule, severity, message and notes.
std::vector<std::string> findings(const assetlint::FileReport& report, const fs::path& root) {
  std::vector<std::string> out;
  for (const auto& d : report.diagnostics) {
    const std::string layer = d.span.file == assetlint::kNoFile
                                  ? ""
                                  : fs::relative(report.source(d.span.file).path(), root).generic_string();
    std::string s = fmt::format("{} [{}] {}: {}", layer, d.rule, static_cast<int>(d.severity), d.message);
    // A fix of a value in a crate layer is shown, not written: the one note a text layer lacks.
    for (const auto& n : d.notes)
      if (n.message.rfind("the value lives in the binary layer", 0) != 0) s += "\n  note: " + n.message;
    out.push_back(s);
  }
  std::sort(out.begin(), out.end());
  return out;
}

assetlint::FileReport lint_in(const fs::path& root, const std::string& file, const std::vector<std::pair<std::string, std::string>>& pins) {
  assetlint::Settings settings;
  const auto error = assetlint::config::load((root / "asset-lint.toml").string(), settings, "asset-lint.toml");
  REQUIRE_FALSE(error);
  for (const auto& [set, name] : pins) settings.usd.variants[set] = {name, "--variant"};
  return assetlint::lint_file((root / file).string(), settings);
}

}  // namespace

TEST_CASE("each variant selection of a crate stack has the findings of its USDA export", "[openusd][usdc][variants]") {
  if (assetlint::test::skip_without_reference("OpenUSD", stacks().skipped)) return;
  using Pins = std::vector<std::pair<std::string, std::string>>;
  const std::vector<Pins> selections{{},
                                     {{"PhysX", "Enabled"}},
                                     {{"PhysX", "Disabled"}},
                                     {{"Newton", "Enabled"}},
                                     {{"Newton", "Enabled"}, {"NewtonSolver", "Featherstone"}},
                                     {{"MuJoCo", "Enabled"}, {"PhysX", "Disabled"}},
                                     {{"Physics", "None"}},
                                     {{"Physics", "PhysX"}},
                                     {{"Physics", "physx-lite"}},
                                     {{"Physics", "arm"}},
                                     {{"Gains", "Stiff"}},
                                     {{"Collider", "Mesh"}}};
  std::size_t compared = 0, in_variant = 0;
  for (const char* root : {"simready/gripper.usd", "simready/runnables/physics/physx.usd", "isaac_arm.usd", "edge_cases.usd",
                           "gripper_physx_enabled.usda", "isaac_arm_without_physics.usda", "edge_cases_soft_gains.usda"}) {
    for (const Pins& pins : selections) {
      std::string label = root;
      for (const auto& [set, name] : pins) label += fmt::format(" --variant {}={}", set, name);
      INFO(label);
      const auto from_crate = lint_in(stacks().crate, root, pins);
      const auto from_text = lint_in(stacks().text, root, pins);
      REQUIRE_FALSE(from_crate.error);
      REQUIRE_FALSE(from_text.error);
      const auto crate = findings(from_crate, stacks().crate);
      CHECK(crate == findings(from_text, stacks().text));
      ++compared;
      for (const auto& f : crate) in_variant += f.find(": in variant") != std::string::npos;
    }
  }
  CHECK(compared == 84);
  CHECK(in_variant >= 10);
}

namespace {

const std::string kCrateGripper = "usdc/variants/simready/gripper.usd";
const std::string kStiffness = ".drive:angular:physics:stiffness>";

}  // namespace

TEST_CASE("cli: a crate gripper's findings name their variant selection, in crate object paths", "[cli][usdc][variants]") {
  const auto fixtures = fixtures_dir();
  auto text = run_cli({kCrateGripper}, fixtures);
  INFO(text.out << text.err);
  CHECK(text.exit_code == 1);
  CHECK(occurrences(text.out, "usdc/variants/simready/runnables/physics/physx.usd </gripper/finger_joint" + kStiffness +
                                  ": error: in variant PhysX=Enabled: drive of 'finger_joint': natural frequency 41540 rad/s") == 1);
  // A nested set's variant is checked with the variant that holds it selected.
  CHECK(occurrences(text.out, "usdc/variants/simready/gripper.usd </gripper{Newton=Enabled}{NewtonSolver=Featherstone}finger_joint" +
                                  kStiffness + ": error: in variant Newton=Enabled, NewtonSolver=Featherstone: drive of "
                                  "'finger_joint': natural frequency 32260 rad/s") == 1);
  CHECK(occurrences(text.out, "info: in variant Newton=Enabled: drive of 'finger_joint': natural frequency 9120 rad/s") == 1);
  CHECK(occurrences(text.out, "mujoco.usda:40:49: info: in variant MuJoCo=Enabled: ") == 1);
  CHECK(occurrences(text.out, "the stage itself selects PhysX=Disabled") == 1);

  auto json = run_cli({"--output-format", "json", kCrateGripper}, fixtures);
  const auto doc = nlohmann::json::parse(json.out);
  std::size_t in_variant = 0;
  for (const auto& d : doc["diagnostics"]) {
    if (d["message"].get<std::string>().rfind("in variant", 0) != 0) continue;
    ++in_variant;
    // A crate layer has no lines: its findings give the object path.
    const std::string file = d["file"].get<std::string>();
    CHECK(d.contains("object_path") == (file.size() > 4 && file.substr(file.size() - 4) == ".usd"));
    if (d["message"].get<std::string>().find("NewtonSolver=Featherstone") != std::string::npos)
      CHECK(d["variants"] == nlohmann::json::parse(R"([[{"set": "Newton", "variant": "Enabled"},
                                                        {"set": "NewtonSolver", "variant": "Featherstone"}]])"));
  }
  CHECK(in_variant == 4);
}

TEST_CASE("cli: --variant and --show-settings on a crate layer", "[cli][usdc][variants]") {
  const auto fixtures = fixtures_dir();
  auto on = run_cli({"--output-format", "concise", "--variant", "PhysX=Enabled", kCrateGripper}, fixtures);
  INFO(on.out << on.err);
  CHECK(occurrences(on.out, "physx.usd </gripper/finger_joint" + kStiffness + ": drive-natural-frequency drive of 'finger_joint'") == 1);
  CHECK(occurrences(on.out, "in variant PhysX") == 0);

  auto nested = run_cli({"--output-format", "concise", "--variant", "Newton=Enabled", "--variant",
                         "NewtonSolver=Featherstone", "--variant", "PhysX=Disabled", "--variant", "MuJoCo=Disabled",
                         kCrateGripper},
                        fixtures);
  INFO(nested.out);
  CHECK(occurrences(nested.out, "{NewtonSolver=Featherstone}finger_joint" + kStiffness +
                                    ": drive-natural-frequency drive of 'finger_joint': natural frequency 32260 rad/s") == 1);
  CHECK(occurrences(nested.out, "\n") == 1);  // that finding only: every set pinned

  auto shown = run_cli({"--show-settings", kCrateGripper}, fixtures);
  INFO(shown.out);
  CHECK(shown.exit_code == 0);
  CHECK(occurrences(shown.out, "#   </gripper> PhysX = [\"Disabled\", \"Enabled\"], selects \"Disabled\"") == 1);
  CHECK(occurrences(shown.out, "#   </gripper> NewtonSolver = [\"Featherstone\", \"XPBD\"], selects \"XPBD\"") == 1);
  CHECK(occurrences(shown.out, "# checked: the stage's selection; PhysX=Enabled; Newton=Enabled; MuJoCo=Enabled; "
                               "Newton=Enabled, NewtonSolver=Featherstone\n") == 1);

  auto pinned = run_cli({"--variant", "Physics=None", "--show-settings", "usdc/variants/isaac_arm.usd"}, fixtures);
  INFO(pinned.out);
  CHECK(occurrences(pinned.out, "#   </arm> Physics = [\"None\", \"PhysX\"], pinned to \"None\"") == 1);
  CHECK(occurrences(pinned.out, "# checked: the stage's selection\n") == 1);

  // An option where --show-settings wants its FILE is a usage error, not a file of that name.
  auto misplaced = run_cli({"--show-settings", "--variant", "Physics=None", "usdc/variants/isaac_arm.usd"}, fixtures);
  CHECK(misplaced.exit_code == 2);
  CHECK(occurrences(misplaced.err, "expects a FILE, not the option --variant") == 1);
  CHECK(misplaced.out.empty());
}

TEST_CASE("a finding's variant selections read back from its message", "[variants]") {
  using assetlint::VariantSelection;
  const std::vector<VariantSelection> selections{{{"PhysX", "Enabled"}},
                                                 {{"Newton", "Enabled"}, {"NewtonSolver", "Featherstone"}},
                                                 {{"Physics", "physx-lite"}}};
  const std::string message = assetlint::variant_prefix(selections) + "drive of 'finger': natural frequency 4 rad/s";
  CHECK(message.rfind("in variants PhysX=Enabled; Newton=Enabled, NewtonSolver=Featherstone; Physics=physx-lite: ", 0) == 0);
  CHECK(assetlint::variant_selections(message) == selections);
  CHECK(assetlint::variant_prefix({selections[0]}) == "in variant PhysX=Enabled: ");
  CHECK(assetlint::variant_selections("in variant PhysX=Enabled: x") == std::vector<VariantSelection>{selections[0]});
  // Messages that only look alike name no selection.
  CHECK(assetlint::variant_selections("drive of 'in variant A=B: '").empty());
  CHECK(assetlint::variant_selections("in variant sets of </a>: nothing").empty());
  CHECK(assetlint::variant_selections("in variants A=B").empty());
}
