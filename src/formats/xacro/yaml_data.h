#pragma once
// xacro.load_yaml(): a YAML document as the values PyYAML's safe_load gives xacro (YAML 1.1
// scalars: yes/no/on/off are booleans, a float needs a point), dictionaries readable with
// dots, and xacro's unit tags (!degrees, !millimeters, …) converted to radians and metres.
#include <functional>
#include <string>

#include "formats/xacro/python_value.h"

namespace assetlint::xacro {

// `evaluate` computes a unit-tagged scalar's expression (xacro allows `!degrees 90/2`).
Value parse_yaml(const std::string& text, const std::function<Value(const std::string&)>& evaluate);

}  // namespace assetlint::xacro
