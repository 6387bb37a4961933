// Small fixed-size types used across Sinew: thin aliases over Eigen.
//
// State arrays are stored flat (std::vector<double>); views reinterpret them
// as arrays of Vec3 (an Eigen::Vector3d is exactly three packed doubles).
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

namespace sinew {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat3 = Eigen::Matrix3d;
template <int N>
using VecN = Eigen::Matrix<double, N, 1>;
template <int N>
using VecNi = Eigen::Matrix<int, N, 1>;

static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");

// View a flat array of doubles (size multiple of 3) as Vec3s.
inline std::span<Vec3> as_vec3(std::vector<double>& v) {
  return {reinterpret_cast<Vec3*>(v.data()), v.size() / 3};
}
inline std::span<const Vec3> as_vec3(const std::vector<double>& v) {
  return {reinterpret_cast<const Vec3*>(v.data()), v.size() / 3};
}

}  // namespace sinew
