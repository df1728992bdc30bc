#pragma once
// When urdfdom has to run. urdfdom's parser (a second XML parse with tinyxml 1) is the
// largest single cost of reading a URDF, yet on most files its verdict is already known:
// this predicate recognises, from asset-lint's own parse, documents that urdfdom 3.0's
// parseURDF certainly turns into a model. It is conservative: anything it does not model
// exactly (non-ASCII bytes or entities outside comments, DOCTYPE/CDATA, control characters
// in attribute values, numbers outside a plain decimal grammar, ...) answers "not certain",
// and urdfdom runs as before. tests/urdfdom_verdict_test.cpp compares it with urdfdom over every
// corpus file, every fixture and mutated variants of them; the URDF fuzz target does too.
#include <functional>
#include <optional>
#include <string_view>

namespace tinyxml2 {
class XMLElement;
}

namespace assetlint::urdf {

// The attribute's bytes exactly as written between the quotes; nullopt when absent.
using RawAttribute = std::function<std::optional<std::string_view>(const tinyxml2::XMLElement*, std::string_view)>;

// `document`: what urdfdom would be given; `robot`: its root element as tinyxml2 parsed it.
bool urdfdom_certainly_accepts(std::string_view document, const tinyxml2::XMLElement* robot, const RawAttribute& raw);

}  // namespace assetlint::urdf
