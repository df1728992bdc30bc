#include "pipeline/lint.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <set>
#include <tuple>
#include <thread>

#include "config/drive_overrides.h"
#include "engine/rule.h"
#include "formats/file_kind.h"
#include "formats/urdf/urdf_reader.h"
#include "formats/usda/usd_reader.h"
#include "pipeline/suppressions.h"
#include "rules/registry.h"

namespace assetlint {
namespace {

// The deepest named tree that holds the file; empty (its own directory) when none does.
std::string tree_of(const std::string& path, const std::vector<std::string>& trees) {
  namespace fs = std::filesystem;
  // Lexical paths, like the composer's own check: a tree named through a symlink keeps
  // the files found through that symlink inside it.
  std::error_code ec;
  const fs::path file = fs::absolute(path, ec).lexically_normal();
  std::string best;
  for (const auto& tree : trees) {
    const fs::path root = fs::absolute(tree, ec).lexically_normal();
    const fs::path relative = file.lexically_relative(root);
    const bool inside = !relative.empty() && *relative.begin() != "..";
    if (inside && root.string().size() > best.size()) best = root.string();
  }
  return best;
}

ReadResult read(const std::string& path, FileKind kind, std::shared_ptr<const SourceFile> file,
                const FileSystem& files, const Settings& settings) {
  switch (kind) {
    case FileKind::Urdf: return urdf::read_urdf(std::move(file));
    case FileKind::Usda:
      return usda::read_usda(std::move(file), files,
                             usda::ComposeOptions{tree_of(path, settings.trees), settings.allow_outside_root});
    default: break;
  }
  ReadResult unsupported;
  unsupported.asset.sources.push_back(std::move(file));
  unsupported.usable = false;
  return unsupported;
}

void sort_diagnostics(std::vector<Diagnostic>& diagnostics) {
  std::stable_sort(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return std::tie(a.span.file, a.span.offset, a.rule) < std::tie(b.span.file, b.span.offset, b.rule);
  });
}

}  // namespace

FileReport lint_text(const std::string& path, std::string text, const Settings& settings, const FileSystem& files) {
  FileReport report;
  report.path = path;
  FileKind kind = file_kind(path);
  if (kind == FileKind::Usd) kind = usd_kind(text);
  if (kind == FileKind::BinaryUsd) {
    report.error = fmt::format("'{}' is a binary USD file; asset-lint reads text USD (.usda, or .usd starting "
                               "with '#usda 1.0')", path);
    return report;
  }
  if (kind == FileKind::Unsupported) {
    report.error = fmt::format("unsupported file type '{}' (asset-lint reads .urdf, .usda and text .usd files)",
                               extension_of(path));
    return report;
  }
  auto file = std::make_shared<const SourceFile>(path, std::move(text));
  ReadResult result = read(path, kind, std::move(file), files, settings);
  std::vector<Diagnostic> diagnostics;
  for (auto& d : result.diagnostics)
    if (settings.selection.enabled(d.rule)) diagnostics.push_back(std::move(d));
  if (result.usable) {
    config::apply_drive_settings(result.asset, settings);
    for (const Rule* rule : rules::checks()) {
      if (!settings.selection.enabled(rule->info().id)) continue;
      Reporter reporter(rule->info(), diagnostics);
      rule->check(result.asset, settings, reporter);
    }
  }
  for (auto& d : diagnostics) {
    // `[rules.<id>] severity` sets every finding of the rule, whatever tier the rule chose.
    d.severity = settings.severity_for(d.rule, d.severity);
  }
  apply_suppressions(result.asset.sources, diagnostics, settings);
  sort_diagnostics(diagnostics);
  report.diagnostics = std::move(diagnostics);
  report.sources = std::move(result.asset.sources);
  return report;
}

FileReport lint_file(const std::string& path, const Settings& settings, const FileSystem& files) {
  std::string error;
  std::optional<std::string> text = files.read(path, error);
  if (!text) {
    FileReport report;
    report.path = path;
    report.error = fmt::format("cannot read '{}': {}", path, error);
    return report;
  }
  return lint_text(path, std::move(*text), settings, files);
}

std::vector<FileReport> lint_files(const std::vector<std::string>& paths, const Settings& settings, unsigned jobs) {
  return lint_files(paths, [&](const std::string&) -> const Settings& { return settings; }, jobs);
}

std::vector<FileReport> lint_files(const std::vector<std::string>& paths, const SettingsFor& settings, unsigned jobs) {
  std::vector<FileReport> reports(paths.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < paths.size(); i = next++) reports[i] = lint_file(paths[i], settings(paths[i]));
  };
  jobs = std::max(1u, std::min<unsigned>(jobs, static_cast<unsigned>(paths.size())));
  std::vector<std::thread> threads;
  for (unsigned j = 1; j < jobs; ++j) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  return reports;
}

void drop_repeated_findings(std::vector<FileReport>& reports) {
  std::set<std::tuple<std::string, std::size_t, std::string, std::string>> seen;
  for (auto& report : reports) {
    std::erase_if(report.diagnostics, [&](const Diagnostic& d) {
      const std::string& layer = d.span.file < report.sources.size() ? report.source(d.span.file).path() : report.path;
      const auto canonical = std::filesystem::weakly_canonical(layer).string();
      return !seen.emplace(canonical, d.span.offset, d.rule, d.message).second;
    });
  }
}

}  // namespace assetlint
