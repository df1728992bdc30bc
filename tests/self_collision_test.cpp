// self-collision through the command line, where the checked file has a directory of its own:
// an SRDF beside it silences the pairs it disables, and meshes are read from the package (an
// STL box written here) and collide as MuJoCo's hulls.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>

#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::run_cli;
using assetlint::test::source_dir;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace {

const std::string kFixture = "fixtures/rules/self-collision/arm_forearm_in_base.urdf";

// A binary STL of an axis-aligned box of half sizes (x, y, z) centred at the origin.
void write_box_stl(const std::filesystem::path& path, float x, float y, float z) {
  const float c[8][3] = {{-x, -y, -z}, {x, -y, -z}, {x, y, -z}, {-x, y, -z},
                         {-x, -y, z},  {x, -y, z},  {x, y, z},  {-x, y, z}};
  const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                            {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::string bytes(80, '\0');
  const std::uint32_t count = 12;
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& f : faces) {
    const float normal[3] = {0, 0, 0};
    bytes.append(reinterpret_cast<const char*>(normal), 12);
    for (int v : f) bytes.append(reinterpret_cast<const char*>(c[v]), 12);
    bytes.append(2, '\0');
  }
  std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace

TEST_CASE("self-collision: an SRDF beside the URDF silences the pairs it disables", "[self-collision]") {
  TempDir dir;
  write_file(dir.path() / "arm.urdf", read_file(source_dir() / kFixture));
  auto before = run_cli({"--fail-on", "info", "--select", "self-collision", "arm.urdf"}, dir.path());
  CHECK(before.exit_code == 1);
  CHECK(before.out.find("links 'base_link' and 'forearm' overlap by 5 mm at the default pose") != std::string::npos);

  // MoveIt's setup assistant writes the pair in either order.
  write_file(dir.path() / "arm.srdf", R"(<?xml version="1.0"?>
<robot name="arm">
  <disable_collisions link1="forearm" link2="base_link" reason="Never"/>
</robot>
)");
  auto after = run_cli({"--fail-on", "info", "--select", "self-collision", "arm.urdf"}, dir.path());
  CHECK(after.exit_code == 0);
  CHECK(after.out == "No problems found in 1 file.\n");

  // An SRDF of another robot is not read for this one.
  write_file(dir.path() / "arm.srdf", R"(<robot name="other"><disable_collisions link1="forearm" link2="base_link" reason="Never"/></robot>)");
  write_file(dir.path() / "other.srdf", R"(<robot name="third"/>)");
  CHECK(run_cli({"--fail-on", "info", "--select", "self-collision", "arm.urdf"}, dir.path()).exit_code == 1);
}

TEST_CASE("self-collision: mesh colliders collide as MuJoCo's hulls, with their scale", "[self-collision]") {
  TempDir dir;
  write_box_stl(dir.path() / "block.stl", 150, 25, 25);  // written in millimetres: scale 0.001
  std::string urdf = read_file(source_dir() / kFixture);
  // The forearm's 0.3 × 0.05 × 0.05 m box becomes the same box as a mesh in millimetres.
  const std::string box = R"(<geometry><box size="0.3 0.05 0.05"/></geometry>)";
  const auto at = urdf.find(box);
  REQUIRE(at != std::string::npos);
  urdf.replace(at, box.size(), R"(<geometry><mesh filename="block.stl" scale="0.001 0.001 0.001"/></geometry>)");
  write_file(dir.path() / "arm.urdf", urdf);
  auto run = run_cli({"--fail-on", "info", "--select", "self-collision", "arm.urdf"}, dir.path());
  INFO(run.out << run.err);
  // Unscaled, the mesh would be 1000 times the box and reach everywhere; scaled, it is the box again.
  CHECK(run.out.find("links 'base_link' and 'forearm' overlap by 5 mm at the default pose") != std::string::npos);
  CHECK(run.out.find("mesh 'block.stl'") != std::string::npos);

  // A mesh that cannot be found leaves its link out, and the check still runs on the rest.
  urdf.replace(urdf.find("block.stl"), 9, "missing.stl");
  write_file(dir.path() / "arm.urdf", urdf);
  CHECK(run_cli({"--fail-on", "info", "--select", "self-collision", "arm.urdf"}, dir.path()).exit_code == 0);
}

TEST_CASE("self-collision: MuJoCo's flags decide the MJCF pairs", "[self-collision]") {
  TempDir dir;
  const std::string model = read_file(source_dir() / "fixtures/rules/self-collision/arm_free_base_control.xml");
  write_file(dir.path() / "arm.xml", model);
  CHECK(run_cli({"--fail-on", "info", "--select", "self-collision", "arm.xml"}, dir.path()).exit_code == 0);

  // The base moves (freejoint), so only the parent filter keeps the shoulder's 1 cm out.
  const auto with_option = [&](const std::string& option) {
    std::string text = model;
    text.replace(text.find("  <worldbody>"), 0, option + "\n");
    write_file(dir.path() / "arm.xml", text);
    return run_cli({"--fail-on", "info", "--select", "self-collision", "arm.xml"}, dir.path());
  };
  auto unfiltered = with_option(R"(  <option><flag filterparent="disable"/></option>)");
  INFO(unfiltered.out);
  CHECK(unfiltered.exit_code == 1);
  CHECK(unfiltered.out.find("links 'base_link' and 'shoulder' overlap by 10 mm at the default pose") != std::string::npos);
  CHECK(unfiltered.out.find("turns MuJoCo's parent filter off") != std::string::npos);

  CHECK(with_option(R"(  <option><flag filterparent="disable" contact="disable"/></option>)").exit_code == 0);
}
