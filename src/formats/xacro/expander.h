#pragma once
// Expands a .xacro file as ROS's xacro does (properties, ${…} expressions, $(…)
// substitution arguments, macros with default and block parameters, conditionals,
// includes, xacro:element/attribute/call, xacro.load_yaml), keeping where each element and
// attribute came from. Recursion, include cycles and blow-ups are bounded.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/work_budget.h"
#include "engine/diagnostic.h"
#include "engine/file_system.h"
#include "formats/xacro/expansion.h"

namespace assetlint::xacro {

struct ExpandOptions {
  std::map<std::string, ArgumentValue> arguments;  // given on the command line or in configuration
  std::string root;                                // the checked tree, where $(find pkg) looks
  FileId first_id = 0;                             // the top file's FileId; included files follow
  std::size_t max_macro_depth = 100;
  std::size_t max_include_depth = 50;
  std::size_t max_output_bytes = std::size_t{64} << 20;
  // Elements and macro calls visited: a macro that calls itself twice per level writes nothing
  // and so passes every other limit, in 2^depth steps.
  std::size_t max_steps = 1'000'000;
  Deadline deadline;  // the file's time budget
};

struct ExpandError {
  Span span;
  std::string message;
  std::vector<Note> notes;  // the macro calls and includes it happened in
};

struct ExpandResult {
  std::optional<Expansion> expansion;
  std::optional<ExpandError> error;
  std::vector<std::shared_ptr<const SourceFile>> files;  // every file read, also on error
};

ExpandResult expand_xacro(std::shared_ptr<const SourceFile> top, const FileSystem& files, const ExpandOptions& options);

}  // namespace assetlint::xacro
