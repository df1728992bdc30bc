#pragma once
// `asset-lint cat FILE...`: a USD layer as USDA text. A binary crate layer is printed as
// the text asset-lint reads it as (which reads back to the same layer); a text layer is
// printed unchanged. Made for `git diff` (a textconv driver, docs/ci.md) and for review.
#include <ostream>
#include <string>
#include <vector>

namespace assetlint::commands {

// Exit status: 0 printed, 2 a file that cannot be read or is not a USD layer (one line on `err`).
int run_cat(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace assetlint::commands
