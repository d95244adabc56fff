#include "node/table_services.hpp"

#include <visualization_msgs/Marker.h>

#include "cue_sim/ExecutedShot.h"
#include "node/game_messages.hpp"
#include "node/ros_conversions.hpp"
#include "node/shot_markers.hpp"

namespace cue_sim
{
namespace
{
/// How long the cue drawn at a strike stays in rviz [s].
constexpr double kCueMarkerLifetime = 1.5;

template <typename Response>
void answer(const session::Outcome& outcome, Response& response)
{
  response.success = outcome.success;
  response.message = outcome.message;
}
}  // namespace

TableServices::TableServices(ros::NodeHandle& private_node, SharedTable& shared, const NodeParameters& parameters)
  : shared_(shared), parameters_(parameters), cue_frames_(parameters.table_frame, parameters.tf_timeout)
{
  cue_publisher_ = private_node.advertise<visualization_msgs::Marker>("cue", 1, true);
  shot_publisher_ = private_node.advertise<cue_sim::ExecutedShot>("shots", 100, true);
  services_ = {
      private_node.advertiseService("strike", &TableServices::onStrike, this),
      private_node.advertiseService("strike_cue", &TableServices::onStrikeCue, this),
      private_node.advertiseService("rack", &TableServices::onRack, this),
      private_node.advertiseService("reset", &TableServices::onReset, this),
      private_node.advertiseService("set_state", &TableServices::onSetState, this),
      private_node.advertiseService("place_ball", &TableServices::onPlaceBall, this),
      private_node.advertiseService("remove_ball", &TableServices::onRemoveBall, this),
      private_node.advertiseService("pause", &TableServices::onPause, this),
      private_node.advertiseService("step", &TableServices::onStep, this),
  };
}

void TableServices::publishStrike(const session::Shot& requested, const session::StrikeOutcome& outcome,
                                  const char* source, const geometry_msgs::PoseStamped& cue)
{
  const ros::Time stamp = toRosTime(outcome.stamp);
  cue_publisher_.publish(cueStickMarker(outcome.cue, parameters_.table_frame, stamp, kCueMarkerLifetime));
  ExecutedShot played;
  played.header.stamp = stamp;
  played.header.frame_id = parameters_.table_frame;
  played.source = source;
  played.requested = toShotMsg(requested);
  played.executed = toShotMsg(outcome.executed);
  played.noise = parameters_.table.noise_enabled;
  played.time_to_rest = outcome.time_to_rest;
  played.num_events = static_cast<uint32_t>(outcome.num_events);
  played.cue = cue;
  played.ruling = toRulingMsg(outcome.ruling, outcome.refereed);
  shot_publisher_.publish(played);
}

session::StrikeOutcome TableServices::strike(const session::Shot& shot, const char* source)
{
  session::StrikeOutcome outcome;
  {
    std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
    outcome = shared_.live->strike(shot, toStamp(shared_.now()));
  }
  if (outcome.success)
    publishStrike(shot, outcome, source, geometry_msgs::PoseStamped());
  return outcome;
}

bool TableServices::onStrike(Strike::Request& request, Strike::Response& response)
{
  const Shot shot = shotOf(request);
  const session::StrikeOutcome outcome = strike(toSessionShot(shot), "strike");
  answer(outcome, response);
  response.executed = outcome.success ? toShotMsg(outcome.executed) : shot;
  response.stamp = toRosTime(outcome.stamp);
  response.time_to_rest = outcome.time_to_rest;
  response.num_events = static_cast<uint32_t>(outcome.num_events);
  response.ball_velocity = toVector3(outcome.ball_velocity);
  response.ball_angular_velocity = toVector3(outcome.ball_angular_velocity);
  response.ruling = toRulingMsg(outcome.ruling, outcome.refereed);
  return true;
}

session::StrikeOutcome TableServices::strikeWithCue(const physics::CueStick& cue, double speed,
                                                    std::optional<ros::Time> stamp, const char* source,
                                                    const geometry_msgs::PoseStamped& pose, session::Shot& aimed)
{
  session::StrikeOutcome outcome;
  {
    std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
    outcome = shared_.live->strikeWithCue(cue, speed, toStamp(stamp ? *stamp : shared_.now()), aimed);
  }
  if (outcome.success)
    publishStrike(aimed, outcome, source, pose);
  return outcome;
}

bool TableServices::onStrikeCue(StrikeCue::Request& request, StrikeCue::Response& response)
{
  physics::CueStick cue;
  response.message = cue_frames_.toTableFrame(request.cue, cue);  // outside the lock: it may wait for tf
  if (!response.message.empty())
    return true;
  session::Shot aimed;
  const session::StrikeOutcome outcome =
      strikeWithCue(cue, request.speed, std::nullopt, "strike_cue", request.cue, aimed);
  answer(outcome, response);
  response.shot = toShotMsg(aimed);
  response.ruling = toRulingMsg(outcome.ruling, outcome.refereed);
  if (!outcome.success)
    return true;
  response.executed = toShotMsg(outcome.executed);
  response.stamp = toRosTime(outcome.stamp);
  response.time_to_rest = outcome.time_to_rest;
  response.num_events = static_cast<uint32_t>(outcome.num_events);
  return true;
}

bool TableServices::onRack(Rack::Request& request, Rack::Response& response)
{
  session::RackRequest rack;
  rack.layout = request.layout;
  rack.ids.assign(request.ids.begin(), request.ids.end());
  for (const auto& p : request.positions)
    rack.positions.emplace_back(p.x, p.y);
  rack.jitter = request.jitter;
  rack.seed = request.seed;
  std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
  response.stamp = shared_.now();
  answer(shared_.live->rack(rack, toStamp(response.stamp)), response);
  return true;
}

bool TableServices::onReset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response)
{
  std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
  answer(shared_.live->reset(toStamp(shared_.now())), response);
  return true;
}

bool TableServices::onSetState(SetState::Request& request, SetState::Response& response)
{
  std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
  response.stamp = shared_.now();
  answer(shared_.live->setState(toBallInputs(request.balls), toStamp(response.stamp)), response);
  return true;
}

bool TableServices::onPlaceBall(PlaceBall::Request& request, PlaceBall::Response& response)
{
  std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
  response.stamp = shared_.now();
  answer(shared_.live->placeBall(toBallInput(request.ball), toStamp(response.stamp)), response);
  return true;
}

bool TableServices::onRemoveBall(RemoveBall::Request& request, RemoveBall::Response& response)
{
  std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
  response.stamp = shared_.now();
  answer(shared_.live->removeBall(request.ball_id, toStamp(response.stamp)), response);
  return true;
}

bool TableServices::onPause(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response)
{
  std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
  answer(shared_.live->pause(request.data, toStamp(shared_.now())), response);
  return true;
}

bool TableServices::onStep(Step::Request& request, Step::Response& response)
{
  std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
  response.stamp = shared_.now();
  answer(shared_.live->step(request.duration, toStamp(response.stamp)), response);
  return true;
}

}  // namespace cue_sim
