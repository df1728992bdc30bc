#pragma once
// Reads an MJCF model (MuJoCo XML, root <mujoco>) with its <include>d files into the model.
// Converts once, here: hinge ranges and frame angles from the <compiler angle> unit
// (degrees unless the file says radian), actuator gains through their gear to joint
// gains, <option timestep> to a rate. Bodies are links; each body's joints connect it to
// its parent body (the world's name is empty); a body without joints is welded to its
// parent by a fixed joint named "<body> (welded)". Mass and inertia that MuJoCo derives
// from geoms are unknown (no Inertial).
//
// Reader diagnostics: parse-error, layer-unresolved (includes), mjcf-unsupported.
#include <memory>

#include "engine/file_system.h"
#include "formats/mjcf/mjcf_sources.h"
#include "formats/read_result.h"

namespace assetlint::mjcf {

ReadResult read_mjcf(std::shared_ptr<const SourceFile> file, const FileSystem& files, const ReadOptions& options = {});

// Whether text is MJCF: its root element is <mujoco> (for *.xml files, which may be anything).
bool looks_like_mjcf(std::string_view text);

}  // namespace assetlint::mjcf
