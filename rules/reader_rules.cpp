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

const RuleInfo kUrdfRepeatedElement{
    "urdf-repeated-element",
    "A URDF element MuJoCo reads once (a link's <inertial>, a visual's <material>, a joint's <limit>, …) written twice: MuJoCo refuses the file, urdfdom ignores all but the first",
    Severity::Error, false, RuleOrigin::Reader, {}};

const RuleInfo kLayerUnresolved{
    "layer-unresolved",
    "A USD layer or reference is missing, binary, outside the checked tree, or cyclic: its opinions are skipped",
    Severity::Info, false, RuleOrigin::Reader, {}};

const RuleInfo kStaleSchemaAttribute{
    "stale-schema-attribute",
    "Attributes authored for a USD API schema that is not applied (or was deleted): PhysX ignores them",
    Severity::Info, false, RuleOrigin::Reader, {}};

const RuleInfo kMimicAxisInstance{
    "mimic-axis-instance",
    "PhysxMimicJointAPI applied with an instance other than rotX/rotY/rotZ: PhysX silently ignores the mimic",
    Severity::Warning, false, RuleOrigin::Reader, {}};

const RuleInfo kUnusedSuppression{
    "unused-suppression",
    "An inline suppression comment that suppresses nothing, names an unknown rule, or is malformed",
    Severity::Warning, true, RuleOrigin::Reader, {}};

const RuleInfo kMjcfUnsupported{
    "mjcf-unsupported",
    "An MJCF construct asset-lint does not model (nonlinear joint coupling, tendon or site transmission, dampratio)",
    Severity::Info, false, RuleOrigin::Reader, {}};

const RuleInfo kDriveInstanceIgnored{
    "drive-instance-ignored",
    "A USD drive instance the joint type does not read (rotX on a revolute joint, …): it drives nothing",
    Severity::Warning, false, RuleOrigin::Reader, {}};

const RuleInfo kMimicLimitsRequired{
    "mimic-limits-required",
    "A USD mimic on (or following) a revolute joint without finite limits: omni.physx refuses to create it",
    Severity::Error, false, RuleOrigin::Reader, {}};

const RuleInfo kXacroUnexpanded{
    "xacro-unexpanded",
    "An <xacro:…> element left in an expanded URDF: URDF readers skip it, so what it stood for is missing",
    Severity::Warning, false, RuleOrigin::Reader, {}};

}  // namespace assetlint::rules
