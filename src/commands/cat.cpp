#include "commands/cat.h"

#include <fmt/format.h>

#include <variant>

#include "commands/exit_status.h"
#include "engine/file_system.h"
#include "formats/usdc/crate_usda.h"

namespace assetlint::commands {

int run_cat(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.empty() || args.front() == "--help" || args.front() == "-h") {
    (args.empty() ? err : out) << "usage: asset-lint cat FILE...\n"
                                  "Prints USD layers as USDA text: a binary crate layer (.usd, .usdc) as the text "
                                  "asset-lint reads it as, a text layer unchanged.\n";
    return args.empty() ? kExitError : kExitClean;
  }
  for (const std::string& path : args) {
    std::string error;
    const std::optional<std::string> bytes = disk().read(path, error);
    if (!bytes) {
      err << fmt::format("asset-lint: error: cannot read '{}': {}\n", path, error);
      return kExitError;
    }
    if (usdc::is_crate(*bytes)) {
      auto result = usdc::crate_to_usda(*bytes);
      if (auto* e = std::get_if<usdc::CrateError>(&result)) {
        err << "asset-lint: error: " << usdc::describe(*e, path) << "\n";
        return kExitError;
      }
      out << std::get<usdc::CrateText>(result).text;
    } else if (bytes->starts_with("#usda")) {
      out << *bytes;
    } else {
      err << fmt::format("asset-lint: error: '{}' is neither a USDA nor a crate layer\n", path);
      return kExitError;
    }
  }
  return kExitClean;
}

}  // namespace assetlint::commands
