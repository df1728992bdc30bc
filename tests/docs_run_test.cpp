// Docs that run: every shell block of README.md and docs/*.md that a reader is told to run is
// run, in page order, in a throwaway git repository (the repository's fixtures beside a small
// assets repository), and a transcript's output lines must come out. A block the test does not
// run says so and why in an HTML comment on the line before it:
//   <!-- illustrative: REASON -->   a synopsis, or the output of a state the page describes
//   <!-- not run: REASON -->        a command this test cannot run (it builds from source, …)
// A shell block is one marked sh/bash/shell/console, or an unmarked one whose first line is a
// command: `$ …`, `asset-lint …`, `./…`.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::run_shell;
using assetlint::test::shell_quote;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace fs = std::filesystem;

namespace {

struct Block {
  std::string page;   // "docs/ci.md"
  std::size_t line;   // of the opening fence
  std::string language;
  std::vector<std::string> lines;
  std::string marker;  // the HTML comment before it, or ""
};

std::string trim(std::string s) {
  s.erase(0, s.find_first_not_of(" \t"));
  s.erase(s.find_last_not_of(" \t\r") + 1);
  return s;
}

std::vector<Block> blocks_of(const fs::path& root, const std::string& page) {
  std::vector<Block> blocks;
  std::istringstream in(read_file(root / page));
  std::string line, previous;
  std::size_t number = 0;
  bool inside = false;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("```", 0) == 0) {
      if (!inside) {
        const std::string before = trim(previous);
        blocks.push_back({page, number, trim(line.substr(3)), {},
                          before.rfind("<!--", 0) == 0 ? before : std::string()});
      }
      inside = !inside;
    } else if (inside) {
      blocks.back().lines.push_back(line);
    }
    previous = line;
  }
  return blocks;
}

std::string first_line(const Block& b) {
  for (const auto& l : b.lines)
    if (!trim(l).empty()) return trim(l);
  return {};
}

bool is_transcript(const Block& b) { return first_line(b).rfind("$ ", 0) == 0; }

bool is_shell(const Block& b) {
  if (b.language == "sh" || b.language == "bash" || b.language == "shell" || b.language == "console") return true;
  if (!b.language.empty()) return false;
  const std::string first = first_line(b);
  return first.rfind("$ ", 0) == 0 || first.rfind("asset-lint ", 0) == 0 || first.rfind("./", 0) == 0;
}

// "illustrative" or "not run", with a reason after the colon; "" when the block runs.
std::string skip_kind(const Block& b) {
  for (const char* kind : {"illustrative", "not run"}) {
    const std::string open = std::string("<!-- ") + kind + ":";
    if (b.marker.rfind(open, 0) == 0 && b.marker.size() > open.size() + 4 && b.marker.ends_with("-->")) return kind;
  }
  return {};
}

std::vector<std::string> pages(const fs::path& root) {
  std::vector<std::string> out{"README.md"};
  std::vector<std::string> docs;
  for (const auto& entry : fs::directory_iterator(root / "docs"))
    if (entry.path().extension() == ".md") docs.push_back("docs/" + entry.path().filename().string());
  std::sort(docs.begin(), docs.end());
  out.insert(out.end(), docs.begin(), docs.end());
  return out;
}

// A repository as a reader of the docs has one: the project's fixtures (git-ignored, so a
// walk leaves them out, as a clone's build directory is) and a few assets of its own.
class Sandbox {
 public:
  Sandbox() {
    const fs::path src = assetlint::test::source_dir();
    for (const char* dir : {"robots", "assets", "build"}) fs::create_directories(root_ / dir);
    fs::copy(src / "fixtures", root_ / "fixtures", fs::copy_options::recursive);
    const fs::path fixtures = src / "fixtures";
    write_file(root_ / "robots" / "gripper.urdf", read_file(fixtures / "report" / "gripper.urdf"));
    write_file(root_ / "buffer", read_file(fixtures / "report" / "gripper.urdf"));  // an editor's unsaved text
    write_file(root_ / "robot.urdf", read_file(fixtures / "fix" / "units-angle-degrees" / "guide_upper_47.urdf"));
    write_file(root_ / "assets" / "hand.urdf", read_file(fixtures / "ci" / "hand.urdf"));
    write_file(root_ / "assets" / "arm.urdf", read_file(fixtures / "ci" / "arm.urdf"));
    write_file(root_ / ".gitignore", "fixtures/\nbuild/\nguide/\n*.svg\n");
    // asset-lint on PATH and at ./build/asset-lint: the built binary, each exit status of 2 or
    // more (usage, configuration or I/O error) written down for the test.
    const std::string wrapper = "#!/bin/sh\n" + shell_quote(assetlint::test::asset_lint_binary().string()) +
                                " \"$@\"\nstatus=$?\nif [ $status -ge 2 ]; then echo \"exit $status: asset-lint $*\" >> " +
                                shell_quote((dir_.path() / "errors").string()) +
                                "; fi\n[ $status -eq 1 ] && [ -n \"$FINDINGS_DO_NOT_STOP\" ] && exit 0\nexit $status\n";
    write_file(root_ / "build" / "asset-lint", wrapper);
    fs::permissions(root_ / "build" / "asset-lint", fs::perms::owner_all, fs::perm_options::add);
    REQUIRE(run(git("init -q") + " && " + git("add .") + " && " + git("commit -q -m assets")) == 0);
  }
  static std::string git(const std::string& args) {
    return "git -c user.name=test -c user.email=test@example.invalid -c init.defaultBranch=main -c commit.gpgsign=false " +
           args;
  }
  // Runs `script` with bash in the repository, asset-lint first on PATH; with `findings_stop`
  // false an exit status of 1 (findings) lets the script go on, as in a reader's shell.
  int run(const std::string& script, bool findings_stop = false) {
    write_file(dir_.path() / "script.sh", std::string(findings_stop ? "" : "export FINDINGS_DO_NOT_STOP=1\n") +
                                              "set -e\n" + script + "\n");
    const std::string env = "PATH=" + shell_quote((root_ / "build").string()) +
                            ":\"$PATH\" NO_COLOR=1 GIT_AUTHOR_NAME=test GIT_AUTHOR_EMAIL=test@example.invalid "
                            "GIT_COMMITTER_NAME=test GIT_COMMITTER_EMAIL=test@example.invalid ";
    return run_shell("cd " + shell_quote(root_.string()) + " && " + env + "bash " +
                         shell_quote((dir_.path() / "script.sh").string()),
                     dir_.path() / "log", output);
  }
  // The asset-lint runs that ended in an error since the last call.
  std::string errors() {
    const fs::path file = dir_.path() / "errors";
    if (!fs::exists(file)) return {};
    std::string text = read_file(file);
    fs::remove(file);
    return text;
  }
  const fs::path& root() const { return root_; }
  std::string output;

