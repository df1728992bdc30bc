#include "pipeline/binary_layer_fixes.h"

#include <fmt/format.h>

#include <algorithm>

namespace assetlint {

void withhold_fixes_in_binary_layers(const std::vector<std::shared_ptr<const SourceFile>>& sources,
                                     std::vector<Diagnostic>& diagnostics) {
  const auto binary = [&](FileId id) { return id < sources.size() && sources[id]->binary(); };
  for (Diagnostic& d : diagnostics) {
    if (!d.fix || std::none_of(d.fix->edits.begin(), d.fix->edits.end(), [&](const Edit& e) { return binary(e.file); }))
      continue;
    for (const Edit& e : d.fix->edits) {
      if (!binary(e.file)) continue;
      const SourceFile& source = *sources[e.file];
      const std::string_view object = source.object_at(e.offset);
      d.note(fmt::format("the value lives in the binary layer '{}' (<{}>), which asset-lint does not write; the fix "
                         "would write `{}` there: author it in a text layer of the stack (an `over`)",
                         source.path(), object.empty() ? "/" : object, e.replacement));
    }
    d.fix.reset();
  }
}

}  // namespace assetlint
