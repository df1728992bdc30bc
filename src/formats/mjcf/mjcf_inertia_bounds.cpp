#include "formats/mjcf/mjcf_inertia_bounds.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <string>
#include <vector>

#include "util/numbers.h"

namespace assetlint::mjcf {
namespace {

std::string moments_text(const Eigen::Vector3d& m) {
  return fmt::format("[{}, {}, {}] kg·m²", format_number(m[0], 4), format_number(m[1], 4), format_number(m[2], 4));
}

bool breaks_triangle(const Eigen::Vector3d& m) {
  return m[0] + m[1] < m[2] || m[0] + m[2] < m[1] || m[1] + m[2] < m[0];
}

}  // namespace

std::string apply_compiler_bounds(const Compiler& compiler, Inertial& inertial) {
  std::vector<std::string> changes;
  if (inertial.mass.value < compiler.boundmass) {
    changes.push_back(fmt::format("its mass {} kg is raised to boundmass {} kg", format_number(inertial.mass.value, 4),
                                  format_number(compiler.boundmass, 4)));
    inertial.mass.value = compiler.boundmass;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertial.inertia);
  if (solver.info() != Eigen::Success) return {};
  const Eigen::Vector3d written = solver.eigenvalues();
  Eigen::Vector3d moments = written.cwiseMax(compiler.boundinertia);
  if (moments != written)
    changes.push_back(fmt::format("its principal moments {} are raised to boundinertia {} kg·m²", moments_text(written),
                                  format_number(compiler.boundinertia, 4)));
  if (compiler.balanceinertia && breaks_triangle(moments)) {
    const double mean = moments.sum() / 3.0;
    changes.push_back(fmt::format("its principal moments {} break A + B ≥ C, and balanceinertia sets each to their mean "
                                  "{} kg·m²",
                                  moments_text(moments), format_number(mean, 4)));
    moments.setConstant(mean);
  }
  if (moments != written)
    inertial.inertia = solver.eigenvectors() * moments.asDiagonal() * solver.eigenvectors().transpose();
  std::string text;
  for (std::size_t i = 0; i < changes.size(); ++i) text += (i == 0 ? "" : "; ") + changes[i];
  return text;
}

}  // namespace assetlint::mjcf
