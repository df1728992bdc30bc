#pragma once
// Decoding of USDA literal tokens: strings, asset paths and numbers.
#include <string>
#include <string_view>

namespace assetlint::usda {

// Decodes a string token's text (with its quotes) into its contents, resolving escapes.
std::string decode_string(std::string_view token_text);
// Decodes an asset path token's text (@...@ or @@@...@@@).
std::string decode_asset_path(std::string_view token_text);
// Parses a number token's text (also "inf", "-inf", "nan", "+1"). Out-of-range values
// become +-inf (overflow) or 0 (underflow).
double parse_number(std::string_view token_text);

}  // namespace assetlint::usda
