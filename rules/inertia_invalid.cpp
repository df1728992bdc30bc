#include <fmt/format.h>

#include "model/topology.h"
#include "physics/inertia.h"
#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

std::string moments_text(const Eigen::Vector3d& m) {
  return fmt::format("[{}, {}, {}] kg·m²", format_number(m[0], 4), format_number(m[1], 4), format_number(m[2], 4));
}

class InertiaInvalid final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double tolerance = rule_option(info_, settings, "triangle_tolerance");
    const bool urdf = asset.format == SourceFormat::Urdf;

    for (const RigidBody& body : moving_bodies(asset)) {
      if (body.links.empty()) continue;  // undefined child: structure-undefined-link reports it
      const Link& child = *body.links.front();
      bool any_inertial = false, any_negative = false;
      double total_mass = 0.0;
      for (const Link* link : body.links) {
        if (!link->inertial) continue;
        any_inertial = true;
        if (!link->inertial->mass_authored) continue;
        if (link->inertial->mass.value > 0) total_mass += link->inertial->mass.value;
        any_negative = any_negative || link->inertial->mass.value < 0;
      }
      if (any_negative) continue;  // reported below, once, as a negative mass
      if (!any_inertial && urdf) {
        out.report(child.name.span,
                   fmt::format("link '{}' moves (child of {}) but has no <inertial>: the simulator has to invent its "
                               "mass and inertia",
                               child.name.text, joint_label(*body.joint)));
      } else if (any_inertial && total_mass <= 0 && urdf) {
        const Link& first = **std::find_if(body.links.begin(), body.links.end(), [](const Link* l) { return l->inertial.has_value(); });
        out.report(first.inertial->mass.span,
                   fmt::format("link '{}' moves (child of {}) but its mass is {} kg: a moving body needs a positive mass",
                               first.name.text, joint_label(*body.joint), format_number(first.inertial->mass.value)));
      }
    }

    for (const Link& link : asset.links) {
      if (!link.inertial || !link.inertial->mass_authored) continue;
      const Inertial& inertial = *link.inertial;
      if (inertial.mass.value < 0) {
        out.report(inertial.mass.span,
                   fmt::format("link '{}' has negative mass {} kg", link.name.text, format_number(inertial.mass.value)));
        continue;
      }
      if (inertial.mass.value == 0 || !inertial.inertia_authored) continue;
      const Eigen::Vector3d moments = physics::principal_moments(inertial.inertia);
      if (moments[0] <= 0) {
        out.report(inertial.inertia_span,
                   fmt::format("inertia of link '{}' (mass {} kg) is not positive definite: principal moments {}",
                               link.name.text, format_number(inertial.mass.value), moments_text(moments)));
      } else if (moments[2] > (moments[0] + moments[1]) * (1 + tolerance)) {
        out.report(inertial.inertia_span,
                   fmt::format("inertia of link '{}' violates the triangle inequality: principal moments {}, and "
                               "{} > {} + {}; no rigid body has such a tensor",
                               link.name.text, moments_text(moments), format_number(moments[2], 4),
                               format_number(moments[0], 4), format_number(moments[1], 4)));
      }
    }
  }

 private:
  RuleInfo info_{"inertia-invalid",
                 "A moving link without mass or inertia, or with an inertia tensor no rigid body can have",
                 Severity::Error,
                 false,
                 RuleOrigin::Check,
                 {{"triangle_tolerance", 1e-6,
                   "relative slack allowed on the triangle inequality I_max ≤ (I_a + I_b)·(1 + tolerance)"}}};
};

}  // namespace

const Rule& inertia_invalid() {
  static const InertiaInvalid rule;
  return rule;
}

}  // namespace assetlint::rules
