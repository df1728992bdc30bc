// Golden fixes (fixtures/fix/<rule>/<case>.{urdf,usda} → <case>.<ext>.fixed, exact bytes,
// with the nearest asset-lint.toml above the case as the CLI finds it) and properties of
// --fix --unsafe-fixes over every fixture and every corpus file, run on copies:
// idempotent, still parsing, fixed findings gone, bytes outside the reported edits
// untouched, untouched files not rewritten.
#include <catch2/catch.hpp>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <set>

#include "config/config.h"
#include "pipeline/lint.h"
#include "fix/fixer.h"
#include "fix/writer.h"
#include "formats/mjcf/mjcf_reader.h"
#include "test_support.h"

using namespace assetlint;
using namespace assetlint::fix;
namespace fs = std::filesystem;

namespace {

// The files under `dir` with one of `extensions` (".urdf", ".usda"), sorted.
std::vector<fs::path> asset_files(const fs::path& dir, std::initializer_list<const char*> extensions) {
  std::vector<fs::path> files;
  if (dir.empty() || !fs::is_directory(dir)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (std::any_of(extensions.begin(), extensions.end(), [&](const char* e) { return ext == e; }))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}
std::vector<fs::path> urdf_files(const fs::path& dir) { return asset_files(dir, {".urdf"}); }

// URDF, USDA and MJCF files under `dir` (an .xml counts when its root is <mujoco>), sorted.
std::vector<fs::path> all_asset_files(const fs::path& dir) {
  std::vector<fs::path> files = asset_files(dir, {".urdf", ".usda"});
  for (const auto& xml : asset_files(dir, {".xml"}))
    if (mjcf::looks_like_mjcf(test::read_file(xml))) files.push_back(xml);
  std::sort(files.begin(), files.end());
  return files;
}

// The settings the CLI would use for `file` below `root`: the nearest asset-lint.toml
// above it (none: the defaults), its path shown relative to `root` like the fixture
// diagnostics (tests/fixtures_test.cpp).
Settings settings_for(const fs::path& file, const fs::path& root) {
  Settings settings;
  if (const auto config_path = config::discover(file); !config_path.empty()) {
    const auto shown = fs::relative(fs::absolute(config_path), root);
    const auto error = config::load(config_path.string(), settings, shown.generic_string());
    INFO((error ? error->to_string() : std::string()));
    REQUIRE_FALSE(error);
  }
  return settings;
}

FixOptions unsafe_options() {
  FixOptions options;
  options.unsafe = true;
  return options;
}

struct FileStamp {
  ino_t inode = 0;
  std::int64_t mtime_ns = 0;
  bool operator==(const FileStamp&) const = default;
};
FileStamp stamp(const fs::path& path) {
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  return {st.st_ino, static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec};
}

// Fixes `file` in place like `asset-lint --fix --unsafe-fixes`.
FixResult fix_in_place(const fs::path& file, const Settings& settings = Settings{}) {
  FixResult r = fix_file(file.string(), settings, unsafe_options());
  if (!r.error)
    for (const auto& f : r.files) {
      const auto message = write_fixed_file(f);
      INFO(message.value_or(""));
      REQUIRE_FALSE(message);
    }
  return r;
}

std::multiset<std::pair<std::string, std::string>> parse_findings(const FileReport& report) {
  std::multiset<std::pair<std::string, std::string>> out;
  for (const auto& d : report.diagnostics)
    if (d.rule == "parse-error" || d.rule == "urdf-invalid") out.emplace(d.rule, d.message);
  return out;
}

// `after` is `before` with exactly `edits` (offsets in `before`) applied: every byte
// outside the edits is unchanged and in place, and each edit wrote its replacement.
void check_only_edits_changed(const std::string& before, const std::string& after,
                              std::vector<AppliedFix::PathEdit> edits) {
  std::sort(edits.begin(), edits.end(), [](const auto& a, const auto& b) { return a.offset < b.offset; });
  std::size_t from = 0, to = 0;
  for (const auto& e : edits) {
    REQUIRE(e.offset >= from);
    const std::size_t keep = e.offset - from;
    REQUIRE(to + keep <= after.size());
    CHECK(before.compare(from, keep, after, to, keep) == 0);
    to += keep;
    CHECK(after.compare(to, e.replacement.size(), e.replacement) == 0);
    to += e.replacement.size();
    from = e.offset + e.length;
  }
  CHECK(before.substr(from) == after.substr(std::min(to, after.size())));
}

// A copy to fix: `source` inside a copy of the whole tree `tree` (so that layers a .usda
// composes and the nearest asset-lint.toml come along), or alone when `tree` is empty.
struct Workspace {
  test::TempDir dir;
  fs::path root;  // the copied tree (or the directory holding the lone copy)
  fs::path file;  // the copy of `source`
  Settings settings;

  Workspace(const fs::path& source, const fs::path& tree) {
    if (tree.empty()) {
      root = dir.path();
      file = root / source.filename();
      fs::copy_file(source, file);
    } else {
      root = dir.path() / tree.filename();
      fs::copy(tree, root, fs::copy_options::recursive);
      file = root / fs::relative(source, tree);
      settings = settings_for(file, root);
    }
  }
};

std::string key(const std::string& path) { return fs::weakly_canonical(fs::path(path)).string(); }

struct Snapshot {
  std::map<std::string, std::pair<std::string, FileStamp>> files;  // canonical path → bytes, stamp
};
Snapshot snapshot(const fs::path& root) {
  Snapshot s;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_regular_file())
      s.files[key(entry.path().string())] = {test::read_file(entry.path()), stamp(entry.path())};
  return s;
}

// Every property of fixing one file (a copy of `source`, see Workspace).
void check_fix_properties(const fs::path& source, const fs::path& tree = {}) {
  INFO("file " << source.string());
  Workspace ws(source, tree);
  const fs::path& file = ws.file;
  const Snapshot before = snapshot(ws.root);

  const FixResult first = fix_in_place(file, ws.settings);
  REQUIRE_FALSE(first.error);
  CHECK(first.internal_errors.empty());
  const Snapshot once = snapshot(ws.root);
  // No file appeared or vanished (no temporary files left behind).
  std::set<std::string> paths_before, paths_once;
  for (const auto& [path, _] : before.files) paths_before.insert(path);
  for (const auto& [path, _] : once.files) paths_once.insert(path);
  CHECK(paths_before == paths_once);

  std::map<std::string, std::string> fixed;  // canonical path → bytes written
  for (const auto& f : first.files) {
    INFO("changed " << f.path);
    const std::string k = key(f.path);
    REQUIRE(before.files.count(k) == 1);
    CHECK(f.original == before.files.at(k).first);
    CHECK(f.fixed == once.files.at(k).first);
    fixed[k] = f.fixed;
  }
  if (!first.changed()) CHECK(first.applied == 0);
  // Files with nothing to fix are not rewritten at all.
  for (const auto& [path, entry] : before.files) {
    if (fixed.count(path) || !once.files.count(path)) continue;
    INFO("untouched " << path);
    CHECK(once.files.at(path).first == entry.first);
    CHECK(once.files.at(path).second == entry.second);
  }

  // Round by round, only the reported edits changed bytes; round 1's fixes are the
  // fixes of the first lint's findings.
  for (std::size_t i = 0; i < first.rounds.size(); ++i) {
    const FixRound& round = first.rounds[i];
    REQUIRE_FALSE(round.texts.empty());
    std::map<std::string, std::vector<AppliedFix::PathEdit>> edits;  // canonical path → edits
    for (const auto& applied : round.applied) {
      for (const auto& e : applied.edits) {
        CHECK(path_within(e.path, ws.root.string()));
        edits[key(e.path)].push_back(e);
      }
      if (i == 0) {
        const bool reported = std::any_of(first.initial.diagnostics.begin(), first.initial.diagnostics.end(),
                                          [&](const Diagnostic& d) {
                                            return d.rule == applied.rule && d.fix && d.fix->title == applied.title &&
                                                   d.fix->edits.size() == applied.edits.size();
                                          });
        CHECK(reported);
      }
    }
    for (const auto& [path, text_before] : round.texts) {
      const std::string k = key(path);
      INFO("round " << i + 1 << " of " << path);
      std::string text_after;
      bool found = false;
      if (i + 1 < first.rounds.size()) {
        for (const auto& [next_path, next_text] : first.rounds[i + 1].texts)
          if (key(next_path) == k) text_after = next_text, found = true;
      } else if (fixed.count(k)) {
        text_after = fixed.at(k), found = true;
      } else if (once.files.count(k)) {
        text_after = once.files.at(k).first, found = true;
      }
      if (!found) {
        // A layer that is not in the next round's stack (or not on disk) was not edited.
        CHECK(edits[k].empty());
        continue;
      }
      check_only_edits_changed(text_before, text_after, edits[k]);
    }
  }

  // The fixed file parses as well as before, and the fixed findings are gone.
  const FileReport after = lint_file(file.string(), ws.settings);
  REQUIRE_FALSE(after.error);
  const auto parse_before = parse_findings(first.initial), parse_after = parse_findings(after);
  CHECK(std::includes(parse_before.begin(), parse_before.end(), parse_after.begin(), parse_after.end()));
  const EditScope scope = default_scope(file.string());
  for (const auto& d : after.diagnostics) {
    INFO("remaining " << d.rule << ": " << d.message);
    if (!d.fix || !fix_applies(*d.fix, true)) continue;
    // Only a fix that may not edit where it would (a layer outside the tree) remains.
    bool in_scope = true;
    for (const auto& e : d.fix->edits)
      if (e.file < after.sources.size() && !scope(after.sources[e.file]->path())) in_scope = false;
    CHECK_FALSE(in_scope);
  }
  if (!first.rounds.empty()) {
    for (const auto& applied : first.rounds[0].applied) {
      for (const auto& d : first.initial.diagnostics) {
        if (d.rule != applied.rule || !d.fix || d.fix->title != applied.title) continue;
        const bool still = std::any_of(after.diagnostics.begin(), after.diagnostics.end(), [&](const Diagnostic& a) {
          return a.rule == d.rule && a.message == d.message;
        });
        CHECK_FALSE(still);
      }
    }
  }

  // Fixing again changes nothing and writes nothing.
  const FixResult second = fix_in_place(file, ws.settings);
  REQUIRE_FALSE(second.error);
  CHECK_FALSE(second.changed());
  CHECK(second.applied == 0);
  const Snapshot twice = snapshot(ws.root);
  CHECK(twice.files == once.files);
}

}  // namespace

