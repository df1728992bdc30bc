#pragma once
// Helpers shared by the test files: paths, file I/O, running the CLI.
#include <filesystem>
#include <string>
#include <vector>

namespace assetlint::test {

// The repository and the asset-lint binary under test (their paths are compiled into one file,
// so every other test file compiles the same in every checkout).
std::filesystem::path source_dir();
std::filesystem::path asset_lint_binary();
inline std::filesystem::path fixtures_dir() { return source_dir() / "fixtures"; }
// The report-format fixtures (gripper.urdf, joints.usda and their goldens).
inline std::filesystem::path report_dir() { return fixtures_dir() / "report"; }
// ../shared/corpus beside the repository; empty when it is absent.
std::filesystem::path corpus_dir();

// CI=true in the environment: a reference implementation bootstrap installs must be there, so a
// test that needs one fails instead of skipping.
bool in_ci();
// Whether a test that needs reference implementation `name` skips: not when `skipped` (why it
// could not run) is empty; under CI=true a missing reference fails the test instead.
bool skip_without_reference(const std::string& name, const std::string& skipped);

std::string read_file(const std::filesystem::path& path);
// `text` with the first `from` replaced by `to`; throws when `from` is not in it.
std::string replace_once(std::string text, const std::string& from, const std::string& to);
void write_file(const std::filesystem::path& path, const std::string& text);

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};
// Runs the built asset-lint binary with `args` (each shell-quoted) in `cwd`.
CommandResult run_cli(const std::vector<std::string>& args, const std::filesystem::path& cwd = source_dir());
// The same, with `input` on standard input.
CommandResult run_cli_with_input(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                                 const std::string& input);

// `arg` quoted for a POSIX shell.
std::string shell_quote(const std::string& arg);
// Whether `tool` is a command on PATH.
bool on_path(const std::string& tool);
// Runs `command` with `sh -c` (stdin from /dev/null, stdout and stderr into the file `log`);
// returns its exit status (-1 when it did not exit) and its combined output in `output`.
int run_shell(const std::string& command, const std::filesystem::path& log, std::string& output);

// A fresh empty directory under the system temp dir, removed by the destructor.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace assetlint::test
