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
  // pybullet's spherical joints and capsules are not URDF: urdfdom says so.
  CHECK(find(nul, "urdf-invalid", "Joint [chest] has no known type [spherical]"));
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
  const Diagnostic* conflict = find(ri, "mimic-limit-conflict", "maps through the mimic (multiplier -1, offset 0) to [-0.8, 0]");
  REQUIRE(conflict);
  CHECK(conflict->message.find("outside the limits [0, 0.8757]") != std::string::npos);

  // Placeholder limits: iCub's 50000 rad/s, R2's 1e7 N·m efforts.
  CHECK(count(lint("humanoid__icub_models_iCubGenova11.urdf"), "units-velocity-implausible") >= 10);
  CHECK(find(lint("humanoid__nasa_r2c6.urdf"), "drive-max-force", "effort limit 1e7 N·m, a placeholder"));
  // Undefined parent links and mimic references.
  CHECK(find(lint("quadruped__spot_ros_spot_arm.urdf"), "structure-undefined-link", "parent link 'body'"));
  CHECK(find(lint("humanoid__erd_alex_psyonic_hands.urdf"), "structure-mimic-reference", "which is not defined"));
  // Missing inertials on moving links and a non-positive-definite tensor.
  CHECK(find(lint("arm__franka_description_fr3.urdf"), "inertia-invalid", "has no <inertial>"));
  CHECK(find(lint("arm__curobo_franka_panda.urdf"), "inertia-invalid", "not positive definite"));
  // Mimic velocity limits below |multiplier| × the followed joint's limit.
  CHECK(count(lint("humanoid__unitree_h1_with_hand.urdf"), "mimic-max-velocity") == 4);
  // A clean, careful asset stays clean of unit findings.
  FileReport g1 = lint("humanoid__unitree_g1_29dof_rev_1_0.urdf");
  CHECK(count(g1, "units-velocity-implausible") == 0);
  CHECK(count(g1, "units-angle-degrees") == 0);
}