TEST_CASE("fix: every fixtures/fix case fixes to exactly its .fixed bytes", "[fix]") {
  const auto files = all_asset_files(test::fixtures_dir() / "fix");
  REQUIRE(files.size() >= 20);
  const bool update = std::getenv("ASSET_LINT_UPDATE_EXPECTED") != nullptr;
  std::set<std::string> rules_covered;
  std::map<std::string, std::set<std::string>> formats_covered;  // rule → extensions
  for (const auto& source : files) {
    INFO("fixture " << source.string());
    // In a copy of fixtures/, with the nearest asset-lint.toml above the case.
    Workspace ws(source, test::fixtures_dir());
    const FixResult r = fix_in_place(ws.file, ws.settings);
    REQUIRE_FALSE(r.error);
    CHECK(r.internal_errors.empty());
    CHECK(r.notes.empty());
    CHECK(r.changed());  // every case here has something to fix
    for (const auto& f : r.files) CHECK(key(f.path) == key(ws.file.string()));  // only the case itself
    for (const auto& round : r.rounds)
      for (const auto& applied : round.applied) {
        rules_covered.insert(applied.rule);
        formats_covered[applied.rule].insert(source.extension().string());
      }
    const std::string actual = test::read_file(ws.file);
    const fs::path expected_path = source.string() + ".fixed";
    if (update) test::write_file(expected_path, actual);
    REQUIRE(fs::exists(expected_path));
    CHECK(actual == test::read_file(expected_path));
  }
  CHECK(rules_covered == std::set<std::string>{"drive-damping-ratio", "drive-max-force", "drive-natural-frequency",
                                              "grasp-slip", "joint-max-velocity", "limits-inverted", "mimic-copied-drive-gains",
                                              "mimic-limit-conflict", "mimic-max-velocity", "structure-joint-axis",
                                              "structure-undefined-link", "units-angle-degrees", "units-velocity-implausible",
                                              "unused-suppression"});
  // Every fixable rule in each format where it has something to edit. URDF has no drive
  // gains (they come from asset-lint.toml, which fixes never edit) and no mimic compliance;
  // USD angles are always degrees, so there is no degree guessing to fix.
  const std::set<std::string> both{".urdf", ".usda"}, usda{".usda"}, urdf{".urdf"}, usda_mjcf{".usda", ".xml"},
      mjcf{".xml"};
  const std::map<std::string, std::set<std::string>> want{
      {"drive-damping-ratio", usda_mjcf}, {"drive-max-force", both},         {"drive-natural-frequency", usda},
      {"joint-max-velocity", both},      {"limits-inverted", both},         {"mimic-copied-drive-gains", usda},
      {"mimic-limit-conflict", both},    {"mimic-max-velocity", both},      {"structure-undefined-link", urdf}, {"units-angle-degrees", urdf},
      {"grasp-slip", mjcf},              {"structure-joint-axis", urdf},
      {"units-velocity-implausible", both}, {"unused-suppression", both}};
  CHECK(formats_covered == want);
}

