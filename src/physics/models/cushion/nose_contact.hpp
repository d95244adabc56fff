// Where a cushion's nose, cushion_height above the cloth, touches a ball against it: alpha =
// asin(h/R - 1) above the ball's equator (Han 2005; Mathavan 2010). Shared by the cushion models.
#pragma once

#include <algorithm>
#include <cmath>

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

  S sin_alpha, cos_alpha;
  Vec3<S> offset;  ///< from the ball's centre to the contact
  Vec3<S> normal;  ///< the contact normal, nose -> centre
};

}  // namespace physics
}  // namespace cue_sim
