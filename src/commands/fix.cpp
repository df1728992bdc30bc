#include "commands/fix.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <map>
#include <set>
#include <thread>

#include "commands/exit_status.h"
#include "fix/diff.h"
#include "fix/fixer.h"
#include "fix/writer.h"

namespace assetlint::commands {
namespace {

struct Target {
  std::string path;
  fix::EditScope scope;
};

std::string canonical_path(const std::string& path) {
  std::error_code ec;
  const auto canonical = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : canonical.string();
}

// Which result writes each file. A layer that a checked stage reads (a USD sublayer or
// reference, an MJCF <include>) is the stage's to fix, in the stage's context (its rate and
// configuration), once, even when it is also checked alone, and whether or not the stage
// has anything to change in it: its findings alone are folded into the stage's, as a check
// folds them, so the stage's edits are the ones that hold (and a second run adds nothing).
// A stage that is itself read by another comes after one that is not. Maps a canonical
// path to the index of the result that owns it.
std::map<std::string, std::size_t> file_owners(const std::vector<fix::FixResult>& results) {
  std::vector<std::set<std::string>> layers(results.size());  // what each stage reads besides itself
  std::set<std::string> read_by_a_stage;
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (results[i].error) continue;
    const FileReport& read = results[i].initial;
    const std::string self = canonical_path(results[i].path);
    for (std::size_t id = 1; id < read.sources.size(); ++id)
      if (auto layer = canonical_path(read.sources[id]->path()); layer != self) layers[i].insert(std::move(layer));
    read_by_a_stage.insert(layers[i].begin(), layers[i].end());
  }
  std::map<std::string, std::size_t> owners;
  for (int top = 1; top >= 0; --top)
    for (std::size_t i = 0; i < results.size(); ++i)
      if ((read_by_a_stage.count(canonical_path(results[i].path)) == 0) == (top == 1))
        for (const auto& layer : layers[i]) owners.try_emplace(layer, i);
  for (std::size_t i = 0; i < results.size(); ++i)
    for (const fix::FixedFile& file : results[i].files) owners.try_emplace(canonical_path(file.path), i);
  return owners;
}

std::string problems(std::size_t n) { return fmt::format("{} problem{}", n, n == 1 ? "" : "s"); }

std::string diff_label(const char* prefix, const std::string& path) {
  std::string p = path;
  // Like git: "./x" and "/abs/x" become "a/x" and "a/abs/x".
  while (p.starts_with("./") || p.starts_with("/")) p.erase(0, p.starts_with("/") ? 1 : 2);
  return prefix + p;
}

}  // namespace

