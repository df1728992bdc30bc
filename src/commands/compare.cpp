#include "commands/compare.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <map>
#include <limits>

#include "commands/compare_names.h"
#include "model/poses.h"
#include "rules/compare_rules.h"
#include "rules/drive_support.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::commands {
namespace {

// How close a ratio must be to a named slip to be called that slip.
constexpr double kSlipTolerance = 1e-3;

Span shifted(Span span, FileId offset) {
  if (span.file != kNoFile) span.file += offset;
  return span;
}

std::string format_name(SourceFormat f) {
  switch (f) {
    case SourceFormat::Urdf: return "URDF";
    case SourceFormat::Usda: return "USD";
    case SourceFormat::Mjcf: return "MJCF";
  }
  return "";
}

// What the ratio a/b looks like, or empty.
std::string slip_name(double ratio) {
  const double degrees_per_radian = degrees_from_radians(1.0);
  auto near = [](double value, double target) { return std::abs(value / target - 1.0) <= kSlipTolerance; };
  if (near(ratio, degrees_per_radian) || near(ratio, 1.0 / degrees_per_radian))
    return "a degree/radian slip (ratio 180/π)";
  if (near(ratio, -1.0)) return "a sign flip";
  if (near(ratio, 1000.0) || near(ratio, 1e-3)) return "a factor of 1000 (mm/m or g/kg)";
  return {};
}

// A quantity as written and, when the file's unit converts, in model units.
std::string as_written(const Quantity& q) {
  const auto symbol = [](Unit u) {
    const auto s = unit_symbol(u);
    return s.empty() ? std::string() : " " + std::string(s);
  };
  const Unit model = model_unit(q.unit);
  const std::string model_text = format_number(q.value, 6) + symbol(model);
  if (!q.is_authored()) return model_text + " (not written in the file: a default or asset-lint.toml)";
  const std::string written = format_number(q.authored, 6) + symbol(q.unit);
  if (written == model_text) return written;
  return fmt::format("{} as written ({} in model units)", written, model_text);
}

class Comparer {
 public:
  Comparer(const Asset& a, const Asset& b, FileId offset, const CompareOptions& options, bool fix_b, bool fix)
      : a_(a), b_(b), offset_(offset), options_(options), fix_b_(fix_b), fix_(fix) {}

  Comparison run() {
    summary_.file_a = file_a();
    summary_.file_b = file_b();
    summary_.format_a = format_name(a_.format);
    summary_.format_b = format_name(b_.format);
    compare_joints();
    compare_links();
    compare_rate();
    return {std::move(out_), std::move(summary_)};
  }

 private:
  std::string file_a() const { return a_.sources.empty() ? "" : a_.source(0).path(); }
  std::string file_b() const { return b_.sources.empty() ? "" : b_.source(0).path(); }

  // One difference in `what` ("upper limit"), `slip` naming it when it is one.
  Diagnostic& report(const std::string& what, const std::string& slip, const Span& at_a, const Span& at_b,
                     std::string message) {
    ComparisonSummary::Difference& counted = summary_.differences[what];
    ++counted.count;
    if (!slip.empty()) ++counted.slips[slip];
    Diagnostic d{std::string(rules::kCompareMismatch.id), rules::kCompareMismatch.default_severity, at_a, std::move(message),
                 std::nullopt, {}, {}, {}};
    out_.push_back(std::move(d));
    Diagnostic& added = out_.back();
    added.note(shifted(at_b, offset_), fmt::format("the counterpart in {} ({})", file_b(), format_name(b_.format)));
    return added;
  }

  bool differs(double x, double y) const {
    const double scale = std::max(std::abs(x), std::abs(y));
    return std::abs(x - y) > options_.rtol * scale;
  }

