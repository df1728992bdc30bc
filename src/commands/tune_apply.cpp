#include "commands/tune_apply.h"

#include <fmt/format.h>

#include <filesystem>
#include <map>

#include "config/config.h"
#include "config/toml_edit.h"
#include "engine/file_system.h"
#include "pipeline/lint.h"
#include "fix/diff.h"
#include "fix/edits.h"
#include "fix/fixer.h"
#include "fix/writer.h"
#include "formats/mjcf/mjcf_edit.h"
#include "formats/urdf/urdf_edit.h"
#include "formats/usda/usda_edit.h"
#include "util/numbers.h"

namespace assetlint::commands {
namespace {

namespace fs = std::filesystem;

// How each recommended value is written: force rounded up (a bound the payload needs),
// the others to the digits a person would write.
std::string force_text(double authored) { return format_number_rounded_up(authored, 3); }
std::string velocity_text(double authored) { return format_number(authored, 3); }
std::string gain_text(double authored) { return format_number(authored, 4); }

// The same number already there: nothing to write (applying twice changes nothing).
bool same_number(const Quantity& q, const std::string& text) {
  const auto value = parse_double(text);
  return value && *value == q.authored;
}

class Planner {
 public:
  Planner(const TuneDerivation& d, const ReadResult& read, const Settings& settings,
          const std::optional<std::string>& config_path)
      : d_(d), read_(read), asset_(read.asset), settings_(settings), config_path_(config_path), joint_(*d.joint) {
    scope_ = fix::default_scope(d.path);
  }

  ApplyPlan run() {
    if (asset_.format == SourceFormat::Urdf) urdf();
    else if (asset_.format == SourceFormat::Mjcf) mjcf();
    else usd();
    if (plan_.error) return std::move(plan_);
    if (read_.relocate) through_xacro();
    for (auto& [file, edits] : edits_) {
      const SourceFile& source = asset_.source(file);
      if (!scope_(source.path())) {
        plan_.notes.push_back(fmt::format("{} lies outside the asset's directory: not edited", source.path()));
        continue;
      }
      PlannedFile planned{source.path(), source.text(), fix::apply_edits(source.view(), edits), false,
                          std::move(changes_[file])};
      if (planned.updated != planned.original) plan_.files.push_back(std::move(planned));
    }
    if (asset_.format == SourceFormat::Urdf) config_table();
    check_still_parses();
    return std::move(plan_);
  }

 private:
  void edit(const Span& span, std::string text, std::string change) {
    edits_[span.file].push_back(Edit{span.file, span.offset, span.length, std::move(text)});
    changes_[span.file].push_back(std::move(change));
  }
  void insert(FileId file, std::size_t offset, std::string text, std::string change) {
    edits_[file].push_back(Edit{file, offset, 0, std::move(text)});
    changes_[file].push_back(std::move(change));
  }

  // The edits were made on a xacro file's expansion: each moves to the literal in the xacro
  // source that wrote the value, as a finding's fix does, or is dropped with the reason.
  void through_xacro() {
    std::vector<Diagnostic> carriers;
    std::vector<std::string> changes;
    for (auto& [file, edits] : edits_)
      for (std::size_t i = 0; i < edits.size(); ++i) {
        const Edit& e = edits[i];
        Diagnostic carrier;
        carrier.span = Span{e.file, e.offset, e.length, 0, 0};
        carrier.fix = Fix{changes_[file][i], Applicability::Safe, {e}};
        carriers.push_back(std::move(carrier));
        changes.push_back(changes_[file][i]);
      }
    const std::vector<std::shared_ptr<const SourceFile>> files = read_.relocate(carriers);
    edits_.clear();
    changes_.clear();
    for (std::size_t i = 0; i < carriers.size(); ++i) {
      const Diagnostic& d = carriers[i];
      if (!d.fix) {
        std::string why = "the xacro source does not write it as a literal";
        for (const Note& n : d.notes)
          if (n.message.starts_with("No fix through xacro: ")) why = n.message.substr(22);
          else if (n.message.starts_with("The fix of this finding")) why = "another value rewrites the same literal";
        if (why.ends_with(".")) why.pop_back();
        plan_.notes.push_back(fmt::format("{} not written: {}", changes[i], why));
        continue;
      }
      for (const Edit& e : d.fix->edits) {
        const FileId in_asset = source_id(*files.at(e.file));
        edits_[in_asset].push_back(Edit{in_asset, e.offset, e.length, e.replacement});
      }
      changes_[source_id(*files.at(d.fix->edits.front().file))].push_back(changes[i]);
    }
  }
  FileId source_id(const SourceFile& file) const {
    for (FileId id = 0; id < asset_.sources.size(); ++id)
      if (asset_.sources[id].get() == &file) return id;
    return kNoFile;
  }

