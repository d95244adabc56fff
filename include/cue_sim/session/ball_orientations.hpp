// Each ball's orientation on the live table, carried along its exact motion event by event
// (physics::rotationAlong between a ball's changes of state), for tf: the node's balls turn as
// they roll and spin.
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
  /// After the balls went from `before` to `after` (the same balls, by id) with every changed
  /// ball changing once, at its new state's time: turns each changed ball along its old motion.
  void turn(const std::vector<physics::Ball<double>>& before, const std::vector<physics::Ball<double>>& after,
            const physics::PhysicsParams<double>& p);
  /// Before `ball`'s state changes at time t (a strike while it moves): turns it on to t.
  void turnTo(const physics::Ball<double>& ball, double t, const physics::PhysicsParams<double>& p);
  /// Each ball of `balls` (states at their own times) as it is at time t.
  std::vector<Eigen::Quaterniond> at(const std::vector<physics::Ball<double>>& balls, double t,
                                     const physics::PhysicsParams<double>& p) const;
  /// A ball new on the table starts unturned; one that left is forgotten.
  void keepOnly(const std::vector<physics::Ball<double>>& balls);

private:
  /// Each ball's orientation at the time its state refers to, by id.
  std::map<int, Eigen::Quaterniond> at_reference_;
};

}  // namespace session
}  // namespace cue_sim
