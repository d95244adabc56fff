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
  /// (0.05 m/s sends a ball about 2 cm). With 0.1 mm of a tracker's jitter the velocity's fit has
  /// a standard deviation of 0.0085 m/s at 1 kHz (a cue resting against a ball reads six of them
  /// under this) and 0.038 m/s at 100 Hz, where a noisy tracker wants a longer velocity_window
  /// (0.05 s: 0.014 m/s) or a higher minimum. A robot's own tf (its joints' encoders) has
  /// micrometres, not tenths of a millimetre.
  double min_speed = 0.05;
  /// [m] a ball touched is not touched again until the tip's sphere has drawn this far clear of it:
  /// a cue resting against a ball with a tracker's jitter touches it once, not at every sample,
  /// and a tip that stays on a ball it struck does not strike it twice. Beyond a tracker's jitter
  /// (tenths of a millimetre), short of any draw back for another stroke (centimetres).
  double rearm_distance = 0.002;
  /// [s] the tip's velocity at a touch is fitted over the samples this long before it (at least
  /// three), a parabola (a stroke still accelerating) extrapolated to the touch, less than a
  /// sample on. Samples after the touch are not used: a real cue is slowed by the ball, and a
  /// robot's follow-through starts there. A cue followed for less than this before it touches a
  /// ball strikes nothing (its speed from two samples a millisecond apart, with 0.1 mm of jitter,
  /// has a standard deviation of 0.14 m/s).
  double velocity_window = 0.03;
  /// [s] two samples further apart are not swept: the cue's path between them is not known.
  double max_gap = 0.1;
  /// [m/s] a tip that moved faster between two samples jumped (a tracker's glitch, a frame
  /// re-parented): not swept. Above the fastest break (12 m/s, CueLimits::max_speed).
  double max_tip_speed = 20.0;

  /// Empty if every setting is within its range (cueFollowerFields), else which is not and why.
  std::string whyInvalid() const;
};

/// One setting as the node's parameters (~cue/<name>) and the docs name it: its unit and range.
struct CueFollowerField
{
  const char* name;
  double CueFollowerSettings::*member;
  const char* unit;
  double min, max;  ///< accepted, bounds included
  const char* description;
};

/// Every setting of CueFollowerSettings, declared once: the node reads and checks them from this.
const std::vector<CueFollowerField>& cueFollowerFields();

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

  /// Forgets the samples and the balls touched: the next sample is swept from nothing.
  void reset();

  const CueFollowerSettings& settings() const { return settings_; }
  /// The samples kept, oldest first.
  const std::deque<physics::CuePose>& samples() const { return samples_; }

private:
  /// The touch made into a contact: where, how fast, the strike's cue, or why no strike.
  CueContact contactOf(const physics::CueTouch& touch, const std::vector<physics::Ball<double>>& balls,
                       const physics::PhysicsParams<double>& params) const;
  /// The tip's velocity at `stamp`, fitted over the samples kept.
  physics::Vec3<double> tipVelocity(double stamp) const;
  void forgetBefore(double stamp);
  /// Follows the cue afresh from `pose`.
  void restart(const physics::CuePose& pose);
  /// Forgets the balls touched that the tip at `pose` is clear of.
  void rearm(const physics::CuePose& pose, const std::vector<physics::Ball<double>>& balls,
             const physics::PhysicsParams<double>& params);

  CueFollowerSettings settings_;
  std::deque<physics::CuePose> samples_;
  /// The balls touched that the tip has not drawn clear of since (rearm_distance).
  std::vector<int> touched_;
  /// [s] the stamp from which the cue has been followed without a gap or a jump.
  double following_since_ = 0;
};

}  // namespace session
}  // namespace cue_sim
