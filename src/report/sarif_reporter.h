#pragma once
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/lint.h"
#include "pipeline/run.h"

namespace assetlint {

struct SarifOptions {
  // Absolute directory that %SRCROOT% stands for (the working directory); its file:// URI
  // goes into originalUriBaseIds. Empty: left out.
  std::string source_root;
};

// SARIF 2.1.0, as GitHub code scanning reads it: one run, the tool's whole rule catalog in
// tool.driver.rules, one result per finding, fixes as byte-range replacements.
void write_sarif(std::ostream& out, const std::vector<FileReport>& reports, const SarifOptions& options,
                 const RunProblems& problems = {});

// A path as a URI reference relative to `source_root` (forward slashes, percent-encoded),
// or an absolute file:// URI for a file outside it. `relative` says which it is.
std::string sarif_uri(std::string_view path, std::string_view source_root, bool& relative);

// The first paragraph of a rule's docs page (after its `# id` title), on one line.
std::string first_paragraph(std::string_view page);

}  // namespace assetlint
