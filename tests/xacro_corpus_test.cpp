// Real xacro packages from ../shared/corpus/packages (skipped when absent): each expands to the
// same robot as the URDF ROS's xacro generated from it, and findings land on .xacro lines.
#include <catch2/catch.hpp>

#include <filesystem>

#include "engine/file_system.h"
#include "formats/urdf/urdf_reader.h"
#include "formats/xacro/xacro_reader.h"
#include "pipeline/lint.h"
#include "test_support.h"

using namespace assetlint;
namespace fs = std::filesystem;

namespace {

bool close(double a, double b) { return std::abs(a - b) <= 1e-12 + 1e-9 * std::max(std::abs(a), std::abs(b)); }

void same_quantity(const OptQuantity& a, const OptQuantity& b, const std::string& what) {
  INFO(what);
  REQUIRE(a.has_value() == b.has_value());
  if (a) CHECK(close(a->value, b->value));
}

// Links, joints, origins, limits, mimics and inertials equal, through the model.
void same_robot(const Asset& expanded, const Asset& generated) {
  REQUIRE(expanded.links.size() == generated.links.size());
  REQUIRE(expanded.joints.size() == generated.joints.size());
  for (const Link& g : generated.links) {
    INFO("link " << g.name.text);
    const Link* e = expanded.find_link(g.name.text);
    REQUIRE(e);
    REQUIRE(e->inertial.has_value() == g.inertial.has_value());
    if (!g.inertial) continue;
    CHECK(close(e->inertial->mass.value, g.inertial->mass.value));
    CHECK(e->inertial->com.isApprox(g.inertial->com, 1e-12));
    CHECK((e->inertial->inertia - g.inertial->inertia).cwiseAbs().maxCoeff() <= 1e-15);
  }
  for (const Joint& g : generated.joints) {
    INFO("joint " << g.name.text);
    const Joint* e = expanded.find_joint(g.name.text);
    REQUIRE(e);
    CHECK(e->type == g.type);
    CHECK(e->parent.text == g.parent.text);
    CHECK(e->child.text == g.child.text);
    CHECK(e->frame_in_link[0].matrix().isApprox(g.frame_in_link[0].matrix(), 1e-12));
    CHECK(e->axis.isApprox(g.axis, 1e-12));
    same_quantity(e->lower, g.lower, "lower");
    same_quantity(e->upper, g.upper, "upper");
    same_quantity(e->effort, g.effort, "effort");
    same_quantity(e->velocity, g.velocity, "velocity");
    REQUIRE(e->is_mimic() == g.is_mimic());
    if (g.is_mimic()) {
      CHECK(e->mimic->reference.text == g.mimic->reference.text);
      CHECK(close(e->mimic->multiplier.value, g.mimic->multiplier.value));
      CHECK(close(e->mimic->offset.value, g.mimic->offset.value));
    }
  }
}

void check_package(const fs::path& top, const fs::path& generated) {
  INFO(top.string());
  const auto file = std::make_shared<const SourceFile>(top.string(), test::read_file(top));
  const ReadResult expanded = xacro::read_xacro(file, disk(), xacro::XacroOptions{{}, top.parent_path().string(), Deadline{}});
  for (const auto& d : expanded.diagnostics) INFO(d.message);
  REQUIRE(expanded.usable);
  const ReadResult reference = urdf::read_urdf(std::make_shared<const SourceFile>(generated.string(), test::read_file(generated)));
  REQUIRE(reference.usable);
  same_robot(expanded.asset, reference.asset);

  // Every finding is reported on a .xacro line of the package, with the macro chain.
  const FileReport report = lint_file(top.string(), Settings{});
  REQUIRE_FALSE(report.error);
  CHECK_FALSE(report.diagnostics.empty());
  for (const Diagnostic& d : report.diagnostics) {
    INFO(d.rule << ": " << d.message);
    REQUIRE(d.span.file < report.sources.size());
    CHECK(report.source(d.span.file).path().ends_with(".xacro"));
    CHECK(d.span.line > 0);
    CHECK(d.span.end() <= report.source(d.span.file).text().size());
  }
}

}  // namespace

TEST_CASE("xacro corpus: the ros-industrial Robotiq 2F-85 and 2F-140 expand to their generated URDFs", "[xacro][corpus]") {
  const fs::path corpus = test::corpus_dir();
  const fs::path package = corpus / "packages" / "ros-industrial-robotiq";
  if (corpus.empty() || !fs::is_directory(package)) {
    WARN("../shared/corpus/packages/ros-industrial-robotiq is absent: xacro corpus test skipped");
    return;
  }
  check_package(package / "robotiq_2f_85_gripper_visualization" / "urdf" / "robotiq_arg2f_85_model.xacro",
                corpus / "urdf" / "robotiq2f85__rosindustrial_arg2f_85_model.urdf");
  const fs::path the_140 = package / "robotiq_2f_140_gripper_visualization" / "urdf" / "robotiq_arg2f_140_model.xacro";
  if (fs::exists(the_140)) check_package(the_140, corpus / "urdf" / "robotiq2f140__rosindustrial_arg2f_140_model.urdf");
}

TEST_CASE("xacro corpus: a finding on the 2F-85 names the literal and walks the macro calls", "[xacro][corpus]") {
  const fs::path corpus = test::corpus_dir();
  const fs::path top = corpus / "packages" / "ros-industrial-robotiq" / "robotiq_2f_85_gripper_visualization" / "urdf" /
                       "robotiq_arg2f_85_model.xacro";
  if (corpus.empty() || !fs::exists(top)) {
    WARN("the ros-industrial Robotiq package is absent: skipped");
    return;
  }
  const FileReport report = lint_file(top.string(), Settings{});
  // Every finding on a mimic joint of the right finger walks right_outer_knuckle_joint → finger_joints → …
  bool walked = false;
  for (const Diagnostic& d : report.diagnostics) {
    for (const Note& n : d.notes)
      walked = walked || (n.message.starts_with("in macro 'robotiq_arg2f_85' called at robotiq_arg2f_85_model.xacro:4:3") &&
                          n.span.line == 4 && n.span.column == 3);
  }
  CHECK(walked);
}
