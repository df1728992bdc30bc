#include "commands/stdin.h"

#include <iterator>

#include "commands/exit_status.h"
#include "engine/file_system.h"
#include "fix/fixer.h"

namespace assetlint::commands {

int run_stdin(std::istream& in, const Settings& settings, const StdinOptions& options, std::ostream& out,
              std::ostream& err, const WriteReport& write_report) {
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (!options.fix) {
    FileReport report = lint_text(options.filename, std::move(text), settings);
    if (report.error) {
      err << "asset-lint: error: " << *report.error << "\n";
      write_report({}, RunProblems{{{options.filename, *report.error}}, 0});
      return kExitError;
    }
    std::vector<FileReport> reports{std::move(report)};
    write_report(reports, {});
    return findings_status(reports, options.fail_on);
  }
  // The fixer reads the file through an overlay that holds the text from stdin; other
  // layers come from the disk. Nothing is written to the disk.
  OverlayFileSystem files(disk());
  files.set(options.filename, text);
  fix::FixOptions fix_options;
  fix_options.unsafe = options.unsafe;
  fix::FixResult result = fix::fix_file(options.filename, settings, fix_options, files);
  if (result.error) {
    err << "asset-lint: error: " << *result.error << "\n";
    out << text;  // an editor replacing its buffer with our output keeps the text
    return kExitError;
  }
  std::string fixed = text;
  for (const auto& file : result.files)
    if (file.path == options.filename) fixed = file.fixed;
  out << fixed;
  return findings_status({result.remaining}, options.fail_on);
}

}  // namespace assetlint::commands
