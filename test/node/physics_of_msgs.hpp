// What the node's messages say, in the physics core's terms, for tests that compare the node
// with the engine run in the test's own process. Written here, apart from the node's own
// conversions (src/node/ros_conversions.cpp), so that the tests check those rather than share them.
#pragma once

#include <cue_sim/BallState.h>
#include <cue_sim/Shot.h>

#include "cue_sim/physics/cue_strike.hpp"
#include "cue_sim/physics/types.hpp"

/// The strike a cue_sim/Shot asks for (its ball_id aside).
inline cue_sim::physics::CueStrike<double> strikeOfShot(const cue_sim::Shot& shot)
{
  cue_sim::physics::CueStrike<double> strike;
  strike.speed = shot.speed;
  strike.phi = shot.phi;
  strike.theta = shot.theta;
  strike.a = shot.a;
  strike.b = shot.b;
  return strike;
}

/// A ball's centre [m] in the table frame.
inline cue_sim::physics::Vec3<double> centreOf(const cue_sim::BallState& ball)
{
  return {ball.position.x, ball.position.y, ball.position.z};
}
