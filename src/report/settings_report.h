#pragma once
// `asset-lint --show-settings FILE`: the settings a check of FILE uses, each value with where
// it came from (a line of asset-lint.toml, a flag, or the default), written as TOML.
#include <ostream>
#include <string>

#include "config/file_selection.h"
#include "engine/settings.h"
#include "pipeline/variant_checks.h"

namespace assetlint {

// `variants`: the file's USD variant sets and the selections a check looks at (null: not USD).
// `config_lookup`: where the configuration was looked for (one line, empty: not shown).
void write_settings(std::ostream& out, const std::string& file, const Settings& settings,
                    const config::FileSelection& files, const std::string& checked_tree,
                    const VariantRun* variants = nullptr, const std::string& config_lookup = "");

}  // namespace assetlint
