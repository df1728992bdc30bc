#include <fmt/format.h>

#include <string>

#include "rules/all_rules.h"
#include "rules/collider_points.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// A centre of mass farther outside the box around a link's colliders than the box is large: no
// distribution of the link's material puts it there (a 5 cm finger with its centre of mass a
// metre away). The engine swings the link about a point where the link is not.
class InertiaComOutside final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double max_ratio = rule_option(info_, settings, "max_ratio");
    ColliderPoints meshes(asset, settings);
    for (const Link& link : asset.links) {
      if (!link.inertial || !link.inertial->com_authored || link.collisions.empty()) continue;
      if (!link.inertial->mass_authored || !(link.inertial->mass.value > 0)) continue;
      const auto box = meshes.box_in_link(link.collisions);
      if (!box) continue;
      const Eigen::Vector3d& com = link.inertial->com;
      const double size = box->sizes().maxCoeff();
      const double outside = box->exteriorDistance(com);
      if (!(outside > max_ratio * size)) continue;
      Diagnostic& d = out.report(
          link.inertial->com_span.valid() ? link.inertial->com_span : link.span,
          fmt::format("centre of mass of '{}' lies {} m outside its colliders ({}× their size)", link.name.text,
                      format_number(outside, 3), format_number(outside / size, 3)));
      const Eigen::Vector3d lo = box->min(), hi = box->max();
      d.note(fmt::format("The centre of mass is at ({}, {}, {}) m in the link frame; the link's colliders fill "
                         "({}, {}, {}) to ({}, {}, {}) m, {} m across.",
                         format_number(com.x(), 4), format_number(com.y(), 4), format_number(com.z(), 4),
                         format_number(lo.x(), 4), format_number(lo.y(), 4), format_number(lo.z(), 4),
                         format_number(hi.x(), 4), format_number(hi.y(), 4), format_number(hi.z(), 4),
                         format_number(size, 4)));
      d.note("No arrangement of the link's material puts its centre of mass that far outside it: gravity and every "
             "contact then act on a lever that is not there, and the joint that carries the link sees a torque of "
             "mass × g × that distance at rest.");
      d.note("Fix: write the centre of mass where the link's material is (CAD's mass properties, or the colliders' "
             "centroid for a uniform part); check for a units slip or a frame offset copied from another link.");
    }
  }

 private:
  RuleInfo info_{"inertia-com-outside",
                 "A link's centre of mass lies outside its colliders by more than their size",
                 // An info: real packages often collide only part of a link (a finger's pad, a
                 // hip's bearing), so a centre of mass outside the colliders is mostly right.
                 Severity::Info,
                 false,
                 RuleOrigin::Check,
                 {{"max_ratio", 1, "Distance outside the colliders' box, in box sizes, from which it is reported"}}};
};

}  // namespace

const Rule& inertia_com_outside() {
  static const InertiaComOutside rule;
  return rule;
}

}  // namespace assetlint::rules
