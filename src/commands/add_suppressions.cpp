#include "commands/add_suppressions.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include "formats/locator.h"
#include "rules/reader_rules.h"

namespace assetlint::commands {

std::function<void(FileReport&)> suppression_inserter() {
  // Findings a comment was already written for (by layer, rule, element and attribute, which
  // the inserted lines do not move): one that survives its comment is not tried again.
  auto tried = std::make_shared<std::set<std::tuple<std::string, std::string, std::string, std::string>>>();
  return [tried](FileReport& report) {
    for (auto& d : report.diagnostics) d.fix.reset();
    struct Insertion {
      FileId file = 0;
      SuppressionSite site;
      std::vector<std::string> rules;
      Diagnostic* owner = nullptr;
    };
    std::map<FileId, std::unique_ptr<SourceLocator>> locators;
    std::set<std::tuple<std::string, std::string, std::string, std::string>> this_round;
    std::map<std::tuple<FileId, std::size_t, bool>, Insertion> insertions;
    for (auto& d : report.diagnostics) {
      if (d.rule == rules::kUnusedSuppression.id) continue;
      const FileId file = d.span.file;
      if (file == kNoFile || file >= report.sources.size()) continue;
      auto& locator = locators[file];
      if (!locator) locator = std::make_unique<SourceLocator>(report.source(file));
      ElementKey key = locator->key_at(d.span.offset);
      auto finding = std::make_tuple(report.source(file).path(), d.rule, std::move(key.element), std::move(key.attribute));
      if (tried->contains(finding)) continue;  // tried in an earlier round (findings of this one may share a key)
      this_round.insert(std::move(finding));
      const std::optional<SuppressionSite> site = locator->site_at(d.span.offset);
      if (!site) continue;
      Insertion& insertion = insertions[{file, site->offset, site->file_level}];
      if (!insertion.owner) insertion = Insertion{file, *site, {}, &d};
      if (std::find(insertion.rules.begin(), insertion.rules.end(), d.rule) == insertion.rules.end())
        insertion.rules.push_back(d.rule);
    }
    tried->insert(this_round.begin(), this_round.end());
    // One fix holds every comment, so that they are written in one round: the fixer
    // applies the rules' own fixes in stages, and the comments must not wait for them.
    if (insertions.empty()) return;
    Fix fix{fmt::format("add {} suppression comment{}", insertions.size(), insertions.size() == 1 ? "" : "s"),
            Applicability::Safe, {}};
    for (auto& [where, insertion] : insertions) {
      std::sort(insertion.rules.begin(), insertion.rules.end());
      const std::string text = locators.at(insertion.file)->suppression_text(insertion.site, insertion.rules);
      fix.edits.push_back(Edit{insertion.file, insertion.site.offset, 0, text});
    }
    insertions.begin()->second.owner->fix = std::move(fix);
  };
}

std::string describe_added_suppressions(const fix::FixedFile& file) {
  auto directives = [](std::string_view text) {
    std::size_t count = 0;
    for (std::size_t at = text.find("asset-lint: ignore"); at != std::string_view::npos;
         at = text.find("asset-lint: ignore", at + 1))
      ++count;
    return count;
  };
  const std::size_t added = directives(file.fixed) - directives(file.original);
  return fmt::format("added {} suppression comment{} to {}", added, added == 1 ? "" : "s", file.path);
}

}  // namespace assetlint::commands
