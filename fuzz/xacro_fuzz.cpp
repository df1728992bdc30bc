// .xacro bytes, split into files at each `\n<robot` (robot.urdf.xacro, i1.xacro, ... for
// xacro:include) → expand → read → every rule, findings relocated to the .xacro files.
// Expansion must end (macro depth, include cycles, output size are bounded) and every
// relocated span must lie inside the file it names.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "memory_file_system.h"

using namespace assetlint;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::MemoryFileSystem files;
  std::string root = fuzz::split_files(std::string_view(reinterpret_cast<const char*>(data), size), files, "\n<robot",
                                       "robot.urdf.xacro", "i", ".xacro");
  Settings settings;
  settings.allow_outside_root = true;
  const FileReport report = lint_text("robot.urdf.xacro", std::move(root), settings, files);
  for (const Diagnostic& d : report.diagnostics) {
    const auto inside = [&](const Span& span) {
      return span.file == kNoFile || (span.file < report.sources.size() && span.end() <= report.source(span.file).text().size());
    };
    if (!inside(d.span)) std::abort();
    for (const Note& n : d.notes)
      if (!inside(n.span)) std::abort();
    if (d.fix)
      for (const Edit& e : d.fix->edits)
        if (e.file >= report.sources.size() || e.offset + e.length > report.source(e.file).text().size()) std::abort();
  }
  return 0;
}
