#include "formats/usdc/crate_types.h"

#include "formats/usdc/crate_values.h"

namespace assetlint::usdc {

const Element* element_of(unsigned type) {
  static const Element table[] = {
      {"bool", Num::Bool, 1, 0, false},        {"uchar", Num::U8, 1, 0, false},
      {"int", Num::I32, 1, 0, false},          {"uint", Num::U32, 1, 0, false},
      {"int64", Num::I64, 1, 0, false},        {"uint64", Num::U64, 1, 0, false},
      {"half", Num::Half, 1, 0, false},        {"float", Num::Float, 1, 0, false},
      {"double", Num::Double, 1, 0, false},    {"string", Num::StringIdx, 1, 0, false},
      {"token", Num::TokenIdx, 1, 0, false},   {"asset", Num::AssetIdx, 1, 0, false},
      {"matrix2d", Num::Double, 4, 2, false},  {"matrix3d", Num::Double, 9, 3, false},
      {"matrix4d", Num::Double, 16, 4, false}, {"quatd", Num::Double, 4, 0, true},
      {"quatf", Num::Float, 4, 0, true},       {"quath", Num::Half, 4, 0, true},
      {"double2", Num::Double, 2, 0, false},   {"float2", Num::Float, 2, 0, false},
      {"half2", Num::Half, 2, 0, false},       {"int2", Num::I32, 2, 0, false},
      {"double3", Num::Double, 3, 0, false},   {"float3", Num::Float, 3, 0, false},
      {"half3", Num::Half, 3, 0, false},       {"int3", Num::I32, 3, 0, false},
      {"double4", Num::Double, 4, 0, false},   {"float4", Num::Float, 4, 0, false},
      {"half4", Num::Half, 4, 0, false},       {"int4", Num::I32, 4, 0, false},
  };
  static const Element timecode{"timecode", Num::Double, 1, 0, false};
  if (type >= kBool && type <= kVec4i) return &table[type - kBool];
  if (type == kTimeCode) return &timecode;
  return nullptr;
}

std::size_t size_of(Num n) {
  switch (n) {
    case Num::Bool:
    case Num::U8: return 1;
    case Num::Half: return 2;
    case Num::I64:
    case Num::U64:
    case Num::Double: return 8;
    default: return 4;
  }
}

float half_to_float(std::uint16_t h) {
  const std::uint32_t sign = (h >> 15) & 1, exponent = (h >> 10) & 0x1F, mantissa = h & 0x3FF;
  float v;
  if (exponent == 0) v = std::ldexp(static_cast<float>(mantissa), -24);
  else if (exponent == 31) v = mantissa ? std::nanf("") : INFINITY;
  else v = std::ldexp(static_cast<float>(mantissa | 0x400), static_cast<int>(exponent) - 25);
  return sign ? -v : v;
}

void append_stored_number(std::string& out, Num num, const char* p) {
  const auto integer = [&](auto v) { append_number(out, v); };
  switch (num) {
    case Num::Bool: out += *p ? "1" : "0"; return;
    case Num::U8: integer(load<std::uint8_t>(p)); return;
    case Num::I32: integer(load<std::int32_t>(p)); return;
    case Num::U32: integer(load<std::uint32_t>(p)); return;
    case Num::I64: integer(load<std::int64_t>(p)); return;
    case Num::U64: integer(load<std::uint64_t>(p)); return;
    case Num::Half: append_real(out, half_to_float(load<std::uint16_t>(p))); return;
    case Num::Float: append_real(out, load<float>(p)); return;
    case Num::Double: append_real(out, load<double>(p)); return;
    default: return;
  }
}

void append_component(std::string& out, const CrateFile& file, Num num, const char* p, const std::string& what) {
  switch (num) {
    case Num::StringIdx: out += quoted(file.string(load<std::uint32_t>(p), what.c_str())); return;
    case Num::TokenIdx: out += quoted(file.token(load<std::uint32_t>(p), what.c_str())); return;
    case Num::AssetIdx: out += asset_literal(file.string(load<std::uint32_t>(p), what.c_str())); return;
    default: append_stored_number(out, num, p); return;
  }
}

void append_element(std::string& out, const CrateFile& file, const Element& e, const char* p, const std::string& what) {
  const std::size_t size = size_of(e.num);
  if (e.components == 1) {
    append_component(out, file, e.num, p, what);
    return;
  }
  // Crate stores a quaternion x, y, z, w; USDA writes w first.
  const auto stored = [&](int i) {
    const int index = e.quat ? (i + 3) % 4 : i;
    return p + static_cast<std::size_t>(index) * size;
  };
  out += '(';
  if (e.rows) {
    for (int r = 0; r < e.rows; ++r) {
      out += r ? ", (" : "(";
      for (int k = 0; k < e.rows; ++k) {
        if (k) out += ", ";
        append_component(out, file, e.num, stored(r * e.rows + k), what);
      }
      out += ')';
    }
  } else {
    for (int i = 0; i < e.components; ++i) {
      if (i) out += ", ";
      append_component(out, file, e.num, stored(i), what);
    }
  }
  out += ')';
}

}  // namespace assetlint::usdc