  // Compares one scalar both files give; `what` reads "stiffness", `owner` "'finger_joint'".
  void scalar(const std::string& what, const std::string& owner, const Quantity& qa, const Span& fa, const Quantity& qb,
              const Span& fb) {
    ++summary_.values_compared;
    if (!differs(qa.value, qb.value)) return;
    const double ratio = qb.value != 0 ? qa.value / qb.value : std::numeric_limits<double>::infinity();
    const std::string slip = std::isfinite(ratio) ? slip_name(ratio) : std::string();
    const Unit model = model_unit(qa.unit);
    const std::string symbol = unit_symbol(model).empty() ? "" : " " + std::string(unit_symbol(model));
    std::string message = fmt::format("{} of {} differs: {}{} vs {}{}", what, owner, format_number(qa.value, 4), symbol,
                                      format_number(qb.value, 4), symbol);
    if (!slip.empty()) message += ": " + slip;
    Diagnostic& d = report(what, slip, qa.span.valid() ? qa.span : fa, qb.span.valid() ? qb.span : fb, std::move(message));
    d.note(fmt::format("{} ({}): {}.", file_a(), format_name(a_.format), as_written(qa)));
    d.note(fmt::format("{} ({}): {}.", file_b(), format_name(b_.format), as_written(qb)));
    if (std::isfinite(ratio)) d.note(fmt::format("Ratio {} / {} = {}.", format_name(a_.format), format_name(b_.format),
                                                 format_number(ratio, 6)));
    const Quantity& target = fix_b_ ? qb : qa;
    const Quantity& source = fix_b_ ? qa : qb;
    if (fix_ && target.span.valid()) {
      Edit edit = rules::replace_value(target, source.value);
      if (fix_b_) edit.file += offset_;
      d.fix = Fix{fmt::format("set {} of {} in {} to {} (the other file's value)", what, owner,
                              fix_b_ ? file_b() : file_a(), edit.replacement),
                  Applicability::Unsafe, {edit}};
    }
  }

  void optional(const std::string& what, const std::string& owner, const OptQuantity& qa, const Span& fa,
                const OptQuantity& qb, const Span& fb) {
    if (qa && qb) scalar(what, owner, *qa, fa, *qb, fb);
  }

  static std::string kind(JointType t) {
    if (t == JointType::Continuous) return std::string(joint_type_name(JointType::Revolute));
    return std::string(joint_type_name(t));
  }

  void compare_joints() {
    std::vector<const Joint*> ja, jb;
    for (const Joint& j : a_.joints)
      if (j.type != JointType::Fixed) ja.push_back(&j);
    for (const Joint& j : b_.joints)
      if (j.type != JointType::Fixed) jb.push_back(&j);
    const NameMatch match = match_names(names(ja), names(jb), options_.map);
    for (auto [i, j] : match.pairs) joint_pairs_[ja[i]->name.text] = jb[j]->name.text;
    for (auto [i, j] : match.pairs) compare_joint(*ja[i], *jb[j]);
    summary_.joints_paired = match.pairs.size();
    summary_.joints_only_a = match.only_a.size();
    summary_.joints_only_b = match.only_b.size();
    unmatched("joint", ja, match.only_a, file_b(), 0);
    unmatched("joint", jb, match.only_b, file_a(), offset_);
  }

  template <class T>
  static std::vector<std::string> names(const std::vector<const T*>& items) {
    std::vector<std::string> out;
    for (const T* item : items) out.push_back(item->name.text);
    return out;
  }

  template <class T>
  void unmatched(const char* what, const std::vector<const T*>& items, const std::vector<std::size_t>& only,
                 const std::string& other, FileId offset) {
    for (std::size_t i : only) {
      out_.push_back({std::string(rules::kCompareUnmatched.id), rules::kCompareUnmatched.default_severity,
                      shifted(items[i]->name.span, offset),
                      fmt::format("{} '{}' has no counterpart in {}", what, items[i]->name.text, other), std::nullopt, {}, {}, {}});
      out_.back().note("Pair it with `--map NAME=OTHER_NAME` (first file's name first) if the other file names it differently.");
    }
  }

  static Eigen::Vector3d world_axis(const Joint& j, const std::map<std::string, Eigen::Isometry3d, std::less<>>& poses,
                                    bool& known) {
    auto child = poses.find(j.child.text);
    known = child != poses.end();
    if (!known) return j.axis;
    return child->second.linear() * j.frame_in_link[1].linear() * j.axis;
  }

