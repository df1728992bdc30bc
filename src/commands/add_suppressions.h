#pragma once
// --add-suppressions (ruff's --add-noqa): every current finding gets an inline suppression
// comment in its file's own syntax, before the element or statement it is in. Runs in the
// fixer (fix/fixer.h), so the files are written byte-exact and atomically, and a second run
// adds nothing.
#include <functional>
#include <string>

#include "fix/fixer.h"

#include "pipeline/lint.h"

namespace assetlint::commands {

// A fixer hook (FixOptions::on_report) for one file: on each lint it replaces the findings'
// fixes with one comment insertion per element or statement (naming every rule found
// there), for findings not given a comment in an earlier round (the fixer applies rules'
// fixes in stages, one stage per round). A finding its comment does not silence is left.
// unused-suppression findings are left alone: their fix is to remove the comment.
std::function<void(FileReport&)> suppression_inserter();

// "added 2 suppression comments to robots/a.urdf", for a file the inserter changed.
std::string describe_added_suppressions(const fix::FixedFile& file);

}  // namespace assetlint::commands