  // A quantity literal rewritten, when the number differs.
  void rewrite(const Quantity& q, const std::string& text, std::string_view what) {
    if (same_number(q, text)) return;
    edit(q.span, text, fmt::format("{} {} → {}", what, format_number(q.authored, 6), text));
  }

  void urdf() {
    const TuneRecommendation& r = d_.recommended;
    const auto limit_attribute = [&](const OptQuantity& q, std::optional<double> value, const char* attribute,
                                     const std::string& text) {
      if (!value) return;
      if (q && q->span.valid()) return rewrite(*q, text, fmt::format("<limit {}>", attribute));
      if (!joint_.limit_span.valid()) {
        plan_.notes.push_back(fmt::format("joint '{}' has no <limit> element: add {}=\"{}\" by hand",
                                          joint_.name.text, attribute, text));
        return;
      }
      const auto at = urdf::start_tag_close(asset_.source(joint_.limit_span.file).view(), joint_.limit_span.offset);
      if (!at) return;
      insert(joint_.limit_span.file, *at, fmt::format(" {}=\"{}\"", attribute, text),
             fmt::format("<limit {}> = {}", attribute, text));
    };
    if (r.max_force) limit_attribute(joint_.effort, r.max_force, "effort", force_text(*r.max_force));
    if (r.max_velocity) limit_attribute(joint_.velocity, r.max_velocity, "velocity", velocity_text(*r.max_velocity));
  }

  // [drives.<joint>] of the nearest asset-lint.toml (or --config's), created beside the
  // asset when there is none: URDF has no place for drive gains.
  void config_table() {
    const TuneRecommendation& r = d_.recommended;
    std::vector<config::TomlValue> values;
    if (r.stiffness) values.push_back({"stiffness", gain_text(*r.stiffness), true});
    if (r.damping) values.push_back({"damping", gain_text(*r.damping), true});
    // A configured max_force wins over <limit effort>: keep the two the same.
    if (r.max_force) values.push_back({"max_force", force_text(*r.max_force), false});
    if (values.empty()) return;
    std::string path = config_path_ ? *config_path_ : config::discover(d_.path).string();
    const bool create = path.empty();
    if (create) path = (fs::path(d_.path).parent_path() / config::kFileName).string();
    std::string original;
    if (!create) {
      std::string error;
      auto text = disk().read(path, error);
      if (!text) {
        plan_.error = fmt::format("cannot read '{}': {}", path, error);
        return;
      }
      original = std::move(*text);
    }
    config::TomlEdit edited = config::set_table_numbers(original, "drives", joint_.name.text, values);
    if (edited.error) {
      plan_.error = fmt::format("{}:{}", path, *edited.error);
      return;
    }
    if (edited.text == original) return;
    plan_.files.push_back(PlannedFile{path, original, edited.text, create, edited.changes});
  }

