// Two balls on the cloth meeting, as a FrictionalImpact (Mathavan, Jackson and Parkin 2014).
// Private to the ball-ball models.
//
// The impulses: P along the line of centres, the friction between the balls (2 components in
// the contact's tangent plane: horizontal and vertical) and the cloth's friction under each ball
// (2 horizontal components each). Both balls stay level: the cloth takes every vertical impulse.
// The vertical friction between the balls presses one of them into the cloth, whose push back
// loads the friction under it; the other is lifted, and nothing loads the cloth under it.
#pragma once

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/physics_params.hpp"
#include "physics/models/frictional_impact.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
using BallPairImpact = FrictionalImpact<S, 3, 2>;

/// The impact of `a` and `b` touching along the unit horizontal `normal` (from a to b), with
/// friction `mu_ball` between them and `mu_cloth` under each. Bodies: a, then b.
template <typename S>
typename BallPairImpact<S>::Setup ballPairImpact(const Ball<S>& a, const Ball<S>& b, const Vec3<S>& normal,
                                                 const PhysicsParams<S>& p, S mu_ball, S mu_cloth);

}  // namespace physics
}  // namespace cue_sim
