#pragma once
#include <optional>

#include "model/source.h"
#include "model/units.h"

namespace assetlint {

// A number read from a file: its value in SI/PhysX units, the literal as written,
// the unit of that literal, and where the literal is.
struct Quantity {
  double value = 0.0;     // model (SI / PhysX) units
  double authored = 0.0;  // as written in the file
  Unit unit = Unit::None; // unit of the literal
  Span span;              // the literal's bytes; invalid when the value is a default or derived
  Span declaration;       // the whole attribute that holds it (for fixes that remove it)
  // Extra factor from the file's own unit system, on top of `unit`: a USD stage's
  // metersPerUnit / kilogramsPerUnit (value = to_model_units(authored, unit) × scale).
  double scale = 1.0;

  static Quantity from_authored(double authored, Unit unit, Span span, double scale = 1.0) {
    return Quantity{to_model_units(authored, unit) * scale, authored, unit, span, span, scale};
  }
  // A value the file does not write (a format default); its span is left invalid.
  static Quantity unauthored(double model_value, Unit unit) {
    return Quantity{model_value, from_model_units(model_value, unit), unit, Span{}, Span{}};
  }
  // The value to write into this quantity's literal for a new model value.
  double authored_for(double model_value) const { return from_model_units(model_value / scale, unit); }
  bool is_authored() const { return span.valid(); }
};

using OptQuantity = std::optional<Quantity>;

}  // namespace assetlint
