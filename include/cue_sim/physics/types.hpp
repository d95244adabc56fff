// Vector aliases and numeric helpers shared by the physics core. The core is templated on the
// scalar type S so the same engine runs in double (production) and long double (reference).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>

namespace cue_sim
{
namespace physics
{
template <typename S>
using Vec3 = Eigen::Matrix<S, 3, 1>;
template <typename S>
using Vec2 = Eigen::Matrix<S, 2, 1>;

template <typename S>
constexpr S infinity()
{
  return std::numeric_limits<S>::infinity();
}

/// Speeds (m/s) and spins (rad/s) below this are zero: far below any physical speed (the
/// stability suite goes down to 1e-9 m/s), yet above the round-off of a collision at 10 m/s.
template <typename S>
constexpr S zeroSpeed()
{
  return S(64) * std::numeric_limits<S>::epsilon();
}

template <typename S>
bool isFinite(const Vec3<S>& v)
{
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

}  // namespace physics
}  // namespace cue_sim
