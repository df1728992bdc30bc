#pragma once
#include <vector>

#include "engine/diagnostic.h"
#include "engine/settings.h"
#include "model/asset.h"

namespace assetlint::config {

// Puts the [drives.<joint>] tables of the configuration into the model, for formats
// that carry no drive (URDF). Values the asset itself authors win; config values have
// no span (they are not in the file) and name their origin.
void apply_drive_settings(Asset& asset, const Settings& settings);

}  // namespace assetlint::config