  void compare_joint(const Joint& ja, const Joint& jb) {
    const std::string owner = fmt::format("'{}'", last_component(ja.name.text));
    if (kind(ja.type) != kind(jb.type)) {
      Diagnostic& d = report("joint type", "", ja.type_span, jb.type_span,
                             fmt::format("joint type of {} differs: {} vs {}", owner, kind(ja.type), kind(jb.type)));
      d.note("The other quantities of this joint are not compared.");
      return;
    }
    if (poses_a_.empty()) poses_a_ = link_poses(a_);
    if (poses_b_.empty()) poses_b_ = link_poses(b_);
    bool known_a = false, known_b = false;
    const Eigen::Vector3d ua = world_axis(ja, poses_a_, known_a), ub = world_axis(jb, poses_b_, known_b);
    if (known_a && known_b && is_single_dof(ja.type)) ++summary_.values_compared;
    if (known_a && known_b && is_single_dof(ja.type) && (ua - ub).norm() > std::max(options_.rtol, 1e-9)) {
      const bool flipped = (ua + ub).norm() <= std::max(options_.rtol, 1e-9);
      Diagnostic& d = report("axis", flipped ? "a sign flip" : "", ja.axis_span, jb.axis_span,
                             fmt::format("axis of {} differs: ({}) vs ({}){}", owner, vec(ua), vec(ub),
                                         flipped ? ": a sign flip" : ""));
      d.note("Both axes are in the frame of the model's root link at the zero configuration.");
      if (flipped) d.note("A flipped axis with negated limits and mimic multipliers is the same joint; here it is not.");
    }
    if (is_single_dof(ja.type)) {
      const bool limited_a = ja.lower && ja.upper, limited_b = jb.lower && jb.upper;
      if (limited_a && limited_b) {
        scalar("lower limit", owner, *ja.lower, ja.limit_span, *jb.lower, jb.limit_span);
        scalar("upper limit", owner, *ja.upper, ja.limit_span, *jb.upper, jb.limit_span);
      } else if (limited_a != limited_b && ja.type != JointType::Continuous && jb.type != JointType::Continuous) {
        report("limits", "", ja.limit_span, jb.limit_span,
               fmt::format("{} is limited in {} only", owner, limited_a ? format_name(a_.format) : format_name(b_.format)));
      }
    }
    optional("max velocity", owner, ja.velocity, ja.limit_span, jb.velocity, jb.limit_span);
    const Quantity* fa = rules::max_force_of(ja);
    const Quantity* fb = rules::max_force_of(jb);
    if (fa && fb && std::isfinite(fa->value) && std::isfinite(fb->value))
      scalar("max force", owner, *fa, ja.limit_span, *fb, jb.limit_span);
    if (ja.drive && jb.drive) {
      optional("drive stiffness", owner, ja.drive->stiffness, ja.drive->span, jb.drive->stiffness, jb.drive->span);
      optional("drive damping", owner, ja.drive->damping, ja.drive->span, jb.drive->damping, jb.drive->span);
    }
    optional("joint damping", owner, ja.joint_damping, ja.span, jb.joint_damping, jb.span);
    armature(owner, ja, jb);
    mimic(owner, ja, jb);
  }

  // No armature anywhere means 0 (PhysX's and MuJoCo's default): one that is lost in a conversion shows.
  void armature(const std::string& owner, const Joint& ja, const Joint& jb) {
    const Unit unit = is_angular(ja.type) ? Unit::KilogramMeter2 : Unit::Kilogram;
    const Quantity za = ja.armature ? *ja.armature : Quantity::unauthored(0.0, unit);
    const Quantity zb = jb.armature ? *jb.armature : Quantity::unauthored(0.0, unit);
    if (za.value == 0 && zb.value == 0) return;
    scalar("armature", owner, za, ja.span, zb, jb.span);
  }

  void mimic(const std::string& owner, const Joint& ja, const Joint& jb) {
    if (!ja.mimic && !jb.mimic) return;
    if (!ja.mimic || !jb.mimic) {
      const Joint& with = ja.mimic ? ja : jb;
      Diagnostic& d = report("mimic", "", ja.mimic ? ja.mimic->span : ja.span, jb.mimic ? jb.mimic->span : jb.span,
                             fmt::format("{} follows '{}' in {} only", owner, last_component(with.mimic->reference.text),
                                         ja.mimic ? format_name(a_.format) : format_name(b_.format)));
      d.note("The other file moves the joint on its own: the coupling is missing there.");
      return;
    }
    const auto paired = joint_pairs_.find(ja.mimic->reference.text);
    if (paired == joint_pairs_.end() || paired->second != jb.mimic->reference.text) {
      report("mimic reference", "", ja.mimic->reference.span, jb.mimic->reference.span,
             fmt::format("{} follows '{}' vs '{}'", owner, last_component(ja.mimic->reference.text),
                         last_component(jb.mimic->reference.text)));
      return;
    }
    scalar("mimic multiplier", owner, ja.mimic->multiplier, ja.mimic->span, jb.mimic->multiplier, jb.mimic->span);
    if (!out_.empty() && out_.back().message.starts_with("mimic multiplier of " + owner) &&
        out_.back().message.ends_with("a sign flip"))
      out_.back().note("USD gearing is −(URDF multiplier) = −(MJCF polycoef c1): q + gearing·q_ref + offset = 0.");
    scalar("mimic offset", owner, ja.mimic->offset, ja.mimic->span, jb.mimic->offset, jb.mimic->span);
  }

