#include "engine/rule.h"

#include <stdexcept>

namespace assetlint {

Diagnostic& Reporter::report(const Span& span, std::string message) {
  return report(span, rule_.default_severity, std::move(message));
}

Diagnostic& Reporter::report(const Span& span, Severity severity, std::string message) {
  sink_.push_back(Diagnostic{std::string(rule_.id), severity, span, std::move(message), std::nullopt, {}, {}, {}});
  return sink_.back();
}

double rule_option(const RuleInfo& rule, const Settings& settings, std::string_view option) {
  if (auto configured = settings.rule_option(rule.id, option)) return *configured;
  for (const auto& declared : rule.options)
    if (declared.name == option) return declared.default_value;
  throw std::logic_error("rule " + std::string(rule.id) + " has no option " + std::string(option));
}

}  // namespace assetlint
