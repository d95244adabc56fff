// A ball standing on the cloth, shared by the tests that place balls by hand.
#pragma once

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/physics_params.hpp"

namespace cue_sim
{
namespace physics
{
/// Ball `id` at rest at (x, y) on the cloth (its centre R above it).
inline Ball<double> restingBall(int id, double x, double y, const PhysicsParams<double>& p = PhysicsParams<double>())
{
  Ball<double> b;
  b.id = id;
  b.r = Vec3<double>(x, y, p.ball_radius);
  return b;
}

}  // namespace physics
}  // namespace cue_sim
