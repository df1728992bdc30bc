#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "usda_test_util.h"

using namespace assetlint;
using namespace assetlint::usda;
using usda_test::parse;
using usda_test::Parsed;

namespace {

// Fails the test with the parser's message when the text does not parse.
Parsed must_parse(std::string text, const ParseOptions& options = {}) {
  Parsed p = parse(std::move(text), options);
  if (!p.ok()) FAIL(p.error().span.line << ":" << p.error().span.column << ": " << p.error().message);
  return p;
}

const Prim& only_root(const Parsed& p) {
  REQUIRE(p.layer().prims.size() == 1);
  return p.layer().prims[0];
}

}  // namespace

TEST_CASE("usda parser: minimal layer", "[usda][parser]") {
  const Parsed p = must_parse("#usda 1.0\n");
  CHECK(p.layer().version == "1.0");
  CHECK(p.layer().file == 7);
  CHECK(p.layer().prims.empty());
  CHECK(p.layer().metadata.empty());
  CHECK(p.text(p.layer().header_span) == "#usda 1.0");
}

TEST_CASE("usda parser: layer metadata", "[usda][parser]") {
  const Parsed p = must_parse(R"(#usda 1.0
(
    "The layer's doc string"
    customLayerData = {
        dictionary cameraSettings = {
            dictionary Front = {
                double3 position = (5, 0, 0)
                double radius = 5
            }
            string boundCamera = "/OmniverseKit_Persp"
        }
        string[] tags = ["a", "b"]
        bool "zUp" = false
    }
    defaultPrim = "Robot"
    metersPerUnit = 0.01
    kilogramsPerUnit = 1
    upAxis = "Z"
    subLayers = [
        @./physics.usda@ (offset = 10; scale = 2),
        @./base.usda@
    ]
    timeCodesPerSecond = 60
)

def Xform "Robot"
{
}
)");
  const Layer& layer = p.layer();
  REQUIRE(layer.metadata.size() == 8);
  CHECK(layer.metadata[0].key == "doc");
  CHECK(layer.metadata[0].is_doc_shorthand);
  CHECK(layer.metadata[0].value.text == "The layer's doc string");
  CHECK(layer.default_prim() == std::optional<std::string_view>("Robot"));
  CHECK(layer.meters_per_unit() == std::optional<double>(0.01));
  CHECK(layer.kilograms_per_unit() == std::optional<double>(1.0));
  CHECK(layer.up_axis() == std::optional<std::string_view>("Z"));
  CHECK(layer.find_metadata("timeCodesPerSecond")->value.is_integer);
  CHECK(layer.find_metadata("metersPerUnit")->value.is_integer == false);
  CHECK(p.text(layer.find_metadata("metersPerUnit")->value.span) == "0.01");
  CHECK(p.text(layer.find_metadata("metersPerUnit")->key_span) == "metersPerUnit");
  CHECK(p.text(layer.find_metadata("upAxis")->span) == "upAxis = \"Z\"");

  const auto subs = layer.sublayers();
  REQUIRE(subs.size() == 2);
  CHECK(subs[0] == "./physics.usda");
  CHECK(subs[1] == "./base.usda");
  const auto arcs = composition_arcs(layer.find_metadata("subLayers")->value);
  REQUIRE(arcs.size() == 2);
  CHECK(arcs[0].offset == std::optional<double>(10));
  CHECK(arcs[0].scale == std::optional<double>(2));
  CHECK_FALSE(arcs[1].offset);
  CHECK(p.text(arcs[0].span) == "@./physics.usda@ (offset = 10; scale = 2)");

  const Value& cld = layer.find_metadata("customLayerData")->value;
  REQUIRE(cld.kind == ValueKind::Dictionary);
  REQUIRE(cld.entries.size() == 3);
  const DictEntry* cam = cld.find_entry("cameraSettings");
  REQUIRE(cam != nullptr);
  CHECK(cam->type_name == "dictionary");
  const DictEntry* front = cam->value.find_entry("Front");
  REQUIRE(front != nullptr);
  const DictEntry* pos = front->value.find_entry("position");
  REQUIRE(pos != nullptr);
  CHECK(pos->type_name == "double3");
  CHECK(pos->value.as_numbers() == std::optional<std::vector<double>>({5, 0, 0}));
  CHECK(p.text(pos->value.span) == "(5, 0, 0)");
  CHECK(p.text(pos->span) == "double3 position = (5, 0, 0)");
  CHECK(cam->value.find_entry("boundCamera")->value.text == "/OmniverseKit_Persp");
  const DictEntry* tags = cld.find_entry("tags");
  REQUIRE(tags != nullptr);
  CHECK(tags->type_is_array);
  CHECK(tags->value.as_string_list() == std::optional<std::vector<std::string_view>>({"a", "b"}));
  const DictEntry* zup = cld.find_entry("zUp");
  REQUIRE(zup != nullptr);
  CHECK(zup->value.as_bool() == std::optional<bool>(false));
}

