// Each ball's orientation on the live table, carried along its exact motion (physics::
// rotationAlong between a ball's changes of state), for tf: the node's balls turn as they roll
// and spin. Each ball's orientation is kept at the last time it was asked for, so that a tick
// costs the turning since the last tick, not since the ball's last event.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <vector>

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/physics_params.hpp"

namespace cue_sim
{
namespace session
{
class BallOrientations
{
public:
  /// Takes the balls' states as they are now. Call it after every change of state (an event, a
  /// strike, an edit), before the next: a ball whose state changed kept its old motion until the
  /// time its new state refers to, and is turned on to then. A ball new on the table starts
  /// unturned; one that left is forgotten.
  void sync(const std::vector<physics::Ball<double>>& balls, const physics::PhysicsParams<double>& p);
  /// Each ball of `balls` (synced) as it is at time t, in order.
  std::vector<Eigen::Quaterniond> advance(const std::vector<physics::Ball<double>>& balls, double t,
                                          const physics::PhysicsParams<double>& p);

private:
  /// A ball's orientation q at time t, while it moves as `state` says (t >= state.time, or the
  /// ball does not move).
  struct Track
  {
    physics::Ball<double> state;
    double t = 0;
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  };
  static Eigen::Quaterniond turnedTo(const Track& track, double t, const physics::PhysicsParams<double>& p);

  std::map<int, Track> tracks_;  ///< by ball id
};

}  // namespace session
}  // namespace cue_sim
