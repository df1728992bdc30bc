// Composition of .usda layer stacks: subLayers, references, payloads, over prims,
// apiSchemas list-ops, unresolved layers and cycles.
#include <catch2/catch.hpp>

#include <map>

#include "engine/file_system.h"
#include "formats/usda/compose.h"

using namespace assetlint;
using namespace assetlint::usda;

namespace {

// Files held in memory; anything else is missing.
class MemoryFileSystem final : public FileSystem {
 public:
  MemoryFileSystem(std::map<std::string, std::string> files) : files_(std::move(files)) {}
  std::optional<std::string> read(const std::string& path, std::string& error) const override {
    ++reads[path];
    auto it = files_.find(path);
    if (it == files_.end()) {
      error = "No such file or directory";
      return std::nullopt;
    }
    return it->second;
  }
  mutable std::map<std::string, int> reads;

 private:
  std::map<std::string, std::string> files_;
};

Stage compose(const MemoryFileSystem& fs, const std::string& root, ComposeOptions options = {}) {
  std::string error;
  auto text = fs.read(root, error);
  REQUIRE(text);
  return compose_stage(std::make_shared<const SourceFile>(root, std::move(*text)), fs, options);
}

double number(const Stage& stage, const char* prim, const char* attr) {
  const ComposedPrim* p = stage.find(prim);
  REQUIRE(p);
  auto a = p->attribute(attr);
  REQUIRE(a);
  return *a->attribute->default_value->as_double();
}

std::string path_of(const Stage& stage, const char* prim, const char* attr) {
  auto a = stage.find(prim)->attribute(attr);
  REQUIRE(a);
  return stage.sources.at(a->file)->path();
}

}  // namespace

TEST_CASE("compose: sublayers are weaker than the layer, earlier sublayers stronger", "[usd][compose]") {
  MemoryFileSystem fs({{"d/root.usda", "#usda 1.0\n(\n subLayers = [@a.usda@, @b.usda@]\n)\nover \"R\" { float x = 1 }\n"},
                       {"d/a.usda", "#usda 1.0\nover \"R\" { float x = 2\n float y = 2 }\n"},
                       {"d/b.usda", "#usda 1.0\ndef Xform \"R\" { float x = 3\n float y = 3\n float z = 3 }\n"}});
  Stage s = compose(fs, "d/root.usda");
  REQUIRE(s.usable);
  CHECK(s.diagnostics.empty());
  REQUIRE(s.root_stack.size() == 3);
  CHECK(number(s, "/R", "x") == 1);
  CHECK(number(s, "/R", "y") == 2);
  CHECK(number(s, "/R", "z") == 3);
  CHECK(path_of(s, "/R", "y") == "d/a.usda");
  const ComposedPrim* r = s.find("/R");
  CHECK(r->defined);
  CHECK(r->type_name == "Xform");
  // The span of the winning opinion points into its layer.
  auto y = r->attribute("y");
  CHECK(y->attribute->default_value->span.file == y->file);
  CHECK(y->attribute->default_value->span.line == 3);
}

TEST_CASE("compose: a diamond is not a cycle, the shared layer keeps its strongest position", "[usd][compose]") {
  MemoryFileSystem fs({{"config.usda", "#usda 1.0\n(\n subLayers = [@physics.usda@, @base.usda@]\n)\n"},
                       {"physics.usda", "#usda 1.0\n(\n subLayers = [@base.usda@]\n)\nover \"R\" { float x = 2 }\n"},
                       {"base.usda", "#usda 1.0\ndef \"R\" { float x = 3 }\n"}});
  Stage s = compose(fs, "config.usda");
  CHECK(s.diagnostics.empty());
  REQUIRE(s.root_stack.size() == 3);
  CHECK(s.sources.at(s.root_stack[1])->path() == "physics.usda");
  CHECK(s.sources.at(s.root_stack[2])->path() == "base.usda");
  CHECK(number(s, "/R", "x") == 2);
  CHECK(fs.reads["base.usda"] == 1);  // each layer is read and parsed once
  CHECK(s.sources.size() == 3);
}

