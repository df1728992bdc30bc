#pragma once
// The expanded URDF as text (indented as xacro's output is), with where each attribute
// value and start tag landed, so that a finding on the text can be traced to its origin.
#include <string>
#include <vector>

#include "formats/xacro/expansion.h"

namespace assetlint::xacro {

struct Placement {
  std::size_t offset = 0;  // in the written text
  std::size_t length = 0;
  const OutAttribute* attribute = nullptr;  // an attribute's value, or
  const OutNode* element = nullptr;         // an element's start tag
};

// `source_name` is named in the banner. Placements are in text order.
std::string write_urdf(const Expansion& expansion, const std::string& source_name, std::vector<Placement>* placements);

}  // namespace assetlint::xacro
