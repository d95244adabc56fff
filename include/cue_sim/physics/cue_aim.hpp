// From a cue's pose to a strike: which ball the tip meets and where (phi, theta, a, b), for a
// robot that holds a cue rather than choosing the strike's parameters.
#pragma once

#include <string>

#include "cue_sim/physics/cue_strike.hpp"
#include "cue_sim/physics/table_state.hpp"

namespace cue_sim
{
namespace physics
{
/// A cue in the table frame.
struct CueStick
{
  Vec3<double> tip;              ///< the end of the tip, on the cue's axis [m]
  Vec3<double> axis;             ///< the direction of the stroke, butt to tip (any length > 0)
  double shaft_radius = 0.0065;  ///< [m] at the tip (a 13 mm tip): what must clear other balls
  double length = 1.47;          ///< [m] tip to butt (58 in)
};

/// Whether the cue is one: its tip and axis finite, the axis not zero.
bool isCue(const CueStick& cue);

struct CueAim
{
  int ball_id = -1;
  CueStrike<double> strike;  ///< phi, theta, a, b from the pose; speed as given
  double travel = 0;         ///< [m] the tip moves this far along the axis before it touches
};

/// Empty if the cue, moving along its axis, first meets a ball it may strike (within the
/// allowed offsets, no other ball in the way of its tip or through its shaft), and `out` says
/// how; else why not. `balls` are where the balls are now (a snapshot).
std::string aimCue(const std::vector<Ball<double>>& balls, const PhysicsParams<double>& params, const CueStick& cue,
                   double speed, CueAim& out);

/// The cue that makes `strike` on `ball` (the inverse of aimCue): its axis along phi, tilted
/// down by theta, passing the centre where the tip's offsets put it (contactOffset), its tip
/// `gap` metres short of touching.
CueStick cueStickFor(const Ball<double>& ball, const CueStrike<double>& strike, const PhysicsParams<double>& params,
                     double gap);

}  // namespace physics
}  // namespace cue_sim
