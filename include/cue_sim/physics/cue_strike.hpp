// The cue's impulse on a ball (Alciatore TP A-30; Leckie and Greenspan 2005, eq. 1, with the tip
// offsets measured on the ball's face seen along the cue, as pooltool measures them since 2025).
#pragma once

#include <string>

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/physics_params.hpp"

namespace cue_sim
{
namespace physics
{
/// A cue strike. Sign conventions (shooter behind the ball, looking along phi):
///  - phi: heading in the table frame, from +x towards +y [rad];
///  - theta: cue elevation above the cloth [rad], 0 = level, in [0, max_elevation];
///  - a: tip offset to the cue's right, b: tip offset along the cue's up, both in units of R and
///    measured on the ball's face perpendicular to the cue's axis (the cue's right is horizontal;
///    its up is perpendicular to the axis and to the right, tilted back by theta from vertical):
///    a = b = 0 is a centre hit, no spin at any elevation.
///    b > 0 is follow (topspin), b < 0 draw; a > 0 (right English) hits right of centre and gives the
///    ball w_z > 0 (counter-clockwise seen from above), and on an elevated cue spin about its
///    heading too, which curves its path while it slides (masse).
template <typename S>
struct CueStrike
{
  S speed = S(0);  ///< V0, the cue's speed at impact [m/s]
  S phi = S(0);
  S theta = S(0);
  S a = S(0);
  S b = S(0);
};

struct CueLimits
{
  static constexpr double max_speed = 12.0;                    ///< [m/s]: a very hard break is about 11 m/s.
  static constexpr double max_offset = 0.5;                    ///< sqrt(a^2 + b^2) [R]: beyond it the tip miscues.
  static constexpr double max_elevation = 1.5707963267948966;  ///< [rad]: vertical (masse).
};

/// Empty if the strike is in range, else which field is out of range and what the range is.
template <typename S>
std::string validateStrike(const CueStrike<S>& strike);

/// The ball's velocity and spin right after the cue leaves it. a and b are where the tip
/// touches the ball; with side offset the ball squirts away from the side struck (TP A-31:
/// 1.9 degrees at a = 0.5 with the default cue). cueImpulse gives the velocity along the cue,
/// down into the slate when the cue is elevated (what the slate then does is the ball-table
/// model's: the `sequential` cue model); applyCueStrike lets the cloth take that vertical part
/// (the `planar` cue model: the ball stays on the cloth). A cue whose axis passes d from the
/// centre touches at d / (1 + r_tip / R): see contactOffset().
/// Where the tip touches the ball, in units of R, for a cue whose axis passes `axis_offset`
/// (units of R) from the ball's centre: the tip's curvature moves the contact point inwards.
template <typename S>
S contactOffset(S axis_offset, const PhysicsParams<S>& p)
{
  return axis_offset / (S(1) + p.cue_tip_radius / p.ball_radius);
}

/// The horizontal angle [rad] by which the ball leaves left (+) of the cue's heading.
template <typename S>
S squirtAngle(S a, const PhysicsParams<S>& p);

template <typename S>
void cueImpulse(Ball<S>& ball, const CueStrike<S>& strike, const PhysicsParams<S>& p);
template <typename S>
void applyCueStrike(Ball<S>& ball, const CueStrike<S>& strike, const PhysicsParams<S>& p);

}  // namespace physics
}  // namespace cue_sim