TEST_CASE("usda parser: prims, specifiers and spans", "[usda][parser]") {
  const std::string text = "#usda 1.0\n"
                           "def Xform \"World\"\n"
                           "{\n"
                           "    over \"arm\" {\n"
                           "    }\n"
                           "    class \"_class_link\"\n"
                           "    {\n"
                           "    }\n"
                           "    def \"typeless\" { }\n"
                           "}\n";
  const Parsed p = must_parse(text);
  const Prim& world = only_root(p);
  CHECK(world.specifier == Specifier::Def);
  CHECK(world.type_name == "Xform");
  CHECK(world.name == "World");
  CHECK(p.text(world.specifier_span) == "def");
  CHECK(world.specifier_span.line == 2);
  CHECK(world.specifier_span.column == 1);
  CHECK(p.text(world.type_span) == "Xform");
  CHECK(p.text(world.name_span) == "\"World\"");
  CHECK(world.name_span.offset == 20);
  CHECK(world.open_brace_span.line == 3);
  CHECK(world.open_brace_span.column == 1);
  CHECK(world.span.offset == 10);
  CHECK(world.span.end() == text.size() - 1);  // through the closing brace
  REQUIRE(world.children.size() == 3);
  CHECK(world.children[0].specifier == Specifier::Over);
  CHECK(world.children[0].name == "arm");
  CHECK(world.children[0].type_name.empty());
  CHECK(world.children[0].specifier_span.line == 4);
  CHECK(world.children[0].specifier_span.column == 5);
  CHECK(world.children[1].specifier == Specifier::Class);
  CHECK(world.children[1].name == "_class_link");
  CHECK(world.children[2].name == "typeless");
  CHECK(p.layer().find_prim("/World/arm") == &world.children[0]);
  CHECK(p.layer().find_prim("/World/typeless") == &world.children[2]);
  CHECK(p.layer().find_prim("/World/nope") == nullptr);
  CHECK(p.layer().find_prim("World") == nullptr);
  CHECK(world.find_child("_class_link") == &world.children[1]);

  std::vector<std::string> paths;
  for_each_prim(p.layer().prims, "", [&](const Prim&, const std::string& path) { paths.push_back(path); });
  CHECK(paths == std::vector<std::string>{"/World", "/World/arm", "/World/_class_link", "/World/typeless"});
}

TEST_CASE("usda parser: attribute value spans point at the literal", "[usda][parser]") {
  const std::string text = "#usda 1.0\n"
                           "def PhysicsRevoluteJoint \"finger_joint\" (\n"
                           "    prepend apiSchemas = [\"PhysicsDriveAPI:angular\"]\n"
                           ")\n"
                           "{\n"
                           "    float drive:angular:physics:stiffness = 3\n"
                           "    float drive:angular:physics:damping = 0.0002\n"
                           "}\n";
  const Parsed p = must_parse(text);
  const Prim& joint = only_root(p);
  const Attribute* a = joint.find_attribute("drive:angular:physics:stiffness");
  REQUIRE(a != nullptr);
  REQUIRE(a->default_value);
  const std::size_t expect = text.find("= 3") + 2;
  CHECK(a->default_value->span.offset == expect);
  CHECK(a->default_value->span.length == 1);
  CHECK(a->default_value->span.line == 6);
  CHECK(a->default_value->span.column == 45);
  CHECK(a->default_value->span.file == 7);
  CHECK(a->default_value->number == 3.0);
  CHECK(a->default_value->is_integer);
  CHECK(p.text(a->name_span) == "drive:angular:physics:stiffness");
  CHECK(a->name_span.column == 11);
  CHECK(p.text(a->type_span) == "float");
  CHECK(p.text(a->span) == "float drive:angular:physics:stiffness = 3");
  CHECK(joint.attribute_double("drive:angular:physics:damping") == std::optional<double>(0.0002));
  CHECK(p.text(joint.find_attribute("drive:angular:physics:damping")->default_value->span) == "0.0002");
}

