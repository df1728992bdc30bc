#include "pipeline/inherited_fixes.h"

#include <fmt/format.h>

namespace assetlint {

void withhold_fixes_on_shared_literals(const Asset& asset, std::vector<Diagnostic>& diagnostics) {
  if (asset.inherited_literals.empty()) return;
  for (Diagnostic& d : diagnostics) {
    if (!d.fix) continue;
    for (const Edit& edit : d.fix->edits) {
      const InheritedLiteral* literal = asset.shared_literal_at(Span{edit.file, edit.offset, edit.length, 1, 1});
      if (!literal) continue;
      d.note(literal->span,
             fmt::format("No fix is offered: this value is written once, in {}, and {} elements take it from there; "
                         "rewriting it would change all of them. Give the element its own attribute, or change the "
                         "class for all of them on purpose (the fix would have been: {}).",
                         literal->owner, literal->uses, d.fix->title));
      d.fix.reset();
      break;
    }
  }
}

}  // namespace assetlint
