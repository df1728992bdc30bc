#pragma once
#include <memory>
#include <vector>

#include "engine/diagnostic.h"
#include "model/asset.h"

namespace assetlint {

// What a reader produces: the asset (with its sources, even when unusable, so that
// diagnostics can be rendered) and what the reader itself found wrong.
struct ReadResult {
  Asset asset;
  std::vector<Diagnostic> diagnostics;
  bool usable = true;  // false: the model is incomplete; rules must not run on it
};

}  // namespace assetlint
