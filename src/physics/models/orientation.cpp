#include "cue_sim/physics/orientation.hpp"

#include <algorithm>
#include <cmath>

#include "cue_sim/physics/motion.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// The rotation by the vector theta (axis theta / |theta|, angle |theta|).
Eigen::Quaterniond rotationBy(const Eigen::Vector3d& theta)
{
  const double angle = theta.norm();
  if (angle == 0)
    return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, theta / angle));
}

/// rotationAlong over an interval on which w(t) is smooth (linear in time).
Eigen::Quaterniond smoothRotation(const Ball<double>& ball, double t, const PhysicsParams<double>& p)
{
  const double duration = t - ball.time;
  // |w| is convex along a motion state (linear in time, a spin component clamped at zero), so
  // its largest value is at an end.
  const double fastest = std::max(ball.w.norm(), evolve(ball, t, p).w.norm());
  const double wanted = std::ceil(fastest * duration / OrientationLimits::max_substep_angle);
  const int substeps = static_cast<int>(std::clamp(wanted, 1.0, double(OrientationLimits::max_substeps)));
  const double h = duration / substeps;
  // Gauss-Legendre nodes on [0, 1].
  const double c1 = 0.5 - std::sqrt(3.0) / 6, c2 = 0.5 + std::sqrt(3.0) / 6;
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  for (int k = 0; k < substeps; ++k)
  {
    const double t0 = ball.time + k * h;
    const Eigen::Vector3d w1 = evolve(ball, t0 + c1 * h, p).w, w2 = evolve(ball, t0 + c2 * h, p).w;
    // Omega = h/2 (A1 + A2) - sqrt(3)/12 h^2 [A1, A2] with A = [w]x, and [[a]x, [b]x] = [a x b]x.
    const Eigen::Vector3d theta = 0.5 * h * (w1 + w2) - std::sqrt(3.0) / 12 * h * h * w1.cross(w2);
    q = rotationBy(theta) * q;
  }
  return q.normalized();
}
}  // namespace

Eigen::Quaterniond rotationAlong(const Ball<double>& ball, double t, const PhysicsParams<double>& p)
{
  if (!ball.moving() || !(t > ball.time))
    return Eigen::Quaterniond::Identity();
  // The z-spin runs out at a constant rate in every state, without an event when the ball still
  // moves: w(t) has a kink there, which a substep across it would integrate to second order only.
  const double spin_out = ball.time + std::abs(ball.w.z()) / p.spinDecel();
  if (ball.w.z() != 0 && spin_out < t)
    return (smoothRotation(evolve(ball, spin_out, p), t, p) * smoothRotation(ball, spin_out, p)).normalized();
  return smoothRotation(ball, t, p);
}

}  // namespace physics
}  // namespace cue_sim
