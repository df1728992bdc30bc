#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace assetlint::urdf {

// Runs urdfdom's parser (what ROS, check_urdf and Isaac's importer use) on a document
// and returns its error messages; empty when urdfdom accepts it.
std::vector<std::string> urdfdom_errors(std::string_view document);

// How many times urdfdom_errors ran in this process (tests check when it is skipped).
std::size_t urdfdom_runs();

}  // namespace assetlint::urdf
