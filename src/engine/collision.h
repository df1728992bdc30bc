#pragma once
// A collision engine that tells which collision shapes of a posed robot overlap, and by how
// much: the geometry rules ask it through this interface, so they stay free of any engine; one
// implementation per engine lives under src/backends/ and is installed by the pipeline.
#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/asset.h"

namespace assetlint::collision {

// One collision shape placed in the world. Shapes of the same body never collide with each other.
struct PlacedShape {
  std::size_t body = 0;
  CollisionShape::Kind kind = CollisionShape::Kind::Box;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // in the world, m
  Eigen::Vector3d size = Eigen::Vector3d::Zero();          // as CollisionShape::size
  // Kind::Mesh: the vertices in the shape frame, scale applied (m); the engine collides their hull.
  std::shared_ptr<const std::vector<Eigen::Vector3d>> points;
};

// The deepest overlap the engine finds between two shapes of different bodies.
struct Overlap {
  std::size_t shape_a = 0, shape_b = 0;  // indices into the shapes asked about, shape_a < shape_b
  double depth = 0;                      // m, > 0
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // the contact point, world frame
};

struct Overlaps {
  std::vector<Overlap> overlaps;
  // Shapes the engine could not collide (a mesh without volume), each with the reason.
  std::vector<std::pair<std::size_t, std::string>> skipped;
};

class Engine {
 public:
  virtual ~Engine() = default;
  // "MuJoCo 2.2.2": named in findings, since depths are the engine's.
  virtual std::string name() const = 0;
  // One overlap per pair of shapes of different bodies that penetrate; nullopt with `error`
  // when the engine cannot build the scene at all.
  virtual std::optional<Overlaps> overlaps(const std::vector<PlacedShape>& shapes, std::string& error) const = 0;
};

// The engine the pipeline installed; nullptr when none (the geometry rules then do nothing).
const Engine* installed_engine();
void install_engine(const Engine* engine);

}  // namespace assetlint::collision
