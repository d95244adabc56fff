// Where a moving cue's tip first touches a ball between two samples of the cue's pose, in closed
// form: for a robot whose cue a tracker follows (a frame in tf), not a strike request.
#pragma once

#include <optional>
#include <vector>

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/cue_aim.hpp"
#include "cue_sim/physics/physics_params.hpp"

namespace cue_sim
{
namespace physics
{
/// The cue's pose at an instant [s, on the table's clock].
struct CuePose
{
  double stamp = 0;
  CueStick cue;
};

/// The tip's first touch of a ball while the cue moves between two poses.
struct CueTouch
{
  int ball_id = -1;
  double stamp = 0;     ///< [s] when the tip touches
  double fraction = 0;  ///< of the way from the first pose to the second, in [0, 1]
  CueStick cue;         ///< the cue at that instant
};

/// The centre of the tip's sphere: the tip's curvature (cue_tip_radius), its front at the tip's
/// end. Every strike the cue may make touches within the tip's cap (at most 0.5 r_tip from the
/// axis, inside a 13 mm tip), where the cap is this sphere.
Vec3<double> tipCentre(const CueStick& cue, const PhysicsParams<double>& params);

/// The cue at `fraction` of the way from `from` to `to`: the tip's sphere's centre on the straight
/// segment between its two places, at a constant rate, and the axis turned in proportion
/// (normalised linear interpolation). Between samples a millisecond apart the tip's path departs
/// from that segment by under a micrometre for any stroke a robot makes.
CueStick cueBetween(const CuePose& from, const CuePose& to, double fraction, const PhysicsParams<double>& params);

/// The first ball in play that the tip's sphere touches as the cue moves from `from` to `to`, or
/// none. The balls stand where `balls` has them (a snapshot). A ball the sphere touches or overlaps
/// at `from` already is not touched again: the tip rests against it or is in it, which the
/// follower of the cue reports. The touch is the smaller root of a quadratic in the fraction of
/// the way, taken in its cancellation-free form, so that a creeping tip (a micrometre a sample)
/// finds it as exactly as a fast one.
std::optional<CueTouch> firstTouch(const CuePose& from, const CuePose& to, const std::vector<Ball<double>>& balls,
                                   const PhysicsParams<double>& params);

}  // namespace physics
}  // namespace cue_sim
