// OpenUSD (22.11 compiled to WASM, npm three-usdz-loader 1.0.9, run with Node) as the reference
// for the USDA reader's composition: tests/usd_reference/flatten.mjs opens every .usda file
// under fixtures/ and ../shared/corpus/usda as the root layer of a stage and flattens the
// composed stage to one layer. This file holds asset-lint's composition of the original layer
// stack to asset-lint's reading of that flattened text: the same prims with the same applied
// API schemas, and the same joints, bodies, drives, mimics, mass properties, scene rate and
// iterations. What OpenUSD composed is then a single layer without arcs, so a difference is
// asset-lint's composition (sublayers, references, payloads, list ops, `delete`), not its
// reading of values.
//
// Skipped with a message when `node` or the package is absent (scripts/bootstrap.sh installs
// it into tools/node_modules); with CI=true in the environment that is a failure instead.
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "test_support.h"
#include "support/openusd_oracle.h"

#include "engine/file_system.h"
#include "formats/usda/compose.h"
#include "formats/usda/usd_reader.h"

using assetlint::test::corpus_dir;
using assetlint::test::fixtures_dir;
using assetlint::test::read_file;

namespace {

namespace usda = assetlint::usda;
using assetlint::Joint;
using assetlint::Link;
using assetlint::OptQuantity;

struct Reference {
  nlohmann::json json;  // flatten.mjs's output; null when skipped
  std::string skipped;  // why, when skipped
};

// A variant selection of a fixture, composed by OpenUSD through a wrapper layer that sublayers
// the fixture and selects the variant on every prim that has the set.
struct VariantCase {
  std::filesystem::path asset;
  std::string set, variant;
  std::filesystem::path wrapper;
};

std::string quoted_prim_path(const std::string& path, const std::string& body) {
  // "/a/b" -> over "a" { over "b" (...) { } }
  std::vector<std::string> names;
  for (std::size_t at = 1; at <= path.size();) {
    const std::size_t next = std::min(path.find('/', at), path.size());
    names.push_back(path.substr(at, next - at));
    at = next + 1;
  }
  std::string open, close;
  for (std::size_t i = 0; i < names.size(); ++i) {
    open += fmt::format("over \"{}\"{}\n{{\n", names[i], i + 1 == names.size() ? body : "");
    close += "}\n";
  }
  return open + close;
}

// The wrapper layers of every variant of every set the fixtures' stages compose, written into
// `dir` (one directory for the test process).
const std::vector<VariantCase>& variant_cases() {
  static const assetlint::test::TempDir dir;
  static const std::vector<VariantCase> cases = [] {
    std::vector<VariantCase> out;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(fixtures_dir())) {
      if (!entry.is_regular_file() || entry.path().extension() != ".usda") continue;
      const auto path = std::filesystem::weakly_canonical(entry.path());
      usda::ComposeOptions options;
      options.root_dir = std::filesystem::weakly_canonical(fixtures_dir()).string();
      const usda::Stage stage = usda::compose_stage(
          std::make_shared<const assetlint::SourceFile>(path.string(), read_file(path)), assetlint::disk(), options);
      if (!stage.usable || stage.variant_sets.empty()) continue;
      std::string units;
      if (const auto* root = stage.root_layer()) {
        if (auto mpu = root->meters_per_unit()) units += fmt::format("    metersPerUnit = {}\n", *mpu);
        if (auto kpu = root->kilograms_per_unit()) units += fmt::format("    kilogramsPerUnit = {}\n", *kpu);
      }
      std::vector<std::pair<std::string, std::string>> seen;
      for (const auto& use : stage.variant_sets) {
        for (const auto& variant : use.variants) {
          if (std::find(seen.begin(), seen.end(), std::pair{use.set, variant}) != seen.end()) continue;
          seen.emplace_back(use.set, variant);
          std::string text = fmt::format("#usda 1.0\n(\n{}    subLayers = [\n        @{}@\n    ]\n)\n\n", units,
                                         path.string());
          const std::string body =
              fmt::format(" (\n    variants = {{\n        string {} = \"{}\"\n    }}\n)", use.set, variant);
          for (const auto& other : stage.variant_sets)
            if (other.set == use.set) text += quoted_prim_path(other.prim, body);
          VariantCase c{path, use.set, variant, dir.path() / fmt::format("variant_{}.usda", out.size())};
          assetlint::test::write_file(c.wrapper, text);
          out.push_back(std::move(c));
        }
      }
    }
    return out;
  }();
  return cases;
}

