#include "pipeline/variant_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <tuple>
#include <utility>

#include "formats/usda/usd_reader.h"
#include "pipeline/variant_label.h"

namespace assetlint {
namespace {

// Compositions beyond the authored one, at most: sets of many variants each multiply the work.
constexpr std::size_t kMaxVariantCompositions = 32;

using Choice = VariantChoice;

struct Pending {
  std::vector<Choice> choices;  // beyond the configured pins; the last one is the variant under test
};

// What the stage selects in the sets a label names: "PhysX=Disabled", "PhysX: none".
std::string authored_selection(const std::vector<usda::VariantSetUse>& sets, const std::vector<Choice>& choices) {
  std::string out;
  for (const Choice& choice : choices) {
    const std::string& set = choice.first;
    auto use = std::find_if(sets.begin(), sets.end(), [&](const usda::VariantSetUse& u) { return u.set == set; });
    if (use == sets.end()) continue;
    out += fmt::format("{}{}", out.empty() ? "" : ", ",
                       use->selection.empty() ? set + " selects no variant" : set + "=" + use->selection);
  }
  return out;
}

class VariantChecker {
 public:
  VariantChecker(const std::shared_ptr<const SourceFile>& root, const FileSystem& files,
                 const usda::ComposeOptions& options)
      : root_(root), files_(files), options_(options) {}

  VariantRun run(const std::vector<usda::VariantSetUse>& authored_sets, const StageCheck* check,
                 std::vector<std::shared_ptr<const SourceFile>>* sources, std::vector<Diagnostic>* diagnostics,
                 std::set<FileId>* unparsable) {
    authored_ = authored_sets;
    if (diagnostics)
      for (const Diagnostic& d : *diagnostics) authored_keys_.insert(key(*sources, d));
    discover(authored_sets, {});
    std::size_t composed = 0;
    for (std::size_t next = 0; next < pending_.size() && composed < kMaxVariantCompositions; ++next, ++composed) {
      const Pending p = pending_[next];
      usda::ComposeOptions options = options_;
      for (const auto& [set, variant] : p.choices) options.pinned_variants[set] = variant;
      usda::Stage stage = usda::compose_stage(root_, files_, options);
      const std::string& set = p.choices.back().first;
      const std::string& variant = p.choices.back().second;
      const bool physics = std::any_of(stage.variant_sets.begin(), stage.variant_sets.end(), [&](const auto& u) {
        return u.set == set && u.selection == variant && u.physics;
      });
      discover(stage.variant_sets, p.choices);
      const std::string label = selection_label(p.choices);
      if (!physics) {
        run_.without_physics.push_back(label);
        continue;
      }
      run_.checked.push_back(label);
      if (!check) continue;
      ReadResult read = usda::read_stage(std::move(stage));
      std::set<FileId> broken;
      std::vector<Diagnostic> found = (*check)(read, broken);
      const std::vector<FileId> ids = merge_sources(read.asset.sources, *sources);
      for (FileId id : broken) unparsable->insert(ids.at(id));
      for (Diagnostic& d : found) add(remapped(std::move(d), ids), *sources, p.choices);
    }
    if (diagnostics) finish(*diagnostics);
    return std::move(run_);
  }

 private:
  // rule, layer, offset, severity and the message with its numbers blanked: the same finding
  // at the same place, whatever numbers a variant's masses put in it (an arm's drive judged
  // with each gripper a variant selects is one finding, not one per gripper).
  using Key = std::tuple<std::string, std::string, std::size_t, int, std::string>;

  static Key key(const std::vector<std::shared_ptr<const SourceFile>>& sources, const Diagnostic& d) {
    const std::string layer = d.span.file < sources.size() ? sources[d.span.file]->path() : std::string();
    return {d.rule, layer, d.span.offset, static_cast<int>(d.severity), without_numbers(d.message)};
  }

  static std::string without_numbers(const std::string& message) {
    std::string out;
    for (std::size_t i = 0; i < message.size(); ++i) {
      const char c = message[i];
      if (std::isdigit(static_cast<unsigned char>(c))) {
        if (out.empty() || out.back() != '#') out += '#';
        continue;
      }
      // The point, sign and exponent of a number belong to it.
      const bool inside = !out.empty() && out.back() == '#' && i + 1 < message.size() &&
                          std::isdigit(static_cast<unsigned char>(message[i + 1])) &&
                          (c == '.' || c == 'e' || c == '-' || c == '+');
      if (!inside) out += c;
    }
    return out;
  }

