#pragma once
// The exit status of every command.

#include <vector>

#include "engine/diagnostic.h"
#include "pipeline/lint.h"

namespace assetlint::commands {

constexpr int kExitClean = 0;     // nothing to report (or nothing at the failing severity)
constexpr int kExitFindings = 1;  // findings remain
constexpr int kExitError = 2;     // usage, configuration or I/O error

// 1 when a finding at or above `fail_on` remains (infos fail only with --fail-on info), else 0.
inline int findings_status(const std::vector<FileReport>& reports, Severity fail_on) {
  for (const auto& report : reports)
    for (const auto& d : report.diagnostics)
      if (d.severity >= fail_on) return kExitFindings;
  return kExitClean;
}

}  // namespace assetlint::commands
