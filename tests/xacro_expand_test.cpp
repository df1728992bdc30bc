// The xacro expander, construct by construct, on small files of our own.
#include <catch2/catch.hpp>

#include "engine/file_system.h"
#include "formats/xacro/expander.h"
#include "formats/xacro/xacro_reader.h"
#include "test_support.h"

using namespace assetlint;

namespace {

struct Expanded {
  std::string text;
  std::string error;
  Span error_span;
  std::vector<Note> notes;
};

Expanded expand_file(const std::filesystem::path& path, std::map<std::string, std::string> args = {}) {
  xacro::XacroOptions options;
  for (auto& [k, v] : args) options.arguments[k] = xacro::ArgumentValue{v, "--xacro-arg", {}};
  options.root = path.parent_path().string();
  auto file = std::make_shared<const SourceFile>(path.string(), test::read_file(path));
  const xacro::ExpandedText out = xacro::expand_to_text(file, disk(), options);
  Expanded e;
  if (out.text) e.text = *out.text;
  if (out.error) {
    e.error = out.error->message;
    e.error_span = out.error->span;
    e.notes = out.error->notes;
  }
  return e;
}

Expanded expand(const std::string& body, std::map<std::string, std::string> args = {}) {
  test::TempDir dir;
  test::write_file(dir.path() / "robot.urdf.xacro",
                   "<?xml version=\"1.0\"?>\n<robot name=\"r\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n" + body +
                       "\n</robot>\n");
  return expand_file(dir.path() / "robot.urdf.xacro", std::move(args));
}

bool has(const Expanded& e, const std::string& text) {
  if (e.text.find(text) != std::string::npos) return true;
  UNSCOPED_INFO("expanded:\n" << e.text << "\nerror: " << e.error);
  return false;
}

}  // namespace

TEST_CASE("xacro properties: values, lazy evaluation, scopes, blocks", "[xacro]") {
  auto e = expand(R"xml(<xacro:property name="w" value="0.5"/>
<xacro:property name="h" value="${w*2}"/>
<xacro:property name="late" value="${later + 1}"/>
<xacro:property name="later" value="2"/>
<xacro:property name="name" value="base"/>
<xacro:property name="q" value="'quoted'"/>
<link name="${name}_link"><box size="${w} ${h} ${late}"/><q v="${q}"/></link>)xml");
  CHECK(e.error.empty());
  CHECK(has(e, "<link name=\"base_link\">"));
  CHECK(has(e, "<box size=\"0.5 1.0 3\"/>"));
  CHECK(has(e, "<q v=\"quoted\"/>"));

  auto scoped = expand(R"xml(<xacro:macro name="m">
  <xacro:property name="inner" value="7" scope="parent"/>
  <xacro:property name="g" value="8" scope="global"/>
</xacro:macro>
<xacro:m/>
<a v="${inner} ${g}"/>)xml");
  CHECK(has(scoped, "<a v=\"7 8\"/>"));

  auto block = expand(R"xml(<xacro:property name="geom"><box size="1 2 3"/></xacro:property>
<link name="l"><xacro:insert_block name="geom"/></link>)xml");
  CHECK(has(block, "<box size=\"1 2 3\"/>"));

  auto cycle = expand(R"xml(<xacro:property name="a" value="${b}"/><xacro:property name="b" value="${a}"/><x v="${a}"/>)xml");
  CHECK(cycle.error.find("circular variable definition: a -> b -> a") != std::string::npos);
  CHECK(cycle.error.find("lazy_eval=\"false\"") != std::string::npos);

  auto removed = expand(R"xml(<xacro:property name="p" value="1"/><xacro:property name="p" remove="true"/><x v="${p}"/>)xml");
  CHECK(removed.error.find("NameError: name 'p' is not defined") != std::string::npos);

  auto defaults = expand(R"xml(<xacro:property name="p" value="1"/><xacro:property name="p" default="2"/><xacro:property name="o" default="3"/><x v="${p}${o}"/>)xml");
  CHECK(has(defaults, "<x v=\"13\"/>"));
}

