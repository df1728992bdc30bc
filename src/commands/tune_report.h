#pragma once
// How `asset-lint tune` prints a derivation: text for people, JSON for tools
// (docs/tune.md documents the JSON schema).
#include <ostream>

#include "commands/tune_derivation.h"

namespace assetlint::commands {

void write_tune_text(std::ostream& out, const TuneDerivation& derivation);
void write_tune_json(std::ostream& out, const TuneDerivation& derivation);

}  // namespace assetlint::commands
