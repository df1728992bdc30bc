#pragma once
// `asset-lint simulate ASSET ...`: steps the driven joint as PhysX's articulation drive
// does, beside the explicit spring at the same step (docs/simulate.md). `args` are the
// words after "simulate".
#include <ostream>
#include <string>
#include <vector>

namespace assetlint::commands {

// Exit status: 0 simulated, 2 bad input (one line on `err` naming it).
int run_simulate(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace assetlint::commands
