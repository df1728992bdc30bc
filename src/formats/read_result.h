#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "engine/diagnostic.h"
#include "model/asset.h"

namespace assetlint {

// Where a span of a model read from generated text was written in the files a person edits.
using WrittenAt = std::function<Span(const Span&)>;

// What a reader produces: the asset (with its sources, even when unusable, so that
// diagnostics can be rendered) and what the reader itself found wrong.
struct ReadResult {
  Asset asset;
  std::vector<Diagnostic> diagnostics;
  bool usable = true;  // false: the model is incomplete; rules must not run on it
  // Set when the model was read from generated text (a xacro file's expansion): moves every
  // finding, its notes and fixes from that text to the files a person edits, and returns
  // those files (the asset's sources from then on).
  std::function<std::vector<std::shared_ptr<const SourceFile>>(std::vector<Diagnostic>&)> relocate;
  // Set with `relocate`, for the commands that show a model's values without relocating
  // findings (tune, verify): a span of the generated text (file 0) → the span in the source
  // files that produced it (sources[1..], before `relocate` renumbers them).
  WrittenAt written_at;
};

}  // namespace assetlint
