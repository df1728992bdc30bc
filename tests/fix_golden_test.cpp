// Golden fixes (fixtures/fix/<rule>/<case>.urdf → <case>.urdf.fixed, exact bytes) and
// properties of --fix --unsafe-fixes over every fixture and every corpus file, run on
// copies: idempotent, still parsing, fixed findings gone, bytes outside the reported
// edits untouched, untouched files not rewritten.
#include <catch2/catch.hpp>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

#include "engine/linter.h"
#include "fix/fixer.h"
#include "fix/writer.h"
#include "test_support.h"

using namespace assetlint;
using namespace assetlint::fix;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> urdf_files(const fs::path& dir) {
  std::vector<fs::path> files;
  if (dir.empty() || !fs::is_directory(dir)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".urdf") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
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
FixResult fix_in_place(const fs::path& file) {
  FixResult r = fix_file(file.string(), Settings{}, unsafe_options());
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

// Every property of fixing one file (a copy of `source`).
void check_fix_properties(const fs::path& source) {
  INFO("file " << source.string());
  test::TempDir dir;
  const fs::path file = dir.path() / source.filename();
  fs::copy_file(source, file);
  const std::string original = test::read_file(file);
  const FileStamp before = stamp(file);

  const FixResult first = fix_in_place(file);
  REQUIRE_FALSE(first.error);
  CHECK(first.internal_errors.empty());
  const std::string fixed = test::read_file(file);

  if (!first.changed()) {
    // Nothing to fix: not rewritten at all.
    CHECK(fixed == original);
    CHECK(stamp(file) == before);
    CHECK(first.applied == 0);
  } else {
    REQUIRE(first.files.size() == 1);
    CHECK(first.files[0].original == original);
    CHECK(first.files[0].fixed == fixed);
  }

  // Round by round, only the reported edits changed bytes; round 1's fixes are the
  // fixes of the first lint's findings.
  for (std::size_t i = 0; i < first.rounds.size(); ++i) {
    const FixRound& round = first.rounds[i];
    REQUIRE(round.texts.size() == 1);
    const std::string& text_before = round.texts[0].second;
    const std::string& text_after = i + 1 < first.rounds.size() ? first.rounds[i + 1].texts[0].second : fixed;
    std::vector<AppliedFix::PathEdit> edits;
    for (const auto& applied : round.applied) {
      for (const auto& e : applied.edits) {
        CHECK(e.path == file.string());
        edits.push_back(e);
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
    check_only_edits_changed(text_before, text_after, edits);
  }

  // The fixed file parses as well as before, and the fixed findings are gone.
  const FileReport after = lint_file(file.string(), Settings{});
  REQUIRE_FALSE(after.error);
  const auto parse_before = parse_findings(first.initial), parse_after = parse_findings(after);
  CHECK(std::includes(parse_before.begin(), parse_before.end(), parse_after.begin(), parse_after.end()));
  for (const auto& d : after.diagnostics) {
    INFO("remaining " << d.rule << ": " << d.message);
    CHECK_FALSE((d.fix && fix_applies(*d.fix, true)));
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
  const FileStamp once = stamp(file);
  const FixResult second = fix_in_place(file);
  REQUIRE_FALSE(second.error);
  CHECK_FALSE(second.changed());
  CHECK(second.applied == 0);
  CHECK(test::read_file(file) == fixed);
  CHECK(stamp(file) == once);
  // No temporary files left behind.
  CHECK(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()) == 1);
}

}  // namespace

TEST_CASE("fix: every fixtures/fix case fixes to exactly its .fixed bytes", "[fix]") {
  const auto files = urdf_files(test::fixtures_dir() / "fix");
  REQUIRE(files.size() >= 8);
  const bool update = std::getenv("ASSET_LINT_UPDATE_EXPECTED") != nullptr;
  std::set<std::string> rules_covered;
  for (const auto& source : files) {
    INFO("fixture " << source.string());
    test::TempDir dir;
    const fs::path file = dir.path() / source.filename();
    fs::copy_file(source, file);
    const FixResult r = fix_in_place(file);
    REQUIRE_FALSE(r.error);
    CHECK(r.internal_errors.empty());
    CHECK(r.changed());  // every case here has something to fix
    for (const auto& round : r.rounds)
      for (const auto& applied : round.applied) rules_covered.insert(applied.rule);
    const std::string actual = test::read_file(file);
    const fs::path expected_path = source.string() + ".fixed";
    if (update) test::write_file(expected_path, actual);
    REQUIRE(fs::exists(expected_path));
    CHECK(actual == test::read_file(expected_path));
  }
  CHECK(rules_covered == std::set<std::string>{"limits-inverted", "mimic-limit-conflict", "mimic-max-velocity",
                                              "units-angle-degrees", "units-velocity-implausible"});
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
  const auto files = urdf_files(test::fixtures_dir());
  REQUIRE(files.size() >= 20);
  for (const auto& file : files) check_fix_properties(file);
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
}
