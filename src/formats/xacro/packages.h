#pragma once
// `$(find pkg)`: the directory of the ROS package named `pkg`, the one whose package.xml
// says <name>pkg</name>. Looked for in the package that holds the including file and the
// directories around it, in the checked tree, then in ROS_PACKAGE_PATH.
#include <optional>
#include <string>

namespace assetlint::xacro {

std::optional<std::string> find_ros_package(const std::string& name, const std::string& from_file, const std::string& root);

// The <name> of a package.xml text (empty when it has none).
std::string package_name(const std::string& package_xml);

}  // namespace assetlint::xacro