std::filesystem::path variant_dir() {
  return variant_cases().empty() ? std::filesystem::path() : variant_cases().front().wrapper.parent_path();
}

// Runs the flattening script once per test process.
const Reference& reference() {
  static const Reference result = [] {
    Reference r;
    r.skipped = assetlint::test::openusd_missing();
    if (!r.skipped.empty()) return r;
    assetlint::test::TempDir dir;
    std::vector<std::string> args{fixtures_dir().string()};
    if (!corpus_dir().empty()) args.push_back((corpus_dir() / "usda").string());
    if (!variant_dir().empty()) args.push_back(variant_dir().string());
    r.json = assetlint::test::run_openusd("flatten.mjs", args, dir.path());
    return r;
  }();
  return result;
}

bool skip_without_openusd() { return assetlint::test::skip_without_reference("OpenUSD", reference().skipped); }

// Files held in memory; anything else is missing.
class OneFile final : public assetlint::FileSystem {
 public:
  OneFile(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {}
  std::optional<std::string> read(const std::string& path, std::string& error) const override {
    if (path == path_) return text_;
    error = "No such file or directory";
    return std::nullopt;
  }

 private:
  std::string path_, text_;
};

// What is compared: per defined prim its type and applied schemas, and the model.
struct Reading {
  bool usable = false;
  std::map<std::string, std::string> prim_types;                 // defined prims
  std::map<std::string, std::vector<std::string>> api_schemas;  // defined prims that apply some
  std::optional<double> kilograms_per_unit;                       // the root layer's
  assetlint::ReadResult result;
};

Reading read(usda::Stage stage) {
  Reading r;
  r.usable = stage.usable;
  if (const auto* root = stage.root_layer()) r.kilograms_per_unit = root->kilograms_per_unit();
  for (const auto& prim : stage.prims) {
    if (!prim.defined) continue;
    r.prim_types[prim.path] = prim.type_name;
    if (!prim.api_schemas.empty()) r.api_schemas[prim.path] = prim.api_schemas;
  }
  r.result = usda::read_stage(std::move(stage));
  return r;
}

Reading read_original(const std::filesystem::path& path, const std::filesystem::path& tree) {
  usda::ComposeOptions options;
  options.root_dir = tree.string();  // flatten.mjs gives OpenUSD the files of the same tree
  return read(usda::compose_stage(std::make_shared<const assetlint::SourceFile>(path.string(), read_file(path)),
                                  assetlint::disk(), options));
}

// The OpenUSD build has no UsdPhysics plugin, so it does not know the layer field
// kilogramsPerUnit and leaves it out of the flattened layer (it says so: "Failed copying
// metadata"); the root layer's value is carried over into the flattened text's metadata.
std::string with_kilograms_per_unit(std::string flattened, std::optional<double> kpu) {
  if (!kpu) return flattened;
  const std::string head = "#usda 1.0\n(\n";
  if (flattened.rfind(head, 0) != 0) return flattened;
  return head + fmt::format("    kilogramsPerUnit = {}\n", *kpu) + flattened.substr(head.size());
}

Reading read_flattened(const std::string& path, const std::string& flattened) {
  const std::string name = path + " (flattened by OpenUSD)";
  OneFile files(name, flattened);
  return read(usda::compose_stage(std::make_shared<const assetlint::SourceFile>(name, flattened), files, {}));
}

class Differences {
 public:
  explicit Differences(std::string file) : file_(std::move(file)) {}

