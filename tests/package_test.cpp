// The Debian package: `cpack -G DEB` from the already built tree (nothing is recompiled:
// cpack installs what the suite's build made) into a temporary directory, inspected with
// dpkg-deb, and checked by lintian when it is installed (its errors fail the test).
// Without cpack, dpkg-deb or a configured build directory the test warns and skips.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "test_support.h"

using assetlint::test::on_path;
using assetlint::test::read_file;
using assetlint::test::run_shell;
using assetlint::test::shell_quote;
using assetlint::test::TempDir;

TEST_CASE("package: cpack -G DEB makes a package with the binary, man page, docs and hooks", "[package]") {
  const auto build = assetlint::test::asset_lint_binary().parent_path();
  if (!on_path("cpack") || !on_path("dpkg-deb") || !std::filesystem::exists(build / "CPackConfig.cmake")) {
    WARN("cpack, dpkg-deb (dpkg) or the build's CPackConfig.cmake missing; skipping the package test");
    return;
  }
  TempDir dir;
  std::string out;
  REQUIRE(run_shell("timeout 300 cpack -G DEB --config " + shell_quote((build / "CPackConfig.cmake").string()) +
                        " -B " + shell_quote(dir.path().string()),
                    dir.path() / "cpack.log", out) == 0);
  INFO(out);
  const auto deb = dir.path() / (std::string("asset-lint_") + ASSET_LINT_VERSION + "_amd64.deb");
  REQUIRE(std::filesystem::exists(deb));
  const std::string package = shell_quote(deb.string());

  REQUIRE(run_shell("dpkg-deb -I " + package, dir.path() / "info.log", out) == 0);
  CHECK(out.find(" Package: asset-lint\n") != std::string::npos);
  CHECK(out.find(std::string(" Version: ") + ASSET_LINT_VERSION + "\n") != std::string::npos);
  // Dependencies computed by dpkg-shlibdeps from what the binary links.
  const auto depends = out.find(" Depends: ");
  REQUIRE(depends != std::string::npos);
  const std::string depends_line = out.substr(depends, out.find('\n', depends) - depends);
  CHECK(depends_line.find("libc6 (>= ") != std::string::npos);
  CHECK(depends_line.find("libmujoco") != std::string::npos);
  CHECK(out.find("libfmt") != std::string::npos);

  REQUIRE(run_shell("dpkg-deb -c " + package, dir.path() / "contents.log", out) == 0);
  for (const char* path : {"./usr/bin/asset-lint", "./usr/share/man/man1/asset-lint.1.gz",
                           "./usr/share/asset-lint/.pre-commit-hooks.yaml", "./usr/share/doc/asset-lint/copyright",
                           "./usr/share/doc/asset-lint/changelog.gz", "./usr/share/doc/asset-lint/README.md",
                           "./usr/share/doc/asset-lint/docs/ci.md",
                           "./usr/share/doc/asset-lint/docs/rules/mimic-max-velocity.md"}) {
    INFO(path);
    CHECK(out.find(std::string(path) + "\n") != std::string::npos);
  }

  // The packaged binary runs.
  const auto root = dir.path() / "root";
  REQUIRE(run_shell("dpkg-deb -x " + package + " " + shell_quote(root.string()), dir.path() / "x.log", out) == 0);
  CHECK(run_shell(shell_quote((root / "usr" / "bin" / "asset-lint").string()) + " --version", dir.path() / "v.log",
                  out) == 0);
  CHECK(out == std::string("asset-lint ") + ASSET_LINT_VERSION + "\n");
  CHECK(read_file(root / "usr" / "share" / "asset-lint" / ".pre-commit-hooks.yaml") ==
        read_file(assetlint::test::source_dir() / ".pre-commit-hooks.yaml"));

  if (!on_path("lintian")) {
    WARN("lintian not installed (apt-get install lintian); the package is not checked by it");
    return;
  }
  // lintian exits non-zero on errors; its E: lines are the failures, warnings are shown only.
  run_shell("timeout 300 lintian --tag-display-limit 0 " + package + " 2>&1 | grep -v 'root privileges'",
            dir.path() / "lintian.log", out);
  INFO("lintian:\n" << out);
  CHECK(out.find("E: ") == std::string::npos);
}
