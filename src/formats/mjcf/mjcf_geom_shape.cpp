#include "formats/mjcf/mjcf_geom_shape.h"

#include "util/numbers.h"

namespace assetlint::mjcf {

GeomShape geom_shape(const tinyxml2::XMLElement* geom, const std::vector<const tinyxml2::XMLElement*>& defaults,
                     const Compiler& compiler, Values& values) {
  auto lookup = [&](const char* name) { return Defaults::lookup(geom, defaults, name); };
  GeomShape shape;
  if (const Attr type = lookup("type")) shape.type = std::string(trim(type.value));
  if (const Attr mesh = lookup("mesh")) shape.mesh = std::string(trim(mesh.value));
  if (auto s = values.numbers(lookup("size"), "size"))
    for (std::size_t i = 0; i < s->size() && i < 3; ++i) shape.size[static_cast<Eigen::Index>(i)] = (*s)[i];
  if (auto ft = values.numbers(lookup("fromto"), "fromto", 6)) {
    const Eigen::Vector3d from((*ft)[0], (*ft)[1], (*ft)[2]), to((*ft)[3], (*ft)[4], (*ft)[5]);
    const Eigen::Vector3d along = to - from;
    // The segment is the shape's z axis; for boxes and ellipsoids size[0] becomes both
    // cross-section half-widths.
    shape.size[1] = along.norm() / 2.0;
    if (shape.type == "box" || shape.type == "ellipsoid") shape.size = {shape.size[0], shape.size[0], shape.size[1]};
    if (along.norm() > 0)
      shape.pose.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), along).toRotationMatrix();
    shape.pose.translation() = (from + to) / 2.0;
  } else {
    if (auto p = values.numbers(lookup("pos"), "pos", 3)) shape.pose.translation() = Eigen::Vector3d((*p)[0], (*p)[1], (*p)[2]);
    shape.pose.linear() = orientation(geom, defaults, compiler, values);
  }
  return shape;
}

}  // namespace assetlint::mjcf
