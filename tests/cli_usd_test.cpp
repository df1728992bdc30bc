// USD assets on the command line: which layers composition may read, and findings in
// a shared layer reported once.
#include <catch2/catch.hpp>

#include "test_support.h"

using assetlint::test::run_cli;

namespace {
std::size_t occurrences(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("cli: a USD file composes layers only inside the checked tree", "[cli][usd]") {
  const auto corpus = assetlint::test::corpus_dir();
  if (corpus.empty()) {
    WARN("../shared/corpus is absent: skipped");
    return;
  }
  const auto stack = corpus / "usda" / "robotiq_2f85";
  const std::string config = (stack / "configuration" / "Robotiq_2F_85_config_physics_parallel_grip.usda").string();
  assetlint::test::TempDir elsewhere;  // a working directory that does not hold the asset

  // Concise: one line per finding (text groups identical findings).
  auto alone = run_cli({"--output-format", "concise", config}, elsewhere.path());
  // The payloads held every joint: skipping them is a warning that says what went unchecked.
  CHECK(alone.exit_code == 1);
  CHECK(occurrences(alone.out, "is outside the checked tree; skipped") == 2);
  CHECK(occurrences(alone.out, " layer-unresolved ") == 2);
  CHECK(occurrences(alone.out, " mimic-max-velocity ") == 0);
  auto alone_text = run_cli({config}, elsewhere.path());
  CHECK(occurrences(alone_text.out, "warning: layer '../payloads/") >= 1);
  CHECK(occurrences(alone_text.out, "note: no joint of the stage was read") >= 1);

  auto allowed = run_cli({"--output-format", "concise", "--allow-outside-root", config}, elsewhere.path());
  CHECK(occurrences(allowed.out, "is outside the checked tree") == 0);
  CHECK(occurrences(allowed.out, " mimic-max-velocity ") == 5);

  // Naming the directory makes it the tree; the physics layer's findings, shared by the
  // configuration layer and the physics layer itself, are printed once.
  auto tree = run_cli({"--output-format", "concise", stack.string()}, elsewhere.path());
  CHECK(occurrences(tree.out, "is outside the checked tree") == 0);
  CHECK(occurrences(tree.out, " mimic-max-velocity ") == 5);
  CHECK(occurrences(tree.out, "sets a max joint velocity: unnecessary") == 5);
  const auto tree_text = run_cli({stack.string()}, elsewhere.path());
  CHECK(occurrences(tree_text.out, "It sets 10000 deg/s (174.5 rad/s)") >= 1);
}
