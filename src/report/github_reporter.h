#pragma once
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/lint.h"
#include "pipeline/run.h"

namespace assetlint {

// GitHub Actions workflow commands, one per finding:
// `::error file=F,line=L,col=C,endLine=L2,endColumn=C2,title=asset-lint (rule)::message`
// (`::warning` and `::notice` for the other severities). Workflow runners turn them into
// annotations on the pull request.
void write_github(std::ostream& out, const std::vector<FileReport>& reports, const RunProblems& problems = {});

// Escaping of a command's message (`%`, CR, LF) and of a property value (also `:` and `,`).
std::string github_escape_data(std::string_view text);
std::string github_escape_property(std::string_view text);

}  // namespace assetlint