TEST_CASE("usda parser: attribute declarations", "[usda][parser]") {
  const Parsed p = must_parse(R"(#usda 1.0
def Xform "x"
{
    custom uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:orient"]
    config double cfg = 1
    varying float v = 2
    float physics:mass
    float blocked = None
    quatf xformOp:orient = (1, 0, 0, 0)
    float3 physics:diagonalInertia = (1e-4, 2.5e-4, 0)
    float physics:lowerLimit = -inf
    float physics:upperLimit = inf
    float weird = nan
    bool flag = true
    asset file = @./mesh.usd@
    string s = "with \"escapes\"\n"
    string doc = """line one
line two"""
    matrix4d xformOp:transform = ( (1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1) )
    float anim = AnimationBlock
    token t = "TGS" (
        allowedTokens = ["TGS", "PGS"]
        doc = "Solver type"
        displayUnit = mm
        permission = public
        symmetryFunction =
        customData = {
            string note = "hi"
        }
    )
    Vec3f[] extent = [(-71.8925, 0, -47.9284), (82.294, 59.873, 47.9284)]
}
)");
  const Prim& x = only_root(p);
  const Attribute* order = x.find_attribute("xformOpOrder");
  REQUIRE(order != nullptr);
  CHECK(order->custom);
  CHECK(order->variability == Variability::Uniform);
  CHECK(order->type_name == "token");
  CHECK(order->is_array);
  CHECK(order->full_type() == "token[]");
  CHECK(order->default_value->as_string_list() ==
        std::optional<std::vector<std::string_view>>({"xformOp:translate", "xformOp:orient"}));
  CHECK(x.find_attribute("cfg")->variability == Variability::Config);
  CHECK(x.find_attribute("v")->variability == Variability::Varying);
  const Attribute* mass = x.find_attribute("physics:mass");
  REQUIRE(mass != nullptr);
  CHECK_FALSE(mass->default_value.has_value());
  CHECK(p.text(mass->span) == "float physics:mass");
  const Attribute* blocked = x.find_attribute("blocked");
  REQUIRE(blocked->default_value.has_value());
  CHECK(blocked->default_value->is_none());
  CHECK(x.find_attribute("xformOp:orient")->default_value->as_numbers() ==
        std::optional<std::vector<double>>({1, 0, 0, 0}));
  CHECK(x.find_attribute("physics:diagonalInertia")->default_value->as_numbers() ==
        std::optional<std::vector<double>>({1e-4, 2.5e-4, 0}));
  const double lo = *x.attribute_double("physics:lowerLimit");
  CHECK(std::isinf(lo));
  CHECK(lo < 0);
  CHECK(p.text(x.find_attribute("physics:lowerLimit")->default_value->span) == "-inf");
  CHECK(std::isinf(*x.attribute_double("physics:upperLimit")));
  CHECK(*x.attribute_double("physics:upperLimit") > 0);
  CHECK(std::isnan(*x.attribute_double("weird")));
  CHECK(x.find_attribute("flag")->default_value->as_bool() == std::optional<bool>(true));
  CHECK(x.find_attribute("file")->default_value->kind == ValueKind::AssetPath);
  CHECK(x.find_attribute("file")->default_value->text == "./mesh.usd");
  CHECK(x.attribute_string("s") == std::optional<std::string_view>("with \"escapes\"\n"));
  CHECK(x.attribute_string("doc") == std::optional<std::string_view>("line one\nline two"));
  const Value& m = *x.find_attribute("xformOp:transform")->default_value;
  CHECK(m.kind == ValueKind::Tuple);
  CHECK(m.count == 4);
  CHECK(m.as_numbers()->size() == 16);
  CHECK(x.find_attribute("anim")->default_value->kind == ValueKind::Identifier);
  CHECK(x.find_attribute("anim")->default_value->text == "AnimationBlock");

  const Attribute* t = x.find_attribute("t");
  REQUIRE(t != nullptr);
  REQUIRE(t->metadata.size() == 6);
  CHECK(t->find_metadata("allowedTokens")->value.as_string_list() ==
        std::optional<std::vector<std::string_view>>({"TGS", "PGS"}));
  CHECK(t->find_metadata("doc")->value.text == "Solver type");
  CHECK(t->find_metadata("displayUnit")->value.text == "mm");
  CHECK(t->find_metadata("permission")->value.text == "public");
  CHECK(t->find_metadata("symmetryFunction")->value.is_none());
  CHECK(t->find_metadata("customData")->value.find_entry("note")->value.text == "hi");
  CHECK(p.text(t->span).substr(0, 19) == "token t = \"TGS\" (\n ");
  CHECK(p.text(t->span).back() == ')');

  const Value& extent = *x.find_attribute("extent")->default_value;
  CHECK(extent.kind == ValueKind::List);
  CHECK_FALSE(extent.lazy);  // small arrays are materialized
  CHECK(extent.count == 2);
  CHECK(extent.elements[1].as_numbers() == std::optional<std::vector<double>>({82.294, 59.873, 47.9284}));
  // property order is file order
  REQUIRE(x.property_order.size() == x.attributes.size());
  CHECK(x.attributes[x.property_order[0].index].name == "xformOpOrder");
}

