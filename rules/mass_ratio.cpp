#include <fmt/format.h>

#include <set>
#include <vector>

#include "physics/articulation.h"
#include "rules/all_rules.h"
#include "rules/drive_support.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// Two bodies joined by a movable joint whose masses differ by max_ratio or more (NAO's
// 2e-6 kg finger links on a 0.185 kg hand: 9.3e4). One warning per file at the lightest
// body of the worst pair; the other pairs are notes.
class MassRatio final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double max_ratio = rule_option(info_, settings, "max_ratio");
    const auto shared = physics::shared_articulation(asset);
    const physics::Articulation& articulation = *shared;
    struct Pair {
      const Joint* joint;
      const physics::Body* light;
      const physics::Body* heavy;
      double ratio;
    };
    // Isaac's URDF importer fixes the base: the root body is then the world, whatever it weighs
    // (a 1e-6 kg dummy root). A floating root (USD) moves and is judged.
    const bool fixed_root = physics::default_free_root(asset) == physics::Articulation::FreeRoot::Fixed;
    std::set<const physics::Body*> moved;
    for (const Joint& joint : asset.joints)
      if (is_single_dof(joint.type)) moved.insert(articulation.side(joint, 1));
    const auto judged = [&](const physics::Body* body) {
      return body && !body->world && body->mass_known && body->mass > 0 && (!fixed_root || moved.count(body));
    };
    // MuJoCo simulates a tree in joint coordinates, and Isaac Sim imports a URDF as a PhysX
    // articulation, which does too (reduced coordinates): a light body between two joints (the
    // virtual link of a two-axis joint) is moved, contacts and all, only through the joints
    // above it, whose inertia holds everything beyond it too; its own mass changes nothing.
    std::set<const physics::Body*> carries_joint;
    for (const Joint& joint : asset.joints)
      if (is_single_dof(joint.type)) carries_joint.insert(articulation.side(joint, 0));
    const auto virtual_link = [&](const physics::Body* body) {
      return (asset.format == SourceFormat::Mjcf || asset.format == SourceFormat::Urdf) && carries_joint.count(body) > 0;
    };
    std::vector<Pair> found;
    for (const Joint& joint : asset.joints) {
      if (!is_single_dof(joint.type)) continue;
      const physics::Body* a = articulation.side(joint, 0);
      const physics::Body* b = articulation.side(joint, 1);
      if (a == b || !judged(a) || !judged(b)) continue;
      const physics::Body* light = a->mass < b->mass ? a : b;
      const physics::Body* heavy = light == a ? b : a;
      if (virtual_link(light)) continue;
      const double ratio = heavy->mass / light->mass;
      if (ratio >= max_ratio) found.push_back({&joint, light, heavy, ratio});
    }
    if (found.empty()) return;
    std::stable_sort(found.begin(), found.end(), [](const Pair& x, const Pair& y) { return x.ratio > y.ratio; });
    const Pair& worst = found.front();
    Diagnostic& d = out.report(
        mass_span(*worst.light), Severity::Warning,
        fmt::format("'{}' weighs {} kg, 1/{} of '{}' across {}{}", short_path(worst.light->name()), format_number(worst.light->mass, 3),
                    format_number(worst.ratio, 3), short_path(worst.heavy->name()), short_name(*worst.joint),
                    found.size() > 1 ? fmt::format(" (and {} more joints)", found.size() - 1) : std::string()));
    d.note(worst.joint->name.span,
           fmt::format("{} joins a {} kg body ('{}') to a {} kg body ('{}'): mass ratio {}, at or above max_ratio {}.",
                       joint_label(*worst.joint), format_number(worst.heavy->mass, 4), worst.heavy->name(),
                       format_number(worst.light->mass, 4), worst.light->name(), format_number(worst.ratio, 3),
                       format_number(max_ratio)));
    if (asset.format == SourceFormat::Mjcf)
      d.note("MuJoCo moves the light body through the joint that carries it, whose inertia is then almost only that "
             "body's: a contact or limit on it acts at a time scale the step barely resolves, and the light body "
             "jitters or passes through what it touches.");
    else
      d.note("PhysX's iterative solvers (TGS and PGS) resolve a constraint between two bodies mostly by moving the "
             "lighter one; at this ratio contacts and limit rows on the light body converge poorly, and the light body "
             "jitters or passes through what it touches.");
    d.note("A mass this small is usually a placeholder for a frame or sensor: weld it with a fixed joint, or give it "
           "its measured mass.");
    for (std::size_t i = 1; i < found.size() && i <= 5; ++i)
      d.note(mass_span(*found[i].light), fmt::format("Also '{}' ({} kg) across '{}': ratio {}.", found[i].light->name(),
                                                     format_number(found[i].light->mass, 3), found[i].joint->name.text,
                                                     format_number(found[i].ratio, 3)));
    if (found.size() > 6) d.note(fmt::format("And {} more joints like these.", found.size() - 6));
  }

 private:
  // The first link of the body that states a mass: where a mass would be written.
  static Span mass_span(const physics::Body& body) {
    for (const Link* link : body.links)
      if (link->inertial && link->inertial->mass.span.valid()) return link->inertial->mass.span;
    return body.links.front()->name.span;
  }

  RuleInfo info_{"mass-ratio",
                 "Two bodies joined by a movable joint whose masses differ by a factor of max_ratio or more",
                 Severity::Warning,
                 false,
                 RuleOrigin::Check,
                 {{"max_ratio", 1e4, "report a movable joint whose two bodies' masses differ by this factor or more"}}};
};

}  // namespace

const Rule& mass_ratio() {
  static const MassRatio rule;
  return rule;
}

}  // namespace assetlint::rules
