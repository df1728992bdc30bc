#pragma once
// A .xacro file checked as the URDF it expands to: expanded, read by the URDF reader, and
// every finding moved back to the place in the .xacro files that produced the value.
#include <map>
#include <memory>
#include <string>

#include "engine/work_budget.h"
#include "engine/file_system.h"
#include "formats/read_result.h"
#include "formats/xacro/expander.h"

namespace assetlint::xacro {

struct XacroOptions {
  std::map<std::string, ArgumentValue> arguments;
  std::string root;  // the checked tree, where $(find pkg) looks first
  Deadline deadline;  // the file's time budget
};

ReadResult read_xacro(std::shared_ptr<const SourceFile> file, const FileSystem& files, const XacroOptions& options);

// `asset-lint expand`: the expanded URDF, or the error (with the files it refers to).
struct ExpandedText {
  std::optional<std::string> text;
  std::optional<ExpandError> error;
  std::vector<std::shared_ptr<const SourceFile>> files;
};
ExpandedText expand_to_text(std::shared_ptr<const SourceFile> file, const FileSystem& files, const XacroOptions& options);

}  // namespace assetlint::xacro