TEST_CASE("usda parser: timeSamples, connect and merged declarations", "[usda][parser]") {
  const Parsed p = must_parse(R"(#usda 1.0
def Shader "s"
{
    float3 xformOp:translate = (0, 0, 0)
    float3 xformOp:translate.timeSamples = {
        0: (0, 0, 0),
        12.5: (1, 2, 3),
        -1: None,
    }
    token outputs:surface.connect = </World/Looks/PreviewSurface/Shader.outputs:surface>
    float inputs:x.connect = [</a.outputs:r>, </b.outputs:g>]
    prepend float inputs:y.connect = </c.outputs:out>
    float inputs:z.connect = None
    double value.timeSamples = { 1: 5, 2: 6 }
}
)");
  const Prim& s = only_root(p);
  const Attribute* tr = s.find_attribute("xformOp:translate");
  REQUIRE(tr != nullptr);
  CHECK(s.attributes.size() == 6);  // the translate declarations were merged
  REQUIRE(tr->default_value);
  CHECK(tr->default_value->as_numbers() == std::optional<std::vector<double>>({0, 0, 0}));
  REQUIRE(tr->time_samples);
  const auto& samples = tr->time_samples->samples;
  REQUIRE(samples.size() == 3);
  CHECK(samples[0].time == 0);
  CHECK(samples[1].time == 12.5);
  CHECK(p.text(samples[1].time_span) == "12.5");
  CHECK(samples[1].value.as_numbers() == std::optional<std::vector<double>>({1, 2, 3}));
  CHECK(p.text(samples[1].value.span) == "(1, 2, 3)");
  CHECK(samples[2].time == -1);
  CHECK(samples[2].value.is_none());
  CHECK(p.text(tr->time_samples->span).front() == '{');
  CHECK(p.text(tr->time_samples->span).back() == '}');
  CHECK(p.text(tr->time_samples->declaration_span).substr(0, 38) == "float3 xformOp:translate.timeSamples =");
  CHECK(p.text(tr->span) == "float3 xformOp:translate = (0, 0, 0)");
  CHECK(p.text(tr->name_span) == "xformOp:translate");

  const Attribute* surf = s.find_attribute("outputs:surface");
  REQUIRE(surf != nullptr);
  CHECK_FALSE(surf->default_value);
  REQUIRE(surf->connections.size() == 1);
  REQUIRE(surf->connections[0].paths.size() == 1);
  CHECK(surf->connections[0].paths[0].text == "/World/Looks/PreviewSurface/Shader.outputs:surface");
  CHECK(p.text(surf->connections[0].paths[0].span) == "</World/Looks/PreviewSurface/Shader.outputs:surface>");
  CHECK(p.text(surf->name_span) == "outputs:surface");

  const Attribute* ix = s.find_attribute("inputs:x");
  REQUIRE(ix->connections.size() == 1);
  REQUIRE(ix->connections[0].paths.size() == 2);
  CHECK(ix->connections[0].paths[1].text == "/b.outputs:g");
  CHECK(s.find_attribute("inputs:y")->connections[0].op == ListOp::Prepend);
  CHECK(s.find_attribute("inputs:z")->connections[0].none);
  const Attribute* value = s.find_attribute("value");
  REQUIRE(value->time_samples);
  REQUIRE(value->time_samples->samples.size() == 2);
  CHECK(value->time_samples->samples[1].value.number == 6);
}

TEST_CASE("usda parser: relationships", "[usda][parser]") {
  const Parsed p = must_parse(R"(#usda 1.0
def PhysicsRevoluteJoint "j"
{
    rel physics:body0 = </World/base>
    rel physics:body1 = [
        </World/a>,
        </World/b>,
    ]
    rel empty = []
    rel none = None
    custom rel extra
    varying rel old = </x>
    prepend rel filtered = </p1>
    append rel filtered = [</p2>, </p3>]
    delete rel filtered = </p1>
    rel material:binding = </Looks/M> (
        bindMaterialAs = "weakerThanDescendants"
    )
    rel proxy.default = </proxy>
}
)");
  const Prim& j = only_root(p);
  const Relationship* b0 = j.find_relationship("physics:body0");
  REQUIRE(b0 != nullptr);
  REQUIRE(b0->targets.size() == 1);
  CHECK(b0->targets[0].op == ListOp::Explicit);
  REQUIRE(b0->targets[0].paths.size() == 1);
  CHECK(b0->targets[0].paths[0].as_path() == std::optional<std::string_view>("/World/base"));
  CHECK(p.text(b0->targets[0].paths[0].span) == "</World/base>");
  CHECK(b0->targets[0].paths[0].span.line == 4);
  CHECK(b0->targets[0].paths[0].span.column == 25);
  CHECK(p.text(b0->name_span) == "physics:body0");
  CHECK(p.text(b0->span) == "rel physics:body0 = </World/base>");

  const Relationship* b1 = j.find_relationship("physics:body1");
  REQUIRE(b1->targets[0].paths.size() == 2);
  CHECK(b1->targets[0].paths[1].text == "/World/b");
  CHECK(j.find_relationship("empty")->targets[0].paths.empty());
  CHECK_FALSE(j.find_relationship("empty")->targets[0].none);
  CHECK(j.find_relationship("none")->targets[0].none);
  CHECK(j.find_relationship("extra")->custom);
  CHECK(j.find_relationship("extra")->targets.empty());
  CHECK(j.find_relationship("old")->varying);

  const Relationship* f = j.find_relationship("filtered");
  REQUIRE(f->targets.size() == 3);
  CHECK(f->targets[0].op == ListOp::Prepend);
  CHECK(f->targets[1].op == ListOp::Append);
  CHECK(f->targets[2].op == ListOp::Delete);
  CHECK(p.text(f->targets[2].declaration_span) == "delete rel filtered = </p1>");
  const auto resolved = f->resolved_targets();
  REQUIRE(resolved.size() == 2);
  CHECK(resolved[0]->text == "/p2");
  CHECK(resolved[1]->text == "/p3");

  const Relationship* mb = j.find_relationship("material:binding");
  REQUIRE(mb->metadata.size() == 1);
  CHECK(mb->find_metadata("bindMaterialAs")->value.text == "weakerThanDescendants");
  REQUIRE(j.find_relationship("proxy")->default_target);
  CHECK(j.find_relationship("proxy")->default_target->text == "/proxy");
  // relationships and attributes keep their order
  REQUIRE(j.property_order.size() == 9);
  CHECK(j.property_order[0].is_relationship);
}