  void add(const std::string& where, const std::string& quantity, const std::string& ours, const std::string& theirs) {
    lines_.push_back(fmt::format("{}: {}: {}: asset-lint composes {}, OpenUSD {}", file_, where, quantity, ours, theirs));
  }

  // Values agree to float32's precision: OpenUSD holds `float` attributes in 32 bits and
  // writes them back rounded, asset-lint reads the literal as a double.
  void number(const std::string& where, const std::string& quantity, const OptQuantity& ours, const OptQuantity& theirs) {
    if (!ours && !theirs) return;
    if (!ours || !theirs) {
      add(where, quantity, ours ? fmt::format("{}", ours->value) : "nothing", theirs ? fmt::format("{}", theirs->value) : "nothing");
      return;
    }
    number(where, quantity, ours->value, theirs->value);
  }
  void number(const std::string& where, const std::string& quantity, double ours, double theirs) {
    if (ours == theirs || (std::isnan(ours) && std::isnan(theirs))) return;
    if (std::abs(ours - theirs) <= 1e-6 * std::max(std::abs(ours), std::abs(theirs))) return;
    add(where, quantity, fmt::format("{}", ours), fmt::format("{}", theirs));
  }
  template <typename T>
  void same(const std::string& where, const std::string& quantity, const T& ours, const T& theirs) {
    if (!(ours == theirs)) add(where, quantity, fmt::format("{}", ours), fmt::format("{}", theirs));
  }

  const std::vector<std::string>& lines() const { return lines_; }

 private:
  std::string file_;
  std::vector<std::string> lines_;
};

std::string joined(const std::vector<std::string>& items) {
  std::string text = "[";
  for (const auto& item : items) text += (text.size() > 1 ? ", " : "") + item;
  return text + "]";
}

void compare_drive(Differences& d, const std::string& where, const char* what, const assetlint::Drive* ours,
                   const assetlint::Drive* theirs) {
  if (!ours || !theirs) {
    if (ours || theirs) d.add(where, what, ours ? "one" : "none", theirs ? "one" : "none");
    return;
  }
  const std::string w = fmt::format("{} {}", where, what);
  d.same(w, "instance", ours->instance, theirs->instance);
  d.number(w, "stiffness", ours->stiffness, theirs->stiffness);
  d.number(w, "damping", ours->damping, theirs->damping);
  d.number(w, "maxForce", ours->max_force, theirs->max_force);
  d.same(w, "type", static_cast<int>(ours->type), static_cast<int>(theirs->type));
  d.same(w, "performance envelope", ours->envelope.has_value(), theirs->envelope.has_value());
  if (ours->envelope && theirs->envelope) {
    d.number(w, "maxActuatorVelocity", ours->envelope->max_actuator_velocity, theirs->envelope->max_actuator_velocity);
    d.number(w, "velocityDependentResistance", ours->envelope->velocity_dependent_resistance,
             theirs->envelope->velocity_dependent_resistance);
    d.number(w, "speedEffortGradient", ours->envelope->speed_effort_gradient, theirs->envelope->speed_effort_gradient);
  }
}

void compare_joint(Differences& d, const Joint& ours, const Joint& theirs) {
  const std::string where = "joint '" + ours.name.text + "'";
  d.same(where, "type", std::string(assetlint::joint_type_name(ours.type)),
         std::string(assetlint::joint_type_name(theirs.type)));
  d.same(where, "body0", ours.parent.text, theirs.parent.text);
  d.same(where, "body1", ours.child.text, theirs.child.text);
  for (int i = 0; i < 3; ++i) d.number(where, "axis", ours.axis[i], theirs.axis[i]);
  for (int side = 0; side < 2; ++side)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c)
        d.number(where, fmt::format("localPos/Rot{}", side), ours.frame_in_link[side].matrix()(r, c),
                 theirs.frame_in_link[side].matrix()(r, c));
  d.number(where, "lowerLimit", ours.lower, theirs.lower);
  d.number(where, "upperLimit", ours.upper, theirs.upper);
  d.number(where, "maxJointVelocity", ours.velocity, theirs.velocity);
  d.number(where, "armature", ours.armature, theirs.armature);
  d.number(where, "jointFriction", ours.joint_friction, theirs.joint_friction);
  d.number(where, "joint damping", ours.joint_damping, theirs.joint_damping);
  compare_drive(d, where, "drive", ours.drive.operator->(), theirs.drive.operator->());
  compare_drive(d, where, "inactive drive", ours.inactive_drive.operator->(), theirs.inactive_drive.operator->());
  if (ours.mimic.has_value() != theirs.mimic.has_value()) {
    d.add(where, "mimic", ours.mimic ? "one" : "none", theirs.mimic ? "one" : "none");
  } else if (ours.mimic) {
    const auto &a = *ours.mimic, &b = *theirs.mimic;
    d.same(where, "mimic instance", a.instance, b.instance);
    d.same(where, "mimic reference", a.reference.text, b.reference.text);
    d.number(where, "mimic gearing", a.multiplier.value, b.multiplier.value);
    d.number(where, "mimic offset", a.offset.value, b.offset.value);
    d.number(where, "mimic naturalFrequency", a.natural_frequency, b.natural_frequency);
    d.number(where, "mimic dampingRatio", a.damping_ratio, b.damping_ratio);
  }
}

