#pragma once
// Where new attributes go in URDF text, for edits that add a value the file lacks.
#include <optional>
#include <string_view>

namespace assetlint::urdf {

// The offset just before the `/>` or `>` that closes the start tag beginning at
// `element_offset` (the `<` of `<limit ...`): ` effort="24"` inserted there becomes the
// tag's last attribute. nullopt when the tag does not close.
std::optional<std::size_t> start_tag_close(std::string_view text, std::size_t element_offset);

}  // namespace assetlint::urdf