TEST_CASE("compose: over prims merge into def prims, only-over prims are not defined", "[usd][compose]") {
  MemoryFileSystem fs({{"r.usda", "#usda 1.0\n(\n subLayers = [@b.usda@]\n)\nover \"A\" { over \"B\" { float m = 5 } }\nover \"Ghost\" {}\n"},
                       {"b.usda", "#usda 1.0\ndef Xform \"A\" { def Xform \"B\" { float m = 1\n float n = 1 } }\n"}});
  Stage s = compose(fs, "r.usda");
  CHECK(number(s, "/A/B", "m") == 5);
  CHECK(number(s, "/A/B", "n") == 1);
  CHECK(s.find("/A/B")->defined);
  CHECK_FALSE(s.find("/Ghost")->defined);
  CHECK(s.find("/A")->children.size() == 1);
}

TEST_CASE("compose: apiSchemas list-ops across layers", "[usd][compose]") {
  MemoryFileSystem fs({{"r.usda",
                        "#usda 1.0\n(\n subLayers = [@b.usda@]\n)\n"
                        "over \"J\" (\n delete apiSchemas = [\"PhysicsDriveAPI:angular\"]\n prepend apiSchemas = [\"PhysxMimicJointAPI:rotZ\"]\n) {}\n"
                        "over \"K\" (\n apiSchemas = [\"Only\"]\n) {}\n"
                        "over \"M\" (\n delete apiSchemas = [\"PhysicsMassAPI\"]\n prepend apiSchemas = [\"PhysicsRigidBodyAPI\", \"PhysicsMassAPI\"]\n) {}\n"},
                       {"b.usda",
                        "#usda 1.0\n"
                        "def \"J\" (\n prepend apiSchemas = [\"PhysxJointAPI\", \"PhysicsDriveAPI:angular\"]\n) { float drive:angular:physics:stiffness = 3 }\n"
                        "def \"K\" (\n prepend apiSchemas = [\"A\", \"B\"]\n) {}\n"
                        "def \"M\" {}\n"}});
  Stage s = compose(fs, "r.usda");
  const ComposedPrim* j = s.find("/J");
  CHECK(j->api_schemas == std::vector<std::string>{"PhysxMimicJointAPI:rotZ", "PhysxJointAPI"});
  CHECK_FALSE(j->has_api_schema("PhysicsDriveAPI:angular"));
  CHECK(j->schema_deleted("PhysicsDriveAPI:angular"));
  CHECK(j->attribute("drive:angular:physics:stiffness"));  // still authored, just not applied
  CHECK(s.find("/K")->api_schemas == std::vector<std::string>{"Only"});
  // Within one spec, delete applies before prepend (SdfListOp order).
  const ComposedPrim* m = s.find("/M");
  CHECK(m->has_api_schema("PhysicsMassAPI"));
  CHECK(m->deleted_api_schemas.empty());
  // The schema span points at the literal that applies it.
  const Span span = j->schema_span("PhysxMimicJointAPI:rotZ");
  CHECK(span.line == 7);
  CHECK(s.sources[span.file]->view().substr(span.offset, span.length) == "\"PhysxMimicJointAPI:rotZ\"");
}

TEST_CASE("compose: references to defaultPrim, to an explicit prim, and internal references", "[usd][compose]") {
  MemoryFileSystem fs({{"w/root.usda",
                        "#usda 1.0\n"
                        "def Xform \"World\" {\n"
                        "  def \"A\" (\n prepend references = @parts/arm.usda@\n ) { float x = 1 }\n"
                        "  def \"B\" (\n references = @parts/arm.usda@</Other>\n ) {}\n"
                        "  def \"C\" (\n prepend references = </Proto>\n ) {}\n"
                        "}\n"
                        "def \"Proto\" { float p = 7\n def \"Kid\" { float k = 8 } }\n"},
                       {"w/parts/arm.usda",
                        "#usda 1.0\n(\n defaultPrim = \"Arm\"\n)\n"
                        "def Xform \"Arm\" { float x = 2\n float y = 2\n def \"Link\" { rel physics:body0 = </Arm/Base> } }\n"
                        "def \"Other\" { float o = 4 }\n"}});
  Stage s = compose(fs, "w/root.usda");
  CHECK(s.diagnostics.empty());
  CHECK(number(s, "/World/A", "x") == 1);  // local opinion beats the reference
  CHECK(number(s, "/World/A", "y") == 2);
  CHECK(path_of(s, "/World/A", "y") == "w/parts/arm.usda");
  REQUIRE(s.find("/World/A/Link"));
  // Paths inside the referenced prim are mapped into the referencing namespace.
  auto rel = s.find("/World/A/Link")->relationship("physics:body0");
  REQUIRE(rel);
  CHECK(rel->targets == std::vector<std::string>{"/World/A/Base"});
  CHECK(number(s, "/World/B", "o") == 4);
  CHECK(number(s, "/World/C", "p") == 7);
  CHECK(number(s, "/World/C/Kid", "k") == 8);
  CHECK(s.find("/World/C")->defined);
}

