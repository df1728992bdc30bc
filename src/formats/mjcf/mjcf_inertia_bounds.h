#pragma once
// What MuJoCo's compiler does to a body's mass and inertia before it simulates them:
// <compiler boundmass>, <compiler boundinertia> and <compiler balanceinertia>.
#include <string>

#include "formats/mjcf/mjcf_values.h"
#include "model/asset.h"

namespace assetlint::mjcf {

// Applies the compiler's floors and balancing to one body's inertial, as MuJoCo compiles it
// (mjCBody::Compile, src/user/user_objects.cc): the mass is raised to boundmass, each principal
// moment to boundinertia, and, with balanceinertia, moments that break A + B >= C become their
// mean. Returns what changed ("" when nothing did).
std::string apply_compiler_bounds(const Compiler& compiler, Inertial& inertial);

}  // namespace assetlint::mjcf
