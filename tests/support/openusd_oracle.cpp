#include "openusd_oracle.h"

#include <cstdlib>
#include <stdexcept>

#include "../test_support.h"

namespace assetlint::test {

std::filesystem::path openusd_package() { return source_dir() / "tools" / "node_modules" / "three-usdz-loader"; }

std::string openusd_missing() {
  if (!on_path("node")) return "node not found on PATH";
  if (!std::filesystem::exists(openusd_package() / "external" / "emHdBindings.wasm"))
    return "three-usdz-loader not installed in tools/node_modules (scripts/bootstrap.sh was not run)";
  return "";
}

nlohmann::json run_openusd(const std::string& script, const std::vector<std::string>& args,
                           const std::filesystem::path& work) {
  const auto out = work / "openusd_out.json", err = work / "openusd_err.txt";
  std::string command = "timeout 300 node " + shell_quote((source_dir() / "tests" / "usd_reference" / script).string()) +
                        " " + shell_quote(openusd_package().string());
  for (const auto& a : args) command += " " + shell_quote(a);
  command += " >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string()) + " </dev/null";
  const int status = std::system(command.c_str());
  // The tools are there, so a failure is a real one, not a reason to skip.
  if (status != 0) throw std::runtime_error(script + " failed (status " + std::to_string(status) + "): " + read_file(err));
  return nlohmann::json::parse(read_file(out));
}

}  // namespace assetlint::test
