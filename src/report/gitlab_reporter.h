#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "pipeline/lint.h"

namespace assetlint {

// GitLab Code Quality (artifacts:reports:codequality): a JSON array with one issue per
// finding: description, check_name, fingerprint, severity, location.path and
// location.lines.begin.
void write_gitlab(std::ostream& out, const std::vector<FileReport>& reports);

// The fingerprint of a finding: 32 hex digits from its rule, path and message and how
// many identical findings came before it in the file. No line numbers: an unrelated edit
// that moves the finding keeps it.
std::string gitlab_fingerprint(std::string_view rule, std::string_view path, std::string_view message,
                               std::size_t occurrence);

}  // namespace assetlint
