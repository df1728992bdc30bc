#pragma once
// When urdfdom has to run. urdfdom's parser (a second XML parse with tinyxml 1) is the
// largest single cost of reading a URDF, yet on most files its verdict is already known:
// this predicate recognises, from asset-lint's own parse, documents that urdfdom 3.0's
// parseURDF certainly turns into a model. It is conservative: anything it does not model
// exactly (non-ASCII bytes or entities outside comments, DOCTYPE/CDATA, control characters
// in attribute values, numbers outside a plain decimal grammar, ...) answers "not certain",
// and urdfdom runs as before. tests/urdfdom_verdict_test.cpp compares it with urdfdom over every
// corpus file, every fixture and mutated variants of them; the URDF fuzz target does too.
#include "formats/xml/scanned_document.h"

namespace assetlint::urdf {

// `doc`: a well-formed document (no errors), what urdfdom would be given.
bool urdfdom_certainly_accepts(const xml::ScannedDocument& doc);

}  // namespace assetlint::urdf
