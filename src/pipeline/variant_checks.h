#pragma once
// A USD stage is checked in its authored variant selections and, for every variant set whose
// variants carry physics (usda::VariantSetUse::physics), once more with each other variant of
// the set selected (the other sets keep their selections): NVIDIA's SimReady assets switch
// each engine's physics on in a variant that is off by default. A set pinned by the
// configuration or --variant is checked in its pinned selection only.
//
// Findings of a variant selection that the authored composition does not have are added to the
// file's report with the selection in their primary message ("in variant PhysX=Enabled: …") and
// a note; a finding several variant selections share is reported once, naming them all. The
// same finding means the same rule, place and severity and the same message up to its numbers:
// an arm's drive judged with each gripper a variant selects is reported once, with the other
// selections' numbers in notes, and not at all when the authored selection already reports it.
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "engine/diagnostic.h"
#include "engine/file_system.h"
#include "formats/read_result.h"
#include "formats/usda/compose.h"

namespace assetlint {

struct VariantRun {
  std::vector<usda::VariantSetUse> sets;  // the authored composition's, then those first seen in a variant
  std::vector<std::string> checked;       // selections checked besides the authored one ("PhysX=Enabled")
  std::vector<std::string> without_physics;  // selections composed but not checked: no physics in them
};

// The reader's and the rules' findings on a read stage; parse errors add their layer to `unparsable`.
using StageCheck = std::function<std::vector<Diagnostic>(ReadResult& read, std::set<FileId>& unparsable)>;

// Checks the variant selections of `root` besides the authored one (whose sets are
// `authored_sets`), adding their layers to `sources` and their new findings to `diagnostics`.
VariantRun check_physics_variants(const std::shared_ptr<const SourceFile>& root, const FileSystem& files,
                                  const usda::ComposeOptions& options,
                                  const std::vector<usda::VariantSetUse>& authored_sets, const StageCheck& check,
                                  std::vector<std::shared_ptr<const SourceFile>>& sources,
                                  std::vector<Diagnostic>& diagnostics, std::set<FileId>& unparsable);

// Which selections such a check composes and checks, without checking them (--show-settings).
VariantRun plan_physics_variants(const std::shared_ptr<const SourceFile>& root, const FileSystem& files,
                                 const usda::ComposeOptions& options);

}  // namespace assetlint
