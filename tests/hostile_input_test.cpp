// Hostile and accidental input (issue 10): each gives a clear error or diagnostic in
// bounded time and memory, and the other files of the run are still checked.
#include <catch2/catch.hpp>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <lz4.h>

#include <cstring>
#include <filesystem>
#include <variant>

#include "engine/file_system.h"
#include "engine/work_budget.h"
#include "formats/xacro/expander.h"
#include "formats/usdc/crate_usda.h"
#include "pipeline/lint.h"
#include "test_support.h"

using namespace assetlint;
namespace fs = std::filesystem;

namespace {

const char* kValidUrdf = R"(<?xml version="1.0"?>
<robot name="ok">
  <link name="base"/>
</robot>
)";

std::string read_error(const FileSystem& files, const std::string& path) {
  std::string error;
  const auto text = files.read(path, error);
  CHECK_FALSE(text);
  return error;
}

std::string rules_of(const FileReport& report) {
  std::string out;
  for (const auto& d : report.diagnostics) out += d.rule + " ";
  return out;
}

}  // namespace

TEST_CASE("hostile: the disk reader refuses FIFOs, devices and directories without blocking", "[hostile]") {
  test::TempDir dir;
  const fs::path fifo = dir.path() / "pipe.urdf";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const DiskFileSystem files;
  CHECK(read_error(files, fifo.string()) == "is a FIFO, not a regular file");
  CHECK(read_error(files, "/dev/zero") == "is a character device, not a regular file");
  CHECK(read_error(files, dir.path().string()) == "is a directory");
  CHECK(read_error(files, (dir.path() / "missing.urdf").string()) == "No such file or directory");
}

TEST_CASE("hostile: a file over the size limit is refused before it is read", "[hostile]") {
  test::TempDir dir;
  // A sparse 1 GiB file: refused from its size alone, nothing is allocated.
  const fs::path huge = dir.path() / "huge.urdf";
  {
    const int fd = ::open(huge.c_str(), O_CREAT | O_WRONLY, 0600);
    REQUIRE(fd >= 0);
    REQUIRE(::ftruncate(fd, 1ll << 30) == 0);
    ::close(fd);
  }
  const DiskFileSystem files;
  CHECK(read_error(files, huge.string()) == "is 1024 MiB, over the 512 MiB limit (--max-file-size)");
  // A configured limit applies the same way.
  test::write_file(dir.path() / "small.urdf", std::string(3 << 20, '<'));
  const DiskFileSystem strict(ReadLimits{1 << 20});
  CHECK(read_error(strict, (dir.path() / "small.urdf").string()) == "is 3 MiB, over the 1 MiB limit (--max-file-size)");
  std::string error;
  CHECK(files.read((dir.path() / "small.urdf").string(), error)->size() == (3u << 20));
}

TEST_CASE("hostile: the other files of a run are still checked", "[hostile]") {
  test::TempDir dir;
  const fs::path fifo = dir.path() / "pipe.urdf";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  test::write_file(dir.path() / "ok.urdf", kValidUrdf);
  const auto reports = lint_files({fifo.string(), (dir.path() / "gone.urdf").string(), (dir.path() / "ok.urdf").string()},
                                  Settings{}, 1);
  REQUIRE(reports.size() == 3);
  CHECK(reports[0].error == "cannot read '" + fifo.string() + "': is a FIFO, not a regular file");
  CHECK(reports[1].error == "cannot read '" + (dir.path() / "gone.urdf").string() + "': No such file or directory");
  CHECK_FALSE(reports[2].error);
}

