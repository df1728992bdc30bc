#pragma once
// Writes a run's reports in the format the command line chose.
#include <ostream>

#include "cli/options.h"
#include "commands/check.h"
#include "config/resolver.h"

namespace assetlint::cli {

// A writer for `options.format` (and --statistics, --quiet, colour) to `out`.
commands::WriteReport report_writer(const Options& options, bool use_color, config::SettingsResolver& resolver,
                                    std::ostream& out);

}  // namespace assetlint::cli
