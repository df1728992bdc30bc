#pragma once
// What a rule is: static metadata plus a check over the Asset model.
#include <string>
#include <string_view>
#include <vector>

#include "engine/diagnostic.h"
#include "engine/settings.h"
#include "model/asset.h"

namespace assetlint {

struct RuleOption {
  std::string_view name;
  double default_value;
  std::string_view description;
};

enum class RuleOrigin {
  Check,   // a Rule subclass that runs on the model
  Reader,  // reported while reading a file (syntax, schema, composition)
};

struct RuleInfo {
  std::string_view id;
  std::string_view summary;
  Severity default_severity = Severity::Warning;
  bool fixable = false;
  RuleOrigin origin = RuleOrigin::Check;
  std::vector<RuleOption> options;
};

class Reporter;

class Rule {
 public:
  virtual ~Rule() = default;
  virtual const RuleInfo& info() const = 0;
  virtual void check(const Asset& asset, const Settings& settings, Reporter& out) const = 0;
};

// Collects the diagnostics of one rule on one asset.
class Reporter {
 public:
  Reporter(const RuleInfo& rule, std::vector<Diagnostic>& sink) : rule_(rule), sink_(sink) {}
  // Adds a finding at `span` with the rule's default severity; returns it so a fix can be attached.
  Diagnostic& report(const Span& span, std::string message);
  Diagnostic& report(const Span& span, Severity severity, std::string message);

 private:
  const RuleInfo& rule_;
  std::vector<Diagnostic>& sink_;
};

// The option's configured value, or its documented default.
double rule_option(const RuleInfo& rule, const Settings& settings, std::string_view option);

}  // namespace assetlint