TEST_CASE("hostile: deep nesting, markup floods, binary garbage and invalid UTF-8 are parse errors", "[hostile]") {
  std::string deep_urdf = "<?xml version=\"1.0\"?>\n<robot name=\"r\">";
  for (int i = 0; i < 100000; ++i) deep_urdf += "<a>";
  std::string deep_usda = "#usda 1.0\n";
  for (int i = 0; i < 100000; ++i) deep_usda += "def \"a\" {\n";
  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage.push_back(static_cast<char>((i * 7919 + 13) % 256));
  const struct {
    const char* path;
    std::string text;
  } cases[] = {
      {"deep.urdf", deep_urdf},
      {"deep.usda", deep_usda},
      {"flood.urdf", std::string(8 << 20, '<')},
      {"flood.usda", "#usda 1.0\n(x = " + std::string(8 << 20, '[')},
      {"garbage.urdf", garbage},
      {"garbage.usda", "#usda 1.0\n" + garbage},
  };
  for (const auto& c : cases) {
    INFO(c.path);
    const FileReport report = lint_text(c.path, c.text, Settings{});
    CHECK_FALSE(report.error);
    CHECK(rules_of(report).find("parse-error") != std::string::npos);
  }
}

TEST_CASE("hostile: invalid UTF-8 in names is reported in every output format", "[hostile]") {
  test::TempDir dir;
  test::write_file(dir.path() / "bytes.urdf",
                   "<?xml version=\"1.0\"?>\n<robot name=\"r\">\n  <link name=\"a\xff\xfe\"/>\n"
                   "  <joint name=\"j\xc3\" type=\"revolute\"><parent link=\"a\xff\xfe\"/><child link=\"b\xe2\x82\"/>"
                   "<limit lower=\"0\" upper=\"90\" effort=\"1\" velocity=\"1\"/></joint>\n</robot>\n");
  for (const char* format : {"text", "concise", "json", "sarif", "github", "junit"}) {
    INFO(format);
    const auto r = test::run_cli({"--output-format", format, "bytes.urdf"}, dir.path());
    CHECK(r.exit_code == 1);
    CHECK(r.err.empty());
  }
}

TEST_CASE("hostile: a layer cycle and layers that are devices or FIFOs are notes, not hangs", "[hostile]") {
  test::TempDir dir;
  REQUIRE(::mkfifo((dir.path() / "pipe.usda").c_str(), 0600) == 0);
  test::write_file(dir.path() / "a.usda", "#usda 1.0\n(\n subLayers = [@b.usda@, @pipe.usda@, @/dev/zero@]\n)\n");
  test::write_file(dir.path() / "b.usda", "#usda 1.0\n(\n subLayers = [@a.usda@]\n)\n");
  const auto r = test::run_cli({"--allow-outside-root", "a.usda"}, dir.path());
  INFO(r.out << r.err);
  CHECK(r.err.empty());
  CHECK(r.out.find("sublayer cycle") != std::string::npos);
  CHECK(r.out.find("layer 'pipe.usda' cannot be read (is a FIFO, not a regular file); skipped") != std::string::npos);
  CHECK(r.out.find("layer '/dev/zero' cannot be read (is a character device, not a regular file); skipped") !=
        std::string::npos);
}

TEST_CASE("hostile: a symlink loop in a checked directory does not stop the walk", "[hostile]") {
  test::TempDir dir;
  fs::create_directories(dir.path() / "robots");
  fs::create_symlink("loop", dir.path() / "robots" / "loop");           // links to itself
  fs::create_symlink(".", dir.path() / "robots" / "again");             // a directory cycle
  fs::create_symlink("a.urdf", dir.path() / "robots" / "a_loop.urdf");  // dangling
  test::write_file(dir.path() / "robots" / "z.urdf", kValidUrdf);
  const auto r = test::run_cli({"robots"}, dir.path());
  INFO(r.out << r.err);
  // The looping link is named (exit 2); the walk goes on and checks z.urdf.
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("robots/loop") != std::string::npos);
  CHECK(r.out.find("1 file") != std::string::npos);
}

TEST_CASE("hostile: --max-file-size names the file and the others are still checked", "[hostile]") {
  test::TempDir dir;
  test::write_file(dir.path() / "big.urdf", std::string((2 << 20) + 1, '<'));
  test::write_file(dir.path() / "ok.urdf", kValidUrdf);
  const auto r = test::run_cli({"--max-file-size", "2", "big.urdf", "ok.urdf"}, dir.path());
  INFO(r.out << r.err);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("is 2.0 MiB (2097153 bytes), over the 2 MiB limit (--max-file-size)") != std::string::npos);
  CHECK(r.out.find("1 file") != std::string::npos);
}

