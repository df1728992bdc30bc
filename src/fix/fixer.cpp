#include "fix/fixer.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

#include "fix/edits.h"

namespace assetlint::fix {
namespace {

namespace fs = std::filesystem;

// The reader rules whose new findings mean a fix broke the file.
constexpr std::string_view kParseRules[] = {"parse-error", "urdf-invalid"};

fs::path resolved(const std::string& path) {
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec);
  if (ec) absolute = path;
  fs::path canonical = fs::weakly_canonical(absolute, ec);
  return (ec ? absolute : canonical).lexically_normal();
}

bool is_under(const fs::path& path, const fs::path& dir) {
  auto p = path.begin(), d = dir.begin();
  for (; d != dir.end(); ++d, ++p) {
    if (d->empty()) continue;  // a trailing separator
    if (p == path.end() || *p != *d) return false;
  }
  return true;
}

// Fixes are applied in stages: first those that correct what a value means (its unit),
// then its order (lower/upper), then fixes that reason about values, often of another
// joint (a mimic joint's limits from the range of the joint it follows). A round applies
// only the earliest stage that has fixes: fixes are computed from the lint of the
// round's text, so a fix of a later stage applied beside one that changes a value it
// read would write a stale result, which the next round could misread again.
int fix_stage(std::string_view rule) {
  if (rule.starts_with("units-")) return 0;
  if (rule.starts_with("limits-")) return 1;
  return 2;
}

// When the rounds came back to texts they started from, the fixes that undo each other:
// "mimic-max-velocity writes '166' for '2' at a.urdf:15:59, then units-velocity-implausible
// writes '2.9' for '166' at a.urdf:15:59". nullopt when the rounds never repeat.
std::optional<std::string> describe_cycle(const std::vector<FixRound>& rounds) {
  auto shorten = [](std::string_view text) {
    return text.size() > 40 ? std::string(text.substr(0, 37)) + "..." : std::string(text);
  };
  for (std::size_t j = 1; j < rounds.size(); ++j) {
    for (std::size_t k = 0; k < j; ++k) {
      if (rounds[j].texts != rounds[k].texts) continue;
      std::vector<std::string> steps;
      for (std::size_t r = k; r < j; ++r) {
        for (const AppliedFix& fix : rounds[r].applied) {
          if (fix.edits.empty()) continue;
          const AppliedFix::PathEdit& edit = fix.edits.front();
          std::string text;
          for (const auto& [path, round_text] : rounds[r].texts)
            if (path == edit.path) text = round_text;
          const std::size_t offset = std::min(edit.offset, text.size());
          const LineColumn at = SourceFile(edit.path, text).position(offset);
          steps.push_back(fmt::format("{} writes '{}' for '{}' at {}:{}:{}", fix.rule, shorten(edit.replacement),
                                      shorten(std::string_view(text).substr(offset, edit.length)), edit.path, at.line,
                                      at.column));
        }
      }
      std::string list;
      for (std::size_t i = 0; i < steps.size(); ++i) list += (i ? ", then " : "") + steps[i];
      return list;
    }
  }
  return std::nullopt;
}

// A candidate fix of one round: the diagnostic's fix, with its edits' paths.
struct Candidate {
  const Diagnostic* diagnostic = nullptr;
  std::string key;  // identifies the fix across rounds (offsets may move)
  FileId first_file = 0;
  std::size_t first_offset = 0;
};

std::string fix_key(const Diagnostic& d, const FileReport& report) {
  std::string key = d.rule + '\0' + d.fix->title;
  for (const Edit& e : d.fix->edits) {
    const SourceFile& source = report.source(e.file);
    key += '\0' + source.path() + '\0' + std::string(source.view().substr(e.offset, e.length)) + '\0' + e.replacement;
  }
  return key;
}

// The multiset of reader complaints (rule, message) of a reader-only lint.
std::multiset<std::pair<std::string, std::string>> reader_findings(const FileReport& report) {
  std::multiset<std::pair<std::string, std::string>> out;
  for (const auto& d : report.diagnostics) out.emplace(d.rule, d.message);
  if (report.error) out.emplace("error", *report.error);
  return out;
}

bool breaks(const std::multiset<std::pair<std::string, std::string>>& before,
            const std::multiset<std::pair<std::string, std::string>>& after) {
  for (auto it = after.begin(); it != after.end(); it = after.upper_bound(*it))
    if (after.count(*it) > before.count(*it)) return true;
  return false;
}

class Fixer {
 public:
  Fixer(const std::string& path, const Settings& settings, const FixOptions& options, const FileSystem& base)
      : path_(path), settings_(settings), options_(options), base_(base), overlay_(base) {
    scope_ = options.scope ? options.scope : default_scope(path);
    for (auto rule : kParseRules) reader_settings_.selection.select.emplace_back(rule);
  }

