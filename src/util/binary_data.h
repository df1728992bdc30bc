#pragma once
// Whether a file that should be text is binary data: a report then describes it instead of
// quoting bytes that mean nothing to a reader (and could be anything the file was a copy of).
#include <cstddef>
#include <optional>
#include <string_view>

namespace assetlint {

// The offset of the first NUL or C0 control character (other than tab, line feed, carriage
// return and form feed) in the first `window` bytes of `text`, or nothing when there is none.
std::optional<std::size_t> first_binary_byte(std::string_view text, std::size_t window = 1024);

}  // namespace assetlint
