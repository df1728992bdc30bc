// Smoke and findings test over the real files in ../shared/corpus/urdf (skipped when absent).
#include <catch2/catch.hpp>

#include <algorithm>

#include "pipeline/lint.h"
#include "test_support.h"

using namespace assetlint;

namespace {

std::vector<std::filesystem::path> corpus_files(const std::string& sub, const std::string& extension) {
  std::vector<std::filesystem::path> files;
  const auto dir = test::corpus_dir();
  if (dir.empty() || !std::filesystem::is_directory(dir / sub)) return files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir / sub))
    if (entry.is_regular_file() && entry.path().extension() == extension) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::size_t count(const FileReport& report, std::string_view rule) {
  return static_cast<std::size_t>(std::count_if(report.diagnostics.begin(), report.diagnostics.end(),
                                                [&](const Diagnostic& d) { return d.rule == rule; }));
}

const Diagnostic* find(const FileReport& report, std::string_view rule, std::string_view text) {
  for (const auto& d : report.diagnostics)
    if (d.rule == rule && d.message.find(text) != std::string::npos) return &d;
  return nullptr;
}

}  // namespace

TEST_CASE("every corpus URDF is read without a crash, with located diagnostics", "[corpus]") {
  const auto files = corpus_files("urdf", ".urdf");
  if (files.empty()) {
    WARN("../shared/corpus/urdf is absent: corpus test skipped");
    return;
  }
  CHECK(files.size() >= 50);
  for (const auto& file : files) {
    INFO(file.filename().string());
    FileReport report = lint_file(file.string(), Settings{});
    REQUIRE_FALSE(report.error.has_value());
    for (const auto& d : report.diagnostics) {
      CHECK(d.span.line >= 1);
      CHECK(d.span.column >= 1);
      CHECK_FALSE(d.message.empty());
    }
    if (file.filename().string().starts_with("malformed__")) {
      CHECK(count(report, "parse-error") >= 1);
    }
  }
}

TEST_CASE("corpus: the malformed files are located precisely", "[corpus]") {
  const auto dir = test::corpus_dir();
  if (dir.empty()) {
    WARN("../shared/corpus is absent: skipped");
    return;
  }
  FileReport prefixed = lint_file((dir / "urdf/malformed__ros2param_prefix_ur12e_picknik_robotiq85.urdf").string(), Settings{});
  const Diagnostic* prefix = find(prefixed, "parse-error", "text before the XML document: 'String value is:'");
  REQUIRE(prefix);
  CHECK(prefix->span.line == 1);
  CHECK(prefix->span.column == 1);

  FileReport nul = lint_file((dir / "urdf/malformed__pybullet_humanoid_trailing_nul.urdf").string(), Settings{});
  const Diagnostic* trailing = find(nul, "parse-error", "NUL byte after the root element");
  REQUIRE(trailing);
  CHECK(trailing->span.line == 288);
  CHECK(trailing->span.column == 1);
  // pybullet's spherical joints and capsules are not URDF: urdfdom says so, in one finding
  // whose notes carry the cascade (issue 15).
  CHECK(count(nul, "urdf-invalid") == 1);
  const Diagnostic* rejected = find(nul, "urdf-invalid", "Unknown geometry type 'capsule'");
  REQUIRE(rejected);
  CHECK(std::any_of(rejected->notes.begin(), rejected->notes.end(),
                    [](const Note& n) { return n.message == "Joint [chest] has no known type [spherical]"; }));
}