  FixResult run() {
    FixResult result;
    result.path = path_;
    result.initial = lint_file(path_, settings_, base_);
    if (options_.on_report && !result.initial.error) options_.on_report(result.initial);
    result.remaining = result.initial;
    if (result.initial.error) {
      result.error = result.initial.error;
      return result;
    }
    FileReport current = result.initial;
    remember_originals(current);
    // Every later lint reads this snapshot, never the disk again.
    auto baseline = reader_findings(lint_file(path_, reader_settings_, overlay_));
    std::map<std::string, std::size_t> fixes_per_path;

    for (;;) {
      std::vector<Candidate> candidates = collect(current, result);
      if (candidates.empty()) break;
      if (static_cast<int>(result.rounds.size()) >= options_.max_rounds) {
        if (auto cycle = describe_cycle(result.rounds))
          result.error = fmt::format("fixes for {} undo each other and never converge: {}; nothing written", path_,
                                     *cycle);
        else
          result.error = fmt::format(
              "fixes for {} did not converge after {} rounds ({} more to apply); nothing written", path_,
              options_.max_rounds, candidates.size());
        result.files.clear();
        result.remaining = result.initial;
        return result;
      }
      std::vector<const Candidate*> accepted = select(candidates);
      std::map<std::string, std::string> texts = apply(current, accepted);
      FileReport after = reader_lint(texts);
      auto after_findings = reader_findings(after);
      if (breaks(baseline, after_findings)) {
        // Keep the fixes that, added one at a time in position order, leave the file
        // parsing as before; the others are broken.
        std::vector<const Candidate*> kept;
        for (const Candidate* c : accepted) {
          kept.push_back(c);
          auto trial = reader_findings(reader_lint(apply(current, kept)));
          if (!breaks(baseline, trial)) continue;
          kept.pop_back();
          blocked_.insert(c->key);
          const Fix& f = *c->diagnostic->fix;
          result.internal_errors.push_back(
              fmt::format("fix '{}' [{}] would make {} unparsable; skipped", f.title, c->diagnostic->rule,
                          current.source(c->first_file).path()));
        }
        accepted = std::move(kept);
        if (accepted.empty()) continue;  // the blocked fixes are no longer candidates
        texts = apply(current, accepted);
        after_findings = reader_findings(reader_lint(texts));
      }

      FixRound round;
      for (const auto& source : current.sources) round.texts.emplace_back(source->path(), source->text());
      for (const Candidate* c : accepted) {
        const Diagnostic& d = *c->diagnostic;
        AppliedFix applied{d.rule, d.fix->title, d.fix->applicability, {}};
        std::set<std::string> paths;
        for (const Edit& e : d.fix->edits) {
          const std::string& p = current.source(e.file).path();
          applied.edits.push_back({p, e.offset, e.length, e.replacement});
          paths.insert(p);
        }
        for (const auto& p : paths) ++fixes_per_path[p];
        round.applied.push_back(std::move(applied));
      }
      result.applied += accepted.size();
      result.rounds.push_back(std::move(round));
      for (auto& [p, text] : texts) overlay_.set(p, std::move(text));
      baseline = std::move(after_findings);

      current = lint_file(path_, settings_, overlay_);
      if (options_.on_report && !current.error) options_.on_report(current);
      if (current.error) {
        result.error = fmt::format("cannot re-read {} after fixing: {}", path_, *current.error);
        result.files.clear();
        result.remaining = result.initial;
        return result;
      }
      remember_originals(current);
    }

    result.remaining = std::move(current);
    for (const auto& [p, text] : overlay_.files()) {
      const std::string& original = originals_.at(p);
      if (text != original) result.files.push_back({p, original, text, fixes_per_path[p]});
    }
    return result;
  }

 private:
  void remember_originals(const FileReport& report) {
    for (const auto& source : report.sources) {
      if (originals_.count(source->path())) continue;
      // First seen: these are the bytes on disk (the overlay only holds sources already
      // seen). Pin them, so that every round and the final write check see the same bytes.
      originals_.emplace(source->path(), source->text());
      overlay_.set(source->path(), source->text());
    }
  }

