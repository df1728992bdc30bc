#include <fmt/format.h>

#include "rules/all_rules.h"
#include "rules/support.h"

namespace assetlint::rules {
namespace {

class StructureUndefinedLink final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    for (const Joint& joint : asset.joints) {
      for (const auto& [role, link] : {std::pair{"parent", &joint.parent}, std::pair{"child", &joint.child}}) {
        if (link->text.empty()) {
          // USD: no body, or a static prim, anchors the joint to the world; MJCF: the worldbody.
          if (asset.format != SourceFormat::Urdf) continue;
          out.report(link->span, fmt::format("{} names no {} link", joint_label(joint), role));
        } else if (!asset.find_link(link->text)) {
          out.report(link->span, fmt::format("{} link '{}' of {} is not defined in the file", role, link->text,
                                             joint_label(joint)));
        }
      }
    }
  }

 private:
  RuleInfo info_{"structure-undefined-link", "A joint's parent or child link is not defined", Severity::Error, false,
                 RuleOrigin::Check, {}};
};

}  // namespace

const Rule& structure_undefined_link() {
  static const StructureUndefinedLink rule;
  return rule;
}

}  // namespace assetlint::rules
