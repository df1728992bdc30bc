#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// The joints whose axis a consumer reads: urdfdom parses <axis> for every type but fixed and
// floating, and a planar joint's axis is its plane's normal.
bool reads_axis(JointType type) {
  return type == JointType::Revolute || type == JointType::Continuous || type == JointType::Prismatic ||
         type == JointType::Planar;
}

// The numbers of an `xyz` value and where each sits in it, so a fix rewrites only the digits.
struct WrittenAxis {
  std::vector<double> values;
  std::vector<std::pair<std::size_t, std::size_t>> tokens;  // (offset in the value, length)
  int significant = 1;                                      // the most digits any component writes
};

std::optional<WrittenAxis> read_written(std::string_view text) {
  WrittenAxis axis;
  std::size_t at = 0;
  while (at < text.size()) {
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
    if (at == text.size()) break;
    std::size_t end = at;
    while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
    const std::string_view token = text.substr(at, end - at);
    const auto value = parse_double(token);
    if (!value) return std::nullopt;  // a xacro expression or a typo: parse-error owns it
    int digits = 0;
    bool leading = true;
    for (char c : token) {
      if (c == 'e' || c == 'E') break;
      if (!std::isdigit(static_cast<unsigned char>(c))) continue;
      if (c != '0') leading = false;
      if (!leading) ++digits;
    }
    axis.significant = std::max(axis.significant, digits);
    axis.values.push_back(*value);
    axis.tokens.emplace_back(at, end - at);
    at = end;
  }
  if (axis.values.size() != 3) return std::nullopt;
  return axis;
}

class StructureJointAxis final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    if (asset.format != SourceFormat::Urdf) return;
    const double tolerance = rule_option(info_, settings, "tolerance");
    for (const Joint& joint : asset.joints) {
      if (!reads_axis(joint.type) || !joint.axis_span.valid() || joint.axis_span.offset == joint.span.offset) continue;
      const std::string_view text =
          asset.source(joint.axis_span.file).view().substr(joint.axis_span.offset, joint.axis_span.length);
      const auto written = read_written(text);
      if (!written) continue;
      const Eigen::Vector3d v(written->values[0], written->values[1], written->values[2]);
      const double length = v.norm();
      if (!std::isfinite(length)) continue;
      if (length == 0) {
        zero_axis(joint, text, out);
      } else if (std::abs(length - 1) > tolerance) {
        non_unit_axis(joint, text, *written, v, length, out);
      }
    }
  }

 private:
  static void zero_axis(const Joint& joint, std::string_view text, Reporter& out) {
    Diagnostic& d = out.report(joint.axis_span, Severity::Error,
                               fmt::format("{} has axis \"{}\" of length 0: it moves about no direction",
                                           joint_label(joint), text));
    d.note("urdfdom (ROS tools, check_urdf, Gazebo's URDF path) accepts the file and hands the zero vector on; "
           "MuJoCo's compiler refuses it (\"axis too small in joint\", mjCJoint::Compile checks the axis length "
           "against mjEPS before normalising it).");
    d.note("A consumer that normalises the axis divides by zero; one that does not builds a joint whose motion "
           "moves nothing, so the drive and limits act on a frozen body.");
    d.note("Write the direction the joint turns or slides along, for example xyz=\"0 0 1\"; a joint meant to be "
           "rigid is type=\"fixed\".");
  }

  static void non_unit_axis(const Joint& joint, std::string_view text, const WrittenAxis& written, const Eigen::Vector3d& v, double length,
                            Reporter& out) {
    const Eigen::Vector3d unit = v / length;
    const int significant = std::max(written.significant, 4);
    const std::string replacement(text);
    std::string fixed_text;
    std::size_t copied = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      const auto [at, size] = written.tokens[i];
      fixed_text += replacement.substr(copied, at - copied);
      const double component = unit[static_cast<Eigen::Index>(i)];
      fixed_text += component == 0 ? std::string("0") : format_number(component, significant);
      copied = at + size;
    }
    fixed_text += replacement.substr(copied);

    Diagnostic& d = out.report(joint.axis_span, Severity::Warning,
                               fmt::format("{} has axis of length {}, not 1", joint_label(joint),
                                           format_number(length, 4)));
    d.note(fmt::format("|({}, {}, {})| = {}: {} % off a unit vector.", format_number(v.x()), format_number(v.y()),
                       format_number(v.z()), format_number(length, 6), format_number(std::abs(length - 1) * 100, 3)));
    d.note("URDF defines the axis as a unit vector; urdfdom does not normalise it. MuJoCo's compiler normalises it "
           "(mjCJoint::Compile), so there the direction is all that counts; a consumer that uses the vector as it "
           "stands turns the joint by |axis|·q instead of q, and its limits, velocities and gains with it.");
    d.fix = Fix{fmt::format("normalise the axis: xyz=\"{}\"", fixed_text), Applicability::Safe,
                {Edit{joint.axis_span.file, joint.axis_span.offset, joint.axis_span.length, fixed_text}}};
  }

  RuleInfo info_{"structure-joint-axis",
                 "A URDF joint axis of length 0 (error) or not of unit length (warning)",
                 Severity::Error,
                 true,
                 RuleOrigin::Check,
                 {{"tolerance", 1e-3,
                   "Relative difference from unit length under which an axis counts as normalised (0.001: what a "
                   "consumer that does not normalise would scale the joint's motion by, at most 0.1 %)"}}};
};

}  // namespace

const Rule& structure_joint_axis() {
  static const StructureJointAxis rule;
  return rule;
}

}  // namespace assetlint::rules
