#include <fmt/format.h>

#include <algorithm>

#include "rules/all_rules.h"
#include "rules/support.h"

namespace assetlint::rules {
namespace {

// The start of the line holding `offset` and its leading whitespace, for inserting an element
// before the joint with the joint's own indentation.
std::pair<std::size_t, std::string> line_indent(std::string_view text, std::size_t offset) {
  std::size_t start = text.rfind('\n', offset == 0 ? 0 : offset - 1);
  start = start == std::string_view::npos ? 0 : start + 1;
  std::size_t end = start;
  while (end < offset && (text[end] == ' ' || text[end] == '\t')) ++end;
  return {start, std::string(text.substr(start, end - start))};
}

class StructureUndefinedLink final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    const bool urdf = asset.format == SourceFormat::Urdf;
    std::vector<std::string_view> undefined_parents, undefined_children;
    // USD: a body that no layer read defines may be defined in one that could not be read;
    // layer-unresolved names the joints this check skipped.
    const auto undefined = [&](const Joint& joint, int side) {
      const Name& link = side == 0 ? joint.parent : joint.child;
      return !link.text.empty() && !asset.side_link(joint, side) && !asset.may_be_unread(link.text);
    };
    for (const Joint& joint : asset.joints) {
      if (undefined(joint, 0)) undefined_parents.push_back(joint.parent.text);
      if (undefined(joint, 1)) undefined_children.push_back(joint.child.text);
    }
    // One undefined parent, never a child, hanging one joint: the attachment point of a
    // fragment meant to be included into a larger robot.
    const bool fragment = undefined_children.empty() && undefined_parents.size() == 1;

    for (const Joint& joint : asset.joints) {
      for (const auto& [role, link] : {std::pair{"parent", &joint.parent}, std::pair{"child", &joint.child}}) {
        if (link->text.empty()) {
          // USD: no body, or a static prim, anchors the joint to the world; MJCF: the worldbody.
          if (!urdf) continue;
          out.report(link->span, fmt::format("{} names no {} link", joint_label(joint), role));
        } else if (undefined(joint, link == &joint.parent ? 0 : 1)) {
          Diagnostic& d = out.report(link->span, fmt::format("{} link '{}' of {} is not defined", role, link->text,
                                                             joint_label(joint)));
          if (!urdf) continue;
          if (link == &joint.parent && link->text == "world") {
            world_parent(asset, joint, d);
            continue;
          }
          d.note("urdfdom (ROS tools, check_urdf, Gazebo's URDF path) rejects a joint whose links are not defined.");
          if (fragment)
            d.note(fmt::format("It is the only undefined link, and the root's parent: the file reads as a fragment "
                               "meant to be included into a robot that defines '{}'. Check the assembled URDF instead.",
                               link->text));
        }
      }
    }
  }

 private:
  static void world_parent(const Asset& asset, const Joint& joint, Diagnostic& d) {
    d.note("Drake reads an undeclared 'world' as the world frame; urdfdom (ROS tools, check_urdf, Gazebo's URDF path) "
           "rejects the file.");
    d.note("Declaring <link name=\"world\"/> means the same to every consumer: the robot welded to the world.");
    const SourceFile& file = asset.source(joint.span.file);
    const auto [start, indent] = line_indent(file.view(), joint.span.offset);
    const bool crlf = start >= 2 && file.view()[start - 2] == '\r';
    d.fix = Fix{"declare the world link: insert <link name=\"world\"/> before the joint",
                Applicability::Unsafe,
                {Edit{joint.span.file, start, 0, indent + "<link name=\"world\"/>" + (crlf ? "\r\n" : "\n")}}};
  }

  RuleInfo info_{"structure-undefined-link", "A joint's parent or child link is not defined", Severity::Error, true,
                 RuleOrigin::Check, {}};
};

}  // namespace

const Rule& structure_undefined_link() {
  static const StructureUndefinedLink rule;
  return rule;
}

}  // namespace assetlint::rules
