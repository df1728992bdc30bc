#pragma once
// Byte-exact edits of an asset-lint.toml: set numbers in one table, keeping every other
// byte (comments, key order, spacing, line endings) as it was.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace assetlint::config {

struct TomlValue {
  std::string key;        // "stiffness"
  std::string text;       // the number as it should be written: "275"
  bool add_when_missing = true;  // false: only rewrite a key that is already there
};

struct TomlEdit {
  std::string text;                   // the new file text (== the old one when nothing changes)
  std::vector<std::string> changes;   // "[drives.finger_joint] stiffness = 275 (was 5700)"
  std::optional<std::string> error;   // the table cannot be edited safely (line:col and why)
};

// Sets `values` in the table [`table`.`name`] of `text` (an existing asset-lint.toml, or
// empty for a new one): a key's value is rewritten in place when it is there, new keys
// go after the table's last key, and a missing table is appended. A key already holding
// the same number is left alone, so applying twice changes nothing.
TomlEdit set_table_numbers(std::string_view text, std::string_view table, std::string_view name,
                           const std::vector<TomlValue>& values);

}  // namespace assetlint::config
