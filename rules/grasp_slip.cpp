#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <vector>
#include <optional>
#include <string>
#include <string_view>

#include "rules/all_rules.h"
#include "rules/gripper_drive.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// Where `name="value"` can be inserted into the start tag that `element` begins: after its name.
std::size_t after_tag_name(std::string_view text, std::size_t element) {
  std::size_t at = element + 1;
  while (at < text.size() && !std::isspace(static_cast<unsigned char>(text[at])) && text[at] != '>' &&
         text[at] != '/')
    ++at;
  return at;
}

class GraspSlip final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    if (asset.format != SourceFormat::Mjcf) return;
    const Scene& scene = asset.scene;
    const bool pyramidal = scene.cone.empty() || scene.cone == "pyramidal";
    const double impratio = scene.impratio.value_or(1.0);
    const bool noslip = scene.noslip_iterations.value_or(0) > 0;
    if (!pyramidal || impratio > 1 || noslip) return;
    const Joint* drive = gripper_drive(asset);
    if (!drive) return;

    const Span& at = scene.cone_span.valid()       ? scene.cone_span
                     : scene.impratio_span.valid() ? scene.impratio_span
                     : scene.solver_span.valid()   ? scene.solver_span
                                                   : asset.robot_span;
    Diagnostic& d = out.report(
        at, fmt::format("gripper '{}' under a pyramidal cone with impratio {}: held objects creep out",
                        drive->name.text, format_number(impratio)));
    d.note(drive->name.span, fmt::format("'{}' drives the fingers ({} mimic it).", drive->name.text,
                                         asset.mimic_followers(drive->name.text).size()));
    d.note(fmt::format("<option> {}: cone {}, impratio {}, noslip_iterations 0.",
                       scene.solver_span.valid() ? "writes" : "is not written, so MuJoCo's defaults hold",
                       scene.cone.empty() ? "pyramidal (the default)" : scene.cone,
                       scene.impratio ? format_number(impratio) : "1 (the default)"));
    d.note("MuJoCo's contacts are soft: mj_makeImpedance gives each friction direction the normal's regularizer "
           "divided by impratio (on a pyramidal cone one value for every edge), and the solver's friction force "
           "holds a load only while the contact slides at a speed proportional to that regularizer times the load. "
           "A squeezed object therefore slides out at a steady speed that grows with its weight, whatever the "
           "friction margin.");
    d.note("Measured in MuJoCo 2.2.2 (implicit, 2 ms steps) on two pads with μ 1 squeezing a 0.1 kg box with 7.3 N "
           "(7.5× the friction it needs): 3.1 mm/s of creep with these options, 0.15 mm/s with cone=\"elliptic\" "
           "impratio=\"10\", under 0.001 mm/s with noslip_iterations=\"3\".");
    d.note("Fix: cone=\"elliptic\" impratio=\"10\" on <option> (what `asset-lint verify` steps grippers with), or "
           "noslip_iterations=\"3\" (mj_solNoSlip re-solves the friction forces without the regularizer after each "
           "step).");
    d.fix = fix(asset);
  }

 private:
  // cone="elliptic" impratio="10": rewrites the written values, adds the missing ones to <option>, or adds an
  // <option> element after <mujoco>'s start tag.
  static std::optional<Fix> fix(const Asset& asset) {
    const Scene& scene = asset.scene;
    Fix f{"use an elliptic friction cone with impratio 10", Applicability::Unsafe, {}};
    if (scene.solver_span.valid()) {
      const std::string_view text = asset.source(scene.solver_span.file).view();
      const std::size_t insert = after_tag_name(text, scene.solver_span.offset);
      std::string added;
      if (scene.cone_span.valid())
        f.edits.push_back(Edit{scene.cone_span.file, scene.cone_span.offset, scene.cone_span.length, "elliptic"});
      else
        added += " cone=\"elliptic\"";
      if (scene.impratio_span.valid())
        f.edits.push_back(Edit{scene.impratio_span.file, scene.impratio_span.offset, scene.impratio_span.length, "10"});
      else
        added += " impratio=\"10\"";
      if (!added.empty()) f.edits.push_back(Edit{scene.solver_span.file, insert, 0, added});
      return f;
    }
    if (!asset.robot_span.valid()) return std::nullopt;
    const std::string_view text = asset.source(asset.robot_span.file).view();
    const std::size_t close = text.find('>', asset.robot_span.offset);
    if (close == std::string_view::npos || text[close - 1] == '/') return std::nullopt;
    // The new element goes on its own line, indented like the line after the start tag.
    std::size_t line = text.find('\n', close);
    if (line == std::string_view::npos) return std::nullopt;
    std::size_t indent_end = line + 1;
    while (indent_end < text.size() && (text[indent_end] == ' ' || text[indent_end] == '\t')) ++indent_end;
    const bool crlf = text[line - 1] == '\r';
    const std::string indent(text.substr(line + 1, indent_end - line - 1));
    f.edits.push_back(Edit{asset.robot_span.file, line + 1, 0,
                           indent + "<option cone=\"elliptic\" impratio=\"10\"/>" + (crlf ? "\r\n" : "\n")});
    return f;
  }

  RuleInfo info_{"grasp-slip",
                 "An MJCF gripper under MuJoCo's default contact options (pyramidal cone, impratio 1, no noslip): "
                 "held objects creep out",
                 Severity::Warning, true, RuleOrigin::Check, {}};
};

}  // namespace

const Rule& grasp_slip() {
  static const GraspSlip rule;
  return rule;
}

}  // namespace assetlint::rules