TEST_CASE("hostile: xacro recursion, include cycles and exponential expansion end with a named error", "[hostile][xacro]") {
  test::TempDir dir;
  const auto lint = [&](const std::string& name, const std::string& body) {
    test::write_file(dir.path() / name, "<robot name=\"r\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">" + body + "</robot>");
    return lint_file((dir.path() / name).string(), Settings{});
  };
  const auto message = [](const FileReport& report) {
    REQUIRE(report.diagnostics.size() == 1);
    CHECK(report.diagnostics[0].rule == "parse-error");
    return report.diagnostics[0].message;
  };

  const FileReport recursive = lint("recursive.xacro", R"xml(<xacro:macro name="a"><xacro:b/></xacro:macro>
<xacro:macro name="b"><xacro:a/></xacro:macro><xacro:a/>)xml");
  CHECK(message(recursive).find("xacro: macro calls nested deeper than 100 (… → a → b → a → b → a → b → a)") == 0);
  CHECK(recursive.diagnostics[0].notes.size() == 100);

  test::write_file(dir.path() / "loop.xacro",
                   R"xml(<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:include filename="cycle.xacro"/></robot>)xml");
  const FileReport cycle = lint("cycle.xacro", R"xml(<xacro:include filename="loop.xacro"/>)xml");
  CHECK(message(cycle) == "xacro: include cycle: cycle.xacro → loop.xacro → cycle.xacro");

  // Each macro calls the next one twice: 2^40 links if nothing stopped it.
  std::string doubling = R"xml(<xacro:macro name="m0"><link name="l"/></xacro:macro>)xml";
  for (int i = 1; i <= 40; ++i)
    doubling += "<xacro:macro name=\"m" + std::to_string(i) + "\"><xacro:m" + std::to_string(i - 1) + "/><xacro:m" +
                std::to_string(i - 1) + "/></xacro:macro>";
  const FileReport exponential = lint("exponential.xacro", doubling + "<xacro:m40/>");
  CHECK(message(exponential).find("xacro: the expansion exceeds 64 MiB") == 0);

  // Lazy properties that double a string: bounded by what one expression may build.
  std::string strings = R"xml(<xacro:property name="p0" value="xxxxxxxxxxxxxxxx"/>)xml";
  for (int i = 1; i <= 40; ++i)
    strings += "<xacro:property name=\"p" + std::to_string(i) + "\" value=\"${p" + std::to_string(i - 1) + " + p" +
               std::to_string(i - 1) + "}\"/>";
  const FileReport doubled = lint("strings.xacro", strings + "<link name=\"${p40}\"/>");
  CHECK(message(doubled).find("MiB an expression may build") != std::string::npos);
}

namespace {

std::string crate_fixture() { return test::read_file(test::fixtures_dir() / "usdc" / "value_types.usd"); }

template <class T>
void poke(std::string& bytes, std::size_t at, T value) {
  REQUIRE(at + sizeof value <= bytes.size());
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

template <class T>
T peek(const std::string& bytes, std::size_t at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  return value;
}

// Where the table of contents puts a section.
std::size_t section_start(const std::string& bytes, std::string_view name) {
  const auto toc = static_cast<std::size_t>(peek<std::int64_t>(bytes, 16));
  const auto n = peek<std::uint64_t>(bytes, toc);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t entry = toc + 8 + i * 32;
    if (std::string_view(bytes.data() + entry) == name) return static_cast<std::size_t>(peek<std::int64_t>(bytes, entry + 16));
  }
  FAIL("no section " << name);
  return 0;
}

usdc::CrateError crate_error(const std::string& bytes) {
  auto result = usdc::crate_to_usda(bytes);
  REQUIRE(std::holds_alternative<usdc::CrateError>(result));
  return std::get<usdc::CrateError>(result);
}

}  // namespace

TEST_CASE("hostile: a xacro macro that doubles without writing anything ends at the step limit or the time budget",
          "[hostile][xacro]") {
  test::TempDir dir;
  // Each level calls the one below twice and writes nothing: the output limit never trips.
  const std::string silent = R"xml(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="m" params="n">
    <xacro:if value="${n > 0}"><xacro:m n="${n-1}"/><xacro:m n="${n-1}"/></xacro:if>
  </xacro:macro>
  <xacro:m n="40"/>
  <link name="base"/>
</robot>
)xml";
  const auto top = std::make_shared<const SourceFile>((dir.path() / "silent.xacro").string(), silent);

  xacro::ExpandOptions few_steps;
  few_steps.max_steps = 500;
  const xacro::ExpandResult stepped = xacro::expand_xacro(top, disk(), few_steps);
  REQUIRE(stepped.error);
  CHECK(stepped.error->message.find("more than 500 elements and macro calls") != std::string::npos);

  xacro::ExpandOptions short_budget;
  short_budget.deadline = Deadline::after(0.05);
  const xacro::ExpandResult timed = xacro::expand_xacro(top, disk(), short_budget);
  REQUIRE(timed.error);
  CHECK(timed.error->message == "the expansion ran out of the file's time budget of 0.05 s (--time-budget)");

  // The CLI's option reaches the expansion, and the file is reported at the call.
  test::write_file(dir.path() / "silent.xacro", silent);
  const auto run = test::run_cli({"--time-budget", "0.2", "silent.xacro"}, dir.path());
  CHECK(run.exit_code == 1);
  CHECK(run.out.find("silent.xacro:3:") != std::string::npos);
  CHECK(run.out.find("time budget of 0.2 s (--time-budget) [parse-error]") != std::string::npos);
}