TEST_CASE("corpus: real findings on real files", "[corpus]") {
  const auto dir = test::corpus_dir();
  if (dir.empty()) {
    WARN("../shared/corpus is absent: skipped");
    return;
  }
  auto lint = [&](const char* name) { return lint_file((dir / "urdf" / name).string(), Settings{}); };

  // PHYSICS.md §4: the ros-industrial 2F-85 mimic with multiplier −1 and limits [0, 0.8757].
  FileReport ri = lint("robotiq2f85__rosindustrial_arg2f_85_model.urdf");
  const Diagnostic* conflict = find(ri, "mimic-limit-conflict", "must reach [-0.8, 0] rad to follow 'finger_joint'");
  REQUIRE(conflict);
  CHECK(conflict->message.find("outside its limits [0, 0.8757]") != std::string::npos);
  // The sign error is mirrored, as the pybullet copy of the same model has it (issue 15).
  REQUIRE(conflict->fix);
  CHECK(conflict->fix->title.find("mirror the limits") == 0);
  CHECK(conflict->fix->title.find("to [-0.8757, 0] rad") != std::string::npos);
  // The H1 thumb: the leader's [-0.1, 0.6] narrows to [0, 0.5], which both followers hold.
  const FileReport h1 = lint("humanoid__unitree_h1_with_hand.urdf");
  const Diagnostic* thumb = find(h1, "mimic-limit-conflict", "'L_thumb_intermediate_joint' must reach");
  REQUIRE(thumb);
  REQUIRE(thumb->fix);
  CHECK(thumb->fix->title == "narrow the limits of 'L_thumb_proximal_pitch_joint' to [0, 0.5] rad");

  // Placeholder limits: iCub's 50000 rad/s on 20 joints is one info (one verdict per value),
  // R2's 1e7 N·m efforts.
  FileReport icub = lint("humanoid__icub_models_iCubGenova11.urdf");
  REQUIRE(count(icub, "units-velocity-implausible") == 1);
  const Diagnostic* icub_placeholder = find(icub, "units-velocity-implausible", "50000 rad/s");
  REQUIRE(icub_placeholder);
  CHECK(icub_placeholder->severity == Severity::Info);
  CHECK(!icub_placeholder->fix);
  CHECK(find(lint("humanoid__nasa_r2c6.urdf"), "drive-max-force", "effort 1e7 N·m of revolute joint 'r2/waist/joint0' looks like a placeholder"));
  // Undefined parent links and mimic references.
  CHECK(find(lint("quadruped__spot_ros_spot_arm.urdf"), "structure-undefined-link", "parent link 'body'"));
  const FileReport alex = lint("humanoid__erd_alex_psyonic_hands.urdf");
  const Diagnostic* missing = find(alex, "structure-mimic-reference", "'Left_index_q2' mimics joint 'index_q1'");
  REQUIRE(missing);
  CHECK(missing->severity == Severity::Error);
  CHECK(std::any_of(missing->notes.begin(), missing->notes.end(),
                    [](const Note& n) { return n.message == "Did you mean 'Left_index_q1'?"; }));
  // A description without any <inertial> is one finding for the file; a moving link without one
  // in a file that has others is an error; and a non-positive-definite tensor.
  const FileReport fr3 = lint("arm__franka_description_fr3.urdf");
  CHECK(count(fr3, "inertia-invalid") == 1);
  CHECK(find(fr3, "inertia-invalid", "no link of 'fr3' has an <inertial>: a kinematic description"));
  CHECK(find(lint("humanoid__erd_romeo.urdf"), "inertia-invalid", "moves but"));
  CHECK(find(lint("arm__curobo_franka_panda.urdf"), "inertia-invalid", "has a negative principal moment"));
  // Mimic velocity limits below |multiplier| × the followed joint's limit.
  CHECK(count(lint("humanoid__unitree_h1_with_hand.urdf"), "mimic-max-velocity") == 4);
  // Issue 15 noise: EVE's 66 dead <mimic> tags on fixed joints are one info; HyQ's rank-one
  // tensors are not "negative"; TIAGo's wrist F/T frame (a point mass on a fixed joint) is silent.
  FileReport eve = lint("humanoid__halodi_eve_r3.urdf");
  REQUIRE(count(eve, "structure-mimic-reference") == 1);
  const Diagnostic* dead = find(eve, "structure-mimic-reference", "66 fixed joints carry a <mimic>");
  REQUIRE(dead);
  CHECK(dead->severity == Severity::Info);
  FileReport hyq = lint("quadruped__erd_hyq_no_sensors.urdf");
  CHECK(!find(hyq, "inertia-invalid", "negative"));
  CHECK(find(hyq, "inertia-invalid", "all six entries equal to 1e-6"));
  CHECK(!find(lint("mobile__erd_tiago_dual.urdf"), "inertia-invalid", "zero inertia tensor"));
  // An undeclared 'world' parent (only Drake accepts it) and a fragment's attachment point:
  // one finding each, not a second urdf-invalid.
  FileReport pr2 = lint("mobile__drake_pr2_simplified.urdf");
  const Diagnostic* world = find(pr2, "structure-undefined-link", "parent link 'world'");
  REQUIRE(world);
  REQUIRE(world->fix);
  CHECK(world->fix->edits.at(0).replacement.find("<link name=\"world\"/>") != std::string::npos);
  FileReport rethink = lint("gripper__rethink_electric_gripper.urdf");
  CHECK(count(rethink, "urdf-invalid") == 0);
  const Diagnostic* fragment = find(rethink, "structure-undefined-link", "parent link 'left_hand'");
  REQUIRE(fragment);
  CHECK(std::any_of(fragment->notes.begin(), fragment->notes.end(),
                    [](const Note& n) { return n.message.find("fragment meant to be included") != std::string::npos; }));
  // A clean, careful asset stays clean of unit findings.
  FileReport g1 = lint("humanoid__unitree_g1_29dof_rev_1_0.urdf");
  CHECK(count(g1, "units-velocity-implausible") == 0);
  CHECK(count(g1, "units-angle-degrees") == 0);
}
