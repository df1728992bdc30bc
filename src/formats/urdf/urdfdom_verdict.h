#pragma once
// When urdfdom has to run. urdfdom's parser (a second XML parse with tinyxml 1) is the
// largest single cost of reading a URDF, yet on most files its verdict is already known:
// this recognises, from asset-lint's own parse, documents that urdfdom 3.0's parseURDF
// certainly turns into a model, and documents it certainly refuses for a reason whose
// messages are known (a revolute or prismatic joint without <limit>, the most common
// refusal in real assets). It is conservative: anything it does not model
// exactly (non-ASCII bytes or entities outside comments, DOCTYPE/CDATA, control characters
// in attribute values, numbers outside a plain decimal grammar, ...) answers "not certain",
// and urdfdom runs as before. tests/urdfdom_verdict_test.cpp compares it with urdfdom over every
// corpus file, every fixture and mutated variants of them; the URDF fuzz target does too.
#include <optional>
#include <string>
#include <vector>

#include "formats/xml/scanned_document.h"

namespace assetlint::urdf {

// The messages urdfdom_errors() would return for `doc` (empty: urdfdom accepts it), or
// nullopt when that is not certain and urdfdom has to run.
std::optional<std::vector<std::string>> predicted_urdfdom_errors(const xml::ScannedDocument& doc);

}  // namespace assetlint::urdf