  std::vector<Candidate> collect(const FileReport& report, FixResult& result) {
    std::vector<Candidate> out;
    for (const Diagnostic& d : report.diagnostics) {
      if (!d.fix || !fix_applies(*d.fix, options_.unsafe) || d.fix->edits.empty()) continue;
      const Fix& f = *d.fix;
      // Every edit names a source of this report and lies inside its text.
      bool valid = true;
      for (const Edit& e : f.edits) {
        if (e.file >= report.sources.size()) {
          valid = false;
          break;
        }
      }
      if (valid) {
        std::map<FileId, std::vector<Edit>> by_file;
        for (const Edit& e : f.edits) by_file[e.file].push_back(e);
        for (const auto& [id, edits] : by_file) valid = valid && edits_fit(edits, report.source(id).view());
      }
      if (!valid) {
        const std::string key = d.rule + '\0' + f.title;
        if (reported_.insert(key).second)
          result.internal_errors.push_back(fmt::format("fix '{}' [{}] has edits outside the text of {}; skipped",
                                                       f.title, d.rule, report.path));
        continue;
      }
      Candidate c{&d, fix_key(d, report), f.edits.front().file, f.edits.front().offset};
      if (blocked_.count(c.key)) continue;
      bool in_scope = true;
      for (const Edit& e : f.edits) {
        const std::string& p = report.source(e.file).path();
        if (scope_(p)) continue;
        in_scope = false;
        if (reported_.insert(c.key).second)
          result.notes.push_back(
              fmt::format("fix '{}' [{}] would edit {}, outside the files being fixed; skipped", f.title, d.rule, p));
        break;
      }
      if (!in_scope) continue;
      for (const Edit& e : f.edits) {
        if (std::tie(e.file, e.offset) < std::tie(c.first_file, c.first_offset)) {
          c.first_file = e.file;
          c.first_offset = e.offset;
        }
      }
      out.push_back(std::move(c));
    }
    int earliest = 2;
    for (const Candidate& c : out) earliest = std::min(earliest, fix_stage(c.diagnostic->rule));
    std::erase_if(out, [&](const Candidate& c) { return fix_stage(c.diagnostic->rule) != earliest; });
    std::stable_sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
      return std::tie(a.first_file, a.first_offset, a.diagnostic->rule, a.diagnostic->fix->title) <
             std::tie(b.first_file, b.first_offset, b.diagnostic->rule, b.diagnostic->fix->title);
    });
    return out;
  }

  // In position order, each fix whose edits conflict with none already accepted.
  static std::vector<const Candidate*> select(const std::vector<Candidate>& candidates) {
    std::vector<const Candidate*> accepted;
    for (const Candidate& c : candidates) {
      bool conflict = false;
      for (const Candidate* a : accepted)
        conflict = conflict || edit_lists_conflict(c.diagnostic->fix->edits, a->diagnostic->fix->edits);
      if (!conflict) accepted.push_back(&c);
    }
    return accepted;
  }

  // The new text of every source the fixes edit, from the texts `report` was linted from.
  static std::map<std::string, std::string> apply(const FileReport& report, const std::vector<const Candidate*>& fixes) {
    std::map<FileId, std::vector<Edit>> by_file;
    for (const Candidate* c : fixes)
      for (const Edit& e : c->diagnostic->fix->edits) by_file[e.file].push_back(e);
    std::map<std::string, std::string> texts;
    for (auto& [id, edits] : by_file) {
      const SourceFile& source = report.source(id);
      texts[source.path()] = apply_edits(source.view(), std::move(edits));
    }
    return texts;
  }

  // Reader-only lint of the file with `texts` laid over what the overlay holds now.
  FileReport reader_lint(const std::map<std::string, std::string>& texts) const {
    OverlayFileSystem trial(overlay_);
    for (const auto& [p, text] : texts) trial.set(p, text);
    return lint_file(path_, reader_settings_, trial);
  }

  std::string path_;
  const Settings& settings_;
  const FixOptions& options_;
  const FileSystem& base_;
  OverlayFileSystem overlay_;
  EditScope scope_;
  Settings reader_settings_;
  std::map<std::string, std::string> originals_;
  std::set<std::string> blocked_;
  std::set<std::string> reported_;
};

}  // namespace

bool path_within(const std::string& path, const std::string& root) {
  const fs::path p = resolved(path), r = resolved(root);
  return p == r || is_under(p, r);
}

EditScope default_scope(const std::string& checked_path) {
  const fs::path file = resolved(checked_path);
  std::error_code ec;
  fs::path dir = fs::absolute(checked_path, ec).lexically_normal().parent_path();
  dir = resolved(dir.string());
  return [file, dir](const std::string& path) {
    const fs::path p = resolved(path);
    return p == file || is_under(p, dir);
  };
}

EditScope tree_scope(const std::string& root) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return default_scope(root);
  const fs::path dir = resolved(root);
  return [dir](const std::string& path) { return is_under(resolved(path), dir); };
}

bool fix_applies(const Fix& fix, bool unsafe) {
  switch (fix.applicability) {
    case Applicability::Safe: return true;
    case Applicability::Unsafe: return unsafe;
    case Applicability::Display: return false;
  }
  return false;
}

FixResult fix_file(const std::string& path, const Settings& settings, const FixOptions& options,
                   const FileSystem& files) {
  return Fixer(path, settings, options, files).run();
}

}  // namespace assetlint::fix