void compare_link(Differences& d, const Link& ours, const Link& theirs) {
  const std::string where = "body '" + ours.name.text + "'";
  d.same(where, "kinematicEnabled", ours.kinematic, theirs.kinematic);
  if (ours.inertial.has_value() != theirs.inertial.has_value()) {
    d.add(where, "PhysicsMassAPI", ours.inertial ? "applied" : "not applied", theirs.inertial ? "applied" : "not applied");
    return;
  }
  if (!ours.inertial) return;
  const auto &a = *ours.inertial, &b = *theirs.inertial;
  d.number(where, "mass", a.mass.value, b.mass.value);
  d.same(where, "mass authored", a.mass_authored, b.mass_authored);
  d.same(where, "diagonalInertia authored", a.inertia_authored, b.inertia_authored);
  d.same(where, "centerOfMass authored", a.com_authored, b.com_authored);
  for (int r = 0; r < 3; ++r) {
    d.number(where, "centerOfMass", a.com[r], b.com[r]);
    for (int c = 0; c < 3; ++c) d.number(where, "inertia tensor", a.inertia(r, c), b.inertia(r, c));
  }
}

void compare_scene(Differences& d, const assetlint::Scene& ours, const assetlint::Scene& theirs) {
  d.number("scene", "timeStepsPerSecond", ours.timesteps_per_second, theirs.timesteps_per_second);
  d.number("articulation", "solverPositionIterationCount", ours.position_iterations, theirs.position_iterations);
  d.number("articulation", "solverVelocityIterationCount", ours.velocity_iterations, theirs.velocity_iterations);
  d.number("scene", "minPositionIterationCount", ours.min_position_iterations, theirs.min_position_iterations);
  d.number("scene", "maxPositionIterationCount", ours.max_position_iterations, theirs.max_position_iterations);
  d.same("scene", "solverType", ours.solver, theirs.solver);
}

// UsdStage::Flatten writes each instance prototype as a root prim `/Flattened_Prototype_<n>` and
// makes the instanceable prims reference it: those roots are flattening's own, not the stage's.
bool flattening_prototype(std::string_view path) { return path.starts_with("/Flattened_Prototype_"); }