TEST_CASE("hostile: a file whose rules outlast the time budget is reported as not checked", "[hostile]") {
  test::TempDir dir;
  test::write_file(dir.path() / "robot.urdf", kValidUrdf);
  // A microsecond is gone before the first rule runs: the file is named, nothing of it is reported.
  const auto stopped = test::run_cli({"--time-budget", "0.000001", "robot.urdf", "--output-format", "json"}, dir.path());
  CHECK(stopped.exit_code == 2);
  CHECK(stopped.err.find("'robot.urdf': checking stopped: the file's time budget of 1e-06 s (--time-budget) ran out "
                         "before rule '") != std::string::npos);
  CHECK(stopped.out.find("\"not_read\": 1") != std::string::npos);
  // The default budget checks it.
  CHECK(test::run_cli({"robot.urdf"}, dir.path()).exit_code == 0);
  // 0 means no budget.
  CHECK(test::run_cli({"--time-budget", "0", "robot.urdf"}, dir.path()).exit_code == 0);
}

TEST_CASE("hostile: a file that is not the format it claims is described, not quoted", "[hostile]") {
  test::TempDir dir;
  const std::string secret = "root:x:0:0:root:/root:/bin/bash\ntoken=3f9a77c1\n";
  std::string binary = "\x7f" "ELF\x02\x01\x01";
  binary += std::string("\0\0\0", 3) + secret;
  test::write_file(dir.path() / "passwd.urdf", secret);
  test::write_file(dir.path() / "program.urdf", binary);
  test::write_file(dir.path() / "program.usda", binary);
  test::write_file(dir.path() / "macro.xacro", secret);
  for (const std::string format : {"text", "json", "sarif", "github", "gitlab", "junit"}) {
    INFO(format);
    const auto run = test::run_cli({"passwd.urdf", "program.urdf", "program.usda", "macro.xacro", "--output-format", format},
                                   dir.path());
    CHECK(run.exit_code == 1);
    CHECK(run.out.find("root:x") == std::string::npos);
    CHECK(run.out.find("3f9a77c1") == std::string::npos);
    CHECK(run.out.find("not XML: the file holds text and no element") != std::string::npos);
    CHECK(run.out.find("binary data, not XML: byte 0 is U+007F") != std::string::npos);
    CHECK(run.out.find("binary data, not a USD layer: byte 0 is U+007F") != std::string::npos);
  }
  // With source excerpts, a line of binary data is not shown either.
  const auto full = test::run_cli({"program.urdf", "program.usda", "--output-format", "full"}, dir.path());
  CHECK(full.out.find("ELF") == std::string::npos);
  CHECK(full.out.find("root:x") == std::string::npos);
}

