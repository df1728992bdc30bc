#include "rules/consumer_concern.h"

#include <fmt/format.h>

namespace assetlint::rules {

bool max_velocity_read(const Asset& asset, const Settings& settings) {
  return consumer_profile(asset.format, settings).any(
      [&](const Consumer& c) { return reads_max_joint_velocity(c, asset.format); });
}

void name_consumers(Diagnostic& d, const Concern& concern, const ConsumerProfile& profile) {
  d.consumers = concern.affected;
  std::string text = fmt::format("Concerns {}", join_labels(concern.affected));
  if (!concern.spared.empty()) text += fmt::format("; not {}", join_labels(concern.spared));
  text += ".";
  if (!profile.configured && !concern.spared.empty())
    text += " An info because no consumers are named: set [targets] consumers in asset-lint.toml (or --target) to the "
            "programs that load the file, and it is reported as a warning when they include one of these.";
  d.note(std::move(text));
}

}  // namespace assetlint::rules