std::vector<std::string> differences(const std::string& file, const Reading& ours, const Reading& theirs) {
  Differences d(file);
  d.same("stage", "usable", ours.usable, theirs.usable);
  for (const auto& [path, type] : ours.prim_types) {
    auto it = theirs.prim_types.find(path);
    if (it == theirs.prim_types.end()) d.add("prim '" + path + "'", "defined", "yes", "no");
    else d.same("prim '" + path + "'", "type", type, it->second);
  }
  for (const auto& [path, type] : theirs.prim_types)
    if (!ours.prim_types.contains(path) && !flattening_prototype(path)) d.add("prim '" + path + "'", "defined", "no", "yes");
  const std::vector<std::string> none;
  for (const auto& [path, type] : ours.prim_types) {
    auto a = ours.api_schemas.find(path), b = theirs.api_schemas.find(path);
    d.same("prim '" + path + "'", "apiSchemas", joined(a == ours.api_schemas.end() ? none : a->second),
           joined(b == theirs.api_schemas.end() ? none : b->second));
  }
  const auto &a = ours.result.asset, &b = theirs.result.asset;
  auto outside_prototypes = [](const auto& items) {
    return std::count_if(items.begin(), items.end(), [](const auto& item) { return !flattening_prototype(item.name.text); });
  };
  d.same("stage", "body count", outside_prototypes(a.links), outside_prototypes(b.links));
  d.same("stage", "joint count", outside_prototypes(a.joints), outside_prototypes(b.joints));
  for (const Link& link : a.links)
    if (const Link* other = b.find_link(link.name.text)) compare_link(d, link, *other);
    else d.add("body '" + link.name.text + "'", "rigid body", "yes", "no");
  for (const Joint& joint : a.joints)
    if (const Joint* other = b.find_joint(joint.name.text)) compare_joint(d, joint, *other);
    else d.add("joint '" + joint.name.text + "'", "joint", "yes", "no");
  compare_scene(d, a.scene, b.scene);
  return d.lines();
}

// Differences kept on purpose: the file (relative to fixtures/ or corpus/usda), the text the
// difference starts with after the file name, and why.
struct Exception {
  const char* file;
  const char* difference;
  const char* reason;
};
const Exception kExceptions[] = {
    {"robustness/internal_reference_chain.usda", "OpenUSD refuses the layer",
     "a property closed by '}' on its own line (`def \"D\" { float d = 4 }`): OpenUSD's grammar wants a line break "
     "or ';' after it, asset-lint's parser reads the property as if it were there (the composition this crash "
     "regression exercises is the same)"},
    {"robustness/reference_and_payload_chain.usda", "OpenUSD refuses the layer", "as above"},
};

const Exception* exception_for(const std::string& relative, const std::string& difference) {
  for (const Exception& e : kExceptions)
    if (relative == e.file && difference.find(e.difference) != std::string::npos) return &e;
  return nullptr;
}

struct Tree {
  std::filesystem::path dir;
  std::string label;
};

}  // namespace

TEST_CASE("usd reference: asset-lint composes every USDA stack as OpenUSD 22.11 does", "[usd][openusd]") {
  if (skip_without_openusd()) return;
  const auto& json = reference().json;
  CHECK(json["openusd"] == "22.11");
  std::vector<Tree> trees{{std::filesystem::weakly_canonical(fixtures_dir()), "fixtures"}};
  if (corpus_dir().empty()) WARN("../shared/corpus is absent: only the fixtures are composed");
  else trees.push_back({std::filesystem::weakly_canonical(corpus_dir() / "usda"), "corpus/usda"});

  std::vector<std::string> found;
  std::size_t stages = 0, joints = 0, bodies = 0, excepted = 0;
  for (const auto& stage : json["stages"]) {
    // Canonical like the trees: ../shared may be a symbolic link (it is one in CI's checkout).
    const std::filesystem::path path = std::filesystem::weakly_canonical(stage["path"].get<std::string>());
    if (!variant_dir().empty() && path.parent_path() == std::filesystem::weakly_canonical(variant_dir())) continue;
    const Tree* tree = nullptr;
    for (const Tree& t : trees)
      if (path.string().rfind(t.dir.string() + "/", 0) == 0) tree = &t;
    REQUIRE(tree != nullptr);
    const std::string relative = std::filesystem::relative(path, tree->dir).string();
    const std::string label = tree->label + "/" + relative;
    ++stages;
    Reading ours = read_original(path, tree->dir);
    std::vector<std::string> lines;
    if (stage["flattened"].is_null()) {
      std::string why;
      for (const auto& e : stage["errors"]) why += (why.empty() ? "" : " | ") + e.get<std::string>();
      if (ours.usable)
        lines.push_back(label + ": OpenUSD refuses the layer, asset-lint reads it (OpenUSD: " + why + ")");
    } else {
      Reading theirs =
          read_flattened(path.string(), with_kilograms_per_unit(stage["flattened"].get<std::string>(), ours.kilograms_per_unit));
      lines = differences(label, ours, theirs);
      joints += ours.result.asset.joints.size();
      bodies += ours.result.asset.links.size();
    }
    for (const auto& line : lines) {
      if (exception_for(relative, line.substr(label.size() + 2))) ++excepted;
      else found.push_back(line);
    }
  }
  INFO(stages << " stages, " << joints << " joints, " << bodies << " bodies compared; " << excepted
              << " differences kept on purpose");
  for (const auto& line : found) FAIL_CHECK(line);
  CHECK(found.empty());
  CHECK(stages >= 60);
  CHECK(joints > 100);
}