TEST_CASE("hostile: a broken crate layer is an error naming its section, never a crash", "[hostile][usdc]") {
  const std::string good = crate_fixture();
  REQUIRE(std::holds_alternative<usdc::CrateText>(usdc::crate_to_usda(good)));

  SECTION("truncated: the table of contents is cut off") {
    const auto e = crate_error(good.substr(0, good.size() - 40));
    CHECK(e.section == "table of contents");
    const auto tiny = crate_error(good.substr(0, 20));
    CHECK(tiny.section == "bootstrap");
    CHECK_THAT(tiny.message, Catch::Contains("fewer than the 88-byte crate header"));
  }
  SECTION("the table of contents past the end of the file") {
    std::string bytes = good;
    poke<std::int64_t>(bytes, 16, static_cast<std::int64_t>(good.size()) + 1000);
    const auto e = crate_error(bytes);
    CHECK(e.section == "bootstrap");
    CHECK_THAT(e.message, Catch::Contains("outside the file"));
  }
  SECTION("a section that claims bytes past the end") {
    std::string bytes = good;
    const auto toc = static_cast<std::size_t>(peek<std::int64_t>(bytes, 16));
    poke<std::int64_t>(bytes, toc + 8 + 24, std::int64_t{1} << 40);  // the first section's size
    CHECK_THAT(crate_error(bytes).message, Catch::Contains("lies outside the file"));
  }
  SECTION("huge counts are refused before anything is allocated") {
    for (const char* section : {"TOKENS", "STRINGS", "FIELDS", "FIELDSETS", "PATHS", "SPECS"}) {
      INFO(section);
      std::string bytes = good;
      poke<std::uint64_t>(bytes, section_start(bytes, section), std::uint64_t{1} << 62);
      CHECK(crate_error(bytes).section == section);
    }
  }
  SECTION("an LZ4 bomb: a claimed size beyond what the compressed bytes can give, or output past the buffer") {
    std::string bytes = good;
    poke<std::uint64_t>(bytes, section_start(bytes, "TOKENS") + 8, std::uint64_t{1} << 50);
    CHECK_THAT(crate_error(bytes).message, Catch::Contains("bytes of tokens claimed"));

    // 16 MB of zeros compress to a few kB; decompressing into a 1 kB buffer stops at its end.
    const std::string zeros(16 << 20, '\0');
    std::string packed(static_cast<std::size_t>(LZ4_compressBound(static_cast<int>(zeros.size()))) + 1, '\0');
    const int n = LZ4_compress_default(zeros.data(), packed.data() + 1, static_cast<int>(zeros.size()),
                                       static_cast<int>(packed.size() - 1));
    REQUIRE(n > 0);
    packed.resize(static_cast<std::size_t>(n) + 1);
    std::string out(1024, 'x');
    const usdc::Cursor where(packed, "test");
    CHECK_THROWS_AS(usdc::decompress(packed, out.data(), out.size(), where), usdc::CrateError);
  }
  SECTION("versions outside 0.4.0 to 0.11 are refused by name") {
    std::string bytes = good;
    bytes[9] = 3;  // 0.3.0
    CHECK_THAT(crate_error(bytes).message, Catch::Contains("crate version 0.3.0 is not supported"));
    bytes[8] = 1;  // 1.3.0
    CHECK_THAT(crate_error(bytes).message, Catch::Contains("crate version 1.3.0 is not supported"));
    const auto report = lint_text("robot.usd", bytes, Settings{});
    REQUIRE(report.error);
    CHECK_THAT(*report.error, Catch::Contains("cannot read the binary USD layer 'robot.usd': bootstrap: crate version 1.3.0"));
  }
  SECTION("every byte flipped in turn: text or an error, never a crash") {
    std::size_t errors = 0;
    for (std::size_t i = 0; i < good.size(); ++i) {
      std::string bytes = good;
      bytes[i] = static_cast<char>(~bytes[i]);
      const auto result = usdc::crate_to_usda(bytes);
      if (std::holds_alternative<usdc::CrateError>(result)) ++errors;
    }
    CHECK(errors > good.size() / 10);
  }
}
