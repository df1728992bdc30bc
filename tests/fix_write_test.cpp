// Writing fixed files: atomic replacement, mode kept, and the failure paths (read-only
// file, read-only directory, file replaced during the run, full disk) leave the
// original intact, exit 2 and name the file.
//
// The tests usually run as root, and root ignores permission bits. So "read-only" is
// made with the immutable flag (`chattr +i`, which binds root too) when running as
// root, with chmod otherwise; and one test drops to the `nobody` user with
// `setpriv` so that plain permission bits are exercised as well. The full-disk test
// mounts a tiny tmpfs in a private mount namespace (`unshare -m`). Each is skipped
// with a warning when the machine does not allow it.
#include <catch2/catch.hpp>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "fix/fixer.h"
#include "fix/writer.h"
#include "test_support.h"

using namespace assetlint;
using namespace assetlint::fix;
namespace fs = std::filesystem;

namespace {

const fs::path kFixture = fs::path("fixtures") / "fix" / "units-angle-degrees" / "guide_upper_47.urdf";

std::string shell_quote(const std::string& arg) {
  std::string quoted = "'";
  for (char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

int shell(const std::string& command) {
  const int status = std::system((command + " >/dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Copies the fixture into `dir` as robot.urdf.
fs::path copy_fixture(const fs::path& dir) {
  const fs::path file = dir / "robot.urdf";
  fs::copy_file(test::source_dir() / kFixture, file);
  return file;
}

std::size_t entries(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

// Makes a file or directory read-only for this process, and undoes it on destruction.
class ReadOnly {
 public:
  explicit ReadOnly(const fs::path& path) : path_(path) {
    if (::geteuid() != 0) {
      fs::permissions(path, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                      fs::perm_options::remove);
      mode_ = Mode::Chmod;
    } else if (shell("chattr +i " + shell_quote(path.string())) == 0) {
      mode_ = Mode::Immutable;
    }
  }
  ~ReadOnly() {
    if (mode_ == Mode::Immutable) shell("chattr -i " + shell_quote(path_.string()));
    if (mode_ == Mode::Chmod) fs::permissions(path_, fs::perms::owner_write, fs::perm_options::add);
  }
  bool active() const { return mode_ != Mode::None; }

 private:
  enum class Mode { None, Chmod, Immutable };
  fs::path path_;
  Mode mode_ = Mode::None;
};

}  // namespace

TEST_CASE("fix: a written file is replaced atomically and keeps its mode", "[fix]") {
  test::TempDir dir;
  const fs::path file = copy_fixture(dir.path());
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  struct stat before {};
  REQUIRE(::stat(file.c_str(), &before) == 0);
  FixOptions options;
  options.unsafe = true;
  const FixResult r = fix_file(file.string(), Settings{}, options);
  REQUIRE(r.files.size() == 1);
  std::string seen_temp;
  WriteOptions hooks;
  hooks.before_rename = [&](const std::string& temp) {
    seen_temp = temp;
    // The temporary file is complete, beside the original, with its mode, before the rename.
    CHECK(fs::path(temp).parent_path() == dir.path());
    CHECK(test::read_file(temp) == r.files[0].fixed);
    CHECK((fs::status(temp).permissions() & fs::perms::all) == (fs::perms::owner_read | fs::perms::owner_write |
                                                                 fs::perms::group_read));
  };
  REQUIRE_FALSE(write_fixed_file(r.files[0], hooks));
  CHECK_FALSE(seen_temp.empty());
  CHECK_FALSE(fs::exists(seen_temp));
  CHECK(test::read_file(file) == r.files[0].fixed);
  struct stat after {};
  REQUIRE(::stat(file.c_str(), &after) == 0);
  CHECK((after.st_mode & 07777) == 0640);
  CHECK(after.st_ino != before.st_ino);  // a new file renamed over the old one
  CHECK(entries(dir.path()) == 1);
}

TEST_CASE("fix: through a symbolic link the target is fixed and the link kept", "[fix]") {
  test::TempDir dir;
  fs::create_directory(dir.path() / "real");
  const fs::path target = copy_fixture(dir.path() / "real");
  const fs::path link = dir.path() / "link.urdf";
  fs::create_symlink(target, link);
  auto r = test::run_cli({"--fix", "--unsafe-fixes", "link.urdf"}, dir.path());
  CHECK(r.exit_code == 0);
  CHECK(fs::is_symlink(link));
  CHECK(test::read_file(target) ==
        test::read_file(test::source_dir() / (kFixture.string() + ".fixed")));
}

TEST_CASE("fix: a read-only file is left intact with exit 2", "[fix]") {
  test::TempDir dir;
  const fs::path file = copy_fixture(dir.path());
  const std::string original = test::read_file(file);
  ReadOnly read_only(file);
  if (!read_only.active()) {
    WARN("cannot make a file read-only here (root without chattr +i); skipped");
    return;
  }
  auto r = test::run_cli({"--fix", "--unsafe-fixes", "robot.urdf"}, dir.path());
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("asset-lint: error: cannot write fixes to 'robot.urdf': the file is read-only (") !=
        std::string::npos);
  CHECK(r.err.find("the file is unchanged") != std::string::npos);
  CHECK(r.err.find("fixed 1 problem") == std::string::npos);
  // What remains is what is still on disk.
  CHECK(r.out.find("[units-angle-degrees]") != std::string::npos);
  CHECK(test::read_file(file) == original);
  CHECK(entries(dir.path()) == 1);
}

TEST_CASE("fix: a file in a read-only directory is left intact with exit 2", "[fix]") {
  test::TempDir dir;
  fs::create_directory(dir.path() / "assets");
  const fs::path file = copy_fixture(dir.path() / "assets");
  const std::string original = test::read_file(file);
  {
    ReadOnly read_only(dir.path() / "assets");
    if (!read_only.active()) {
      WARN("cannot make a directory read-only here (root without chattr +i); skipped");
      return;
    }
    auto r = test::run_cli({"--fix", "--unsafe-fixes", "assets"}, dir.path());
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("asset-lint: error: cannot write fixes to 'assets/robot.urdf': cannot create a temporary file "
                     "in 'assets' (") != std::string::npos);
    CHECK(test::read_file(file) == original);
    CHECK(entries(dir.path() / "assets") == 1);
  }
}

TEST_CASE("fix: permission bits are respected (as an unprivileged user)", "[fix]") {
  if (::geteuid() != 0 || shell("command -v setpriv") != 0) {
    WARN("needs root and setpriv to switch to the nobody user; skipped");
    return;
  }
  test::TempDir dir;
  const fs::path work = dir.path() / "work";
  fs::create_directory(work);
  const fs::path file = copy_fixture(work);
  const std::string original = test::read_file(file);
  fs::permissions(dir.path(), fs::perms::others_exec, fs::perm_options::add);
  REQUIRE(shell("chown -R nobody " + shell_quote(work.string())) == 0);
  fs::permissions(file, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  const fs::path out = dir.path() / "out", err = dir.path() / "err";
  const std::string command = "cd " + shell_quote(work.string()) +
                              " && setpriv --reuid=nobody --regid=nogroup --clear-groups " +
                              shell_quote(assetlint::test::asset_lint_binary().string()) + " --fix --unsafe-fixes robot.urdf >" +
                              shell_quote(out.string()) + " 2>" + shell_quote(err.string());
  const int status = std::system(command.c_str());
  const std::string err_text = test::read_file(err);
  if (err_text.find("Permission denied") != std::string::npos && err_text.find("cannot write fixes") == std::string::npos) {
    WARN("the nobody user cannot run the binary here (" << err_text << "); skipped");
    return;
  }
  CHECK(WEXITSTATUS(status) == 2);
  CHECK(err_text.find("cannot write fixes to 'robot.urdf': the file is read-only (Permission denied)") !=
        std::string::npos);
  CHECK(test::read_file(file) == original);
  CHECK(entries(work) == 1);
}

TEST_CASE("fix: a file replaced during the run is left as it is", "[fix]") {
  test::TempDir dir;
  const fs::path file = copy_fixture(dir.path());
  FixOptions options;
  options.unsafe = true;
  const FixResult r = fix_file(file.string(), Settings{}, options);
  REQUIRE(r.files.size() == 1);

  SECTION("edited in place after the lint") {
    test::write_file(file, "<robot name=\"edited meanwhile\"/>\n");
    const auto message = write_fixed_file(r.files[0]);
    REQUIRE(message);
    CHECK(*message == "cannot write fixes to '" + file.string() +
                          "': it changed on disk while it was being checked; the file is unchanged");
    CHECK(test::read_file(file) == "<robot name=\"edited meanwhile\"/>\n");
  }
  SECTION("replaced by rename while the temporary file was written") {
    WriteOptions hooks;
    hooks.before_rename = [&](const std::string&) {
      test::write_file(dir.path() / "new", "replaced\n");
      fs::rename(dir.path() / "new", file);
    };
    const auto message = write_fixed_file(r.files[0], hooks);
    REQUIRE(message);
    CHECK(message->find("it changed on disk while it was being checked") != std::string::npos);
    CHECK(test::read_file(file) == "replaced\n");
  }
  SECTION("deleted") {
    fs::remove(file);
    const auto message = write_fixed_file(r.files[0]);
    REQUIRE(message);
    CHECK(message->find("it can no longer be read") != std::string::npos);
    CHECK_FALSE(fs::exists(file));
  }
  CHECK(entries(dir.path()) <= 1);  // no temporary file left
}

TEST_CASE("fix: a full disk leaves the file intact with exit 2", "[fix]") {
  if (::geteuid() != 0 || shell("unshare -m true") != 0) {
    WARN("needs root and unshare -m to mount a small tmpfs; skipped");
    return;
  }
  test::TempDir dir;
  const fs::path mount = dir.path() / "small";
  fs::create_directory(mount);
  const fs::path out = dir.path() / "out", err = dir.path() / "err", rc = dir.path() / "rc";
  const fs::path fixture = test::source_dir() / kFixture;
  // In a private mount namespace: a 16 KiB tmpfs with the asset, filled up, then --fix.
  const std::string script =
      "set -e; mount -t tmpfs -o size=16k tmpfs " + shell_quote(mount.string()) + "; cp " +
      shell_quote(fixture.string()) + " " + shell_quote((mount / "robot.urdf").string()) +
      "; dd if=/dev/zero of=" + shell_quote((mount / "fill").string()) +
      " bs=1024 count=64 2>/dev/null || true; cd " + shell_quote(mount.string()) + "; set +e; " +
      shell_quote(assetlint::test::asset_lint_binary().string()) + " --fix --unsafe-fixes robot.urdf >" + shell_quote(out.string()) + " 2>" +
      shell_quote(err.string()) + "; echo $? >" + shell_quote(rc.string()) + "; cmp -s robot.urdf " +
      shell_quote(fixture.string()) + " && echo intact >>" + shell_quote(rc.string()) + "; ls -A | wc -l >>" +
      shell_quote(rc.string());
  if (std::system(("unshare -m sh -c " + shell_quote(script)).c_str()) != 0 || !fs::exists(rc)) {
    WARN("cannot mount a tmpfs here; skipped");
    return;
  }
  CHECK(test::read_file(rc) == "2\nintact\n2\n");  // exit 2, original intact, only robot.urdf and fill
  const std::string err_text = test::read_file(err);
  CHECK(err_text.find("asset-lint: error: cannot write fixes to 'robot.urdf': writing the temporary file") !=
        std::string::npos);
  CHECK(err_text.find("No space left on device") != std::string::npos);
}
