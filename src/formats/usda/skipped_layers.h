#pragma once
// What a run lost to layers it could not compose: a skipped arc that could have carried
// physics opinions, where the composed asset then lacks what the rules need (no joints at
// all, drives whose bodies have no mass), becomes a warning whose notes name the checks
// that were skipped because of it. Arcs that only bring geometry stay informational.
#include "formats/read_result.h"
#include "formats/usda/compose.h"

namespace assetlint::usda {

void weigh_skipped_arcs(const Stage& stage, ReadResult& result);

}  // namespace assetlint::usda
