// Fix round trip: lint, apply every fix (unsafe ones too) in memory, re-read. The result
// must parse whenever the input parsed, and a second round must change nothing.
// The first byte picks the format by its value modulo 3: 0 URDF ('0'), 1 USDA layers ('1'),
// 2 MJCF files ('2').
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fix/fixer.h"
#include "memory_file_system.h"

using namespace assetlint;

namespace {

bool parses(const FileReport& report) {
  if (report.error) return false;
  for (const auto& d : report.diagnostics)
    if (d.rule == "parse-error") return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const int format = data[0] % 3;
  const std::string_view input(reinterpret_cast<const char*>(data) + 1, size - 1);
  fuzz::MemoryFileSystem files;
  // MJCF as .mjcf: an .xml file is MJCF only when its root is <mujoco>; anything else is
  // refused before reading, which is not what this target tests.
  const std::string path = format == 1 ? "root.usda" : format == 2 ? "robot.mjcf" : "robot.urdf";
  if (format == 1) fuzz::split_layers(input, files);
  else if (format == 2) files.set(path, fuzz::split_mjcf(input, files));
  else files.set(path, std::string(input));
  Settings settings;
  settings.allow_outside_root = true;
  fix::FixOptions options;
  options.unsafe = true;
  options.scope = [](const std::string&) { return true; };
  const fix::FixResult first = fix::fix_file(path, settings, options, files);
  // A file the readers refuse (a .urdf holding a binary USD crate's bytes is read as a crate,
  // and may be one the crate reader rejects) is reported before any fix: nothing to round-trip.
  if (first.initial.error) return 0;
  if (first.error) std::abort();  // a readable file: in memory only "the fixes did not converge" is possible
  if (!first.changed()) return 0;
  if (!first.internal_errors.empty()) std::abort();
  if (parses(first.initial) && !parses(first.remaining)) std::abort();
  fuzz::MemoryFileSystem fixed = files;
  for (const auto& f : first.files) fixed.set(f.path, f.fixed);
  const fix::FixResult second = fix::fix_file(path, settings, options, fixed);
  if (second.changed()) std::abort();  // not idempotent
  return 0;
}
