#pragma once
// Unified diffs (`diff -u` style) of two versions of a text.
#include <string>
#include <string_view>

namespace assetlint::fix {

// The unified diff turning `before` into `after`: `--- a_label` / `+++ b_label`
// headers, then `@@ -l,n +l,n @@` hunks with `context` lines of context around
// each change, hunks closer than 2×context merged, like GNU `diff -u`. Lines keep
// their bytes exactly (a CRLF line shows its \r); a last line without a newline is
// followed by `\ No newline at end of file`. Empty when the texts are equal.
std::string unified_diff(std::string_view before, std::string_view after, std::string_view a_label,
                         std::string_view b_label, int context = 3);

}  // namespace assetlint::fix