 private:
  TempDir dir_;
  fs::path root_ = dir_.path() / "repository";
};

// A transcript: each `$ command` (with its `\` continuation lines) and the lines shown after it.
struct Step {
  std::string command;
  std::vector<std::string> shown;
};
std::vector<Step> steps_of(const Block& b) {
  std::vector<Step> steps;
  bool continued = false;
  for (const auto& line : b.lines) {
    if (continued) {
      steps.back().command += "\n" + line;
      continued = line.ends_with("\\");
    } else if (line.rfind("$ ", 0) == 0) {
      steps.push_back({line.substr(2), {}});
      continued = line.ends_with("\\");
    } else if (!steps.empty() && !trim(line).empty()) {
      steps.back().shown.push_back(line);
    }
  }
  return steps;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

}  // namespace

TEST_CASE("docs: every shell block of README.md and docs/ runs as written, or says why not", "[docs][docs-run]") {
  const fs::path root = assetlint::test::source_dir();
  Sandbox sandbox;
  std::size_t ran = 0;
  for (const std::string& page : pages(root)) {
    for (const Block& block : blocks_of(root, page)) {
      if (!is_shell(block)) continue;
      INFO(block.page << ":" << block.line);
      const std::string kind = skip_kind(block);
      if (!block.marker.empty() && kind.empty())
        FAIL("the comment before the block is neither '<!-- illustrative: why -->' nor '<!-- not run: why -->'");
      if (!kind.empty()) continue;
      ++ran;
      if (!is_transcript(block)) {
        std::string script;
        for (const auto& line : block.lines) script += line + "\n";
        const int status = sandbox.run(script);
        INFO(sandbox.output);
        CHECK(status == 0);
        CHECK(sandbox.errors().empty());
        continue;
      }
      for (const Step& step : steps_of(block)) {
        INFO("$ " << step.command);
        // The exit status is the page's point only when it shows an error; the output must come out.
        const int status = sandbox.run(step.command + "\n");
        INFO(sandbox.output);
        CHECK(status >= 0);
        CHECK(sandbox.errors().empty());
        const std::vector<std::string> actual = lines_of(sandbox.output);
        // Each line shown comes out; "…" stands for what the page leaves out.
        for (const std::string& shown : step.shown) {
          const auto cut = shown.find("…");
          std::string prefix = shown.substr(0, cut);
          while (cut != std::string::npos && !prefix.empty() && (prefix.back() == ' ' || prefix.back() == '('))
            prefix.pop_back();
          if (cut != std::string::npos && trim(prefix).empty()) continue;
          INFO("shown: " << shown);
          CHECK(std::any_of(actual.begin(), actual.end(), [&](const std::string& a) {
            return cut == std::string::npos ? a == shown : a.rfind(prefix, 0) == 0;
          }));
        }
      }
    }
  }
  CHECK(ran >= 15);
}