TEST_CASE("compose: payloads compose like references", "[usd][compose]") {
  MemoryFileSystem fs({{"root.usda", "#usda 1.0\ndef \"R\" (\n payload = @p.usda@\n) {}\n"},
                       {"p.usda", "#usda 1.0\n(\n defaultPrim = \"P\"\n)\ndef \"P\" { float q = 9 }\n"}});
  Stage s = compose(fs, "root.usda");
  CHECK(number(s, "/R", "q") == 9);
}

TEST_CASE("compose: missing, binary and outside-root layers are notes and are skipped", "[usd][compose]") {
  MemoryFileSystem fs({{"a/b/root.usda",
                        "#usda 1.0\n(\n subLayers = [@missing.usda@, @../outside.usda@, @crate.usd@, @mesh.usdc@]\n)\n"
                        "def \"R\" (\n prepend references = @missing.usda@\n) { float x = 1 }\n"},
                       {"a/outside.usda", "#usda 1.0\ndef \"R\" { float x = 5 }\n"},
                       {"a/b/crate.usd", std::string("PXR-USDC\0\0", 10)}});
  Stage s = compose(fs, "a/b/root.usda");
  REQUIRE(s.usable);
  CHECK(number(s, "/R", "x") == 1);
  REQUIRE(s.diagnostics.size() == 5);
  for (const auto& d : s.diagnostics) {
    CHECK(d.rule == "layer-unresolved");
    // A crate layer that is broken loses opinions the author wrote: a warning.
    CHECK(d.severity == (d.message.find("crate.usd") != std::string::npos ? Severity::Warning : Severity::Info));
  }
  CHECK(s.diagnostics[0].message.find("'missing.usda' cannot be read") != std::string::npos);
  CHECK(s.diagnostics[0].span.line == 3);
  CHECK(s.diagnostics[0].span.column == 15);
  CHECK(s.diagnostics[1].message == "layer '../outside.usda' is outside the checked tree; skipped");
  REQUIRE(s.diagnostics[1].notes.size() == 1);
  CHECK(s.diagnostics[1].notes[0].message.starts_with("the checked tree is 'a/b' "));
  CHECK(s.diagnostics[2].message == "layer 'crate.usd' cannot be read; its opinions are skipped");
  REQUIRE(s.diagnostics[2].notes.size() == 1);
  CHECK(s.diagnostics[2].notes[0].message.find("bootstrap: the file has 10 bytes") != std::string::npos);
  CHECK(s.diagnostics[3].message.find("'mesh.usdc' cannot be read (No such file") != std::string::npos);
  CHECK(s.diagnostics[4].span.line == 6);  // the reference to the same missing file, at its own literal
  CHECK(fs.reads.count("a/outside.usda") == 0);

  SECTION("a wider root or --allow-outside-root reads it") {
    ComposeOptions wide;
    wide.root_dir = "a";
    Stage w = compose(fs, "a/b/root.usda", wide);
    CHECK(w.diagnostics.size() == 4);
    ComposeOptions allow;
    allow.allow_outside_root = true;
    Stage a = compose(fs, "a/b/root.usda", allow);
    CHECK(a.diagnostics.size() == 4);
  }
}

TEST_CASE("compose: sublayer and reference cycles are reported and cut", "[usd][compose]") {
  MemoryFileSystem fs({{"a.usda", "#usda 1.0\n(\n subLayers = [@b.usda@]\n)\ndef \"X\" (\n references = </Y>\n) {}\n"
                                  "def \"Y\" (\n references = </X>\n) { float v = 1 }\n"
                                  "def \"Z\" { def \"Inner\" (\n references = </Z>\n) {} }\n"},
                       {"b.usda", "#usda 1.0\n(\n subLayers = [@a.usda@]\n)\n"}});
  Stage s = compose(fs, "a.usda");
  REQUIRE(s.usable);
  std::vector<std::string> messages;
  for (const auto& d : s.diagnostics) {
    CHECK(d.rule == "layer-unresolved");
    CHECK(d.severity == Severity::Warning);
    messages.push_back(d.message);
  }
  REQUIRE(messages.size() >= 3);
  CHECK(messages[0].find("sublayer cycle") != std::string::npos);
  CHECK(number(s, "/X", "v") == 1);
  CHECK(s.find("/Z/Inner"));
  CHECK(std::count_if(messages.begin(), messages.end(), [](const std::string& m) { return m.starts_with("reference cycle"); }) >= 2);
}