  void usd() {
    const TuneRecommendation& r = d_.recommended;
    if (!joint_.drive) {
      plan_.notes.push_back(fmt::format("joint '{}' has no PhysicsDriveAPI: stiffness, damping and max force are "
                                        "not written",
                                        joint_.name.text));
    } else {
      const Drive& drive = *joint_.drive;
      const std::string ns = "drive:" + drive.instance + ":physics:";
      // New attributes go beside one the drive already authors, in the same prim spec.
      const Quantity* anchor = nullptr;
      for (const OptQuantity* q : {&drive.stiffness, &drive.damping, &drive.max_force})
        if (*q && (*q)->span.valid() && !anchor) anchor = &**q;
      const auto set = [&](const OptQuantity& q, std::optional<double> value, const char* name, Unit unit,
                           std::string (*text_of)(double)) {
        if (!value) return;
        if (q && q->span.valid()) return rewrite(*q, text_of(q->authored_for(*value)), ns + name);
        if (!anchor || !is_angular(joint_.type)) {
          plan_.notes.push_back(fmt::format("joint '{}' does not author {}{}: add it by hand", joint_.name.text, ns,
                                            name));
          return;
        }
        Quantity model = *anchor;  // the stage's scale of the drive's torques
        model.unit = unit;
        const std::string text = text_of(model.authored_for(*value));
        const auto line = usda::attribute_before(asset_.source(anchor->span.file).view(), anchor->span.offset,
                                                fmt::format("float {}{} = {}", ns, name, text));
        insert(anchor->span.file, line.offset, line.text, fmt::format("{}{} = {}", ns, name, text));
      };
      set(drive.max_force, r.max_force, "maxForce", Unit::NewtonMeter, force_text);
      set(drive.stiffness, r.stiffness, "stiffness", Unit::NewtonMeterPerDegree, gain_text);
      set(drive.damping, r.damping, "damping", Unit::NewtonMeterSecondPerDegree, gain_text);
    }
    if (r.max_velocity) {
      if (joint_.velocity && joint_.velocity->span.valid())
        rewrite(*joint_.velocity, velocity_text(joint_.velocity->authored_for(*r.max_velocity)),
                "physxJoint:maxJointVelocity");
      else
        plan_.notes.push_back(fmt::format(
            "joint '{}' authors no physxJoint:maxJointVelocity (PhysxJointAPI): add {} by hand", joint_.name.text,
            velocity_text(from_model_units(*r.max_velocity, is_angular(joint_.type) ? Unit::DegreePerSecond
                                                                                    : Unit::MeterPerSecond))));
    }
    // The guide: no max joint velocity on mimic joints; the driven joint's bounds them.
    for (const Joint* mimic : d_.mimics) {
      if (!mimic->velocity || !mimic->velocity->declaration.valid()) continue;
      const Span& s = mimic->velocity->declaration;
      edit(s, "", fmt::format("physxJoint:maxJointVelocity removed from mimic '{}'", mimic->name.text));
    }
  }

  // MJCF: the actuator's own kp, kv and forcerange. A value read from biasprm or from a
  // default class other elements share is left for the author, with a note.
  void mjcf() {
    const TuneRecommendation& r = d_.recommended;
    if (!joint_.drive) {
      plan_.notes.push_back(fmt::format("joint '{}' has no <position> or affine <general> actuator: stiffness, "
                                        "damping and max force are not written",
                                        joint_.name.text));
    } else {
      const Drive& drive = *joint_.drive;
      const auto gain = [&](const OptQuantity& q, std::optional<double> value, const char* attribute) {
        if (!value) return;
        if (!q || !q->span.valid() || !mjcf::read_from_attribute(asset_.source(q->span.file), *q, attribute)) {
          plan_.notes.push_back(fmt::format("the actuator of joint '{}' writes no {}=\"…\" of its own (it comes from "
                                            "biasprm, or the joint's damping adds to it): set {} by hand",
                                            joint_.name.text, attribute, gain_text(*value)));
          return;
        }
        if (shared(*q, attribute)) return;
        rewrite(*q, gain_text(q->authored_for(*value)), fmt::format("<actuator {}>", attribute));
      };
      gain(drive.stiffness, r.stiffness, "kp");
      gain(drive.damping, r.damping, "kv");
      if (r.max_force) max_force_range(drive, *r.max_force);
    }
    if (r.max_velocity)
      plan_.notes.push_back(fmt::format("MuJoCo has no joint velocity limit: the recommended {} {} for joint '{}' is "
                                        "not written",
                                        velocity_text(*r.max_velocity),
                                        unit_symbol(is_angular(joint_.type) ? Unit::RadianPerSecond : Unit::MeterPerSecond),
                                        joint_.name.text));
  }

