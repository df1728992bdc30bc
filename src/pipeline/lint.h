#pragma once
// Runs the readers and the rules over files: the one entry point the commands, the
// fixer and the tests share.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/diagnostic.h"
#include "engine/file_system.h"
#include "engine/settings.h"
#include "formats/read_result.h"
#include "pipeline/variant_checks.h"
#include "model/source.h"

namespace assetlint {

struct FileReport {
  std::string path;                                       // as the user named it
  std::vector<std::shared_ptr<const SourceFile>> sources; // [0] is the file itself; more for composed layers
  std::vector<Diagnostic> diagnostics;                    // sorted by file, position, rule
  std::optional<std::string> error;                       // unreadable or unsupported file

  const SourceFile& source(FileId id) const { return *sources.at(id); }
};

// Reads a file into the model (with the configuration's [drives.*] applied) without
// running the rules; nullopt with `error` set when it cannot be read or is not a model.
std::optional<ReadResult> read_asset(const std::string& path, const Settings& settings, std::string& error,
                                     const FileSystem& files = disk());

// The variant sets of a USD file and the selections a check of it composes and checks
// (variant_checks.h); nullopt for a file that is not USD or cannot be read.
std::optional<VariantRun> plan_variants(const std::string& path, const Settings& settings,
                                        const FileSystem& files = disk());

// Reads and lints one file (through `files`, the disk by default).
FileReport lint_file(const std::string& path, const Settings& settings, const FileSystem& files = disk());
// Lints text as if it were the file `path` (its extension picks the reader).
// Other files it refers to (USD layers) are read through `files`.
FileReport lint_text(const std::string& path, std::string text, const Settings& settings,
                     const FileSystem& files = disk());
// Reads one file into the model the rules check (the configuration's [drives] applied),
// for commands that compare one asset's lines (compare). `error` when the file cannot
// be read or is of an unsupported type; otherwise `read.usable` says whether the reader
// could build the model (its diagnostics say why not).
struct LoadedAsset {
  ReadResult read;
  std::optional<std::string> error;
};
LoadedAsset load_asset(const std::string& path, const Settings& settings, const FileSystem& files = disk());
// The same for the commands that read one model's values (init, tune, simulate, verify): a
// .xacro file is read as its expansion (its arguments and packages as the check reads them),
// whose spans point into the expanded text; read.written_at maps them to the xacro source and
// read.relocate moves edits there.
LoadedAsset load_model(const std::string& path, const Settings& settings, const FileSystem& files = disk());
// Lints files in parallel on `jobs` threads; the reports keep the order of `paths`.
std::vector<FileReport> lint_files(const std::vector<std::string>& paths, const Settings& settings, unsigned jobs);
// The same, with each file's own settings (its asset-lint.toml).
using SettingsFor = std::function<const Settings&(const std::string& path)>;
std::vector<FileReport> lint_files(const std::vector<std::string>& paths, const SettingsFor& settings, unsigned jobs);

// A layer checked on its own and also composed into another checked USD stage would get a
// verdict from each context (60 Hz alone, 250 Hz under the stage's configuration layer) on the
// same lines. It is judged once, in the stage that uses it: the findings of its own report that
// lie in layers such a stage composes are dropped. Only a stage that no other checked file
// composes counts, so a cycle of layers keeps its findings. Returns how many reports were
// folded into a stage.
std::size_t judge_layers_in_stage_context(std::vector<FileReport>& reports);

// A layer shared by several checked USD files (a physics layer and the configuration
// layer that sublayers it) yields the same finding once per file that composes it:
// keeps the first, drops the repeats (same layer, position, rule and message).
void drop_repeated_findings(std::vector<FileReport>& reports);

}  // namespace assetlint
