#pragma once
// `asset-lint expand FILE.xacro [--xacro-arg name:=value]…`: prints the URDF the file expands to.
#include <ostream>
#include <string>
#include <vector>

namespace assetlint::commands {

int run_expand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace assetlint::commands
