#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "rules/all_rules.h"
#include "rules/collider_points.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// Densities between which every part of a robot lies (kg/m³): foam and hollow shells, tungsten.
constexpr double kLightest = 50, kDensest = 20000;
// Below a milligram a mass is a placeholder for "no mass", not a part's.
constexpr double kPlaceholderMass = 1e-6;

// One estimate of how large a link is, from something other than its colliders.
struct Reference {
  double low, high;  // m: the size lies between them
  std::string how;   // for the note
};

// The sizes the link's other data give it: the joints it carries (their offsets from its
// frame), its inertia's radius of gyration (a solid of side a has sqrt(2·trace(I)/m) = a), its
// mass at any plausible density.
std::vector<Reference> references(const Asset& asset, const Link& link) {
  std::vector<Reference> out;
  double reach = 0;
  for (const Joint& joint : asset.joints) {
    if (joint.parent.text == link.name.text) reach = std::max(reach, joint.frame_in_link[0].translation().norm());
    if (joint.child.text == link.name.text) reach = std::max(reach, joint.frame_in_link[1].translation().norm());
  }
  if (reach > 1e-6)
    out.push_back({reach / 4, reach * 4, fmt::format("its joints sit up to {} m from its origin", format_number(reach, 3))});
  // A placeholder mass (Unitree's lidar link weighs 4.19e-15 kg) says nothing about a size.
  if (!link.inertial || !link.inertial->mass_authored || !(link.inertial->mass.value >= kPlaceholderMass)) return out;
  const double m = link.inertial->mass.value;
  if (link.inertial->inertia_authored) {
    const double trace = link.inertial->inertia.trace();
    if (trace > 0) {
      const double side = std::sqrt(2 * trace / m);
      out.push_back({side / 4, side * 4,
                     fmt::format("its inertia is that of a solid {} m across", format_number(side, 3))});
    }
  }
  out.push_back({std::cbrt(m / kDensest), std::cbrt(m / kLightest) * 4,
                 fmt::format("its {} kg fill a cube of {} to {} m at 50 to 20000 kg/m³", format_number(m, 3),
                             format_number(std::cbrt(m / kDensest), 3), format_number(std::cbrt(m / kLightest), 3))});
  return out;
}

// A collider 100 times or more off from every estimate of its link's size: the units slip it
// looks like (a mesh in millimetres read as metres is 1000x its link).
class UnitsColliderScale final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double min_factor = rule_option(info_, settings, "min_factor");
    ColliderPoints meshes(asset, settings);
    for (const Link& link : asset.links) {
      if (link.collisions.empty()) continue;
      const auto refs = references(asset, link);
      if (refs.size() < 2) continue;  // one estimate alone is too easily off itself
      for (const CollisionShape& shape : link.collisions) {
        const auto box = meshes.box_in_link(shape);
        if (!box) continue;
        const double extent = box->sizes().maxCoeff();
        // Reported when every estimate agrees (the least ratio to their bounds); named by the
        // median ratio to their middles, the best guess of the slip.
        double too_big = HUGE_VAL, too_small = HUGE_VAL;
        std::vector<double> ratios;
        for (const Reference& r : refs) {
          too_big = std::min(too_big, extent / r.high);
          too_small = std::min(too_small, r.low / extent);
          ratios.push_back(extent / std::sqrt(r.low * r.high));
        }
        std::sort(ratios.begin(), ratios.end());
        const double typical = ratios[ratios.size() / 2];
        if (too_big >= min_factor) report(asset, link, shape, extent, typical, too_big, refs, true, out);
        else if (too_small >= min_factor) report(asset, link, shape, extent, 1 / typical, too_small, refs, false, out);
      }
    }
  }

 private:
  static void report(const Asset& asset, const Link& link, const CollisionShape& shape, double extent, double factor,
                     double least, const std::vector<Reference>& refs, bool big, Reporter& out) {
    // The slip the factor fits: a thousand (millimetres and metres) unless it is nearer a hundred.
    const bool centi = std::abs(std::log10(factor) - 2) < std::abs(std::log10(factor) - 3) && factor < 300;
    const int slip = centi ? 100 : 1000;
    const std::string unit = centi ? "centimetres" : "millimetres";
    const std::string what = shape.kind == CollisionShape::Kind::Mesh
                                 ? fmt::format("mesh '{}'", std::filesystem::path(shape.mesh).filename().string())
                                 : std::string("collider");
    Diagnostic& d = out.report(
        shape.span.valid() ? shape.span : link.span,
        big ? fmt::format("{} of '{}' is ~{}× its link: {} read as metres?", what, link.name.text,
                          format_number(factor, 2), unit)
            : fmt::format("{} of '{}' is ~1/{} of its link: metres scaled as {}?", what, link.name.text,
                          format_number(factor, 2), unit));
    d.note(fmt::format("The collider spans {} m (scale applied): ~{}× {} than the link's other measures, at least "
                       "{}× even at their {} bound: {}.",
                       format_number(extent, 4), format_number(factor, 2), big ? "larger" : "smaller",
                       format_number(least, 3), big ? "upper" : "lower",
                       [&] {
                         std::string list;
                         for (const Reference& r : refs) list += (list.empty() ? "" : "; ") + r.how;
                         return list;
                       }()));
    d.note(big ? "The engine collides the shape as written: the link collides with everything around it, and a "
                 "simulator that derives mass from colliders (PhysX without physics:mass, MuJoCo without "
                 "<inertial>) weighs it by the cube of the factor."
               : "The engine collides the shape as written: the link passes through what it should touch.");
    const std::string scale = big ? (slip == 1000 ? "0.001 0.001 0.001" : "0.01 0.01 0.01") : "1 1 1";
    if (asset.format == SourceFormat::Urdf)
      d.note(fmt::format("Fix: {} on the <mesh> element (scale=\"{}\"), or export the mesh in metres.",
                         big ? "scale it" : "drop the extra scale", scale));
    else if (asset.format == SourceFormat::Mjcf)
      d.note(fmt::format("Fix: scale=\"{}\" on the <mesh> asset, or export the mesh in metres.", scale));
    else
      d.note(fmt::format("Fix: {} the collider by {} (xformOp:scale), or set the layer's metersPerUnit to what its "
                         "points are written in.",
                         big ? "scale" : "enlarge", big ? fmt::format("1/{}", slip) : std::to_string(slip)));
  }

  RuleInfo info_{"units-collider-scale",
                 "A collider 100× or more larger or smaller than its link (joint offsets, inertia, mass): a units slip",
                 Severity::Warning,
                 false,
                 RuleOrigin::Check,
                 {{"min_factor", 100, "Ratio to every other measure of the link's size from which a collider is reported"}}};
};

}  // namespace

const Rule& units_collider_scale() {
  static const UnitsColliderScale rule;
  return rule;
}

}  // namespace assetlint::rules
