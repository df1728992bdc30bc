#include "mujoco_oracle.h"

#include <cstdlib>
#include <stdexcept>

#include "../test_support.h"

namespace assetlint::test {
namespace {

std::filesystem::path mujoco_package() { return source_dir() / "tools" / "node_modules" / "@mujoco" / "mujoco"; }

}  // namespace

std::string mujoco_missing() {
  if (!on_path("node")) return "node not found on PATH";
  if (!std::filesystem::exists(mujoco_package() / "mujoco.js"))
    return "@mujoco/mujoco is not installed in tools/node_modules: scripts/bootstrap.sh was not run";
  return "";
}

nlohmann::json compile_with_mujoco(const std::vector<std::filesystem::path>& models) {
  TempDir dir;
  const auto out = dir.path() / "out.json", err = dir.path() / "err.txt";
  std::string command = "timeout 300 node " +
                        shell_quote((source_dir() / "tests" / "mujoco_reference" / "compile.mjs").string()) + " " +
                        shell_quote(mujoco_package().string());
  for (const auto& model : models) command += " " + shell_quote(model.string());
  command += " >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string()) + " </dev/null";
  const int status = std::system(command.c_str());
  // The tools are there, so a failure is a real one, not a reason to skip.
  if (status != 0)
    throw std::runtime_error("compile.mjs failed (status " + std::to_string(status) + "): " + read_file(err));
  return nlohmann::json::parse(read_file(out));
}

}  // namespace assetlint::test
