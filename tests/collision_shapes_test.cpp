// Collision shapes as the USD and MJCF readers fill them: poses relative to the body, sizes and
// points scaled and in metres, what does not collide left out.
#include <catch2/catch.hpp>

#include "formats/mjcf/mjcf_reader.h"
#include "formats/usda/usd_reader.h"
#include "test_support.h"

using namespace assetlint;
using Catch::Matchers::WithinAbs;

namespace {

const Link& link_named(const Asset& asset, std::string_view name) {
  const Link* link = asset.find_link(name);
  REQUIRE(link);
  return *link;
}

void check_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected) {
  INFO("actual " << actual.transpose() << ", expected " << expected.transpose());
  CHECK((actual - expected).norm() < 1e-9);
}

}  // namespace

TEST_CASE("USD colliders: gprims with PhysicsCollisionAPI under a body, its scale and metersPerUnit applied",
          "[usd][collisions]") {
  const char* text = R"(#usda 1.0
(
    metersPerUnit = 0.01
)
def Xform "r"
{
    def Cube "b" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"]
    )
    {
        double size = 1
        double3 xformOp:translate = (100, 0, 0)
        float3 xformOp:scale = (2, 2, 2)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]

        def Xform "offset"
        {
            double3 xformOp:translate = (0, 10, 0)
            uniform token[] xformOpOrder = ["xformOp:translate"]

            def Cylinder "rod" (
                prepend apiSchemas = ["PhysicsCollisionAPI"]
            )
            {
                uniform token axis = "X"
                double radius = 1
                double height = 4
            }
        }
        def Capsule "off" (
            prepend apiSchemas = ["PhysicsCollisionAPI"]
        )
        {
            bool physics:collisionEnabled = false
        }
        def Sphere "visual"
        {
        }
        def Mesh "hull" (
            prepend apiSchemas = ["PhysicsCollisionAPI"]
        )
        {
            point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
            float3 xformOp:scale = (1, 2, 3)
            uniform token[] xformOpOrder = ["xformOp:scale"]
        }
        def Xform "inner" (
            prepend apiSchemas = ["PhysicsRigidBodyAPI"]
        )
        {
            def Sphere "ball" (
                prepend apiSchemas = ["PhysicsCollisionAPI"]
            )
            {
                double radius = 3
                double3 xformOp:translate = (0, 0, 5)
                uniform token[] xformOpOrder = ["xformOp:translate"]
            }
        }
    }
}
)";
  const ReadResult r = usda::read_usda(std::make_shared<const SourceFile>("mem/colliders.usda", text), disk());
  REQUIRE(r.usable);
  const Link& body = link_named(r.asset, "/r/b");
  REQUIRE(body.collisions.size() == 3);
  // The body's own Cube: 1 unit × its scale 2 = 0.02 m edges, at the body frame (which has no scale).
  const CollisionShape& cube = body.collisions[0];
  CHECK(cube.kind == CollisionShape::Kind::Box);
  check_near(cube.size, {0.02, 0.02, 0.02});
  check_near(cube.pose.translation(), Eigen::Vector3d::Zero());
  // The rod: 10 units up under the body's scale 2 = 0.2 m; radius 2 units, height 8, along x.
  const CollisionShape& rod = body.collisions[1];
  CHECK(rod.kind == CollisionShape::Kind::Cylinder);
  check_near(rod.size, {0.02, 0.08, 0});
  check_near(rod.pose.translation(), {0, 0.2, 0});
  check_near(rod.pose.linear() * Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX());
  // The hull's points under its scale (1, 2, 3) and the body's 2, in metres.
  const CollisionShape& hull = body.collisions[2];
  CHECK(hull.kind == CollisionShape::Kind::Mesh);
  CHECK(hull.mesh == "/r/b/hull");
  REQUIRE(hull.points.size() == 4);
  check_near(hull.points[1], {0.02, 0, 0});
  check_near(hull.points[2], {0, 0.04, 0});
  check_near(hull.points[3], {0, 0, 0.06});
  // A body below a body owns its own shapes.
  const Link& inner = link_named(r.asset, "/r/b/inner");
  REQUIRE(inner.collisions.size() == 1);
  CHECK(inner.collisions[0].kind == CollisionShape::Kind::Sphere);
  CHECK_THAT(inner.collisions[0].size.x(), WithinAbs(0.03, 1e-12));
  check_near(inner.collisions[0].pose.translation(), {0, 0, 0.05});
}

TEST_CASE("MJCF collisions: geoms that collide, sizes in full lengths, fromto, euler, meshdir and scale",
          "[mjcf][collisions]") {
  const char* text = R"(<mujoco>
  <compiler angle="radian" eulerseq="zyx" meshdir="assets"/>
  <default>
    <default class="vis"><geom contype="0" conaffinity="0"/></default>
  </default>
  <asset>
    <mesh file="parts/part.stl" scale="2 2 2"/>
    <mesh name="tri" vertex="0 0 0 1 0 0 0 1 0 0 0 1" scale="1 1 0.5"/>
  </asset>
  <worldbody>
    <body name="b">
      <inertial mass="1" diaginertia="1 1 1"/>
      <geom type="capsule" fromto="0 0 0 0 0 0.2" size="0.01"/>
      <geom type="box" size="0.1 0.2 0.3" euler="1.5707963267948966 0 0"/>
      <geom class="vis" type="box" size="1 1 1"/>
      <geom type="sphere" size="0.05" contype="0" conaffinity="2"/>
      <geom type="mesh" mesh="part"/>
      <geom type="mesh" mesh="tri" pos="0 0 1"/>
    </body>
  </worldbody>
</mujoco>
)";
  const ReadResult r = mjcf::read_mjcf(std::make_shared<const SourceFile>("mem/model.xml", text), disk());
  REQUIRE(r.usable);
  const Link& body = link_named(r.asset, "b");
  REQUIRE(body.collisions.size() == 5);
  const CollisionShape& capsule = body.collisions[0];
  CHECK(capsule.kind == CollisionShape::Kind::Capsule);
  check_near(capsule.size, {0.01, 0.2, 0});
  check_near(capsule.pose.translation(), {0, 0, 0.1});
  const CollisionShape& box = body.collisions[1];
  CHECK(box.kind == CollisionShape::Kind::Box);
  check_near(box.size, {0.2, 0.4, 0.6});
  check_near(box.pose.linear() * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY());  // z first: 90° about z
  CHECK(body.collisions[2].kind == CollisionShape::Kind::Sphere);
  const CollisionShape& part = body.collisions[3];
  CHECK(part.kind == CollisionShape::Kind::Mesh);
  CHECK(part.mesh == "assets/parts/part.stl");
  check_near(part.mesh_scale, {2, 2, 2});
  CHECK(part.points.empty());
  const CollisionShape& tri = body.collisions[4];
  CHECK(tri.mesh == "tri");
  REQUIRE(tri.points.size() == 4);
  check_near(tri.points[3], {0, 0, 0.5});
  check_near(tri.pose.translation(), {0, 0, 1});
}
