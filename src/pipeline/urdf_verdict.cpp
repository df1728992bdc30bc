#include "pipeline/urdf_verdict.h"

#include "engine/rule.h"
#include "rules/registry.h"

namespace assetlint {

bool rejects_as_urdfdom_would(const ReadResult& read) {
  if (!read.usable) return true;
  for (const auto& d : read.diagnostics)
    if (d.rule == "urdf-invalid" || d.rule == "parse-error") return true;
  for (const Rule* rule : rules::checks()) {
    if (rule->info().id != "structure-undefined-link") continue;
    std::vector<Diagnostic> found;
    Reporter out(rule->info(), found);
    rule->check(read.asset, Settings{}, out);
    for (const auto& d : found)
      if (d.severity == Severity::Error) return true;
  }
  return false;
}

}  // namespace assetlint