TEST_CASE("compose: a sublayer two referenced stacks share is no cycle", "[usd][compose]") {
  // Part files of an Onshape import each sublayer one materials layer that also defines
  // /World: a frame references one part and its plate another. OpenUSD composes this without
  // a cycle: a cycle is an arc back to the same prim of the same layer stack.
  MemoryFileSystem fs({{"top.usda", "#usda 1.0\ndef \"Robot\" {\n def \"Frame\" (\n references = @a.usda@\n) {\n"
                                    "  def \"Plate\" (\n references = @b.usda@\n) {}\n }\n}\n"},
                       {"a.usda", "#usda 1.0\n(\n defaultPrim = \"World\"\n subLayers = [@m.usda@]\n)\ndef \"World\" { float a = 1 }\n"},
                       {"b.usda", "#usda 1.0\n(\n defaultPrim = \"World\"\n subLayers = [@m.usda@]\n)\ndef \"World\" { float b = 2 }\n"},
                       {"m.usda", "#usda 1.0\ndef \"World\" { float m = 3 }\n"}});
  Stage s = compose(fs, "top.usda");
  REQUIRE(s.usable);
  CHECK(s.diagnostics.empty());
  CHECK(number(s, "/Robot/Frame", "a") == 1);
  CHECK(number(s, "/Robot/Frame/Plate", "b") == 2);
  CHECK(number(s, "/Robot/Frame/Plate", "m") == 3);
}

TEST_CASE("compose: a syntax error in a sublayer makes the stage unusable", "[usd][compose]") {
  MemoryFileSystem fs({{"r.usda", "#usda 1.0\n(\n subLayers = [@bad.usda@]\n)\n"},
                       {"bad.usda", "#usda 1.0\ndef \"R\" {\n float x = \n}\n"}});
  Stage s = compose(fs, "r.usda");
  CHECK_FALSE(s.usable);
  REQUIRE(s.diagnostics.size() == 1);
  CHECK(s.diagnostics[0].rule == "parse-error");
  CHECK(s.sources.at(s.diagnostics[0].span.file)->path() == "bad.usda");
  CHECK(s.diagnostics[0].span.line == 4);
}

TEST_CASE("compose: layers are read through the given FileSystem (fixer overlay)", "[usd][compose]") {
  MemoryFileSystem base({{"r.usda", "#usda 1.0\n(\n subLayers = [@s.usda@]\n)\n"},
                         {"s.usda", "#usda 1.0\ndef \"R\" { float x = 1 }\n"}});
  OverlayFileSystem overlay(base);
  overlay.set("s.usda", "#usda 1.0\ndef \"R\" { float x = 42 }\n");
  Stage s = compose(base, "r.usda");
  CHECK(number(s, "/R", "x") == 1);
  std::string error;
  Stage o = compose_stage(std::make_shared<const SourceFile>("r.usda", *base.read("r.usda", error)), overlay);
  CHECK(number(o, "/R", "x") == 42);
}

TEST_CASE("compose: internal reference and payload chains compose through every link", "[usd][compose]") {
  // Regression (issue 10): the nested arcs of a chain shrank the cycle guard below its
  // size (internal error: vector::_M_default_append).
  const std::string references = "#usda 1.0\ndef \"A\" (references = </B>) {}\ndef \"B\" (references = </C>) {}\n"
                                 "def \"C\" (references = </D>) {}\ndef \"D\" { float d = 4 }\n";
  const std::string both = "#usda 1.0\ndef \"A\" (references = </B>\n payload = </B>) {}\n"
                           "def \"B\" (references = </C>\n payload = </C>) {}\n"
                           "def \"C\" (references = </D>\n payload = </D>) {}\ndef \"D\" { float d = 4 }\n";
  for (const std::string& text : {references, both}) {
    MemoryFileSystem fs({{"chain.usda", text}});
    Stage s = compose(fs, "chain.usda");
    INFO(text);
    CHECK(s.diagnostics.empty());
    for (const char* prim : {"/A", "/B", "/C", "/D"}) CHECK(number(s, prim, "d") == 4);
  }
}