TEST_CASE("usda parser: prim metadata and list ops", "[usda][parser]") {
  const Parsed p = must_parse(R"(#usda 1.0
def Xform "robot" (
    "doc shorthand"
    kind = "model"
    prepend apiSchemas = ["PhysicsDriveAPI:angular", "PhysxJointAPI"]
    append apiSchemas = ["PhysxMimicJointAPI:rotZ"]
    delete apiSchemas = ["PhysicsDriveAPI:angular"]
    instanceable = true
    hide_in_stage_window = true
    customData = {
        int version = 3
    }
    prepend references = @./parts/base.usd@</Meshes/base_link> (offset = 1.5; scale = 2)
    references = [</Internal/Prim>, @./other.usda@]
    payload = @./payload.usda@
    inherits = </_class_link>
    specializes = [</Base>]
    variants = {
        string mode = "compliant"
    }
    prepend variantSets = "mode"
    relocates = {
        </a/b>: </a/c>
    }
    prefixSubstitutions = {"$ROOT": "/root"}
    active = false
)
{
}
)");
  const Prim& r = only_root(p);
  CHECK(r.metadata.size() == 18);
  CHECK(r.find_metadata("doc")->is_doc_shorthand);
  CHECK(r.find_metadata("doc")->value.text == "doc shorthand");
  CHECK(r.find_metadata("kind")->value.text == "model");
  CHECK(r.api_schemas(ListOp::Prepend) ==
        std::vector<std::string_view>{"PhysicsDriveAPI:angular", "PhysxJointAPI"});
  CHECK(r.api_schemas(ListOp::Append) == std::vector<std::string_view>{"PhysxMimicJointAPI:rotZ"});
  CHECK(r.api_schemas(ListOp::Delete) == std::vector<std::string_view>{"PhysicsDriveAPI:angular"});
  CHECK(r.applied_api_schemas() == std::vector<std::string_view>{"PhysxJointAPI", "PhysxMimicJointAPI:rotZ"});
  CHECK_FALSE(r.has_api_schema("PhysicsDriveAPI:angular"));
  CHECK(r.has_api_schema("PhysxJointAPI"));
  const Metadata* del = r.find_metadata("apiSchemas", ListOp::Delete);
  REQUIRE(del != nullptr);
  CHECK(p.text(del->op_span) == "delete");
  CHECK(p.text(del->span) == "delete apiSchemas = [\"PhysicsDriveAPI:angular\"]");
  CHECK(p.text(del->value.elements[0].span) == "\"PhysicsDriveAPI:angular\"");
  CHECK(r.find_metadata("instanceable")->value.as_bool() == std::optional<bool>(true));
  CHECK(r.find_metadata("hide_in_stage_window")->value.as_bool() == std::optional<bool>(true));
  CHECK(r.find_metadata("customData")->value.find_entry("version")->value.number == 3);

  const Metadata* pre = r.find_metadata("references", ListOp::Prepend);
  REQUIRE(pre != nullptr);
  auto arcs = composition_arcs(pre->value);
  REQUIRE(arcs.size() == 1);
  CHECK(arcs[0].asset == "./parts/base.usd");
  CHECK(arcs[0].prim_path == "/Meshes/base_link");
  CHECK(arcs[0].offset == std::optional<double>(1.5));
  CHECK(arcs[0].scale == std::optional<double>(2));
  CHECK(p.text(pre->value.prim_path_span) == "</Meshes/base_link>");

  arcs = composition_arcs(r.find_metadata("references", ListOp::Explicit)->value);
  REQUIRE(arcs.size() == 2);
  CHECK(arcs[0].asset.empty());
  CHECK(arcs[0].prim_path == "/Internal/Prim");
  CHECK(arcs[1].asset == "./other.usda");
  CHECK(arcs[1].prim_path.empty());
  CHECK(composition_arcs(r.find_metadata("payload")->value)[0].asset == "./payload.usda");
  CHECK(composition_arcs(r.find_metadata("inherits")->value)[0].prim_path == "/_class_link");
  CHECK(composition_arcs(r.find_metadata("specializes")->value)[0].prim_path == "/Base");
  CHECK(r.find_metadata("variants")->value.find_entry("mode")->value.text == "compliant");
  CHECK(r.find_metadata("variantSets")->op == ListOp::Prepend);
  const Value& reloc = r.find_metadata("relocates")->value;
  REQUIRE(reloc.entries.size() == 1);
  CHECK(reloc.entries[0].key == "/a/b");
  CHECK(reloc.entries[0].value.text == "/a/c");
  CHECK(r.find_metadata("prefixSubstitutions")->value.find_entry("$ROOT")->value.text == "/root");
  CHECK(r.find_metadata("active")->value.as_bool() == std::optional<bool>(false));
}

