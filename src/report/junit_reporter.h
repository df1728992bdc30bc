#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/lint.h"
#include "pipeline/run.h"

namespace assetlint {

// The rules that ran on a file (its testcases): every rule of the catalog that the
// file's settings enable, per-file-ignores included.
std::vector<std::string> rules_run_on(const Settings& settings, std::string_view path);

using RulesRun = std::function<std::vector<std::string>(const FileReport&)>;

// JUnit XML: one <testsuite> per checked file (name = its path); one <testcase> per
// finding (classname = the path, name = "rule-id (line:column)", file and line
// attributes) holding its <failure>, and one passing <testcase> per rule that ran on the
// file without a finding (name = the rule id). Paths not read are <error> testcases.
void write_junit(std::ostream& out, const std::vector<FileReport>& reports, const RulesRun& rules_run,
                 const RunProblems& problems = {});

// XML text with &, <, >, " and ' escaped, and characters XML 1.0 cannot hold replaced.
std::string xml_escape(std::string_view text);

}  // namespace assetlint
