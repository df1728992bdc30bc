// --output-format full (the source line, the span underlined) and the colour switches
// (--color, NO_COLOR, CLICOLOR_FORCE, FORCE_COLOR, TERM=dumb).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <optional>

#include "test_support.h"

using assetlint::test::report_dir;
using assetlint::test::run_cli;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace {

// Sets an environment variable for the scope (the CLI runs as a child process and inherits it).
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) ::setenv(name, value, 1);
    else ::unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_) ::setenv(name_, old_->c_str(), 1);
    else ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

}  // namespace

TEST_CASE("full: the source line under the primary line, the span underlined", "[output-full]") {
  auto r = run_cli({"--output-format", "full", "--select", "limits-inverted,mimic-max-velocity", "gripper.urdf"},
                   report_dir());
  CHECK(r.exit_code == 1);
  CHECK(r.out ==
        "gripper.urdf:9:19: error: revolute joint 'finger_joint' has lower limit 0.82 rad above upper limit 0 rad "
        "[limits-inverted] (unsafe fix)\n"
        "   |\n"
        " 9 |     <limit lower=\"0.82\" upper=\"0\" effort=\"24\" velocity=\"2.9\"/>\n"
        "   |                   ^^^^\n"
        "  note: The joint has no valid position: every pose violates one of its limits.\n"
        "  help: unsafe fix: swap lower and upper\n"
        "gripper.urdf:14:60: warning: mimic revolute joint 'inner_finger_joint' is limited below the velocity its "
        "gearing demands [mimic-max-velocity] (unsafe fix)\n"
        "    |\n"
        " 14 |     <limit lower=\"-0.82\" upper=\"0\" effort=\"1000\" velocity=\"2.0\"/>\n"
        "    |                                                            ^^^\n"
        "  note: Its own limit is 2 rad/s; it must reach 2.9 rad/s.\n"
        "  gripper.urdf:6:16: note: 'finger_joint' is limited to 2.9 rad/s; through |multiplier -1| this joint must "
        "reach 2.9 rad/s.\n"
        "  note: The velocity clamp then fights the mimic constraint; with a hard mimic the guide warns this can make "
        "the simulation unstable.\n"
        "  help: unsafe fix: raise the limit to 2.9 rad/s\n"
        "Found 2 problems (1 error, 1 warning, 0 infos) in 1 file. 0 fixable with --fix (2 more with --unsafe-fixes).\n");
}

TEST_CASE("full: a tab is shown as four spaces on both lines", "[output-full]") {
  TempDir dir;
  write_file(dir.path() / "t.urdf",
             "<robot name=\"r\">\n  <link name=\"a\"/>\n  <link name=\"b\"/>\n  <joint name=\"é\" type=\"revolute\">\n"
             "    <parent link=\"a\"/>\n    <child link=\"b\"/>\n"
             "\t<limit lower=\"1\" upper=\"0\" effort=\"1\" velocity=\"1\"/>\n  </joint>\n</robot>\n");
  auto r = run_cli({"--output-format", "full", "--select", "limits-inverted", "-q", "t.urdf"}, dir.path());
  CHECK(r.out.find(" 7 |     <limit lower=\"1\" upper=\"0\" effort=\"1\" velocity=\"1\"/>\n"
                   "   |                   ^\n") != std::string::npos);
}

TEST_CASE("colour: --color, NO_COLOR, CLICOLOR_FORCE, FORCE_COLOR and TERM=dumb", "[output-full]") {
  const std::vector<std::string> args = {"--select", "limits-inverted", "gripper.urdf"};
  auto colored = [&](std::vector<std::string> extra = {}) {
    extra.insert(extra.end(), args.begin(), args.end());
    return run_cli(extra, report_dir()).out.find('\033') != std::string::npos;
  };
  ScopedEnv no_color("NO_COLOR", nullptr), clicolor("CLICOLOR_FORCE", nullptr), force("FORCE_COLOR", nullptr);
  CHECK_FALSE(colored());  // not a terminal
  CHECK(colored({"--color", "always"}));
  {
    ScopedEnv set("FORCE_COLOR", "1");
    CHECK(colored());
    CHECK_FALSE(colored({"--color", "never"}));
    ScopedEnv off("NO_COLOR", "1");
    CHECK_FALSE(colored());
  }
  {
    ScopedEnv set("CLICOLOR_FORCE", "1");
    CHECK(colored());
  }
  {
    ScopedEnv zero("FORCE_COLOR", "0");
    CHECK_FALSE(colored());
  }
  ScopedEnv dumb("TERM", "dumb");
  CHECK_FALSE(colored());
  ScopedEnv set("CLICOLOR_FORCE", "1");
  CHECK(colored());
}