  // Queues each variant of the sets first seen here that the composition does not already select.
  void discover(const std::vector<usda::VariantSetUse>& sets, const std::vector<Choice>& base) {
    std::vector<std::string> names;
    for (const usda::VariantSetUse& use : sets) {
      if (std::find(names.begin(), names.end(), use.set) != names.end()) continue;
      names.push_back(use.set);
      if (!seen_sets_.insert(use.set).second) continue;
      run_.sets.push_back(use);
      if (options_.pinned_variants.count(use.set)) continue;
      std::vector<std::string> variants;
      for (const usda::VariantSetUse& u : sets)
        if (u.set == use.set)
          for (const std::string& v : u.variants)
            if (std::find(variants.begin(), variants.end(), v) == variants.end()) variants.push_back(v);
      for (const std::string& v : variants) {
        const bool selected_everywhere = std::all_of(sets.begin(), sets.end(), [&](const usda::VariantSetUse& u) {
          return u.set != use.set || u.selection == v;
        });
        if (selected_everywhere) continue;
        Pending p{base};
        p.choices.emplace_back(use.set, v);
        pending_.push_back(std::move(p));
      }
    }
  }

  // The FileIds of a variant composition's sources in the report's sources (appending new layers).
  static std::vector<FileId> merge_sources(const std::vector<std::shared_ptr<const SourceFile>>& from,
                                           std::vector<std::shared_ptr<const SourceFile>>& into) {
    std::vector<FileId> ids;
    for (const auto& source : from) {
      auto it = std::find_if(into.begin(), into.end(), [&](const auto& s) { return s->path() == source->path(); });
      if (it == into.end()) it = into.insert(into.end(), source);
      ids.push_back(static_cast<FileId>(it - into.begin()));
    }
    return ids;
  }

  static Diagnostic remapped(Diagnostic d, const std::vector<FileId>& ids) {
    auto map = [&](FileId& file) {
      if (file != kNoFile && file < ids.size()) file = ids[file];
    };
    map(d.span.file);
    for (Note& n : d.notes) map(n.span.file);
    if (d.fix)
      for (Edit& e : d.fix->edits) map(e.file);
    return d;
  }

  void add(Diagnostic d, const std::vector<std::shared_ptr<const SourceFile>>& sources, const std::vector<Choice>& choices) {
    const Key k = key(sources, d);
    if (authored_keys_.count(k)) return;
    auto [it, fresh] = found_.try_emplace(k, added_.size());
    if (fresh) added_.push_back({std::move(d), {}, {}});
    Added& added = added_[it->second];
    if (!fresh && d.message != added.diagnostic.message)
      added.variant_notes.push_back(fmt::format("With {} selected: {}.", selection_label(choices), d.message));
    added.choices.push_back(choices);
  }

  void finish(std::vector<Diagnostic>& diagnostics) {
    for (auto& [d, choices, variant_notes] : added_) {
      std::vector<Choice> sets;
      for (const auto& c : choices)
        for (const Choice& choice : c)
          if (std::none_of(sets.begin(), sets.end(), [&](const Choice& s) { return s.first == choice.first; }))
            sets.push_back(choice);
      std::string joined;
      for (const auto& c : choices) joined += (joined.empty() ? "" : "; ") + selection_label(c);
      d.message = variant_prefix(choices) + d.message;
      d.notes.insert(d.notes.begin(),
                     Note{fmt::format("Found with {} selected; the stage itself selects {}. asset-lint checks each "
                                      "variant whose opinions carry physics.",
                                      choices.size() == 1 ? joined : "each of " + joined,
                                      authored_selection(authored_, sets)),
                          Span{}});
      for (std::size_t i = 0; i < variant_notes.size(); ++i)
        d.notes.insert(d.notes.begin() + 1 + static_cast<std::ptrdiff_t>(i), Note{variant_notes[i], Span{}});
      diagnostics.push_back(std::move(d));
    }
  }

  struct Added {
    Diagnostic diagnostic;
    std::vector<std::vector<Choice>> choices;
    std::vector<std::string> variant_notes;  // the same finding in another selection, in its own numbers
  };

  const std::shared_ptr<const SourceFile>& root_;
  const FileSystem& files_;
  const usda::ComposeOptions& options_;
  VariantRun run_;
  std::vector<usda::VariantSetUse> authored_;
  std::set<std::string> seen_sets_;
  std::vector<Pending> pending_;
  std::set<Key> authored_keys_;
  std::map<Key, std::size_t> found_;
  std::vector<Added> added_;
};

}  // namespace

VariantRun check_physics_variants(const std::shared_ptr<const SourceFile>& root, const FileSystem& files,
                                  const usda::ComposeOptions& options,
                                  const std::vector<usda::VariantSetUse>& authored_sets, const StageCheck& check,
                                  std::vector<std::shared_ptr<const SourceFile>>& sources,
                                  std::vector<Diagnostic>& diagnostics, std::set<FileId>& unparsable) {
  return VariantChecker(root, files, options).run(authored_sets, &check, &sources, &diagnostics, &unparsable);
}

VariantRun plan_physics_variants(const std::shared_ptr<const SourceFile>& root, const FileSystem& files,
                                 const usda::ComposeOptions& options) {
  const usda::Stage stage = usda::compose_stage(root, files, options);
  return VariantChecker(root, files, options).run(stage.variant_sets, nullptr, nullptr, nullptr, nullptr);
}

}  // namespace assetlint
