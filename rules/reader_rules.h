#pragma once
// Rules whose findings come from the readers (syntax, schema and composition
// problems) rather than from a check over the model.
#include "engine/rule.h"

namespace assetlint::rules {

extern const RuleInfo kParseError;
extern const RuleInfo kUrdfInvalid;
extern const RuleInfo kUrdfRepeatedElement;
extern const RuleInfo kLayerUnresolved;
extern const RuleInfo kStaleSchemaAttribute;
extern const RuleInfo kMimicAxisInstance;
extern const RuleInfo kUnusedSuppression;
extern const RuleInfo kMjcfUnsupported;
extern const RuleInfo kDriveInstanceIgnored;
extern const RuleInfo kMimicLimitsRequired;
extern const RuleInfo kXacroUnexpanded;

}  // namespace assetlint::rules
