// Coulomb friction at a point contact during an impact, shared by the contact models.
#pragma once

#include <algorithm>

#include "cue_sim/physics/types.hpp"

namespace cue_sim
{
namespace physics
{
/// The friction impulse against `slip`, the tangential velocity of the contact: `limit` (mu times
/// the normal impulse) at most, and never more than the impulse that stops the slip,
/// |slip| / `inverse_mass` (the slip's change per unit impulse).
template <typename S>
Vec3<S> frictionImpulse(const Vec3<S>& slip, S limit, S inverse_mass)
{
  const S speed = slip.norm();
  if (!(speed > zeroSpeed<S>()))
    return Vec3<S>::Zero();
  return -(std::min(limit, speed / inverse_mass) / speed) * slip;
}

}  // namespace physics
}  // namespace cue_sim