TEST_CASE("usda parser: references = None and empty lists", "[usda][parser]") {
  const Parsed p = must_parse("#usda 1.0\ndef \"a\" (\n references = None\n payload = []\n apiSchemas = []\n) {}\n");
  const Prim& a = only_root(p);
  CHECK(a.find_metadata("references")->value.is_none());
  CHECK(composition_arcs(a.find_metadata("references")->value).empty());
  CHECK(a.find_metadata("payload")->value.count == 0);
  CHECK(a.applied_api_schemas().empty());
}

TEST_CASE("usda parser: variant sets and reorder statements", "[usda][parser]") {
  const Parsed p = must_parse(R"(#usda 1.0
def Xform "gripper" (
    variants = {
        string mode = "rigid"
    }
    prepend variantSets = ["mode", "color"]
)
{
    reorder nameChildren = ["b", "a"]
    reorder properties = ["y", "x"]
    float x = 1
    float y = 2
    variantSet "mode" = {
        "compliant" (
            doc = "soft"
        ) {
            float physxMimicJoint:rotZ:naturalFrequency = 5000
            def "child" {
            }
        }
        "rigid" {
            variantSet "nested" = {
                "v" {
                }
            }
        }
    }
    variantSet "color" = {
    }
    def "a" {}
    def "b" {}
}
reorder rootPrims = ["gripper"]
)");
  const Prim& g = only_root(p);
  REQUIRE(g.reorders.size() == 2);
  CHECK(g.reorders[0].what == "nameChildren");
  CHECK(g.reorders[0].names.as_string_list() == std::optional<std::vector<std::string_view>>({"b", "a"}));
  CHECK(g.reorders[1].what == "properties");
  REQUIRE(p.layer().reorders.size() == 1);
  CHECK(p.layer().reorders[0].what == "rootPrims");
  REQUIRE(g.variant_sets.size() == 2);
  const VariantSet& mode = g.variant_sets[0];
  CHECK(mode.name == "mode");
  CHECK(p.text(mode.name_span) == "\"mode\"");
  REQUIRE(mode.variants.size() == 2);
  const Variant* compliant = mode.find_variant("compliant");
  REQUIRE(compliant != nullptr);
  CHECK(compliant->body.find_metadata("doc")->value.text == "soft");
  CHECK(compliant->body.attribute_double("physxMimicJoint:rotZ:naturalFrequency") == std::optional<double>(5000));
  REQUIRE(compliant->body.children.size() == 1);
  CHECK(compliant->body.children[0].name == "child");
  CHECK(p.text(compliant->name_span) == "\"compliant\"");
  CHECK(p.text(compliant->span).back() == '}');
  const Variant* rigid = mode.find_variant("rigid");
  REQUIRE(rigid->body.variant_sets.size() == 1);
  CHECK(rigid->body.variant_sets[0].variants[0].name == "v");
  CHECK(g.variant_sets[1].variants.empty());
  CHECK(g.children.size() == 2);
  CHECK(g.attributes.size() == 2);
}

TEST_CASE("usda parser: large numeric arrays are lazy", "[usda][parser]") {
  std::string text = "#usda 1.0\ndef Mesh \"m\"\n{\n    point3f[] points = [";
  for (int i = 0; i < 100; ++i) text += (i ? ", " : "") + std::string("(") + std::to_string(i) + ", 0.5, -1e-3)";
  text += "]\n    int[] faceVertexCounts = [";
  for (int i = 0; i < 50; ++i) text += (i ? ", " : "") + std::to_string(i);
  text += "]\n    int[] small = [1, 2, 3]\n    token[] names = [";
  for (int i = 0; i < 50; ++i) text += (i ? ", " : "") + std::string("\"n") + std::to_string(i) + "\"";
  text += "]\n    float[] weights.timeSamples = { 0: [";
  for (int i = 0; i < 40; ++i) text += (i ? ", " : "") + std::to_string(i) + ".5";
  text += "] }\n    float[] edge = [inf, -inf, nan, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16]\n}\n";
  const Parsed p = must_parse(text);
  const Prim& m = only_root(p);
  const Value& pts = *m.find_attribute("points")->default_value;
  CHECK(pts.kind == ValueKind::List);
  CHECK(pts.lazy);
  CHECK(pts.count == 100);
  CHECK(pts.elements.empty());
  CHECK(p.text(pts.span).front() == '[');
  CHECK(p.text(pts.span).back() == ']');
  CHECK(p.text(pts.span).size() == pts.span.length);
  std::vector<double> numbers;
  REQUIRE(read_numbers(pts, p.file->view(), numbers));
  REQUIRE(numbers.size() == 300);
  CHECK(numbers[3] == 1);
  CHECK(numbers[4] == 0.5);
  CHECK(numbers[299] == -1e-3);
  auto elems = parse_elements(pts, *p.file, 7);
  REQUIRE(std::holds_alternative<std::vector<Value>>(elems));
  const auto& list = std::get<std::vector<Value>>(elems);
  REQUIRE(list.size() == 100);
  CHECK(list[99].as_numbers() == std::optional<std::vector<double>>({99, 0.5, -1e-3}));
  CHECK(p.text(list[99].span) == "(99, 0.5, -1e-3)");

  Value copy = pts;
  CHECK_FALSE(materialize(copy, *p.file, 7).has_value());
  CHECK_FALSE(copy.lazy);
  CHECK(copy.elements.size() == 100);

  CHECK(m.find_attribute("faceVertexCounts")->default_value->lazy);
  CHECK(m.find_attribute("faceVertexCounts")->default_value->count == 50);
  CHECK_FALSE(m.find_attribute("small")->default_value->lazy);
  CHECK(m.find_attribute("small")->default_value->elements.size() == 3);
  CHECK_FALSE(m.find_attribute("names")->default_value->lazy);  // token arrays are kept
  CHECK(m.find_attribute("names")->default_value->elements.size() == 50);
  const auto& ws = m.find_attribute("weights")->time_samples->samples;
  REQUIRE(ws.size() == 1);
  CHECK(ws[0].value.lazy);
  CHECK(ws[0].value.count == 40);
  const Value& edge = *m.find_attribute("edge")->default_value;
  CHECK(edge.lazy);
  CHECK(edge.count == 19);
  numbers.clear();
  REQUIRE(read_numbers(edge, p.file->view(), numbers));
  CHECK(std::isinf(numbers[0]));
  CHECK(numbers[1] < 0);
  CHECK(std::isnan(numbers[2]));

  ParseOptions eager;
  eager.lazy_arrays = false;
  const Parsed e = must_parse(text, eager);
  CHECK_FALSE(only_root(e).find_attribute("points")->default_value->lazy);
  CHECK(only_root(e).find_attribute("points")->default_value->elements.size() == 100);
}