  static std::string vec(const Eigen::Vector3d& v) {
    return fmt::format("{}, {}, {}", format_number(v.x(), 4), format_number(v.y(), 4), format_number(v.z(), 4));
  }

  void compare_links() {
    std::vector<const Link*> la, lb;
    for (const Link& l : a_.links) la.push_back(&l);
    for (const Link& l : b_.links) lb.push_back(&l);
    const NameMatch match = match_names(names(la), names(lb), options_.map);
    if (poses_a_.empty()) poses_a_ = link_poses(a_);
    if (poses_b_.empty()) poses_b_ = link_poses(b_);
    for (auto [i, j] : match.pairs) compare_link(*la[i], *lb[j]);
    summary_.links_paired = match.pairs.size();
    summary_.links_only_a = match.only_a.size();
    summary_.links_only_b = match.only_b.size();
    unmatched("link", la, match.only_a, file_b(), 0);
    unmatched("link", lb, match.only_b, file_a(), offset_);
  }

  void compare_link(const Link& la, const Link& lb) {
    if (!la.inertial || !lb.inertial) return;
    const Inertial& ia = *la.inertial;
    const Inertial& ib = *lb.inertial;
    const std::string owner = fmt::format("link '{}'", last_component(la.name.text));
    if (ia.mass_authored && ib.mass_authored) scalar("mass", owner, ia.mass, ia.span, ib.mass, ib.span);
    auto pa = poses_a_.find(la.name.text);
    auto pb = poses_b_.find(lb.name.text);
    if (pa == poses_a_.end() || pb == poses_b_.end()) return;
    const Eigen::Vector3d ca = pa->second * ia.com, cb = pb->second * ib.com;
    const double length = std::max(ca.norm(), cb.norm());
    if (ia.com_span.valid() && ib.com_span.valid()) ++summary_.values_compared;
    if (ia.com_span.valid() && ib.com_span.valid() && (ca - cb).norm() > options_.rtol * std::max(length, 1e-3)) {
      Diagnostic& d = report("centre of mass", "", ia.com_span, ib.com_span,
                             fmt::format("centre of mass of {} differs: ({}) vs ({}) m", owner, vec(ca), vec(cb)));
      d.note("Both are in the frame of the model's root link at the zero configuration.");
    }
    if (!ia.inertia_authored || !ib.inertia_authored) return;
    const Eigen::Matrix3d ta = pa->second.linear() * ia.inertia * pa->second.linear().transpose();
    const Eigen::Matrix3d tb = pb->second.linear() * ib.inertia * pb->second.linear().transpose();
    const double size = std::max(ta.norm(), tb.norm());
    ++summary_.values_compared;
    if ((ta - tb).norm() > options_.rtol * size) {
      const double ratio = tb.norm() > 0 ? ta.norm() / tb.norm() : 0.0;
      const std::string slip = ratio > 0 ? slip_name(ratio) : std::string();
      Diagnostic& d = report("inertia", slip, ia.inertia_span, ib.inertia_span,
                             fmt::format("inertia of {} differs{}", owner, slip.empty() ? "" : ": " + slip));
      d.note(fmt::format("{}: diagonal ({}) kg·m², off-diagonal ({}) in the root frame.", file_a(), vec(ta.diagonal()),
                         vec(Eigen::Vector3d(ta(0, 1), ta(0, 2), ta(1, 2)))));
      d.note(fmt::format("{}: diagonal ({}) kg·m², off-diagonal ({}) in the root frame.", file_b(), vec(tb.diagonal()),
                         vec(Eigen::Vector3d(tb(0, 1), tb(0, 2), tb(1, 2)))));
    }
  }

  void compare_rate() {
    const OptQuantity& ra = a_.scene.timesteps_per_second;
    const OptQuantity& rb = b_.scene.timesteps_per_second;
    if (!ra || !rb || !ra->is_authored() || !rb->is_authored()) return;
    scalar("simulation rate", "the model", *ra, a_.robot_span, *rb, b_.robot_span);
  }

  const Asset& a_;
  const Asset& b_;
  FileId offset_;
  const CompareOptions& options_;
  bool fix_b_;
  bool fix_;
  std::vector<Diagnostic> out_;
  ComparisonSummary summary_;
  std::map<std::string, std::string> joint_pairs_;
  std::map<std::string, Eigen::Isometry3d, std::less<>> poses_a_, poses_b_;
};

}  // namespace

