#include "test_support.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace assetlint::test {

std::filesystem::path corpus_dir() {
  const auto dir = source_dir().parent_path() / "shared" / "corpus";
  return std::filesystem::is_directory(dir) ? dir : std::filesystem::path();
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::string shell_quote(const std::string& arg) {
  std::string quoted = "'";
  for (char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

bool on_path(const std::string& tool) {
  return std::system(("command -v " + shell_quote(tool) + " >/dev/null 2>&1").c_str()) == 0;
}

int run_shell(const std::string& command, const std::filesystem::path& log, std::string& output) {
  const int status =
      std::system(("{ " + command + "\n} >" + shell_quote(log.string()) + " 2>&1 </dev/null").c_str());
  output = std::filesystem::exists(log) ? read_file(log) : "";
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

CommandResult run_cli(const std::vector<std::string>& args, const std::filesystem::path& cwd) {
  return run_cli_with_input(args, cwd, "");
}

CommandResult run_cli_with_input(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                                 const std::string& input) {
  TempDir capture;
  const auto out_path = capture.path() / "out", err_path = capture.path() / "err", in_path = capture.path() / "in";
  write_file(in_path, input);
  std::string command = "cd " + shell_quote(cwd.string()) + " && " + shell_quote(assetlint::test::asset_lint_binary().string());
  for (const auto& arg : args) command += " " + shell_quote(arg);
  command += " >" + shell_quote(out_path.string()) + " 2>" + shell_quote(err_path.string()) + " <" +
             shell_quote(in_path.string());
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_file(out_path);
  result.err = read_file(err_path);
  return result;
}

std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("'" + from + "' is not in the text");
  return text.replace(at, from.size(), to);
}

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  path_ = std::filesystem::temp_directory_path() /
          ("asset-lint-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::permissions(path_, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ec);
  std::filesystem::remove_all(path_, ec);
}

bool skip_without_reference(const std::string& name, const std::string& skipped) {
  if (skipped.empty()) return false;
  if (in_ci()) FAIL(name << " reference missing under CI=true: " << skipped);
  WARN(name << " reference skipped: " << skipped << "; run scripts/bootstrap.sh");
  return true;
}

bool in_ci() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string(ci) == "true";
}

}  // namespace assetlint::test
