#pragma once
// Reads a .usda layer (with the local layers it composes, see compose.h) into the model:
// UsdPhysics / PhysxSchema joints, drives, mimic joints, rigid bodies with their mass
// properties, the physics scene and articulation settings. Converts to SI/PhysX units
// here, once: degrees to radians, per-degree gains to per-radian, stage units
// (metersPerUnit, fallback 0.01; kilogramsPerUnit, fallback 1) to metres and kilograms.
//
// Links and joints are named by their prim paths ("/robot/joints/finger_joint").
//
// Reader diagnostics: parse-error, layer-unresolved, stale-schema-attribute (attributes of
// a schema that is not applied), mimic-axis-instance (PhysxMimicJointAPI:<not rotX|Y|Z>).
#include <memory>

#include "engine/file_system.h"
#include "formats/read_result.h"
#include "formats/usda/compose.h"

namespace assetlint::usda {

ReadResult read_usda(std::shared_ptr<const SourceFile> file, const FileSystem& files,
                     const ComposeOptions& options = {});

// The model of an already composed stage (takes the stage's sources and diagnostics).
ReadResult read_stage(Stage stage);

}  // namespace assetlint::usda
