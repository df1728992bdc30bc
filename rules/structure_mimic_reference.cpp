#include <fmt/format.h>

#include <algorithm>

#include "rules/all_rules.h"
#include "rules/support.h"

namespace assetlint::rules {
namespace {

std::size_t common_prefix(std::string_view a, std::string_view b) {
  std::size_t n = 0;
  while (n < a.size() && n < b.size() && a[n] == b[n]) ++n;
  return n;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The joint a missing mimic reference most likely meant: one whose name ends with the
// reference (a dropped prefix: 'index_q1' for 'Left_index_q1'), preferring the one that
// shares the mimic joint's own prefix; else the nearest name within a few edits.
const Joint* closest_joint(const Asset& asset, const Joint& mimic_joint, std::string_view missing) {
  const Joint* best = nullptr;
  std::size_t best_prefix = 0;
  for (const Joint& j : asset.joints) {
    if (&j == &mimic_joint || !j.name.text.ends_with(missing)) continue;
    const std::size_t prefix = common_prefix(j.name.text, mimic_joint.name.text);
    if (!best || prefix > best_prefix) best = &j, best_prefix = prefix;
  }
  if (best) return best;
  std::size_t best_distance = std::max<std::size_t>(2, missing.size() / 4) + 1;
  for (const Joint& j : asset.joints) {
    if (&j == &mimic_joint) continue;
    const std::size_t d = edit_distance(j.name.text, missing);
    if (d < best_distance) best = &j, best_distance = d;
  }
  return best;
}

class StructureMimicReference final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    std::vector<const Joint*> dead;  // mimic tags on joints that cannot move
    for (const Joint& joint : asset.joints) {
      if (!joint.mimic) continue;
      const Mimic& mimic = *joint.mimic;
      if (!is_single_dof(joint.type)) {
        dead.push_back(&joint);
        continue;
      }
      if (mimic.reference.text.empty()) {
        out.report(mimic.span, fmt::format("the mimic of {} names no joint to follow", joint_label(joint)));
        continue;
      }
      if (mimic.reference.text == joint.name.text) {
        out.report(mimic.reference.span, fmt::format("{} mimics itself", joint_label(joint)));
        continue;
      }
      const Joint* reference = asset.find_joint(mimic.reference.text);
      if (!reference) {
        Diagnostic& d = out.report(mimic.reference.span, fmt::format("{} mimics joint '{}', which is not defined",
                                                                     joint_label(joint), mimic.reference.text));
        if (const Joint* guess = closest_joint(asset, joint, mimic.reference.text))
          d.note(guess->name.span, fmt::format("Did you mean '{}'?", guess->name.text));
        if (asset.format == SourceFormat::Mjcf)
          d.note("MuJoCo's compiler rejects an equality constraint that names an undefined joint.");
        else
          d.note(fmt::format("{}the joint follows nothing: it moves freely or stays where the simulator leaves it.",
                             asset.format == SourceFormat::Urdf ? "urdfdom accepts the file, but " : "The file loads, but "));
      } else if (reference->is_mimic()) {
        const bool mujoco = asset.format == SourceFormat::Mjcf;
        const bool physx = asset.format == SourceFormat::Usda;
        Diagnostic& d =
            out.report(mimic.reference.span, mujoco || physx ? Severity::Info : Severity::Error,
                       fmt::format("{} {} '{}', which itself {} '{}'", joint_label(joint),
                                   mujoco ? "is coupled to" : "mimics", reference->name.text,
                                   mujoco ? "is coupled to" : "mimics", reference->mimic->reference.text));
        // MuJoCo solves all equality constraints together (engine_core_constraint.c builds one
        // row per equality in the same constraint system), so a chain is as valid as a star.
        // PhysX 5 solves each mimic joint as its own constraint between two dofs, iteration by
        // iteration (FeatherstoneArticulation::solveInternalMimicJointConstraints), so a chain
        // converges like any set of coupled constraints.
        if (mujoco)
          d.note("MuJoCo solves every equality constraint together, so the chain simulates as written there; a "
                 "conversion to URDF needs it flattened, because most URDF consumers follow only a joint that is not "
                 "itself a mimic.");
        else if (physx)
          d.note("PhysX solves each mimic joint as its own constraint between two joint coordinates, so the chain "
                 "simulates as written; each link's compliance (naturalFrequency, dampingRatio) adds up along it, and a "
                 "conversion to URDF needs it flattened.");
        else
          d.note("Most URDF consumers follow only a joint that is not itself a mimic: importers drop the inner link "
                 "or refuse the file.");
        d.note(reference->name.span, fmt::format("Make both follow '{}'.", reference->mimic->reference.text));
      } else if (!is_single_dof(reference->type)) {
        out.report(mimic.reference.span,
                   fmt::format("{} mimics {}, which has no single degree of freedom", joint_label(joint),
                               joint_label(*reference)));
      }
    }
    report_dead_tags(dead, out);
  }

 private:
  // A <mimic> on a fixed joint is ignored by every consumer: often a joint frozen on purpose
  // (halodi EVE's qb hands). One info per file, not one error per tag.
  static void report_dead_tags(const std::vector<const Joint*>& dead, Reporter& out) {
    if (dead.empty()) return;
    const Joint& first = *dead.front();
    Diagnostic& d = out.report(
        first.mimic->span, Severity::Info,
        dead.size() == 1 ? fmt::format("{} has a <mimic> that nothing reads", joint_label(first))
                         : fmt::format("{} {} joints carry a <mimic> that nothing reads", dead.size(),
                                       joint_type_name(first.type)));
    d.note("Only revolute, continuous and prismatic joints can follow another joint; urdfdom, ROS and the "
           "simulator importers ignore the tag on any other type.");
    if (dead.size() > 1) {
      std::string names;
      for (std::size_t i = 0; i < dead.size() && i < 5; ++i) names += fmt::format("{}'{}'", i ? ", " : "", dead[i]->name.text);
      d.note(fmt::format("They include {}{}.", names, dead.size() > 5 ? fmt::format(" and {} more", dead.size() - 5) : ""));
    }
    d.note("If the joints were frozen on purpose, delete the tags; if they should move, give them a movable type.");
  }

  RuleInfo info_{"structure-mimic-reference",
                 "A mimic joint follows a missing joint, itself, another mimic joint, or sits on a fixed joint",
                 Severity::Error, false, RuleOrigin::Check, {}};
};

}  // namespace

const Rule& structure_mimic_reference() {
  static const StructureMimicReference rule;
  return rule;
}

}  // namespace assetlint::rules
