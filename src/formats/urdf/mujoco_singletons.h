#pragma once
// The children MuJoCo's URDF importer reads at most once per parent. It looks each of them up
// with one helper that throws "repeated element" when the name occurs twice, so a URDF with,
// say, two <inertial> in one link or four <material> in one <visual> does not load in MuJoCo,
// while urdfdom takes the first and ignores the rest.
#include <vector>

#include "engine/diagnostic.h"
#include "formats/xml/scanned_document.h"

namespace assetlint::urdf {

// The finding of rule urdf-repeated-element, at the first repetition (where MuJoCo stops), with
// every other parent that repeats a child listed in notes; empty when nothing repeats.
std::vector<Diagnostic> repeated_singletons(const xml::ScannedDocument& doc);

}  // namespace assetlint::urdf
