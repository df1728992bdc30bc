#pragma once
// Where an offset of a source lies in the file's own structure: the element (URDF) or the
// prim and statement (USDA) that holds it. Baseline keys name findings by it, so that they
// survive edits elsewhere in the file, and --add-suppressions puts its comments before it.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/source.h"

namespace assetlint {

struct ElementKey {
  // The innermost named element or prim holding the offset: "joint 'finger_joint'" (XML),
  // "/gripper/driven" (USDA); empty when the offset lies in none.
  std::string element;
  // The attribute or statement inside it: "limit.velocity" (XML: tag.attribute, or the tag),
  // "drive:angular:physics:stiffness" (USDA: property or metadata key); may be empty.
  std::string attribute;
};

// Where a suppression comment for an offset goes: before the innermost element or statement
// holding it, or, when there is none, an ignore-file comment at the top.
struct SuppressionSite {
  std::size_t offset = 0;  // insert here
  bool file_level = false;
  bool own_line = true;    // the comment gets a line of its own, with `indent`
  std::string indent;
  std::string line_end;    // "\n" or "\r\n", as the file writes them
};

class SourceLocator {
 public:
  explicit SourceLocator(const SourceFile& file);
  ~SourceLocator();
  SourceLocator(const SourceLocator&) = delete;
  SourceLocator& operator=(const SourceLocator&) = delete;

  ElementKey key_at(std::size_t offset) const;
  // nullopt when no comment can be placed (an XML text without a root element).
  std::optional<SuppressionSite> site_at(std::size_t offset) const;
  // The text to insert at `site` that suppresses `rules` there, in the file's syntax.
  std::string suppression_text(const SuppressionSite& site, const std::vector<std::string>& rules) const;

  struct Unit;

 private:
  const SourceFile& file_;
  std::vector<Unit> units_;
  bool xml_ = false;
};

}  // namespace assetlint
