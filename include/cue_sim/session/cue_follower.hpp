// Following a robot's cue through the samples a tracker gives of its pose (a frame in tf): the
// tip's first touch of a ball between two samples, found exactly (physics/cue_sweep.hpp), its
// velocity there from the cue's recent motion, and the cue and speed a strike takes from them, or
// why there is no strike. Needs no ROS: the node's cue adapter feeds it.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "cue_sim/physics/cue_sweep.hpp"

namespace cue_sim
{
namespace session
{
/// What the follower takes as given.
struct CueFollowerSettings
{
  /// [m/s] along the cue's axis at the touch: slower is a push or a tracker's jitter, not a strike
  /// (0.05 m/s sends a ball about 2 cm; a cue resting against a ball with 0.1 mm of jitter at
  /// 1 kHz reads about 0.01 m/s over the velocity's fit).
  double min_speed = 0.05;
  /// [s] the tip's velocity at a touch is fitted over the samples this long before it, and the one
  /// after it: a line through 2 or 3, a parabola through more (a stroke still accelerating).
  double velocity_window = 0.03;
  /// [s] two samples further apart are not swept: the cue's path between them is not known.
  double max_gap = 0.1;
  /// [m/s] a tip that moved faster between two samples jumped (a tracker's glitch, a frame
  /// re-parented): not swept. Above the fastest break (12 m/s, CueLimits::max_speed).
  double max_tip_speed = 20.0;
};

/// A touch of a ball by the cue's tip.
struct CueContact
{
  int ball_id = -1;
  double stamp = 0;                ///< [s] when the tip touched
  physics::Vec3<double> point;     ///< where the tip touched the ball [m]
  physics::Vec3<double> velocity;  ///< the tip's velocity at the touch [m/s]
  double speed = 0;                ///< its component along the cue's axis [m/s]
  physics::CueStick cue;           ///< the cue at the touch, its tip a hair short of the ball
  std::string refusal;             ///< empty: a strike with `cue` at `speed`; else why not
};

/// What one sample did: a touch if there was one, and a note if the sample was not swept (why).
struct CueStep
{
  std::optional<CueContact> contact;
  std::string note;
};

class CueFollower
{
public:
  explicit CueFollower(const CueFollowerSettings& settings = CueFollowerSettings());

  /// Takes the cue's pose at its stamp, the balls standing where they are then. A sample not after
  /// the last one, or not a pose, is dropped with a note and changes nothing.
  CueStep observe(const physics::CuePose& pose, const std::vector<physics::Ball<double>>& balls,
                  const physics::PhysicsParams<double>& params);

  /// Forgets the samples: the next is swept from nothing.
  void reset();

  const CueFollowerSettings& settings() const { return settings_; }
  /// The samples kept, oldest first.
  const std::deque<physics::CuePose>& samples() const { return samples_; }

private:
  /// The tip's velocity at `stamp`, fitted over the samples kept.
  physics::Vec3<double> tipVelocity(double stamp) const;
  void forgetBefore(double stamp);

  CueFollowerSettings settings_;
  std::deque<physics::CuePose> samples_;
};

}  // namespace session
}  // namespace cue_sim