TEST_CASE("compose: the selected variant's opinions are weaker than the prim's, stronger than its references",
          "[usd][compose]") {
  MemoryFileSystem fs({{"robot.usda", "#usda 1.0\n(\n defaultPrim = \"R\"\n)\n"
                                      "def Xform \"R\" (\n variants = {\n string Physics = \"physx\"\n }\n"
                                      " prepend variantSets = \"Physics\"\n)\n{\n float x = 1\n\n"
                                      " variantSet \"Physics\" = {\n"
                                      "  \"none\" {\n  }\n"
                                      "  \"physx\" (\n prepend apiSchemas = [\"PhysicsArticulationRootAPI\"]\n"
                                      "   references = @physics.usda@\n  ) {\n"
                                      "   float x = 2\n   float y = 2\n"
                                      "   def PhysicsRevoluteJoint \"J\"\n   {\n   }\n  }\n }\n}\n"},
                       {"physics.usda", "#usda 1.0\n(\n defaultPrim = \"P\"\n)\n"
                                        "def Xform \"P\"\n{\n float y = 3\n float z = 3\n}\n"},
                       {"scene.usda", "#usda 1.0\n"
                                      "def Xform \"S\" (\n references = @robot.usda@\n"
                                      " variants = {\n string Physics = \"none\"\n }\n)\n{\n}\n"}});
  Stage s = compose(fs, "robot.usda");
  REQUIRE(s.usable);
  CHECK(number(s, "/R", "x") == 1);  // the prim's own opinion beats its variant's
  CHECK(number(s, "/R", "y") == 2);  // the variant beats the reference it brings in
  CHECK(number(s, "/R", "z") == 3);  // which still contributes
  CHECK(s.find("/R")->has_api_schema("PhysicsArticulationRootAPI"));
  REQUIRE(s.find("/R/J") != nullptr);
  CHECK(s.find("/R/J")->defined);

  // A referencing layer's selection is stronger than the referenced asset's own.
  Stage scene = compose(fs, "scene.usda");
  CHECK(scene.find("/S/J") == nullptr);
  CHECK_FALSE(scene.find("/S")->has_api_schema("PhysicsArticulationRootAPI"));
  CHECK(number(scene, "/S", "x") == 1);
}

TEST_CASE("compose: a variant's payload is stronger than the prim's own references", "[usd][compose][variants]") {
  // LIVRPS: the variant node and what it brings in come before the prim's references.
  MemoryFileSystem fs({{"asset.usda", "#usda 1.0\n(\n defaultPrim = \"R\"\n)\n"
                                      "def Xform \"R\" (\n references = @base.usda@\n"
                                      " variants = {\n string PhysX = \"Enabled\"\n }\n"
                                      " prepend variantSets = \"PhysX\"\n)\n{\n"
                                      " variantSet \"PhysX\" = {\n  \"Disabled\" {\n  }\n"
                                      "  \"Enabled\" (\n prepend payload = @physx.usda@\n  ) {\n  }\n }\n}\n"},
                       {"base.usda", "#usda 1.0\n(\n defaultPrim = \"B\"\n)\ndef Xform \"B\"\n{\n float k = 1\n}\n"},
                       {"physx.usda", "#usda 1.0\n(\n defaultPrim = \"P\"\n)\nover \"P\"\n{\n float k = 2\n}\n"}});
  Stage s = compose(fs, "asset.usda");
  REQUIRE(s.usable);
  CHECK(number(s, "/R", "k") == 2);
  REQUIRE(s.variant_sets.size() == 1);
  CHECK(s.variant_sets[0].prim == "/R");
  CHECK(s.variant_sets[0].set == "PhysX");
  CHECK(s.variant_sets[0].variants == std::vector<std::string>{"Disabled", "Enabled"});
  CHECK(s.variant_sets[0].selection == "Enabled");
  CHECK_FALSE(s.variant_sets[0].physics);  // `k` is no physics attribute

  ComposeOptions pinned;
  pinned.pinned_variants["PhysX"] = "Disabled";
  Stage off = compose(fs, "asset.usda", pinned);
  CHECK(number(off, "/R", "k") == 1);
  CHECK(off.variant_sets[0].pinned);
  CHECK(off.variant_sets[0].selection == "Disabled");
}

