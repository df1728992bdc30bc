// Every read confined to the checked tree: a reference in a checked file (a xacro include,
// load_yaml, $(find), an MJCF include, a USD layer, a symbolic link) never makes asset-lint read
// a file outside it, so no report shows a byte of such a file; --allow-outside-root opts out.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "engine/file_system.h"
#include "engine/read_policy.h"
#include "test_support.h"

using namespace assetlint;
namespace fs = std::filesystem;

namespace {

// The bytes of the planted file outside the tree; no report may contain them.
constexpr const char* kSecret = "PLANTED_SECRET_7d41";

const std::vector<std::string> kFormats = {"text", "full", "concise", "json", "sarif", "github", "gitlab", "junit"};

// tmp/outside/{secret.txt (a passwd line whose first field is the secret),secret.yaml} and tmp/repo (a git work tree) holding one file per route.
struct Checkout {
  test::TempDir dir;
  fs::path repo = dir.path() / "repo";
  fs::path outside = dir.path() / "outside";

  Checkout() {
    fs::create_directories(repo / ".git");
    fs::create_directories(repo / "pkg");
    fs::create_directories(outside);
    test::write_file(outside / "secret.txt", std::string(kSecret) + ":x:0:0:root:/root:/bin/bash\n");
    test::write_file(outside / "secret.yaml", std::string("name: ") + kSecret + "\n");
    test::write_file(repo / "pkg" / "package.xml", "<package format=\"3\"><name>pkg</name></package>\n");
  }

  std::string secret_path() const { return (outside / "secret.txt").string(); }
};

std::string xacro_robot(const std::string& body) {
  return "<?xml version=\"1.0\"?>\n<robot name=\"r\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n" + body +
         "\n</robot>\n";
}

// A joint that moves a link named by `name`, without <inertial>: a finding quotes the name.
std::string moving_link(const std::string& name) {
  return "<link name=\"base\"><inertial><mass value=\"1\"/><inertia ixx=\"0.01\" iyy=\"0.01\" izz=\"0.01\" ixy=\"0\" "
         "ixz=\"0\" iyz=\"0\"/></inertial></link>\n<link name=\"" + name +
         "\"/>\n<joint name=\"j\" type=\"revolute\"><parent link=\"base\"/><child link=\"" + name +
         "\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>";
}

// Checks `file` (relative to the checkout's repo) in every report format: the secret is in no
// output, and `refused` (the refusal's words) is in each. With --allow-outside-root the refusal
// is gone, so each route is one the policy really closes.
void holds_for_every_format(const Checkout& c, const std::string& file, const std::string& refused = "outside the checked tree") {
  for (const std::string& format : kFormats) {
    CAPTURE(file, format);
    const auto r = test::run_cli({"--output-format", format, "--exit-zero", file}, c.repo);
    CHECK(r.out.find(kSecret) == std::string::npos);
    CHECK(r.err.find(kSecret) == std::string::npos);
    CHECK((r.out + r.err).find(refused) != std::string::npos);
  }
  // Opted in, the reference is followed: the refusal is gone (what the file then says depends on
  // the route: a passwd line included as xacro is described as "not XML", never quoted).
  const auto opened = test::run_cli({"--allow-outside-root", "--exit-zero", file}, c.repo);
  CAPTURE(file, opened.out, opened.err);
  CHECK((opened.out + opened.err).find(refused) == std::string::npos);
}

}  // namespace

TEST_CASE("read policy: only files whose real path is inside a root are read", "[read-policy]") {
  test::TempDir dir;
  const fs::path tree = dir.path() / "tree";
  fs::create_directories(tree / "sub");
  fs::create_directories(dir.path() / "elsewhere");
  test::write_file(tree / "sub" / "a.urdf", "a");
  test::write_file(dir.path() / "elsewhere" / "b.urdf", "b");
  fs::create_symlink(dir.path() / "elsewhere" / "b.urdf", tree / "link_out.urdf");
  fs::create_symlink(tree / "sub" / "a.urdf", dir.path() / "elsewhere" / "link_in.urdf");

  const ReadPolicy policy = ReadPolicy::confined_to({tree.string()});
  CHECK_FALSE(policy.refusal((tree / "sub" / "a.urdf").string()));
  CHECK_FALSE(policy.refusal((tree / "sub" / "missing.urdf").string()));  // the reader says "No such file"
  CHECK(policy.refusal((tree / "sub" / ".." / ".." / "elsewhere" / "b.urdf").string()));
  CHECK(policy.refusal("/etc/passwd"));
  // A link inside the tree to a file outside is outside; the reverse is inside.
  const auto through_link = policy.refusal((tree / "link_out.urdf").string());
  REQUIRE(through_link);
  CHECK(through_link->find("its real path is") != std::string::npos);
  CHECK_FALSE(policy.refusal((dir.path() / "elsewhere" / "link_in.urdf").string()));
  CHECK_FALSE(ReadPolicy::unconfined().refusal("/etc/passwd"));

  // A tree named through a symbolic link holds what its target holds.
  fs::create_symlink(tree, dir.path() / "tree_link");
  const ReadPolicy through = ReadPolicy::confined_to({(dir.path() / "tree_link").string()});
  CHECK_FALSE(through.refusal((dir.path() / "tree_link" / "sub" / "a.urdf").string()));
  CHECK_FALSE(through.refusal((tree / "sub" / "a.urdf").string()));
}