Comparison compare_assets(const Asset& a, const Asset& b, FileId b_offset, const CompareOptions& options, bool fix_b,
                          bool fix_enabled) {
  return Comparer(a, b, b_offset, options, fix_b, fix_enabled).run();
}

std::size_t ComparisonSummary::differing() const {
  std::size_t n = 0;
  for (const auto& [what, difference] : differences) n += difference.count;
  return n;
}

std::vector<std::string> summary_lines(const ComparisonSummary& s) {
  const auto file = [](const std::string& path) { return std::filesystem::path(path).filename().string(); };
  const auto counted = [](std::size_t n, const char* noun) {
    return fmt::format("{} {}{}", n, noun, n == 1 ? "" : "s");
  };
  const auto unpaired = [&](std::size_t joints, std::size_t links, const std::string& format) -> std::string {
    if (joints == 0 && links == 0) return {};
    std::vector<std::string> parts;
    if (joints) parts.push_back(counted(joints, "joint"));
    if (links) parts.push_back(counted(links, "link"));
    return fmt::format("{} only in the {}", fmt::join(parts, " and "), format);
  };
  std::vector<std::string> lines;
  lines.push_back(fmt::format("compare: {} ({}) and {} ({})", file(s.file_a), s.format_a, file(s.file_b), s.format_b));
  std::string paired = fmt::format("  paired {} and {} by name", counted(s.joints_paired, "movable joint"),
                                   counted(s.links_paired, "link"));
  std::vector<std::string> missing;
  for (auto text : {unpaired(s.joints_only_a, s.links_only_a, s.format_a),
                    unpaired(s.joints_only_b, s.links_only_b, s.format_b)})
    if (!text.empty()) missing.push_back(std::move(text));
  if (!missing.empty()) paired += fmt::format("; {}", fmt::join(missing, ", "));
  lines.push_back(paired);
  if (s.differences.empty()) {
    lines.push_back(fmt::format("  all {} compared values agree", s.values_compared));
    return lines;
  }
  std::vector<const std::pair<const std::string, ComparisonSummary::Difference>*> order;
  for (const auto& entry : s.differences) order.push_back(&entry);
  std::stable_sort(order.begin(), order.end(), [](auto* x, auto* y) { return x->second.count > y->second.count; });
  std::vector<std::string> parts;
  for (const auto* entry : order) {
    std::string part = fmt::format("{} ×{}", entry->first, entry->second.count);
    std::vector<std::string> slips;
    for (const auto& [slip, n] : entry->second.slips)
      slips.push_back(n == entry->second.count ? slip : fmt::format("{} of them {}", n, slip));
    if (!slips.empty()) part += fmt::format(" ({})", fmt::join(slips, ", "));
    parts.push_back(std::move(part));
  }
  lines.push_back(fmt::format("  {} of {} compared values differ: {}", s.differing(), s.values_compared,
                              fmt::join(parts, ", ")));
  return lines;
}

FileReport compare_files(const std::vector<std::string>& paths, const SettingsFor& settings,
                         const CompareOptions& options, std::string& error,
                         std::vector<ComparisonSummary>* summaries) {
  FileReport report;
  report.path = paths.empty() ? std::string() : paths.front();
  std::vector<ReadResult> reads;
  for (const auto& path : paths) {
    auto read = read_asset(path, settings(path), error);
    if (!read) return report;
    if (!read->usable) {
      std::string first;
      for (const auto& d : read->diagnostics)
        if (d.severity == Severity::Error) {
          first = fmt::format("{}:{}:{}: {}", read->asset.source(d.span.file).path(), d.span.line, d.span.column, d.message);
          break;
        }
      error = fmt::format("'{}' cannot be compared: {}", path, first.empty() ? "it could not be read as a model" : first);
      return report;
    }
    reads.push_back(std::move(*read));
  }
  for (const auto& r : reads)
    for (const auto& s : r.asset.sources) report.sources.push_back(s);
  FileId offset = static_cast<FileId>(reads.front().asset.sources.size());
  for (std::size_t k = 1; k < reads.size(); ++k) {
    const bool fix_b = options.fix_side == static_cast<int>(k);
    const bool fix = options.fix_side == 0 || fix_b;
    Comparison found = compare_assets(reads.front().asset, reads[k].asset, offset, options, fix_b, fix);
    report.diagnostics.insert(report.diagnostics.end(), std::make_move_iterator(found.diagnostics.begin()),
                              std::make_move_iterator(found.diagnostics.end()));
    if (summaries) summaries->push_back(std::move(found.summary));
    offset += static_cast<FileId>(reads[k].asset.sources.size());
  }
  return report;
}

}  // namespace assetlint::commands