TEST_CASE("xacro macros: parameters, defaults, forwarding, blocks", "[xacro]") {
  auto e = expand(R"xml(<xacro:property name="side" value="left"/>
<xacro:macro name="wheel" params="prefix radius:=0.1 side:=^ mass:=^|2.5 *origin **inside">
  <link name="${prefix}_${side}_wheel" r="${radius}" m="${mass}">
    <xacro:insert_block name="origin"/>
    <xacro:insert_block name="inside"/>
  </link>
</xacro:macro>
<xacro:wheel prefix="front">
  <origin xyz="1 2 3"/>
  <inside><collision/><visual/></inside>
</xacro:wheel>)xml");
  CHECK(e.error.empty());
  CHECK(has(e, "<link name=\"front_left_wheel\" r=\"0.1\" m=\"2.5\">"));
  CHECK(has(e, "<origin xyz=\"1 2 3\"/>"));
  CHECK(has(e, "<collision/>"));
  CHECK(e.text.find("<inside>") == std::string::npos);

  auto missing = expand(R"xml(<xacro:macro name="m" params="a b"><x/></xacro:macro><xacro:m a="1"/>)xml");
  CHECK(missing.error == "Undefined parameters [b] of macro 'm'");
  auto invalid = expand(R"xml(<xacro:macro name="m" params="a"><x/></xacro:macro><xacro:m a="1" c="2"/>)xml");
  CHECK(invalid.error == "Invalid parameter \"c\" of macro 'm'");
  auto unknown = expand(R"xml(<xacro:nothing/>)xml");
  CHECK(unknown.error == "unknown macro name: xacro:nothing");
  auto nested = expand(R"xml(<xacro:macro name="outer" params="n"><xacro:inner n="${n*2}"/></xacro:macro>
<xacro:macro name="inner" params="n"><x v="${n}"/></xacro:macro><xacro:outer n="3"/>)xml");
  CHECK(has(nested, "<x v=\"6\"/>"));
  auto call = expand(R"xml(<xacro:macro name="m" params="v"><x v="${v}"/></xacro:macro><xacro:property name="which" value="m"/><xacro:call macro="${which}" v="9"/>)xml");
  CHECK(has(call, "<x v=\"9\"/>"));
}

TEST_CASE("xacro conditionals accept true/false/1/0 and expressions only", "[xacro]") {
  auto e = expand(R"xml(<xacro:if value="true"><a/></xacro:if><xacro:if value="0"><b/></xacro:if>
<xacro:unless value="${1 > 2}"><c/></xacro:unless><xacro:if value="${[1]}"><d/></xacro:if>)xml");
  CHECK(has(e, "<a/>"));
  CHECK(e.text.find("<b/>") == std::string::npos);
  CHECK(has(e, "<c/>"));
  CHECK(has(e, "<d/>"));
  auto bad = expand(R"xml(<xacro:if value="yes"><a/></xacro:if>)xml");
  CHECK(bad.error == "Xacro conditional \"yes\" evaluated to \"yes\", which is not a boolean expression.");
  CHECK(bad.error_span.line == 3);
}

TEST_CASE("xacro element, attribute, escapes and comments", "[xacro]") {
  auto e = expand(R"xml(<xacro:property name="tag" value="joint"/>
<xacro:element xacro:name="${tag}" name="j"><xacro:attribute name="type" value="fixed"/></xacro:element>
<text v="$${literal} $$(not_an_arg) cost $5"/>)xml");
  CHECK(has(e, "<joint name=\"j\" type=\"fixed\"/>"));
  CHECK(has(e, "v=\"${literal} $(not_an_arg) cost $5\""));
}