TEST_CASE("fix: CRLF, BOM, comments, quoting and trailing bytes survive", "[fix]") {
  const fs::path dir = test::fixtures_dir() / "fix";
  const std::string crlf = test::read_file(dir / "units-angle-degrees" / "crlf_bom.urdf.fixed");
  CHECK(crlf.starts_with("\xEF\xBB\xBF<?xml"));
  CHECK(crlf.find("<limit lower=\"-1.5708\" upper=\"1.5708\" effort=\"24\" velocity=\"2.9\"/>\r\n") !=
        std::string::npos);
  std::size_t bare_lf = 0;
  for (std::size_t i = 0; i < crlf.size(); ++i) bare_lf += crlf[i] == '\n' && (i == 0 || crlf[i - 1] != '\r');
  CHECK(bare_lf == 0);

  const std::string odd = test::read_file(dir / "limits-inverted" / "odd_quoting_comments.urdf.fixed");
  CHECK(odd.find("    <!-- keep me: lower > upper on purpose -->\n"
                 "    <limit\teffort='24'  lower = '-0.25'\n"
                 "           upper =\"0.5E0\" velocity='2.9' />\n") != std::string::npos);
  CHECK(odd.ends_with("</robot>\n<!-- trailing comment -->\n\n"));
}

TEST_CASE("fix: properties hold for every fixture", "[fix]") {
  // Each in a copy of fixtures/, with its layers and the nearest asset-lint.toml.
  const auto files = all_asset_files(test::fixtures_dir());
  REQUIRE(files.size() >= 40);
  for (const auto& file : files) check_fix_properties(file, test::fixtures_dir());
}

TEST_CASE("fix: properties hold for every corpus file", "[fix][corpus]") {
  const fs::path corpus = test::corpus_dir();
  if (corpus.empty()) {
    WARN("../shared/corpus is absent; corpus fix properties skipped");
    return;
  }
  const auto files = urdf_files(corpus / "urdf");
  REQUIRE_FALSE(files.empty());
  for (const auto& file : files) check_fix_properties(file);
  // MJCF models, each in its own directory with the files it includes.
  const auto models = all_asset_files(corpus / "mjcf");
  REQUIRE_FALSE(models.empty());
  for (const auto& file : models) check_fix_properties(file, file.parent_path());
}
