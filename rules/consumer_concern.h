#pragma once
// Findings that concern some of the programs an asset is loaded by: which consumers of the
// profile a quirk touches, how loud the finding is, and the consumers it names.
#include <string>
#include <vector>

#include "engine/consumers.h"
#include "engine/diagnostic.h"

namespace assetlint::rules {

// Whether any consumer the asset is judged for bounds a joint's speed by its max joint
// velocity: the velocity rules judge nothing that no consumer reads.
bool max_velocity_read(const Asset& asset, const Settings& settings);

// The consumers of `profile` a quirk touches, and the severity of its finding: `targeted`
// when the consumers were named ([targets], --target) or the quirk touches every default
// consumer; an info otherwise (the default profile guesses who loads the file).
struct Concern {
  std::vector<std::string> affected;  // labels, in profile order
  std::vector<std::string> spared;    // the profile's other consumers
  Severity severity = Severity::Info;
  bool any() const { return !affected.empty(); }
};

template <typename Affected>
Concern concern(const ConsumerProfile& profile, Affected affected, Severity targeted) {
  Concern c;
  c.affected = profile.labels(affected);
  c.spared = profile.labels([&](const Consumer& x) { return !affected(x); });
  c.severity = profile.configured || c.spared.empty() ? targeted : Severity::Info;
  return c;
}

// Names the consumers on the finding (Diagnostic::consumers, and a note saying who is and
// who is not touched, and why an info when the consumers were not named).
void name_consumers(Diagnostic& d, const Concern& concern, const ConsumerProfile& profile);

}  // namespace assetlint::rules