TEST_CASE("xacro substitution arguments: arg, eval, env, optenv, find, dirname", "[xacro]") {
  auto e = expand(R"xml(<xacro:arg name="n" default="3"/><xacro:arg name="prefix" default="p_"/>
<x a="$(arg prefix)$(arg n)" b="${2*$(arg n)}" c="$(eval 2 * n + 1)" d="$(optenv ASSET_LINT_NOT_SET fall back)"/>)xml",
                  {{"n", "4"}});
  CHECK(e.error.empty());
  CHECK(has(e, "a=\"p_4\""));
  CHECK(has(e, "b=\"8\""));
  CHECK(has(e, "c=\"9\""));
  CHECK(has(e, "d=\"fall back\""));
  auto undefined = expand(R"xml(<x a="$(arg nope)"/>)xml");
  CHECK(undefined.error.find("Undefined substitution argument nope") == 0);
  auto unknown = expand(R"xml(<x a="$(pwd)"/>)xml");
  CHECK(unknown.error.find("Unknown substitution command [pwd]") == 0);

  test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "ws" / "my_pkg" / "urdf");
  std::filesystem::create_directories(dir.path() / "ws" / "robot");
  test::write_file(dir.path() / "ws" / "my_pkg" / "package.xml", "<package><name>my_pkg</name></package>");
  test::write_file(dir.path() / "ws" / "robot" / "package.xml", "<package><name>robot</name></package>");
  test::write_file(dir.path() / "ws" / "my_pkg" / "urdf" / "part.xacro",
                   R"xml(<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:macro name="part" params="n"><link name="${n}" d="$(dirname)"/></xacro:macro></robot>)xml");
  test::write_file(dir.path() / "ws" / "robot" / "top.urdf.xacro",
                   R"xml(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
<xacro:include filename="$(find my_pkg)/urdf/part.xacro"/>
<xacro:include filename="$(find my_pkg)/urdf/part.xacro" ns="lib"/>
<xacro:part n="a"/><xacro:lib.part n="b"/></robot>)xml");
  auto found = expand_file(dir.path() / "ws" / "robot" / "top.urdf.xacro");
  CHECK(found.error.empty());
  CHECK(has(found, "<link name=\"a\""));
  CHECK(has(found, "<link name=\"b\""));
  CHECK(has(found, (dir.path() / "ws" / "robot").string()));  // $(dirname) is the processed file's
}

TEST_CASE("xacro $(anon name): one reproducible name per name", "[xacro]") {
  auto e = expand(R"xml(<xacro:arg name="ns" default="$(anon cam)"/><node a="$(anon cam)" b="$(arg ns)/x" c="$(anon imu)"/>)xml");
  CHECK(e.error.empty());
  CHECK(has(e, R"(a="cam_anon" b="cam_anon/x" c="imu_anon")"));
  CHECK(expand(R"xml(<x a="$(anon)"/>)xml").error == "$(anon var) must specify a name [anon]");
  CHECK(expand(R"xml(<x a="$(anon a b)"/>)xml").error == "$(anon var) may only specify one name [anon a b]");
}

TEST_CASE("xacro drops the comments right before a construct, up to a blank line or the last construct", "[xacro]") {
  auto e = expand(R"xml(<!-- kept: a blank line follows -->

<!-- dropped: documents the property -->
<!-- dropped too -->
<xacro:property name="p" value="1"/>
<xacro:if value="true"><!-- kept: ends the conditional's content --></xacro:if>
<!-- dropped: documents the macro -->
<xacro:macro name="m"><!-- kept: from the macro --></xacro:macro>
<xacro:m/>)xml");
  CHECK(e.error.empty());
  CHECK(has(e, "kept: a blank line follows"));
  CHECK(has(e, "kept: ends the conditional's content"));
  CHECK(has(e, "kept: from the macro"));
  CHECK(e.text.find("dropped") == std::string::npos);
}

