// Findings grouped alike in every format that groups: xacro findings as URDF ones, and the
// `github` format's annotations as the text format's blocks.
#include <catch2/catch.hpp>

#include "test_support.h"

using assetlint::test::run_cli;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("grouping: github annotations are grouped as text groups them", "[report][grouping]") {
  const std::string file = "fixtures/mjcf/dampratio/gear_and_geom_inertia.xml";
  const auto text = run_cli({file, "--select", "mjcf-unsupported"});
  const auto github = run_cli({file, "--output-format", "github", "--select", "mjcf-unsupported"});
  INFO(text.out << github.out);
  REQUIRE(count(text.out, "and the same on 4 more: 'wrist_pitch' (37:99)") == 1);
  // One annotation per text block, the group's places in its message.
  CHECK(count(github.out, "::notice ") == count(text.out, "[mjcf-unsupported]"));
  CHECK(count(github.out, "%0Aand the same on 4 more: 'wrist_pitch' (37:99), 'finger' (38:68)") == 1);
}

TEST_CASE("grouping: xacro findings made by one macro group as URDF findings do", "[report][grouping][xacro]") {
  const auto corpus = assetlint::test::corpus_dir();
  const auto top = corpus / "packages" / "ros-industrial-robotiq" / "robotiq_2f_85_gripper_visualization" / "urdf" /
                   "robotiq_arg2f_85_model.xacro";
  if (corpus.empty() || !std::filesystem::exists(top)) {
    WARN("../shared/corpus is absent: the xacro package is skipped");
    return;
  }
  const auto text = run_cli({top.string(), "--select", "inertia-invalid,mimic-limit-conflict"});
  INFO(text.out);
  // Six links without <inertial> in three macros, each macro called for both fingers: one block.
  CHECK(count(text.out, "[inertia-invalid]") == 1);
  CHECK(count(text.out, "and the same on 5 more: 'right_outer_knuckle' (6:17)") == 1);
  // The mirrored-limit conflict of both inner fingers: one literal, one fix, one block.
  CHECK(count(text.out, "[mimic-limit-conflict]") == 1);
  const auto github = run_cli({top.string(), "--select", "inertia-invalid,mimic-limit-conflict", "--output-format", "github"});
  CHECK(count(github.out, "::error ") == 2);
}
