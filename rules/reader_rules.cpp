#include "rules/reader_rules.h"

namespace assetlint::rules {

const RuleInfo kParseError{
    "parse-error",
    "The file is not well-formed XML/USDA, or not a URDF: nothing after the problem can be trusted",
    Severity::Error, false, RuleOrigin::Reader, {}};

const RuleInfo kUrdfInvalid{
    "urdf-invalid",
    "urdfdom (and so ROS, check_urdf and simulator importers) rejects the model",
    Severity::Error, false, RuleOrigin::Reader, {}};

}  // namespace assetlint::rules
