// table_node's control services: what is on the table (~rack, ~reset, ~set_state) and how
// its time runs (~pause, ~step). Each validates its request in full before changing anything.
#include <sstream>

#include "cue_sim/physics/rack.hpp"
#include "node/ros_conversions.hpp"
#include "node/table_node.hpp"

namespace cue_sim
{
using physics::Ball;
using PhysicsState = physics::TableState<double>;

bool TableNode::onRack(Rack::Request& request, Rack::Response& response)
{
  const double R = engine_->params().ball_radius;
  PhysicsState rack;
  response.success = false;
  if (request.layout == "custom")
  {
    if (request.ids.size() != request.positions.size())
    {
      response.message = "ids and positions must have the same length (got " + std::to_string(request.ids.size()) +
                         " and " + std::to_string(request.positions.size()) + ")";
      return true;
    }
    for (std::size_t i = 0; i < request.ids.size(); ++i)
    {
      if (request.ids[i] < 0 || request.ids[i] > 15)
      {
        response.message = "ids[" + std::to_string(i) + "] = " + std::to_string(request.ids[i]) + " is not in [0, 15]";
        return true;
      }
      Ball<double> b;
      b.id = request.ids[i];
      b.r = physics::Vec3<double>(request.positions[i].x, request.positions[i].y, R);
      rack.balls.push_back(b);
    }
  }
  else
  {
    if (!request.ids.empty() || !request.positions.empty())
    {
      response.message = "ids and positions are for layout 'custom' only";
      return true;
    }
    try
    {
      physics::RackOptions options;
      options.gap = config_.rack_gap;
      rack = physics::rackLayout<double>(request.layout, *table_, R, options);
    }
    catch (const std::invalid_argument&)
    {
      response.message = "layout must be one of eight, nine, empty, custom; got '" + request.layout + "'";
      return true;
    }
  }
  const std::string why = engine_->whyInvalid(rack);
  if (!why.empty())
  {
    response.message = "positions: " + why;
    return true;
  }
  const ros::Time stamp = ros::Time::now();
  catchUp(stamp);
  setRack(rack, stamp);
  response.success = true;
  response.message = "racked '" + request.layout + "': " + std::to_string(rack.balls.size()) + " balls";
  return true;
}

bool TableNode::onReset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response)
{
  const ros::Time stamp = ros::Time::now();
  catchUp(stamp);
  setRack(last_rack_, stamp);
  response.success = true;
  response.message = "back to the last rack (" + std::to_string(last_rack_.balls.size()) + " balls)";
  return true;
}

bool TableNode::onSetState(SetState::Request& request, SetState::Response& response)
{
  PhysicsState state;
  std::string why = fromBallStateMsgs(request.balls, *table_, engine_->params().ball_radius, state);
  if (why.empty() && state.balls.empty())
    why = "balls: give at least one ball";
  if (why.empty())
  {
    why = engine_->whyInvalid(state);
    if (!why.empty())
      why = "balls: " + why;
  }
  response.success = why.empty();
  response.message = why;
  if (!why.empty())
    return true;
  const ros::Time stamp = ros::Time::now();
  catchUp(stamp);
  clock_.restart(stamp);
  live_->reset(state);  // every ball at time 0: now
  snapshot_at_rest_ = false;
  response.stamp = stamp;
  publishMarkers();
  response.message = "placed " + std::to_string(state.balls.size()) + " balls" +
                     (state.anyMoving() ? ", some moving" : ", all at rest");
  return true;
}

bool TableNode::onPause(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response)
{
  const ros::Time stamp = ros::Time::now();
  catchUp(stamp);
  paused_ = request.data;
  // With sim time the clock itself stops; otherwise physics stops following ROS time.
  if (!sim_time_)
    clock_.setRate(stamp, paused_ ? 0 : config_.real_time_factor);
  response.success = true;
  response.message = paused_ ? "paused" : "running";
  return true;
}

bool TableNode::onStep(Step::Request& request, Step::Response& response)
{
  response.success = false;
  if (!paused_)
  {
    response.message = "not paused: a step advances a paused table (~pause first)";
    return true;
  }
  if (!(request.duration > 0 && request.duration <= 60))
  {
    std::ostringstream why;
    why << "duration must be in (0, 60] s, got " << request.duration;
    response.message = why.str();
    return true;
  }
  if (sim_time_)
  {
    // The clock moves by exactly the duration, in publish periods, publishing along the way.
    const ros::Time until = sim_now_ + ros::Duration(request.duration);
    const ros::Duration period(1.0 / config_.publish_rate);
    while (sim_now_ + period < until)
      advanceSimClock(period);
    advanceSimClock(until - sim_now_);
  }
  else
  {
    const ros::Time stamp = ros::Time::now();
    clock_.step(stamp, request.duration);
    catchUp(stamp);
  }
  response.success = true;
  response.stamp = ros::Time::now();
  std::ostringstream message;
  message << "stepped " << request.duration << " s";
  response.message = message.str();
  return true;
}

}  // namespace cue_sim