TEST_CASE("usda parser: CRLF and BOM input", "[usda][parser]") {
  const std::string text = "\xEF\xBB\xBF#usda 1.0\r\n(\r\n    metersPerUnit = 0.01\r\n)\r\n\r\n"
                           "def Xform \"a\"\r\n{\r\n    float physics:mass = 2.5\r\n}\r\n";
  const Parsed p = must_parse(text);
  CHECK(p.layer().header_span.offset == 3);
  CHECK(p.layer().header_span.column == 1);
  CHECK(p.layer().meters_per_unit() == std::optional<double>(0.01));
  const Prim& a = only_root(p);
  CHECK(a.specifier_span.line == 6);
  CHECK(a.specifier_span.column == 1);
  const Value& mass = *a.find_attribute("physics:mass")->default_value;
  CHECK(mass.number == 2.5);
  CHECK(mass.span.line == 8);
  CHECK(mass.span.column == 26);
  CHECK(p.text(mass.span) == "2.5");

  const Parsed bad = parse("\xEF\xBB\xBF#usda 1.0\r\ndef \"a\" {\r\n  float x = \r\n}\r\n");
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.error().span.line == 4);
  CHECK(bad.error().span.column == 1);
}

TEST_CASE("usda parser: statements separated by ',' and comments", "[usda][parser]") {
  const Parsed p = must_parse("#usda 1.0 # trailing comment\n( upAxis = \"Y\"; metersPerUnit = 1 )\n"
                              "def \"a\" { float x = 1; float y = 2 } // done\n/* block */ def \"b\" {}\n");
  CHECK(p.layer().metadata.size() == 2);
  CHECK(p.layer().prims.size() == 2);
  CHECK(p.layer().prims[0].attributes.size() == 2);
}