TEST_CASE("usd reference: asset-lint composes every variant selection of the fixtures as OpenUSD 22.11 does",
          "[usd][openusd][variants]") {
  // OpenUSD opens a layer that sublayers the fixture and selects one variant; asset-lint composes
  // that layer, and the fixture itself with the selection pinned (--variant): all three agree.
  if (skip_without_openusd()) return;
  std::map<std::string, const nlohmann::json*> flattened;
  for (const auto& stage : reference().json["stages"])
    flattened[std::filesystem::weakly_canonical(stage["path"].get<std::string>()).string()] = &stage;
  std::size_t compared = 0, with_joints = 0;
  std::set<std::string> sets;
  for (const VariantCase& c : variant_cases()) {
    const std::string label = fmt::format("{} {}={}", std::filesystem::relative(c.asset, fixtures_dir()).string(), c.set, c.variant);
    INFO(label);
    const auto it = flattened.find(std::filesystem::weakly_canonical(c.wrapper).string());
    REQUIRE(it != flattened.end());
    REQUIRE_FALSE((*it->second)["flattened"].is_null());
    usda::ComposeOptions pinned;
    pinned.root_dir = std::filesystem::weakly_canonical(fixtures_dir()).string();
    pinned.pinned_variants[c.set] = c.variant;
    Reading ours_pinned = read(usda::compose_stage(
        std::make_shared<const assetlint::SourceFile>(c.asset.string(), read_file(c.asset)), assetlint::disk(), pinned));
    usda::ComposeOptions anywhere;
    anywhere.allow_outside_root = true;
    Reading ours_wrapped = read(usda::compose_stage(
        std::make_shared<const assetlint::SourceFile>(c.wrapper.string(), read_file(c.wrapper)), assetlint::disk(), anywhere));
    const std::string text = (*it->second)["flattened"].get<std::string>();
    Reading theirs = read_flattened(c.wrapper.string(), with_kilograms_per_unit(text, ours_pinned.kilograms_per_unit));
    for (const auto& line : differences(label + " (pinned)", ours_pinned, theirs)) FAIL_CHECK(line);
    for (const auto& line : differences(label + " (wrapper layer)", ours_wrapped, theirs)) FAIL_CHECK(line);
    ++compared;
    sets.insert(c.set);
    if (!ours_pinned.result.asset.joints.empty()) ++with_joints;
  }
  INFO(compared << " variant selections compared, " << with_joints << " with joints");
  CHECK(compared >= 8);
  CHECK(with_joints >= 4);
  CHECK(sets.count("PhysX") == 1);
}

TEST_CASE("usd reference: every deliberate exception still happens", "[usd][openusd]") {
  // An exception that no longer matches anything hides nothing and should go.
  if (skip_without_openusd()) return;
  for (const Exception& e : kExceptions) {
    INFO(e.file);
    bool refused = false;
    for (const auto& stage : reference().json["stages"])
      if (stage["path"].get<std::string>().ends_with(std::string("/") + e.file)) refused = stage["flattened"].is_null();
    CHECK(refused);
  }
}
