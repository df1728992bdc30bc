#pragma once
#include <string_view>
#include <utility>
#include <vector>

namespace assetlint {

// (rule id, Markdown page) for every docs/rules/<id>.md, embedded at build time.
const std::vector<std::pair<std::string_view, std::string_view>>& rule_docs();

}  // namespace assetlint