TEST_CASE("read policy: a refused read fails as a missing file would, with the reason", "[read-policy]") {
  test::TempDir dir;
  test::write_file(dir.path() / "in.txt", "inside");
  const ConfinedFileSystem files(disk(), ReadPolicy::confined_to({dir.path().string()}));
  std::string error;
  CHECK(files.read((dir.path() / "in.txt").string(), error) == std::optional<std::string>("inside"));
  CHECK_FALSE(files.read("/etc/hostname", error));
  CHECK(error.find("outside the checked tree '" + fs::weakly_canonical(dir.path()).string() + "'") != std::string::npos);
  CHECK(error.find("--allow-outside-root") != std::string::npos);
}

TEST_CASE("read policy: a xacro include of a file outside the tree is refused in every report", "[read-policy]") {
  Checkout c;
  test::write_file(c.repo / "abs.urdf.xacro", xacro_robot("<xacro:include filename=\"" + c.secret_path() + "\"/>"));
  holds_for_every_format(c, "abs.urdf.xacro");
}

TEST_CASE("read policy: $(find pkg)/.. climbing out of the tree is refused", "[read-policy]") {
  Checkout c;
  test::write_file(c.repo / "pkg" / "find.urdf.xacro",
                   xacro_robot("<xacro:include filename=\"$(find pkg)/../../outside/secret.txt\"/>"));
  holds_for_every_format(c, "pkg/find.urdf.xacro");
}

TEST_CASE("read policy: xacro.load_yaml of a file outside the tree is refused", "[read-policy]") {
  Checkout c;
  const std::string yaml = (c.outside / "secret.yaml").string();
  test::write_file(c.repo / "yaml.urdf.xacro",
                   xacro_robot("<xacro:property name=\"y\" value=\"${xacro.load_yaml('" + yaml + "')}\"/>\n" +
                               moving_link("${y['name']}")));
  holds_for_every_format(c, "yaml.urdf.xacro");
}

TEST_CASE("read policy: a symbolic link out of the tree is not followed, named or walked", "[read-policy]") {
  Checkout c;
  fs::create_symlink(c.outside / "secret.txt", c.repo / "evil.urdf");
  holds_for_every_format(c, "evil.urdf");
  // The directory walk lists the link and the read refuses it.
  const auto walked = test::run_cli({"--output-format", "json", "--exit-zero", "."}, c.repo);
  CHECK(walked.out.find(kSecret) == std::string::npos);
  CHECK(walked.out.find("evil.urdf") != std::string::npos);
  CHECK(walked.out.find("outside the checked tree") != std::string::npos);
}

TEST_CASE("read policy: an MJCF include through a link out of the tree is refused", "[read-policy]") {
  Checkout c;
  fs::create_symlink(c.outside / "secret.txt", c.repo / "parts.xml");
  test::write_file(c.repo / "model.xml", "<mujoco model=\"m\">\n  <include file=\"parts.xml\"/>\n</mujoco>\n");
  holds_for_every_format(c, "model.xml");
}

TEST_CASE("read policy: expand refuses the same references", "[read-policy]") {
  Checkout c;
  test::write_file(c.repo / "abs.urdf.xacro", xacro_robot("<xacro:include filename=\"" + c.secret_path() + "\"/>"));
  const auto r = test::run_cli({"expand", "abs.urdf.xacro"}, c.repo);
  CHECK(r.exit_code != 0);
  CHECK((r.out + r.err).find(kSecret) == std::string::npos);
  CHECK(r.err.find("outside the checked tree") != std::string::npos);
  const auto opened = test::run_cli({"expand", "--allow-outside-root", "abs.urdf.xacro"}, c.repo);
  CHECK(opened.err.find("outside the checked tree") == std::string::npos);
  CHECK(opened.err.find("not XML: the file holds text and no element") != std::string::npos);
}

TEST_CASE("read policy: --package-path names a workspace whose packages are found and read", "[read-policy]") {
  Checkout c;
  const fs::path workspace = c.dir.path() / "workspace";
  fs::create_directories(workspace / "arm_description");
  test::write_file(workspace / "arm_description" / "package.xml",
                   "<package format=\"3\"><name>arm_description</name></package>\n");
  test::write_file(workspace / "arm_description" / "arm.xacro",
                   xacro_robot("<xacro:macro name=\"arm\">" + moving_link("forearm") + "</xacro:macro>"));
  test::write_file(c.repo / "pkg" / "robot.urdf.xacro",
                   xacro_robot("<xacro:include filename=\"$(find arm_description)/arm.xacro\"/>\n<xacro:arm/>"));
  for (const std::string command : {"check", "expand"}) {
    CAPTURE(command);
    std::vector<std::string> args;
    if (command == "expand") args.push_back("expand");
    args.push_back("pkg/robot.urdf.xacro");
    const auto unnamed = test::run_cli(args, c.repo);
    CHECK((unnamed.out + unnamed.err).find("arm_description") != std::string::npos);
    CHECK((unnamed.out + unnamed.err).find("forearm") == std::string::npos);
    args.insert(args.end(), {"--package-path", workspace.string(), "--exit-zero"});
    if (command == "expand") args.pop_back();
    const auto named = test::run_cli(args, c.repo);
    CAPTURE(named.out, named.err);
    CHECK(named.exit_code == 0);
    // The macro from the workspace was expanded: its link is in the model (a finding or the URDF names it).
    CHECK((named.out + named.err).find("forearm") != std::string::npos);
  }
}