int run_fix_command(const std::vector<std::string>& paths, const SettingsFor& settings,
                    const FixCommandOptions& options, std::ostream& out, std::ostream& err,
                    const WriteReport& write_report) {
  RunProblems run_problems;
  // Each file may be edited within the tree it was found in: a directory argument's
  // tree, or a file argument's own directory.
  std::vector<Target> targets;
  std::set<std::string> seen;
  for (const auto& argument : paths) {
    PathExpansion expansion = expand_paths({argument}, options.selection_for);
    RunProblems found = announce_expansion(expansion, err);
    run_problems.errors.insert(run_problems.errors.end(), found.errors.begin(), found.errors.end());
    run_problems.binary_usd += found.binary_usd;
    for (auto& file : expansion.files) {
      // A file named twice (`a.urdf a.urdf`, `dir dir/a.urdf`) is fixed once.
      std::error_code ec;
      const auto canonical = std::filesystem::weakly_canonical(file, ec);
      if (!seen.insert(ec ? file : canonical.string()).second) continue;
      std::error_code dir_ec;
      fix::EditScope scope = std::filesystem::is_directory(argument, dir_ec) ? fix::tree_scope(argument)
                                                                              : fix::default_scope(file);
      targets.push_back({std::move(file), std::move(scope)});
    }
  }

  std::vector<fix::FixResult> results(targets.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < targets.size(); i = next++) {
      fix::FixOptions fix_options;
      fix_options.unsafe = options.unsafe;
      fix_options.scope = targets[i].scope;
      if (options.make_hook) fix_options.on_report = options.make_hook();
      results[i] = fix::fix_file(targets[i].path, settings(targets[i].path), fix_options);
    }
  };
  const unsigned jobs = std::max(1u, std::min<unsigned>(options.jobs, static_cast<unsigned>(targets.size())));
  std::vector<std::thread> threads;
  for (unsigned j = 1; j < jobs; ++j) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();

  bool any_diff = false;
  std::size_t unsafe_left = 0;  // with --diff: unsafe fixes --unsafe-fixes would apply too
  std::vector<FileReport> remaining;
  const auto owners = file_owners(results);
  std::vector<std::string> pending_relint;
  for (std::size_t index = 0; index < results.size(); ++index) {
    fix::FixResult& result = results[index];
    for (const auto& message : result.internal_errors) err << "asset-lint: internal error: " << message << "\n";
    for (const auto& message : result.notes) err << "asset-lint: note: " << message << "\n";
    if (result.error) {
      err << "asset-lint: error: " << *result.error << "\n";
      run_problems.errors.push_back({result.path, *result.error});
      if (!result.initial.error) remaining.push_back(std::move(result.initial));
      continue;
    }
    // Files another result writes: left to it, and this file is judged again afterwards.
    bool deferred = false;
    std::erase_if(result.files, [&](const fix::FixedFile& file) {
      const bool other = owners.at(canonical_path(file.path)) != index;
      deferred = deferred || other;
      return other;
    });
    if (options.diff) {
      for (const Diagnostic& d : result.remaining.diagnostics)
        unsafe_left += d.fix && d.fix->applicability == Applicability::Unsafe ? 1 : 0;
      for (const fix::FixedFile& file : result.files) {
        out << fix::unified_diff(file.original, file.fixed, diff_label("a/", file.path), diff_label("b/", file.path));
        err << fmt::format("asset-lint: would fix {} in {}\n", problems(file.fixes), file.path);
        any_diff = true;
      }
      continue;
    }
    bool write_failed = false;
    for (const fix::FixedFile& file : result.files) {
      if (auto message = fix::write_fixed_file(file)) {
        err << "asset-lint: error: " << *message << "\n";
        run_problems.errors.push_back({file.path, *message});
        write_failed = true;
        continue;
      }
      err << "asset-lint: "
          << (options.written ? options.written(file)
                              : fmt::format("fixed {} in {}", problems(file.fixes), file.path))
          << "\n";
    }
    if (write_failed || deferred) {
      // Report what is on disk now (the writer of a shared layer may come later).
      pending_relint.push_back(result.path);
    } else {
      remaining.push_back(std::move(result.remaining));
    }
  }

  for (const std::string& path : pending_relint) remaining.push_back(lint_file(path, settings(path)));
  const bool failed = !run_problems.errors.empty();
  if (options.diff) {
    const std::string unsafe =
        fmt::format("{} unsafe fix{} {}", unsafe_left, unsafe_left == 1 ? "" : "es", unsafe_left == 1 ? "exists" : "exist");
    if (!failed && !any_diff && unsafe_left == 0) err << "asset-lint: no fix applies; nothing to change\n";
    else if (!failed && !any_diff)
      err << "asset-lint: no safe fix applies; " << unsafe << ", applied with --unsafe-fixes (review with --diff --unsafe-fixes)\n";
    else if (!failed && unsafe_left > 0)
      err << "asset-lint: " << unsafe << " too, applied with --unsafe-fixes\n";
    return failed ? kExitError : any_diff ? kExitFindings : kExitClean;
  }
  std::erase_if(remaining, [](const FileReport& r) { return r.error.has_value(); });
  // What is left, judged as a check judges it: a layer's findings alone folded into its stage's.
  judge_layers_in_stage_context(remaining);
  drop_repeated_findings(remaining);
  write_report(remaining, run_problems);
  if (failed) return kExitError;
  return findings_status(remaining, options.fail_on);
}

}  // namespace assetlint::commands
