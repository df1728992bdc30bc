#pragma once
// `asset-lint verify --drives` (and `verify` without a [gripper] spec): the drive tests of every
// actuated joint (docs/verify.md "Drive tests"), stepped in parallel, reported as text, JSON and SVG.
#include <optional>
#include <ostream>
#include <string>

#include "commands/command_input.h"

namespace assetlint::commands {

struct DriveTestOptions {
  std::string path;
  std::string format = "text";
  std::optional<std::string> plot;
  unsigned jobs = 0;  // 0: one per core
  bool fine_tune = false;  // propose gains for each failing joint and test the robot again with them
};

// Whether [gripper] says anything: a spec sheet makes `verify` run the gripper's scenes.
bool has_gripper_spec(const GripperSpec& spec);

int run_drive_tests(const DriveTestOptions& options, const CommandAsset& input, std::ostream& out, std::ostream& err);

}  // namespace assetlint::commands
