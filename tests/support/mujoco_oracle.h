#pragma once
// MuJoCo 3.14 compiled to WASM (npm @mujoco/mujoco in tools/node_modules, which
// scripts/bootstrap.sh installs), run with Node through tests/mujoco_reference/compile.mjs.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace assetlint::test {

// Why MuJoCo cannot run on this machine ("node not found on PATH", ...); empty when it can.
std::string mujoco_missing();
// Compiles `models` with compile.mjs and returns the JSON it prints ({"mujoco": version,
// "models": [...]} in the order given). Throws std::runtime_error with the script's messages
// when it fails.
nlohmann::json compile_with_mujoco(const std::vector<std::filesystem::path>& models);

}  // namespace assetlint::test