namespace {

// A step of a GitHub Actions job: its name, and the command it runs or the action it uses.
struct WorkflowStep {
  std::string name, run, uses;
  std::vector<std::pair<std::string, std::string>> with;
};

std::size_t indent_of(const std::string& line) { return line.find_first_not_of(' '); }

std::vector<WorkflowStep> workflow_steps(const Block& block) {
  std::vector<WorkflowStep> steps;
  std::size_t item = std::string::npos;  // the indentation of "- " items
  bool in_steps = false;
  std::string* literal = nullptr;         // a `run: |` being read
  std::size_t literal_indent = 0;
  bool in_with = false;
  for (const std::string& line : block.lines) {
    const std::string text = trim(line);
    if (text.empty() || text[0] == '#') continue;
    const std::size_t indent = indent_of(line);
    if (literal && indent >= literal_indent) {
      *literal += line.substr(literal_indent) + "\n";
      continue;
    }
    literal = nullptr;
    if (text == "steps:") {
      in_steps = true;
      continue;
    }
    if (!in_steps) continue;
    if (text.rfind("- ", 0) == 0 && (item == std::string::npos || indent == item)) {
      item = indent;
      steps.emplace_back();
      in_with = false;
    } else if (item != std::string::npos && indent <= item) {
      break;  // the job's steps end
    }
    const std::string entry = text.rfind("- ", 0) == 0 ? text.substr(2) : text;
    const auto colon = entry.find(':');
    const std::string key = entry.substr(0, colon), value = colon == std::string::npos ? "" : trim(entry.substr(colon + 1));
    WorkflowStep& step = steps.back();
    if (in_with && indent > item + 2) {
      step.with.emplace_back(key, value);
    } else if (key == "name") {
      step.name = value;
    } else if (key == "uses") {
      step.uses = value;
    } else if (key == "with") {
      in_with = true;
    } else if (key == "run") {
      if (value == "|") {
        literal = &step.run;
        literal_indent = item + 4;
      } else {
        step.run = value + "\n";
      }
    }
  }
  return steps;
}

}  // namespace

// The GitHub Actions workflow of docs/ci.md, its steps in order in the repository of assets.
// Not run, and why: the steps that need GitHub (the checkout, which the repository stands for,
// and the SARIF upload, whose file is checked instead), `apt-get update` (it downloads the
// archive's index; the install is run with -s, resolving every package without changing the
// machine), and the build (minutes of compiling; the suite's own build of the same
// CMakeLists.txt stands for it, and its -D options are checked to exist).
TEST_CASE("docs/ci.md: the GitHub Actions workflow's steps run in order", "[docs][docs-run][ci-recipe]") {
  const fs::path root = assetlint::test::source_dir();
  const Block* workflow = nullptr;
  const std::vector<Block> blocks = blocks_of(root, "docs/ci.md");
  for (const Block& b : blocks)
    if (b.language == "yaml" && !b.lines.empty() && b.lines.front().find(".github/workflows/") != std::string::npos)
      workflow = &b;
  REQUIRE(workflow);
  const std::vector<WorkflowStep> steps = workflow_steps(*workflow);
  REQUIRE(steps.size() == 6);
  Sandbox sandbox;
  std::string cmake_lists = read_file(root / "CMakeLists.txt");
  std::vector<std::string> done;
  for (const WorkflowStep& step : steps) {
    INFO("step '" << step.name << "' " << step.uses);
    if (step.uses.rfind("actions/checkout@", 0) == 0) {
      done.push_back("checkout (the repository)");
      continue;
    }
    if (step.uses.rfind("github/codeql-action/upload-sarif@", 0) == 0) {
      const auto file = std::find_if(step.with.begin(), step.with.end(), [](const auto& kv) { return kv.first == "sarif_file"; });
      REQUIRE(file != step.with.end());
      CHECK(read_file(sandbox.root() / file->second).find("\"version\": \"2.1.0\"") != std::string::npos);
      done.push_back("upload (its file)");
      continue;
    }
    REQUIRE(!step.run.empty());
    if (step.run.find("cmake --build") != std::string::npos) {
      std::istringstream options(step.run);
      std::string word;
      while (options >> word)
        if (word.rfind("-DASSET_LINT_", 0) == 0) {
          const std::string option = word.substr(2, word.find('=') - 2);
          INFO(option);
          CHECK(cmake_lists.find("option(" + option + " ") != std::string::npos);
        }
      done.push_back("build (its options)");
      continue;
    }
    std::string script;
    std::istringstream lines(step.run);
    std::string line;
    bool continued = false;
    while (std::getline(lines, line)) {
      const bool update = !continued && trim(line) == "apt-get update";
      if (!update) {
        const auto install = line.find("apt-get install -y");
        script += install == std::string::npos ? line : line.replace(install, 18, "apt-get install -s -y");
        script += "\n";
      }
      continued = line.ends_with("\\");
    }
    const int status = sandbox.run(script, true);
    INFO(script << "\n" << sandbox.output);
    if (step.name == "Gate") {
      // The gate fails the job on the assets' warning (hand.urdf's mimic follower), annotated.
      CHECK(status == 1);
      CHECK(sandbox.output.find("::warning file=assets/hand.urdf,line=") != std::string::npos);
    } else {
      CHECK(status == 0);
    }
    CHECK(sandbox.errors().empty());
    done.push_back(step.name);
  }
  CHECK(done.size() == steps.size());
}
