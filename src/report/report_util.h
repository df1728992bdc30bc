#pragma once
// Small helpers the report writers share.
#include <string>

#include "engine/linter.h"

namespace assetlint {

// The path of the file a finding is in: a composed layer's path, or the checked file's.
inline const std::string& diagnostic_path(const FileReport& report, const Diagnostic& d) {
  return d.span.file < report.sources.size() ? report.source(d.span.file).path() : report.path;
}

}  // namespace assetlint