TEST_CASE("usda parser: errors report line, column and what was expected", "[usda][parser]") {
  struct Case {
    std::string name;
    std::string text;
    std::uint32_t line;
    std::uint32_t column;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"missing header", "def \"a\" {}\n", 1, 1, "missing '#usda 1.0' header on the first line"},
      {"empty file", "", 1, 1, "missing '#usda 1.0' header on the first line"},
      {"bad header", "#usda\ndef \"a\" {}\n", 1, 1,
       "malformed header: expected '#usda <version>' on the first line"},
      {"unterminated string", "#usda 1.0\ndef \"a\" {\n    string s = \"abc\n}\n", 3, 16, "unterminated string"},
      {"unterminated triple string", "#usda 1.0\n(\n  doc = \"\"\"abc\n)\n", 3, 9,
       "unterminated triple-quoted string"},
      {"missing closing brace", "#usda 1.0\ndef \"a\"\n{\n    float x = 1\n", 3, 1,
       "unterminated prim 'a': missing '}' for the '{' here"},
      {"missing '=' after attribute name", "#usda 1.0\ndef \"a\" {\n    float physics:mass )\n}\n", 3, 24,
       "expected '=' after attribute name 'physics:mass', found ')'"},
      {"unexpected token at top level", "#usda 1.0\nfloat x = 1\n", 2, 1,
       "expected 'def', 'over' or 'class' to start a prim, found 'float'"},
      {"missing prim name", "#usda 1.0\ndef Xform {\n}\n", 2, 11,
       "expected a quoted prim name after 'def', found '{'"},
      {"missing value", "#usda 1.0\ndef \"a\" {\n    float x =\n}\n", 4, 1,
       "expected a value after 'x =', found '}'"},
      {"metadata without '='", "#usda 1.0\n(\n    upAxis \"Z\"\n)\n", 3, 12,
       "expected '=' after metadata key 'upAxis', found string \"Z\""},
      {"unterminated metadata", "#usda 1.0\n(\n    upAxis = \"Z\"\n", 2, 1,
       "unterminated layer metadata: missing ')' for the '(' here"},
      {"bad list", "#usda 1.0\ndef \"a\" {\n    int[] x = [1, 2 3]\n}\n", 3, 21, "expected ',' or ']' in list, found number 3"},
      {"unterminated list", "#usda 1.0\ndef \"a\" {\n    int[] x = [1, 2,\n", 3, 15,
       "unterminated list: missing ']' for the one here"},
      {"relationship target not a path", "#usda 1.0\ndef \"a\" {\n    rel r = \"x\"\n}\n", 3, 13,
       "expected a path <...>, a list of paths or None for relationship 'r', found string \"x\""},
      {"two statements on a line", "#usda 1.0\ndef \"a\" {\n    float x = 1 float y = 2\n}\n", 3, 17,
       "expected a line break or ';' after attribute 'x', found 'float'"},
      {"list-op on a plain attribute", "#usda 1.0\ndef \"a\" {\n    prepend float x = 1\n}\n", 3, 5,
       "list-op 'prepend' is only allowed on relationships and attribute connections"},
      {"unknown property field", "#usda 1.0\ndef \"a\" {\n    float x.bogus = 1\n}\n", 3, 12,
       "unknown property field '.bogus' (expected .timeSamples, .connect or .spline)"},
      {"bad time sample", "#usda 1.0\ndef \"a\" {\n    float x.timeSamples = { 1 2 }\n}\n", 3, 31,
       "expected ':' after time code in timeSamples, found number 2"},
      {"unterminated path", "#usda 1.0\ndef \"a\" {\n    rel r = </a\n}\n", 3, 13, "unterminated path (missing '>')"},
      {"stray character", "#usda 1.0\ndef \"a\" {\n    float x = 1 ?\n}\n", 3, 17, "unexpected character"},
  };
  for (const auto& c : cases) {
    INFO(c.name);
    const Parsed p = parse(c.text);
    REQUIRE_FALSE(p.ok());
    CHECK(p.error().message == c.message);
    CHECK(p.error().span.line == c.line);
    CHECK(p.error().span.column == c.column);
    CHECK(p.error().span.file == 7);
    CHECK(p.error().span.end() <= c.text.size());
  }
}

TEST_CASE("usda parser: nesting depth is bounded", "[usda][parser]") {
  std::string deep_list = "#usda 1.0\n(\n    x = " + std::string(5000, '[') + std::string(5000, ']') + "\n)\n";
  const Parsed a = parse(deep_list);
  REQUIRE_FALSE(a.ok());
  CHECK(a.error().message == "nesting deeper than 256 levels");
  CHECK(a.error().span.line == 3);

  std::string deep_prims = "#usda 1.0\n";
  for (int i = 0; i < 3000; ++i) deep_prims += "def \"p\" {\n";
  for (int i = 0; i < 3000; ++i) deep_prims += "}\n";
  const Parsed b = parse(deep_prims);
  REQUIRE_FALSE(b.ok());
  CHECK(b.error().message == "nesting deeper than 256 levels");
  CHECK(b.error().span.line == 258);  // prim number 257 (line 1 is the header)

  std::string ok_prims = "#usda 1.0\n";
  for (int i = 0; i < 100; ++i) ok_prims += "def \"p\" {\n";
  for (int i = 0; i < 100; ++i) ok_prims += "}\n";
  CHECK(parse(ok_prims).ok());
}

TEST_CASE("usda parser: malformed large arrays get the precise error", "[usda][parser]") {
  std::string text = "#usda 1.0\ndef Mesh \"m\" {\n    int[] faceVertexIndices = [";
  for (int i = 0; i < 30; ++i) text += std::to_string(i) + ", ";
  text += "30 31]\n}\n";
  const Parsed p = parse(text);
  REQUIRE_FALSE(p.ok());
  CHECK(p.error().message == "expected ',' or ']' in list, found number 31");
  CHECK(p.error().span.line == 3);
  CHECK(p.error().span.column == text.find("31]") - text.rfind('\n', text.find("31]")));

  // comments inside a large array are fine and the array stays lazy
  std::string commented = "#usda 1.0\ndef Mesh \"m\" {\n    float[] w = [ # weights\n";
  for (int i = 0; i < 30; ++i) commented += "        " + std::to_string(i) + ", // item\n";
  commented += "    ]\n    float after = 1\n}\n";
  const Parsed c = must_parse(commented);
  const Prim& m = only_root(c);
  CHECK(m.find_attribute("w")->default_value->lazy);
  CHECK(m.find_attribute("w")->default_value->count == 30);
  CHECK(m.find_attribute("after")->default_value->span.line == 35);
}
