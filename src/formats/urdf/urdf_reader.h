#pragma once
#include <memory>

#include "formats/read_result.h"

namespace assetlint::urdf {

// Reads a URDF document into the model. Reports `parse-error` for text that is not
// well-formed XML or not a URDF, and `urdf-invalid` for what urdfdom rejects.
ReadResult read_urdf(std::shared_ptr<const SourceFile> file);

}  // namespace assetlint::urdf