TEST_CASE("xacro list comprehensions over YAML lists and properties", "[xacro]") {
  test::TempDir dir;
  test::write_file(dir.path() / "fingers.yaml", "- name: left\n  offset: {y: 0.02}\n- name: right\n  offset: {y: -0.02}\n");
  test::write_file(dir.path() / "r.xacro", R"xml(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
<xacro:property name="fingers" value="${xacro.load_yaml('fingers.yaml')}"/>
<xacro:property name="names" value="${[f.name + '_finger' for f in fingers if f.offset.y > 0]}"/>
<x ys="${[10 * f.offset.y for f in fingers]}" names="${names}" n="${len([c for c in 'abc' if c != 'b'])}"/></robot>)xml");
  auto e = expand_file(dir.path() / "r.xacro");
  CHECK(e.error.empty());
  CHECK(has(e, R"(ys="[0.2, -0.2]")"));
  CHECK(has(e, R"(names="['left_finger']")"));
  CHECK(has(e, R"(n="2")"));
}

TEST_CASE("xacro includes: relative paths, cycles named with their chain", "[xacro]") {
  test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "sub");
  test::write_file(dir.path() / "top.xacro", R"xml(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:include filename="sub/a.xacro"/><xacro:a/></robot>)xml");
  test::write_file(dir.path() / "sub" / "a.xacro", R"xml(<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:macro name="a"><link name="from_a"/></xacro:macro></robot>)xml");
  auto ok = expand_file(dir.path() / "top.xacro");
  CHECK(has(ok, "<link name=\"from_a\"/>"));

  test::write_file(dir.path() / "sub" / "a.xacro", R"xml(<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:include filename="b.xacro"/></robot>)xml");
  test::write_file(dir.path() / "sub" / "b.xacro", R"xml(<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:include filename="a.xacro"/></robot>)xml");
  auto cycle = expand_file(dir.path() / "top.xacro");
  CHECK(cycle.error == "include cycle: top.xacro → a.xacro → b.xacro → a.xacro");
  CHECK(cycle.notes.size() == 2);
}

TEST_CASE("xacro.load_yaml reads YAML as PyYAML does, with xacro's unit tags", "[xacro]") {
  test::TempDir dir;
  test::write_file(dir.path() / "params.yaml", "joint:\n  lower: !degrees -90\n  upper: !degrees 90\n  mass: 1.5\n"
                                                "  enabled: yes\n  name: shoulder\n  list: [1, 2, 3]\n  exp: 1e-3\n");
  test::write_file(dir.path() / "r.xacro", R"xml(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
<xacro:property name="p" value="${xacro.load_yaml('params.yaml')}"/>
<x lower="${p.joint.lower}" upper="${p['joint']['upper']}" m="${p.joint.mass * 2}" on="${p.joint.enabled}" n="${p.joint.name}" l="${p.joint.list[1]}" e="${p.joint.exp}"/></robot>)xml");
  auto e = expand_file(dir.path() / "r.xacro");
  CHECK(e.error.empty());
  CHECK(has(e, "lower=\"-1.5707963267948966\""));
  CHECK(has(e, "upper=\"1.5707963267948966\""));
  CHECK(has(e, "m=\"3.0\""));
  CHECK(has(e, "on=\"True\""));
  CHECK(has(e, "n=\"shoulder\""));
  CHECK(has(e, "l=\"2\""));
  CHECK(has(e, "e=\"1e-3\""));  // YAML 1.1 reads 1e-3 (no point) as a string
}

TEST_CASE("xacro errors point at the source line with the macro chain", "[xacro]") {
  auto e = expand(R"xml(<xacro:macro name="inner" params="v"><x v="${v / 0}"/></xacro:macro>
<xacro:macro name="outer"><xacro:inner v="1"/></xacro:macro>
<xacro:outer/>)xml");
  CHECK(e.error == "ZeroDivisionError: division by zero when evaluating expression 'v / 0'");
  CHECK(e.error_span.line == 3);
  REQUIRE(e.notes.size() == 2);
  CHECK(e.notes[0].message == "in macro 'inner' called at robot.urdf.xacro:4:27");
  CHECK(e.notes[1].message == "in macro 'outer' called at robot.urdf.xacro:5:1");
  auto lambda = expand(R"xml(<x v="${(lambda: 1)()}"/>)xml");
  CHECK(lambda.error.find("unsupported in ${…}: lambda") == 0);
}
