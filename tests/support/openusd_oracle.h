#pragma once
// OpenUSD 22.11 compiled to WASM (npm three-usdz-loader in tools/node_modules, which
// scripts/bootstrap.sh installs), run with Node through the scripts in tests/usd_reference.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace assetlint::test {

// The package directory the scripts load OpenUSD from.
std::filesystem::path openusd_package();
// Why OpenUSD cannot run on this machine ("node not found on PATH", ...); empty when it can.
std::string openusd_missing();
// Runs tests/usd_reference/<script> with the package and `args`, in `work` (its output and
// error files go there), and returns the JSON it prints. Throws std::runtime_error with the
// script's messages when it fails.
nlohmann::json run_openusd(const std::string& script, const std::vector<std::string>& args,
                           const std::filesystem::path& work);

}  // namespace assetlint::test
