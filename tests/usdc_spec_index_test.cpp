// Specs of a crate layer found by parent path and name (formats/usdc/crate_spec_index.h):
// the same specs the whole path's text finds, and names that are not one path element told apart.
#include <catch2/catch.hpp>

#include <string>

#include "formats/usdc/crate_file.h"
#include "formats/usdc/crate_spec_index.h"
#include "support/crate_writer.h"

namespace {

namespace usdc = assetlint::usdc;
namespace crate = assetlint::test::crate;

// The path text of a lookup's result, or "" when nothing is found.
std::string found(const usdc::CrateFile& file, const std::optional<usdc::SpecAt>& at) {
  if (!at) return "";
  CHECK(file.specs()[at->spec].path == at->path);
  return file.paths()[at->path].text;
}

}  // namespace

TEST_CASE("a crate spec is found by its parent path and name", "[usdc]") {
  const std::string bytes = crate::write_crate({
      crate::pseudo_root(),
      crate::prim("/arm", crate::Specifier::Def, "Xform"),
      crate::prim("/arm/link1", crate::Specifier::Def, "Xform"),
      crate::attribute("/arm/link1.physics:mass", "float", crate::Float{2.0f}),
      crate::prim("/arm/link1/physics", crate::Specifier::Def),
      crate::variant_set("/arm", "PhysX"),
      crate::variant("/arm", "PhysX", "Enabled"),
      crate::attribute("/arm{PhysX=Enabled}.physics:mass", "float", crate::Float{3.0f}),
  });
  const usdc::CrateFile file(bytes);
  const auto index = usdc::SpecIndex::build(file);
  REQUIRE(index);
  const auto root = index->root();
  REQUIRE(root);
  CHECK(found(file, root) == "/");
  const auto arm = index->child(root->path, "arm", false);
  CHECK(found(file, arm) == "/arm");
  const auto link = index->child(arm->path, "link1", false);
  CHECK(found(file, link) == "/arm/link1");
  CHECK(found(file, index->child(link->path, "physics:mass", true)) == "/arm/link1.physics:mass");
  // A prim and a property of the same name are different paths.
  CHECK(found(file, index->child(link->path, "physics", false)) == "/arm/link1/physics");
  CHECK(found(file, index->child(link->path, "physics", true)) == "");
  CHECK(found(file, index->child(arm->path, "{PhysX=}", false)) == "/arm{PhysX=}");
  const auto enabled = index->child(arm->path, "{PhysX=Enabled}", false);
  CHECK(found(file, enabled) == "/arm{PhysX=Enabled}");
  CHECK(found(file, index->child(enabled->path, "physics:mass", true)) == "/arm{PhysX=Enabled}.physics:mass");
  CHECK(found(file, index->child(arm->path, "link2", false)) == "");
  CHECK(found(file, index->child(root->path, "link1", false)) == "");
}

TEST_CASE("only a name that is one path element is looked up by parent and name", "[usdc]") {
  CHECK(usdc::SpecIndex::is_element("LF_HAA", false));
  CHECK(usdc::SpecIndex::is_element("drive:angular:physics:stiffness", true));
  CHECK(usdc::SpecIndex::is_element("{PhysX=Enabled}", false));
  CHECK(usdc::SpecIndex::is_element("{PhysX=}", false));
  // Spelled as several elements: found by the whole path it spells.
  CHECK_FALSE(usdc::SpecIndex::is_element("{PhysX=Enabled}", true));
  CHECK_FALSE(usdc::SpecIndex::is_element("a/b", false));
  CHECK_FALSE(usdc::SpecIndex::is_element("a.b", true));
  CHECK_FALSE(usdc::SpecIndex::is_element("{a=b}c", false));
  CHECK_FALSE(usdc::SpecIndex::is_element("{a={b}}", false));
  CHECK_FALSE(usdc::SpecIndex::is_element("rel[/a]", true));
  CHECK_FALSE(usdc::SpecIndex::is_element("", false));
}
