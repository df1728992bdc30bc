// Rule selection: the more specific selector wins (ruff's rule), extend-select and
// extend-ignore add to the lists, extend-per-file-ignores adds entries.
#include <catch2/catch.hpp>

#include "engine/settings.h"
#include "test_support.h"

using assetlint::RuleSelection;
using assetlint::test::read_file;
using assetlint::test::report_dir;
using assetlint::test::run_cli;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace {

bool runs(std::vector<std::string> select, std::vector<std::string> ignore, const char* rule) {
  RuleSelection selection;
  selection.select = std::move(select);
  selection.ignore = std::move(ignore);
  return selection.enabled(rule);
}

}  // namespace

TEST_CASE("selection: the more specific selector wins, ignore wins a tie", "[selection]") {
  CHECK(runs({"mimic-max-velocity"}, {"mimic-*"}, "mimic-max-velocity"));
  CHECK_FALSE(runs({"mimic-max-velocity"}, {"mimic-*"}, "mimic-limit-conflict"));
  CHECK_FALSE(runs({"mimic-*"}, {"mimic-max-velocity"}, "mimic-max-velocity"));
  CHECK(runs({"mimic-*"}, {"mimic-max-velocity"}, "mimic-limit-conflict"));
  CHECK_FALSE(runs({"mimic-*"}, {"mimic-max-*"}, "mimic-max-velocity"));
  CHECK(runs({"mimic-max-*"}, {"mimic-*"}, "mimic-max-velocity"));
  CHECK_FALSE(runs({"mimic-*"}, {"mimic-*"}, "mimic-max-velocity"));
  CHECK_FALSE(runs({"mimic-max-velocity"}, {"mimic-max-velocity"}, "mimic-max-velocity"));
  CHECK_FALSE(runs({}, {"*-velocity"}, "mimic-max-velocity"));
  CHECK(runs({"*", "mimic-max-velocity"}, {"mimic-*"}, "mimic-max-velocity"));
  CHECK_FALSE(runs({"*", "mimic-max-velocity"}, {"mimic-*"}, "mimic-limit-conflict"));
  CHECK(runs({}, {}, "limits-inverted"));
}

TEST_CASE("selection: --select of an id beats --ignore of its glob on the command line", "[selection]") {
  auto r = run_cli({"--select", "mimic-max-velocity", "--ignore", "mimic-*", "--output-format", "concise",
                    "gripper.urdf"},
                   report_dir());
  CHECK(r.exit_code == 1);
  CHECK(r.out ==
        "gripper.urdf:14:60: mimic-max-velocity mimic revolute joint 'inner_finger_joint' is limited below the velocity "
        "its gearing demands\n");
}

TEST_CASE("selection: --extend-select and --extend-ignore add to the lists in effect", "[selection]") {
  auto more = run_cli({"--select", "limits-inverted", "--extend-select", "mimic-max-velocity", "--output-format",
                       "concise", "gripper.urdf"},
                      report_dir());
  CHECK(more.out ==
        "gripper.urdf:9:19: limits-inverted revolute joint 'finger_joint' has lower limit 0.82 rad above upper limit "
        "0 rad\n"
        "gripper.urdf:14:60: mimic-max-velocity mimic revolute joint 'inner_finger_joint' is limited below the "
        "velocity its gearing demands\n");
  auto fewer = run_cli({"--select", "limits-*,mimic-max-velocity", "--extend-ignore", "limits-inverted",
                        "--output-format", "concise", "gripper.urdf"},
                       report_dir());
  CHECK(fewer.out ==
        "gripper.urdf:14:60: mimic-max-velocity mimic revolute joint 'inner_finger_joint' is limited below the "
        "velocity its gearing demands\n");
  auto typo = run_cli({"--extend-select", "mimick-*", "gripper.urdf"}, report_dir());
  CHECK(typo.exit_code == 2);
  CHECK(typo.err == "asset-lint: error: --extend-select 'mimick-*' matches no rule; `asset-lint --list-rules` lists them\n");
}

TEST_CASE("selection: extend-select, extend-ignore and extend-per-file-ignores in asset-lint.toml", "[selection]") {
  TempDir dir;
  write_file(dir.path() / "gripper.urdf", read_file(report_dir() / "gripper.urdf"));
  write_file(dir.path() / "asset-lint.toml",
             "extend-ignore = [\"units-*\"]\n"
             "select = [\"limits-inverted\"]\n"
             "extend-select = [\"mimic-*\"]\n"
             "[per-file-ignores]\n\"other.urdf\" = [\"limits-inverted\"]\n"
             "[extend-per-file-ignores]\n\"grip*.urdf\" = [\"mimic-limit-conflict\"]\n");
  auto r = run_cli({"--output-format", "concise", "gripper.urdf"}, dir.path());
  CHECK(r.exit_code == 1);
  CHECK(r.out ==
        "gripper.urdf:9:19: limits-inverted revolute joint 'finger_joint' has lower limit 0.82 rad above upper limit "
        "0 rad\n"
        "gripper.urdf:14:60: mimic-max-velocity mimic revolute joint 'inner_finger_joint' is limited below the "
        "velocity its gearing demands\n");
}
