#pragma once
// asset-lint's own verdict on a URDF, the one that must never be "accepted" where urdfdom
// rejects the file (docs/limits.md, the urdfdom skip): the reader's parse-error and
// urdf-invalid findings, and the structure-undefined-link errors that stand for urdfdom's
// "Failed to build tree" refusals. Suppressions are not applied.
#include "formats/read_result.h"

namespace assetlint {

bool rejects_as_urdfdom_would(const ReadResult& read);

}  // namespace assetlint
