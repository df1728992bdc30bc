#pragma once
// A small writer of binary USD crate layers (PXR-USDC 0.8.0), for tests only: OpenUSD's own
// export flattens the stage, so crate files with variant sets, variant specs and list-edited
// metadata are made here from a list of specs, then read by OpenUSD and by asset-lint.
//
// The children fields (primChildren, properties, variantSetChildren, variantChildren) are
// derived from the spec paths in the order the specs are listed; every other field is written
// as given, in the given order.
#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace assetlint::test::crate {

// Sdf's spec types.
enum class SpecType : std::uint32_t { Attribute = 1, Prim = 6, PseudoRoot = 7, Relationship = 8, Variant = 10, VariantSet = 11 };
enum class Specifier : std::uint32_t { Def = 0, Over = 1, Class = 2 };
enum class Variability : std::uint32_t { Varying = 0, Uniform = 1 };

struct Float { float value; };
struct Double { double value; };
struct Float3 { float x, y, z; };
struct Token { std::string value; };
struct String { std::string value; };
struct TokenVector { std::vector<std::string> items; };
// variantSelection: set name → selected variant.
struct Selections { std::vector<std::pair<std::string, std::string>> items; };

struct Payload {
  std::string asset;
  std::string prim;  // empty: the layer's default prim
};
struct Reference : Payload {};  // written without layer offset or custom data

template <class T>
struct ListOp {
  bool is_explicit = false;
  std::vector<T> explicit_items, prepended, appended, deleted;
};
struct TokenListOp : ListOp<std::string> {};   // apiSchemas
struct StringListOp : ListOp<std::string> {};  // variantSetNames
struct PathListOp : ListOp<std::string> {};    // relationship targets
struct PayloadListOp : ListOp<Payload> {};
struct ReferenceListOp : ListOp<Reference> {};

using Value = std::variant<bool, Float, Double, Float3, Token, String, Specifier, Variability, TokenVector, Selections,
                           TokenListOp, StringListOp, PathListOp, PayloadListOp, ReferenceListOp>;

struct Spec {
  std::string path;  // "/", "/gripper", "/gripper{PhysX=}", "/gripper{PhysX=Enabled}joint.drive:x"
  SpecType type;
  std::vector<std::pair<std::string, Value>> fields;
};

// The crate file's bytes. Throws std::invalid_argument for a spec whose parent has no spec.
std::string write_crate(const std::vector<Spec>& specs);

// Specs as the USDA parser of OpenUSD makes them.
Spec pseudo_root(std::vector<std::pair<std::string, Value>> metadata = {});
Spec prim(std::string path, Specifier specifier, std::string type_name = "",
          std::vector<std::pair<std::string, Value>> metadata = {});
Spec attribute(std::string path, std::string type_name, Value value, Variability variability = Variability::Varying);
Spec relationship(std::string path, std::vector<std::string> targets);
Spec variant_set(const std::string& prim_path, const std::string& set);
// A variant spec (specifier over, as SdfVariantSpec::New makes it) with the given metadata.
Spec variant(const std::string& prim_path, const std::string& set, const std::string& name,
             std::vector<std::pair<std::string, Value>> metadata = {});

TokenListOp prepend_tokens(std::vector<std::string> items);
StringListOp prepend_strings(std::vector<std::string> items);
PayloadListOp prepend_payload(std::string asset, std::string prim = "");
ReferenceListOp prepend_reference(std::string asset, std::string prim = "");

}  // namespace assetlint::test::crate
