// A ball-cushion impact as a FrictionalImpact (Mathavan, Jackson and Parkin 2010). Private to the
// cushion models.
//
// The impulses: P at the nose (along the contact normal, nose -> centre), the friction there (2
// components in the nose's tangent plane) and the friction at the cloth (2 horizontal
// components). The cloth's normal push takes whatever vertical impulse the nose gives, so the
// ball stays level, and that push, friction's part included, is what presses the cloth.
#pragma once

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/physics_params.hpp"
#include "physics/models/frictional_impact.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
using CushionImpact = FrictionalImpact<S, 2, 1>;

/// The impact of `ball` with a cushion whose unit xy normal into play is `normal`: the nose
/// touches the ball alpha = asin(cushion_height/R - 1) above its equator, with friction
/// `mu_nose` there and `mu_cloth` at the cloth.
template <typename S>
typename CushionImpact<S>::Setup cushionImpact(const Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p,
                                               S mu_nose, S mu_cloth);

}  // namespace physics
}  // namespace cue_sim
