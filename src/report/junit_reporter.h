#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/lint.h"

namespace assetlint {

// The rules that ran on a file (its testcases): every rule of the catalog that the
// file's settings enable, per-file-ignores included.
std::vector<std::string> rules_run_on(const Settings& settings, std::string_view path);

using RulesRun = std::function<std::vector<std::string>(const FileReport&)>;

// JUnit XML: one <testsuite> per checked file (name = its path), one <testcase> per rule
// that ran on it (classname = the path, name = the rule id), a <failure> per finding.
void write_junit(std::ostream& out, const std::vector<FileReport>& reports, const RulesRun& rules_run);

// XML text with &, <, >, " and ' escaped, and characters XML 1.0 cannot hold replaced.
std::string xml_escape(std::string_view text);

}  // namespace assetlint
