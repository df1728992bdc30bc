#pragma once
// Applies inline suppressions (found by each format's scanner, formats/suppressions.h)
// and per-file ignores to a file's findings after the rules ran. A suppression that
// suppresses nothing in the run (for rules that ran), names no known rule, or is
// malformed is reported as `unused-suppression`.
#include <memory>
#include <set>
#include <string_view>
#include <vector>

#include "engine/diagnostic.h"
#include "engine/settings.h"
#include "model/source.h"

namespace assetlint {

// Whether `path` (as the checked file was named) matches a per-file-ignores glob of
// `settings` for `rule_id`. Globs are matched against the path relative to the directory
// of the configuration file; `**` spans directories, `*` and `?` stay within one.
bool per_file_ignored(const Settings& settings, std::string_view path, std::string_view rule_id);

// Drops the suppressed findings of `diagnostics` (located in `sources`), then adds the
// unused-suppression findings when that rule is enabled. In the files of `unparsable`
// (those with a parse error, selected or not) those findings offer no edit: a comment
// need not end where it seems to (an unclosed one swallows what follows).
void apply_suppressions(const std::vector<std::shared_ptr<const SourceFile>>& sources,
                        std::vector<Diagnostic>& diagnostics, const Settings& settings,
                        const std::set<FileId>& unparsable = {});

}  // namespace assetlint
