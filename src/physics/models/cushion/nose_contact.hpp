// Where a cushion's nose, cushion_height above the cloth, touches a ball against it: alpha =
// asin(h/R - 1) above the ball's equator (Han 2005; Mathavan 2010). Shared by the cushion models.
#pragma once

#include <algorithm>
#include <cmath>

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/physics_params.hpp"
#include "cue_sim/physics/types.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
struct NoseContact
{
  /// `cushion_normal`: the cushion's unit xy normal into play.
  NoseContact(const Vec3<S>& cushion_normal, const PhysicsParams<S>& p)
  {
    const S R = p.ball_radius;
    sin_alpha = std::clamp(p.cushion_height / R - S(1), S(-1), S(1));
    cos_alpha = std::sqrt(S(1) - sin_alpha * sin_alpha);
    offset = -R * cos_alpha * cushion_normal + R * sin_alpha * Vec3<S>::UnitZ();
    normal = cos_alpha * cushion_normal - sin_alpha * Vec3<S>::UnitZ();
  }

  /// The ball's closing speed on the nose along the contact normal (a sphere's spin adds
  /// nothing along it); > 0 while closing.
  S approach(const Ball<S>& ball) const { return -ball.v.dot(normal); }
  /// The velocity of the ball's surface at the nose, in the contact's tangent plane.
  Vec3<S> slip(const Ball<S>& ball) const
  {
    const Vec3<S> at_nose = ball.v + ball.w.cross(offset);
    return at_nose - at_nose.dot(normal) * normal;
  }
  /// Applies an impulse at the nose: the ball's velocity and spin change, and the cloth takes
  /// the part pressing the ball into it.
  void push(Ball<S>& ball, const Vec3<S>& impulse, const PhysicsParams<S>& p) const
  {
    const S m = p.ball_mass, R = p.ball_radius;
    ball.v += impulse / m;
    ball.v.z() = S(0);
    ball.w += offset.cross(impulse) / (S(0.4) * m * R * R);
  }

  S sin_alpha, cos_alpha;
  Vec3<S> offset;  ///< from the ball's centre to the contact
  Vec3<S> normal;  ///< the contact normal, nose -> centre
};

}  // namespace physics
}  // namespace cue_sim
