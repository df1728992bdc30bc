#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace assetlint::urdf {

// Runs urdfdom's parser (what ROS, check_urdf and Isaac's importer use) on a document
// and returns its error messages; empty when urdfdom accepts it.
std::vector<std::string> urdfdom_errors(std::string_view document);

}  // namespace assetlint::urdf
