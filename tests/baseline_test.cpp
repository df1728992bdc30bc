// --write-baseline / --baseline: keys that survive unrelated edits, stale entries named,
// the same keys from any working directory.
#include <catch2/catch.hpp>

#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::report_dir;
using assetlint::test::replace_once;
using assetlint::test::run_cli;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace {

const std::string kSelect = "limits-inverted,mimic-max-velocity,stale-schema-attribute";

const char* kBaseline = R"({
  "asset-lint-baseline": 1,
  "findings": [
    {
      "path": "gripper.urdf",
      "element": "joint 'finger_joint'",
      "attribute": "limit.lower",
      "rule": "limits-inverted",
      "count": 1
    },
    {
      "path": "gripper.urdf",
      "element": "joint 'inner_finger_joint'",
      "attribute": "limit.velocity",
      "rule": "mimic-max-velocity",
      "count": 1
    },
    {
      "path": "joints.usda",
      "element": "/gripper/driven",
      "attribute": "physxJoint:jointFriction",
      "rule": "stale-schema-attribute",
      "count": 1
    },
    {
      "path": "joints.usda",
      "element": "/gripper/follower",
      "attribute": "drive:angular:physics:damping",
      "rule": "stale-schema-attribute",
      "count": 1
    }
  ]
}
)";

void copy_assets(const std::filesystem::path& dir) {
  write_file(dir / "gripper.urdf", read_file(report_dir() / "gripper.urdf"));
  write_file(dir / "joints.usda", read_file(report_dir() / "joints.usda"));
}

}  // namespace

TEST_CASE("baseline: --write-baseline records rule, path, element and attribute", "[baseline]") {
  TempDir dir;
  copy_assets(dir.path());
  auto r = run_cli({"--select", kSelect, "--write-baseline", "asset-lint-baseline.json"}, dir.path());
  CHECK(r.exit_code == 0);
  CHECK(r.out.empty());
  CHECK(r.err == "asset-lint: wrote 4 findings (4 entries) to baseline 'asset-lint-baseline.json'\n");
  CHECK(read_file(dir.path() / "asset-lint-baseline.json") == kBaseline);

  auto clean = run_cli({"--select", kSelect, "--baseline", "asset-lint-baseline.json"}, dir.path());
  CHECK(clean.exit_code == 0);
  CHECK(clean.out == "No problems found in 2 files.\n");
  CHECK(clean.err == "asset-lint: 4 findings recorded in baseline 'asset-lint-baseline.json' not reported\n");
}

TEST_CASE("baseline: unrelated edits keep the keys (URDF and USDA), new findings are reported, stale entries named",
          "[baseline]") {
  TempDir dir;
  copy_assets(dir.path());
  write_file(dir.path() / "asset-lint-baseline.json", kBaseline);
  // Lines added above every finding, finger_joint's limits repaired, a new inverted joint.
  std::string urdf = read_file(dir.path() / "gripper.urdf");
  urdf = replace_once(urdf, "<robot name=\"gripper\">\n", "<robot name=\"gripper\">\n  <!-- moved down -->\n  <link name=\"thumb\"/>\n");
  urdf = replace_once(urdf, "lower=\"0.82\" upper=\"0\"", "lower=\"0\" upper=\"0.82\"");
  urdf = replace_once(urdf, "</robot>",
                  "  <joint name=\"thumb_joint\" type=\"revolute\">\n    <parent link=\"base_link\"/>\n"
                  "    <child link=\"thumb\"/>\n    <limit lower=\"1\" upper=\"0\" effort=\"1\" velocity=\"1\"/>\n"
                  "  </joint>\n</robot>");
  write_file(dir.path() / "gripper.urdf", urdf);
  // A new prim above the recorded ones, and a recorded attribute moved up its prim.
  std::string usda = read_file(dir.path() / "joints.usda");
  usda = replace_once(usda, "    def PhysicsRevoluteJoint \"driven\"", "    def Xform \"extra\"\n    {\n    }\n\n"
                                                                      "    def PhysicsRevoluteJoint \"driven\"");
  usda = replace_once(usda, "        float physxJoint:jointFriction = 0.05\n", "");
  usda = replace_once(usda, "        float physics:lowerLimit = 0\n",
                      "        float physxJoint:jointFriction = 0.05\n        float physics:lowerLimit = 0\n");
  write_file(dir.path() / "joints.usda", usda);
  auto r = run_cli({"--select", kSelect, "--output-format", "concise", "--baseline", "asset-lint-baseline.json"},
                   dir.path());
  CHECK(r.exit_code == 1);
  CHECK(r.out ==
        "gripper.urdf:22:19: limits-inverted revolute joint 'thumb_joint' has lower limit 1 rad above upper limit 0 rad\n");
  CHECK(r.err ==
        "asset-lint: 3 findings recorded in baseline 'asset-lint-baseline.json' not reported\n"
        "asset-lint: warning: 1 baseline entry no longer occurs (`--write-baseline asset-lint-baseline.json` drops it):\n"
        "  gripper.urdf: joint 'finger_joint' limit.lower [limits-inverted]\n");
}

TEST_CASE("baseline: keys do not depend on the working directory, unchecked files are not stale", "[baseline]") {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "assets");
  copy_assets(dir.path() / "assets");
  write_file(dir.path() / "assets" / "asset-lint-baseline.json", kBaseline);
  auto from_parent = run_cli({"--select", kSelect, "--baseline", "assets/asset-lint-baseline.json", "assets"}, dir.path());
  CHECK(from_parent.exit_code == 0);
  CHECK(from_parent.err == "asset-lint: 4 findings recorded in baseline 'assets/asset-lint-baseline.json' not reported\n");
  // Only gripper.urdf is checked: the entries of joints.usda are not stale.
  auto one_file = run_cli({"--select", kSelect, "--baseline", "asset-lint-baseline.json", "gripper.urdf"},
                          dir.path() / "assets");
  CHECK(one_file.exit_code == 0);
  CHECK(one_file.err == "asset-lint: 2 findings recorded in baseline 'asset-lint-baseline.json' not reported\n");
}

TEST_CASE("baseline: unreadable or malformed baselines and misuse are errors", "[baseline]") {
  TempDir dir;
  copy_assets(dir.path());
  auto missing = run_cli({"--baseline", "nope.json", "gripper.urdf"}, dir.path());
  CHECK(missing.exit_code == 2);
  CHECK(missing.err == "asset-lint: error: cannot read baseline 'nope.json'\n");
  write_file(dir.path() / "bad.json", "{\"findings\": []}");
  auto bad = run_cli({"--baseline", "bad.json", "gripper.urdf"}, dir.path());
  CHECK(bad.exit_code == 2);
  CHECK(bad.err ==
        "asset-lint: error: 'bad.json' is not an asset-lint baseline: expected {\"asset-lint-baseline\": 1, "
        "\"findings\": [...]}\n");
  write_file(dir.path() / "entry.json", "{\"asset-lint-baseline\": 1, \"findings\": [{\"path\": \"a\"}]}");
  auto entry = run_cli({"--baseline", "entry.json", "gripper.urdf"}, dir.path());
  CHECK(entry.err ==
        "asset-lint: error: 'entry.json' is not an asset-lint baseline: entry 1 needs path, element, attribute, rule "
        "(strings) and count\n");
  auto with_fix = run_cli({"--fix", "--baseline", "bad.json", "gripper.urdf"}, dir.path());
  CHECK(with_fix.exit_code == 2);
  CHECK(with_fix.err ==
        "asset-lint: error: --baseline and --write-baseline work on a check of files, not with --fix, --diff or "
        "standard input\n");
}
