#pragma once
// Rewriting MJCF values in place: which attribute a value was read from, and a range
// attribute ("lo hi") rescaled as a whole so that it keeps its shape.
#include <optional>
#include <string>
#include <string_view>

#include "engine/diagnostic.h"
#include "model/quantity.h"
#include "model/source.h"

namespace assetlint::mjcf {

// Whether `q` is the whole value of the attribute `name` (kp="2000"), not one token of a
// list such as biasprm or forcerange.
bool read_from_attribute(const SourceFile& file, const Quantity& q, std::string_view name);

// The edit that rescales the two-number range attribute holding the token `bound` (its larger
// end, as the reader takes a force range) so that this end becomes `magnitude` (authored units,
// > 0): "-100 100" → "-2.46 2.46", "-50 100" → "-1.23 2.46". `format` writes one magnitude.
std::optional<Edit> rescaled_range(const SourceFile& file, const Quantity& bound, double magnitude,
                                   std::string (*format)(double));

}  // namespace assetlint::mjcf
