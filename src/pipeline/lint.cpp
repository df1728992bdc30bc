#include "pipeline/lint.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>
#include <thread>

#include "backends/mujoco/mujoco_collision.h"
#include "config/drive_overrides.h"
#include "config/project_root.h"
#include "engine/collision.h"
#include "engine/read_policy.h"
#include "engine/rule.h"
#include "fix/trailing_comments.h"
#include "formats/file_kind.h"
#include "formats/mjcf/mjcf_reader.h"
#include "formats/urdf/urdf_reader.h"
#include "formats/usda/usd_reader.h"
#include "formats/xacro/xacro_reader.h"
#include "formats/usdc/crate_layer.h"
#include "formats/usdc/crate_usda.h"
#include "physics/articulation.h"
#include "pipeline/binary_layer_fixes.h"
#include "pipeline/inherited_fixes.h"
#include "pipeline/suppressions.h"
#include "pipeline/variant_checks.h"
#include "pipeline/xacro_includers.h"
#include "rules/reader_rules.h"
#include "rules/registry.h"

namespace assetlint {
namespace {

xacro::XacroOptions xacro_options(const std::string& path, const Settings& settings, const Deadline& deadline) {
  xacro::XacroOptions options;
  options.root = config::checked_root(path, settings);
  options.deadline = deadline;
  for (const auto& [name, value] : settings.xacro.args) options.arguments[name] = xacro::ArgumentValue{value.value, value.origin, {}};
  return options;
}

usda::ComposeOptions compose_options(const std::string& path, const Settings& settings) {
  usda::ComposeOptions options{config::checked_root(path, settings), settings.allow_outside_root, {}, {}};
  for (const auto& [set, variant] : settings.usd.variants) options.pinned_variants[set] = variant.value;
  return options;
}

ReadResult read(const std::string& path, FileKind kind, std::shared_ptr<const SourceFile> file,
                const FileSystem& files, const Settings& settings, const Deadline& deadline) {
  switch (kind) {
    case FileKind::Urdf: return urdf::read_urdf(std::move(file));
    case FileKind::Mjcf:
      return mjcf::read_mjcf(std::move(file), files,
                             mjcf::ReadOptions{config::checked_root(path, settings), settings.allow_outside_root,
                                               settings.mujoco.parsed()});
    case FileKind::Usda:
      return usda::read_usda(std::move(file), files, compose_options(path, settings));
    case FileKind::Xacro: return xacro::read_xacro(std::move(file), files, xacro_options(path, settings, deadline));
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

// The reader for `path` (text USD is told from binary by its first bytes), or why none.
std::optional<std::string> kind_of(const std::string& path, std::string_view text, FileKind& kind) {
  kind = file_kind(path, text);
  if (is_lfs_pointer(text)) return fmt::format("'{}' {}", path, lfs_pointer_message());
  if (kind == FileKind::Usd) kind = usd_kind(text);
  if (kind == FileKind::BinaryUsd && usdc::is_crate(text)) kind = FileKind::Usda;
  if (kind == FileKind::BinaryUsd)
    return fmt::format("'{}' is a binary USD file that is not a crate layer (a .usdz package?); asset-lint reads "
                       "USDA and crate layers (.usda, .usd, .usdc)", path);
  if (kind == FileKind::Unsupported && extension_of(path) == ".xml")
    return std::string("not a robot model: the root element of this .xml file is neither <mujoco> nor <robot>");
  if (kind == FileKind::Unsupported)
    return fmt::format("unsupported file type '{}' (asset-lint reads .urdf, .xacro, .usda, text .usd, .mjcf and MJCF "
                       ".xml files)", extension_of(path));
  return std::nullopt;
}

// The source the reader reads: the file's text, or the USDA a crate layer reads as.
std::shared_ptr<const SourceFile> source_of(const std::string& path, std::string text, std::string& error) {
  if (usdc::is_crate(text)) return usdc::crate_source(path, text, error);
  return std::make_shared<const SourceFile>(path, std::move(text));
}

// The source lint reads, and for a crate layer the layer read from it already.
std::shared_ptr<const SourceFile> root_of(const std::string& path, std::string text, std::string& error,
                                          std::shared_ptr<const usda::Layer>& layer) {
  if (!usdc::is_crate(text)) return std::make_shared<const SourceFile>(path, std::move(text));
  auto crate = usdc::read_crate_layer(path, text, 0, error);
  if (!crate) return nullptr;
  layer = std::move(crate->layer);
  return std::move(crate->source);
}

// The reader's findings the selection keeps, then the rules' (when the model is usable).
std::vector<Diagnostic> check(ReadResult& result, const Settings& settings, std::set<FileId>& unparsable,
                              const Deadline& deadline) {
  std::vector<Diagnostic> diagnostics;
  for (auto& d : result.diagnostics) {
    if (d.rule == rules::kParseError.id) unparsable.insert(d.span.file == kNoFile ? 0 : d.span.file);
    if (settings.selection.enabled(d.rule)) diagnostics.push_back(std::move(d));
  }
  if (!result.usable) return diagnostics;
  config::apply_drive_settings(result.asset, settings);
  // The geometry rules collide shapes through MuJoCo's pipeline; rules/ knows only engine/collision.h.
  static const bool collision_engine_installed =
      (collision::install_engine(&backends::mujoco::collision_engine()), true);
  (void)collision_engine_installed;
  const physics::SharedArticulationScope shared_articulation(result.asset);
  for (const Rule* rule : rules::checks()) {
    if (!settings.selection.enabled(rule->info().id)) continue;
    if (deadline.passed())
      throw TimeBudgetExceeded(fmt::format("checking stopped: the file's time budget of {:g} s (--time-budget) ran out "
                                           "before rule '{}'; the file is not checked",
                                           deadline.budget_seconds(), rule->info().id));
    Reporter reporter(rule->info(), diagnostics);
    rule->check(result.asset, settings, reporter);
  }
  withhold_fixes_on_shared_literals(result.asset, diagnostics);
  withhold_fixes_in_binary_layers(result.asset.sources, diagnostics);
  return diagnostics;
}

}  // namespace

namespace {

FileReport lint_text_within(const std::string& path, std::string text, const Settings& settings,
                            const FileSystem& unconfined, const Deadline& deadline) {
  const ConfinedFileSystem files(unconfined, config::read_policy(path, settings));
  FileReport report;
  report.path = path;
  FileKind kind;
  if (auto why = kind_of(path, text, kind)) {
    report.error = std::move(*why);
    return report;
  }
  if (auto through = lint_through_includers(path, text, settings, files)) return std::move(*through);
  std::shared_ptr<const usda::Layer> crate_layer;
  auto file = root_of(path, std::move(text), report.error.emplace(), crate_layer);
  if (!file) return report;
  report.error.reset();
  std::set<FileId> unparsable;
  ReadResult result;
  std::vector<Diagnostic> diagnostics;
  if (kind == FileKind::Usda) {
    usda::ComposeOptions options = compose_options(path, settings);
    options.root_layer = std::move(crate_layer);
    usda::Stage stage = usda::compose_stage(file, files, options);
    const std::vector<usda::VariantSetUse> sets = stage.variant_sets;
    result = usda::read_stage(std::move(stage));
    diagnostics = check(result, settings, unparsable, deadline);
    const StageCheck check_variant = [&](ReadResult& read, std::set<FileId>& broken) {
      return check(read, settings, broken, deadline);
    };
    check_physics_variants(file, files, options, sets, check_variant, result.asset.sources, diagnostics, unparsable);
  } else {
    result = read(path, kind, std::move(file), files, settings, deadline);
    diagnostics = check(result, settings, unparsable, deadline);
  }
  if (result.relocate) result.asset.sources = result.relocate(diagnostics);
  for (auto& d : diagnostics)
    if (d.fix) fix::restate_trailing_comments(result.asset.sources, *d.fix);
  for (auto& d : diagnostics) {
    // `[rules.<id>] severity` sets every finding of the rule, whatever tier the rule chose.
    d.severity = settings.severity_for(d.rule, d.severity);
  }
  apply_suppressions(result.asset.sources, diagnostics, settings, unparsable);
  sort_diagnostics(diagnostics);
  report.diagnostics = std::move(diagnostics);
  report.sources = std::move(result.asset.sources);
  return report;
}

}  // namespace

FileReport lint_text(const std::string& path, std::string text, const Settings& settings, const FileSystem& unconfined) {
  try {
    return lint_text_within(path, std::move(text), settings, unconfined, Deadline::for_one_file());
  } catch (const TimeBudgetExceeded& stopped) {
    FileReport report;
    report.path = path;
    report.error = fmt::format("'{}': {}", path, stopped.what());
    return report;
  }
}

std::optional<ReadResult> read_asset(const std::string& path, const Settings& settings, std::string& error,
                                     const FileSystem& files) {
  LoadedAsset loaded = load_asset(path, settings, files);
  if (loaded.error) {
    error = std::move(*loaded.error);
    return std::nullopt;
  }
  return std::move(loaded.read);
}

FileReport lint_file(const std::string& path, const Settings& settings, const FileSystem& unconfined) {
  std::string error;
  std::optional<std::string> text = ConfinedFileSystem(unconfined, config::read_policy(path, settings)).read(path, error);
  if (!text) {
    FileReport report;
    report.path = path;
    report.error = fmt::format("cannot read '{}': {}", path, error);
    return report;
  }
  return lint_text(path, std::move(*text), settings, unconfined);
}

namespace {

LoadedAsset load(const std::string& path, const Settings& settings, const FileSystem& unconfined, bool expand_xacro) {
  const ConfinedFileSystem files(unconfined, config::read_policy(path, settings));
  LoadedAsset loaded;
  std::string error;
  std::optional<std::string> text = files.read(path, error);
  if (!text) {
    loaded.error = fmt::format("cannot read '{}': {}", path, error);
    return loaded;
  }
  FileKind kind;
  if (auto why = kind_of(path, *text, kind)) {
    loaded.error = std::move(*why);
    return loaded;
  }
  if (kind == FileKind::Xacro && !expand_xacro) {
    // compare shows and rewrites its file's lines; a xacro file's model is its expansion's.
    loaded.error = fmt::format("'{}' is xacro source: expand it first (asset-lint expand {} -o robot.urdf)", path, path);
    return loaded;
  }
  auto file = source_of(path, std::move(*text), error);
  if (!file) {
    loaded.error = std::move(error);
    return loaded;
  }
  loaded.read = read(path, kind, std::move(file), files, settings, Deadline::for_one_file());
  if (loaded.read.usable) config::apply_drive_settings(loaded.read.asset, settings);
  return loaded;
}

}  // namespace

LoadedAsset load_asset(const std::string& path, const Settings& settings, const FileSystem& files) {
  return load(path, settings, files, false);
}

LoadedAsset load_model(const std::string& path, const Settings& settings, const FileSystem& files) {
  return load(path, settings, files, true);
}

std::optional<VariantRun> plan_variants(const std::string& path, const Settings& settings, const FileSystem& unconfined) {
  const ConfinedFileSystem files(unconfined, config::read_policy(path, settings));
  std::string error;
  std::optional<std::string> text = files.read(path, error);
  FileKind kind;
  if (!text || kind_of(path, *text, kind) || kind != FileKind::Usda) return std::nullopt;
  auto file = source_of(path, std::move(*text), error);
  if (!file) return std::nullopt;
  return plan_physics_variants(file, files, compose_options(path, settings));
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

std::size_t judge_layers_in_stage_context(std::vector<FileReport>& reports) {
  const auto canonical = [](const std::string& path) {
    std::error_code ec;
    const auto c = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : c.string();
  };
  std::vector<std::string> roots;
  std::vector<std::set<std::string>> composed(reports.size());  // each report's layers, its own file aside
  std::map<std::string, std::vector<std::size_t>> composers;     // layer → reports that compose it
  for (std::size_t i = 0; i < reports.size(); ++i) {
    roots.push_back(canonical(reports[i].path));
    for (std::size_t id = 1; id < reports[i].sources.size(); ++id) {
      std::string layer = canonical(reports[i].sources[id]->path());
      if (layer == roots[i] || !composed[i].insert(layer).second) continue;
      composers[layer].push_back(i);
    }
  }
  const auto top_level = [&](std::size_t i) {
    const auto it = composers.find(roots[i]);
    return it == composers.end() || std::all_of(it->second.begin(), it->second.end(), [&](std::size_t j) { return j == i; });
  };
  std::size_t folded = 0;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const auto it = composers.find(roots[i]);
    if (it == composers.end() || reports[i].error) continue;
    const auto stage = std::find_if(it->second.begin(), it->second.end(), [&](std::size_t j) { return j != i && top_level(j); });
    if (stage == it->second.end()) continue;
    FileReport& report = reports[i];
    std::erase_if(report.diagnostics, [&](const Diagnostic& d) {
      const std::string layer = d.span.file < report.sources.size() ? canonical(report.source(d.span.file).path()) : roots[i];
      return layer == roots[i] || composed[*stage].count(layer) > 0;
    });
    ++folded;
  }
  return folded;
}

void drop_repeated_findings(std::vector<FileReport>& reports) {
  std::set<std::tuple<std::string, std::size_t, std::string, std::string>> seen;
  // weakly_canonical asks the file system about every component of the path: once per file.
  std::map<std::string, std::string> canonical;
  for (auto& report : reports) {
    std::erase_if(report.diagnostics, [&](const Diagnostic& d) {
      const std::string& layer = d.span.file < report.sources.size() ? report.source(d.span.file).path() : report.path;
      auto it = canonical.find(layer);
      if (it == canonical.end()) it = canonical.emplace(layer, std::filesystem::weakly_canonical(layer).string()).first;
      return !seen.emplace(it->second, d.span.offset, d.rule, d.message).second;
    });
  }
}

}  // namespace assetlint
