#include <fmt/format.h>

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "rules/all_rules.h"
#include "rules/support.h"

namespace assetlint::rules {
namespace {

class StructureMultipleParents final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    // USD: a body that is body1 of two joints closes a loop PhysX solves as a constraint; MJCF
    // nests bodies, so no body has two parents. Only URDF's tree forbids it.
    if (asset.format != SourceFormat::Urdf) return;
    std::map<std::string_view, std::vector<const Joint*>> by_child;
    std::vector<std::string_view> order;
    for (const Joint& joint : asset.joints) {
      if (joint.child.text.empty()) continue;
      auto& joints = by_child[joint.child.text];
      if (joints.empty()) order.push_back(joint.child.text);
      joints.push_back(&joint);
    }
    for (std::string_view child : order) {
      const auto& joints = by_child[child];
      if (joints.size() < 2) continue;
      const Joint& first = *joints.front();
      for (std::size_t i = 1; i < joints.size(); ++i) report(*joints[i], first, joints.size(), out);
    }
  }

 private:
  static void report(const Joint& joint, const Joint& first, std::size_t count, Reporter& out) {
    Diagnostic& d = out.report(joint.child.span,
                               fmt::format("link '{}' is the child of joints '{}' and '{}'", joint.child.text,
                                           joint.name.text, first.name.text));
    d.note(first.child.span, fmt::format("'{}' names it as its child first.", first.name.text));
    d.note(fmt::format("A URDF is a tree: each link has one parent joint. {} joints name '{}' as their child.",
                       count, joint.child.text));
    d.note("urdfdom (ROS tools, check_urdf) accepts the file, lists the link under every parent and keeps one of the "
           "joints as its parent, so the transforms published for it depend on which; MuJoCo's URDF import refuses "
           "the file (\"URDF body has multiple parents\").");
    if (joint.parent.text == first.parent.text) {
      d.note(fmt::format("Both joints hang it from '{}': to give a link two degrees of freedom, chain the joints "
                         "through an intermediate link (with a small <inertial> of its own).",
                         joint.parent.text));
    } else {
      d.note("The joints close a loop, which URDF cannot express: keep one joint in the tree and model the other "
             "with a mimic joint, or in the simulator's own format (an MJCF <equality>, a USD joint outside the "
             "articulation's tree).");
    }
  }

  RuleInfo info_{"structure-multiple-parents", "A URDF link is the child of more than one joint", Severity::Error,
                 false, RuleOrigin::Check, {}};
};

}  // namespace

const Rule& structure_multiple_parents() {
  static const StructureMultipleParents rule;
  return rule;
}

}  // namespace assetlint::rules
