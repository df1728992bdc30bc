#pragma once
// The exit status of every command.

namespace assetlint::commands {

constexpr int kExitClean = 0;     // nothing to report (or nothing at the failing severity)
constexpr int kExitFindings = 1;  // findings remain
constexpr int kExitError = 2;     // usage, configuration or I/O error

}  // namespace assetlint::commands
