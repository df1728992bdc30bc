#pragma once
// A fix reported on one element must not rewrite a value other elements inherit (an MJCF
// default class): it would change all of them while the finding names one.
#include <vector>

#include "engine/diagnostic.h"
#include "model/asset.h"

namespace assetlint {

// Drops every fix with an edit on a literal of more than one use, and says why in a note.
void withhold_fixes_on_shared_literals(const Asset& asset, std::vector<Diagnostic>& diagnostics);

}  // namespace assetlint