TEST_CASE("compose: variantSets is list-edited; a set it does not name is not composed", "[usd][compose][variants]") {
  MemoryFileSystem fs({{"a.usda", "#usda 1.0\n(\n subLayers = [@b.usda@]\n)\n"
                                  "over \"R\" (\n delete variantSets = \"Old\"\n)\n{\n}\n"},
                       {"b.usda", "#usda 1.0\ndef Xform \"R\" (\n"
                                  " variants = {\n string New = \"on\"\n string Old = \"on\"\n string Unlisted = \"on\"\n }\n"
                                  " prepend variantSets = [\"Old\", \"New\"]\n)\n{\n"
                                  " variantSet \"Old\" = {\n  \"on\" {\n   float old = 1\n  }\n }\n"
                                  " variantSet \"New\" = {\n  \"on\" {\n   float physics:mass = 2\n  }\n }\n"
                                  " variantSet \"Unlisted\" = {\n  \"on\" {\n   float unlisted = 3\n  }\n }\n}\n"}});
  Stage s = compose(fs, "a.usda");
  REQUIRE(s.usable);
  const ComposedPrim* r = s.find("/R");
  CHECK_FALSE(r->attribute("old"));
  CHECK_FALSE(r->attribute("unlisted"));
  CHECK(number(s, "/R", "physics:mass") == 2);
  REQUIRE(s.variant_sets.size() == 1);
  CHECK(s.variant_sets[0].set == "New");
  CHECK(s.variant_sets[0].physics);
}

TEST_CASE("compose: nested variant sets, and a selection authored inside a variant", "[usd][compose][variants]") {
  MemoryFileSystem fs(std::map<std::string, std::string>{{"a.usda", "#usda 1.0\ndef Xform \"R\" (\n"
                                  " variants = {\n string Engine = \"physx\"\n }\n"
                                  " prepend variantSets = \"Engine\"\n)\n{\n"
                                  " variantSet \"Engine\" = {\n"
                                  "  \"none\" {\n  }\n"
                                  "  \"physx\" (\n variants = {\n string Gains = \"stiff\"\n }\n"
                                  "   prepend variantSets = \"Gains\"\n  ) {\n"
                                  "   float k = 1\n"
                                  "   variantSet \"Gains\" = {\n"
                                  "    \"soft\" {\n     float drive:angular:physics:stiffness = 4.8\n    }\n"
                                  "    \"stiff\" {\n     float drive:angular:physics:stiffness = 99.48\n    }\n   }\n"
                                  "  }\n }\n}\n"}});
  Stage s = compose(fs, "a.usda");
  REQUIRE(s.usable);
  CHECK(number(s, "/R", "k") == 1);
  CHECK(number(s, "/R", "drive:angular:physics:stiffness") == 99.48);
  REQUIRE(s.variant_sets.size() == 2);
  CHECK(s.variant_sets[0].set == "Engine");
  CHECK(s.variant_sets[1].set == "Gains");
  CHECK(s.variant_sets[1].parent == 0);
  CHECK(s.variant_sets[1].physics);
  CHECK(s.variant_sets[0].physics);  // through the set nested in it

  ComposeOptions soft;
  soft.pinned_variants["Gains"] = "soft";
  CHECK(number(compose(fs, "a.usda", soft), "/R", "drive:angular:physics:stiffness") == 4.8);
}

TEST_CASE("compose: the strongest layer's variant selection wins", "[usd][compose][variants]") {
  MemoryFileSystem fs({{"stage.usda", "#usda 1.0\n(\n subLayers = [@asset.usda@]\n)\n"
                                      "over \"R\" (\n variants = {\n string PhysX = \"Enabled\"\n }\n)\n{\n}\n"},
                       {"asset.usda", "#usda 1.0\ndef Xform \"R\" (\n variants = {\n string PhysX = \"Disabled\"\n }\n"
                                      " prepend variantSets = \"PhysX\"\n)\n{\n"
                                      " variantSet \"PhysX\" = {\n  \"Disabled\" {\n  }\n"
                                      "  \"Enabled\" {\n   def PhysicsRevoluteJoint \"J\"\n   {\n   }\n  }\n }\n}\n"}});
  Stage s = compose(fs, "stage.usda");
  REQUIRE(s.find("/R/J") != nullptr);
  CHECK(s.variant_sets.at(0).selection == "Enabled");
  CHECK(s.variant_sets.at(0).physics);  // a child prim of the variant
  CHECK(compose(fs, "asset.usda").find("/R/J") == nullptr);
}
