#pragma once
// asset-lint never writes a binary (crate) layer: a fix whose edit falls in one is turned
// into a note that names the layer, the object and the exact value the fix would write, for
// the user to author in a text layer of the stack.
#include <memory>
#include <vector>

#include "engine/diagnostic.h"
#include "model/source.h"

namespace assetlint {

void withhold_fixes_in_binary_layers(const std::vector<std::shared_ptr<const SourceFile>>& sources,
                                     std::vector<Diagnostic>& diagnostics);

}  // namespace assetlint