  void max_force_range(const Drive& drive, double max_force) {
    if (!drive.max_force || !drive.max_force->span.valid()) {
      plan_.notes.push_back(fmt::format("the actuator of joint '{}' has no forcerange: add forcerange=\"-{} {}\" by "
                                        "hand",
                                        joint_.name.text, force_text(max_force), force_text(max_force)));
      return;
    }
    const Quantity& bound = *drive.max_force;
    if (shared(bound, "forcerange")) return;
    const SourceFile& source = asset_.source(bound.span.file);
    const auto range = mjcf::rescaled_range(source, bound, std::abs(bound.authored_for(max_force)), force_text);
    if (!range) {
      plan_.notes.push_back(fmt::format("the forcerange of joint '{}' is not two numbers: set ±{} by hand",
                                        joint_.name.text, force_text(max_force)));
      return;
    }
    const std::string_view old_text = source.view().substr(range->offset, range->length);
    if (old_text == range->replacement) return;
    changes_[range->file].push_back(fmt::format("<actuator forcerange> {} → {}", old_text, range->replacement));
    edits_[range->file].push_back(*range);
  }

  // A value written once for several elements (an MJCF default class): not edited here.
  bool shared(const Quantity& q, const char* attribute) {
    const InheritedLiteral* literal = asset_.shared_literal_at(q.span);
    if (!literal) return false;
    plan_.notes.push_back(fmt::format("{} of joint '{}' is written once, in {}, which {} elements use: not edited; "
                                      "give its actuator its own {}",
                                      attribute, joint_.name.text, literal->owner, literal->uses, attribute));
    return true;
  }

  // The edited asset must read as before: never leave an unparsable file.
  void check_still_parses() {
    if (asset_.format != SourceFormat::Usda && asset_.format != SourceFormat::Urdf &&
        asset_.format != SourceFormat::Mjcf)
      return;
    OverlayFileSystem overlay(disk());
    bool asset_changed = false;
    for (const PlannedFile& f : plan_.files) {
      if (f.create || f.path.ends_with(config::kFileName)) continue;
      overlay.set(f.path, f.updated);
      asset_changed = true;
    }
    if (!asset_changed) return;
    Settings reader = settings_;
    reader.selection.select = {"parse-error", "urdf-invalid"};
    const FileReport after = lint_file(d_.path, reader, overlay);
    if (after.error || !after.diagnostics.empty())
      plan_.error = fmt::format("internal error: the edits would make {} unreadable; nothing written", d_.path);
  }

  const TuneDerivation& d_;
  const ReadResult& read_;
  const Asset& asset_;
  const Settings& settings_;
  const std::optional<std::string>& config_path_;
  const Joint& joint_;
  fix::EditScope scope_;
  std::map<FileId, std::vector<Edit>> edits_;
  std::map<FileId, std::vector<std::string>> changes_;
  ApplyPlan plan_;
};

std::string diff_label(const char* prefix, const std::string& path) {
  std::string p = path;
  while (p.starts_with("./") || p.starts_with("/")) p.erase(0, p.starts_with("/") ? 1 : 2);
  return prefix + p;
}

}  // namespace

ApplyPlan plan_tune_apply(const TuneDerivation& derivation, const ReadResult& read, const Settings& settings,
                          const std::optional<std::string>& config_path) {
  return Planner(derivation, read, settings, config_path).run();
}

int carry_out(const ApplyPlan& plan, bool diff, std::ostream& out, std::ostream& err) {
  for (const auto& note : plan.notes) err << "asset-lint tune: note: " << note << "\n";
  if (plan.error) {
    err << "asset-lint tune: error: " << *plan.error << "\n";
    return 2;
  }
  if (diff) {
    for (const PlannedFile& f : plan.files)
      out << fix::unified_diff(f.original, f.updated, f.create ? "/dev/null" : diff_label("a/", f.path),
                               diff_label("b/", f.path));
    return plan.files.empty() ? 0 : 1;
  }
  for (const PlannedFile& f : plan.files) {
    const auto problem = f.create ? fix::create_atomically(f.path, f.updated)
                                  : fix::write_atomically(f.path, f.original, f.updated);
    if (problem) {
      err << "asset-lint tune: error: " << *problem << "\n";
      return 2;
    }
    for (const auto& change : f.changes) err << fmt::format("asset-lint tune: {}: {}\n", f.path, change);
  }
  if (plan.files.empty()) err << "asset-lint tune: nothing to change\n";
  return 0;
}

}  // namespace assetlint::commands
