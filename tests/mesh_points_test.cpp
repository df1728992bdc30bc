// Collision mesh files for `verify`: binary and ASCII STL, OBJ, Collada through assimp, and
// package:// resolved by the package.xml found in the checked tree.
#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>

#include "formats/mesh/mesh_points.h"
#include "test_support.h"

using assetlint::test::write_file;
namespace mesh = assetlint::mesh;

namespace {

std::string binary_stl(int triangles) {
  std::string bytes(80, '\0');
  bytes.replace(0, 5, "solid");  // a binary STL may start with "solid" too
  const std::uint32_t count = triangles;
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (int t = 0; t < triangles; ++t) {
    const float values[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, static_cast<float>(t + 1), 0.5f};
    bytes.append(reinterpret_cast<const char*>(values), sizeof values);
    bytes.append(2, '\0');
  }
  return bytes;
}

}  // namespace

TEST_CASE("mesh points: binary and ASCII STL, OBJ and Collada", "[verify][mesh]") {
  assetlint::test::TempDir dir;
  std::string error;
  write_file(dir.path() / "b.stl", binary_stl(2));
  auto points = mesh::read_points((dir.path() / "b.stl").string(), error);
  REQUIRE(points);
  CHECK(points->size() == 6);
  CHECK((*points)[5].y() == Approx(2.0));
  write_file(dir.path() / "a.STL",
             "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
             "facet normal 0 0 1\nouter loop\nvertex 0 0 2\nvertex 1 0 2\nvertex 0 1 2\nendloop\nendfacet\nendsolid a\n");
  points = mesh::read_points((dir.path() / "a.STL").string(), error);
  REQUIRE(points);
  CHECK(points->size() == 6);
  CHECK((*points)[3].z() == Approx(2.0));
  write_file(dir.path() / "c.obj", "# box corner\nv 0 0 0\nv 1 0 0\nvt 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nf 1 2 3\n");
  points = mesh::read_points((dir.path() / "c.obj").string(), error);
  REQUIRE(points);
  CHECK(points->size() == 4);
  write_file(dir.path() / "d.dae", R"(<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><up_axis>Y_UP</up_axis></asset>
  <library_geometries><geometry id="g"><mesh>
    <source id="p"><float_array id="pa" count="12">0 0 0 1 0 0 0 1 0 0 0 3</float_array>
      <technique_common><accessor source="#pa" count="4" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <triangles count="2"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2 0 1 3</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)");
  points = mesh::read_points((dir.path() / "d.dae").string(), error);
  INFO(error);
  REQUIRE(points);
  double top = 0;
  for (const auto& p : *points) top = std::max(top, p.z());
  CHECK(top == Approx(3.0));
  CHECK_FALSE(mesh::read_points((dir.path() / "e.ply").string(), error));
  CHECK(error.find("STL (binary and ASCII), OBJ and Collada") != std::string::npos);
}

TEST_CASE("mesh points: package:// resolves through the package.xml in the checked tree", "[verify][mesh]") {
  assetlint::test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "src" / "grip_description");
  std::filesystem::create_directories(dir.path() / "other");
  write_file(dir.path() / "src" / "grip_description" / "package.xml",
             "<package format=\"2\">\n  <name>grip_description</name>\n</package>\n");
  write_file(dir.path() / "other" / "package.xml", "<package><name>grip_other</name></package>\n");
  std::string error;
  const auto file = mesh::resolve_mesh("package://grip_description/meshes/finger.stl", "urdf", dir.path().string(), error);
  REQUIRE(file);
  CHECK(*file == (dir.path() / "src" / "grip_description" / "meshes" / "finger.stl").lexically_normal().string());
  CHECK(*mesh::resolve_mesh("meshes/f.stl", "/robot/urdf", "", error) == "/robot/urdf/meshes/f.stl");
  CHECK_FALSE(mesh::resolve_mesh("package://missing/f.stl", ".", dir.path().string(), error));
  CHECK(error.find("no package.xml named 'missing'") != std::string::npos);
}
