#pragma once
// Crate's value types as this reader decodes them, and how USDA writes their components:
// the type numbers, the element table (components, matrix rows, quaternion order) and the
// number formatting the text writer and the layer reader share.
#include <fmt/compile.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "formats/usdc/crate_file.h"

namespace assetlint::usdc {

// Crate's type numbers (crateDataTypes.h).
enum Type : unsigned {
  kBool = 1, kUChar, kInt, kUInt, kInt64, kUInt64, kHalf, kFloat, kDouble, kString, kToken, kAssetPath,
  kMatrix2d, kMatrix3d, kMatrix4d, kQuatd, kQuatf, kQuath, kVec2d, kVec2f, kVec2h, kVec2i, kVec3d, kVec3f,
  kVec3h, kVec3i, kVec4d, kVec4f, kVec4h, kVec4i, kDictionary, kTokenListOp, kStringListOp, kPathListOp,
  kReferenceListOp, kIntListOp, kInt64ListOp, kUIntListOp, kUInt64ListOp, kPathVector, kTokenVector,
  kSpecifier, kPermission, kVariability, kVariantSelectionMap, kTimeSamples, kPayload, kDoubleVector,
  kLayerOffsetVector, kStringVector, kValueBlock, kValue, kUnregisteredValue, kUnregisteredValueListOp,
  kPayloadListOp, kTimeCode, kPathExpression, kRelocates
};

enum class Num { Bool, U8, I32, U32, I64, U64, Half, Float, Double, StringIdx, TokenIdx, AssetIdx };

// An element type: its number kind, how many components, matrix rows (0: not a matrix),
// quaternion (stored x, y, z, w).
struct Element {
  const char* name;
  Num num;
  int components;
  int rows;
  bool quat;
};

const Element* element_of(unsigned type);  // null for non-element types
std::size_t size_of(Num n);
float half_to_float(std::uint16_t h);

// Formats into a buffer on the stack, with the format compiled: appending through a back
// inserter, or a bounded one, costs a call per character, and mesh arrays hold millions of
// numbers. (The longest number written is 24 characters, -1.7976931348623157e+308.)
template <class T>
void append_number(std::string& out, T v) {
  char buffer[48];
  const char* end = fmt::format_to(buffer, FMT_COMPILE("{}"), v);
  out.append(buffer, static_cast<std::size_t>(end - buffer));
}

template <class F>
void append_real(std::string& out, F v) {
  if (std::isnan(v)) out += "nan";
  else if (std::isinf(v)) out += v < 0 ? "-inf" : "inf";
  else append_number(out, v);
}


template <class T>
T load(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Appends one stored number (any Num but the string, token and asset indexes) as USDA writes it.
void append_stored_number(std::string& out, Num num, const char* p);
// Appends one stored component as USDA writes it. Large arrays are millions of these: they
// are formatted in place, without a string per component.
void append_component(std::string& out, const CrateFile& file, Num num, const char* p, const std::string& what);
// A whole element (scalar, vector, quaternion w first, matrix rows) from its stored components.
void append_element(std::string& out, const CrateFile& file, const Element& e, const char* p, const std::string& what);

}  // namespace assetlint::usdc
