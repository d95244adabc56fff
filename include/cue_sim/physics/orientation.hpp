// A ball's orientation, for pictures: tf, rviz and a camera show stripes and numbers turning as
// a ball rolls or spins. Nothing in the physics depends on it, so the engine never computes it;
// whoever draws the balls carries it along (session::LiveTable does for the node).
//
// The orientation q turns the ball's own frame into the table frame and follows dq/dt = w/2 q
// (w, the angular velocity, in the table frame). Along one motion state w(t) is known in closed
// form (evolve); the rotation over an interval is integrated with the fourth-order Magnus method
// at the two Gauss-Legendre points (Iserles and Norsett, Phil. Trans. R. Soc. A 357, 1999;
// Blanes, Casas, Oteo and Ros, Physics Reports 470, 2009), on substeps over each of which the
// ball turns by at most OrientationLimits::max_substep_angle, split where the z-spin runs out (a
// kink in w). Where w keeps its direction (rolling or sliding straight without side spin) the
// result is exact to rounding; otherwise the error is O(angle^5) a substep: about 1e-9 rad over a
// motion state with side spin, a few 1e-9 over a whole break (test_orientation.cpp and
// test/session/test_ball_orientations.cpp measure it).
#pragma once

#include <Eigen/Geometry>

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/physics_params.hpp"

namespace cue_sim
{
namespace physics
{
struct OrientationLimits
{
  /// [rad] the most a ball turns over one substep (the error a substep is O(its fifth power)).
  static constexpr double max_substep_angle = 0.02;
  /// Substeps an interval gets at most, so that a request's cost stays bounded whatever the spin
  /// (at BallLimits::max_spin for a long stretch the bound on the angle a substep is then exceeded).
  static constexpr int max_substeps = 100000;
};

/// The rotation the ball makes from ball.time to t (t >= ball.time, and no later than the end of
/// its current motion state: evolve's range), in the table frame: q(t) = rotationAlong(...) q.
Eigen::Quaterniond rotationAlong(const Ball<double>& ball, double t, const PhysicsParams<double>& p);

}  // namespace physics
}  // namespace cue_sim
