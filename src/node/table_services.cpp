// table_node's services: each converts its request, calls the live table under the lock (or,
// for predictions, takes its starting point under the lock and runs outside it), and converts
// the answer. What is checked and why a request is refused is the live table's.
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <cmath>

#include "cue_sim/ExecutedShot.h"
#include "node/ros_conversions.hpp"
#include "node/shot_markers.hpp"
#include "node/table_node.hpp"

namespace cue_sim
{
namespace
{
/// How long the cue drawn at a strike stays in rviz [s].
constexpr double kCueMarkerLifetime = 1.5;

/// The heavy requests' thread runs below the publishing thread's priority.
void lowerPriorityOnce()
{
  thread_local bool lowered = false;
  if (!lowered)
    lowerThisThreadsPriority();
  lowered = true;
}

template <typename Response>
void answer(const session::Outcome& outcome, Response& response)
{
  response.success = outcome.success;
  response.message = outcome.message;
}
}  // namespace

void TableNode::advertiseServices(ros::NodeHandle& private_node)
{
  ros::AdvertiseServiceOptions predict, batch;
  predict.init<Predict::Request, Predict::Response>(private_node.resolveName("predict"),
                                                    [this](Predict::Request& q, Predict::Response& r) {
                                                      lowerPriorityOnce();
                                                      return onPredict(q, r);
                                                    });
  batch.init<PredictBatch::Request, PredictBatch::Response>(
      private_node.resolveName("predict_batch"), [this](PredictBatch::Request& q, PredictBatch::Response& r) {
        lowerPriorityOnce();
        return onPredictBatch(q, r);
      });
  predict.callback_queue = batch.callback_queue = &heavy_queue_;
  services_ = {
      private_node.advertiseService("strike", &TableNode::onStrike, this),
      private_node.advertiseService("strike_cue", &TableNode::onStrikeCue, this),
      private_node.advertiseService(predict),
      private_node.advertiseService(batch),
      private_node.advertiseService("rack", &TableNode::onRack, this),
      private_node.advertiseService("reset", &TableNode::onReset, this),
      private_node.advertiseService("set_state", &TableNode::onSetState, this),
      private_node.advertiseService("place_ball", &TableNode::onPlaceBall, this),
      private_node.advertiseService("remove_ball", &TableNode::onRemoveBall, this),
      private_node.advertiseService("pause", &TableNode::onPause, this),
      private_node.advertiseService("step", &TableNode::onStep, this),
  };
}

session::StrikeOutcome TableNode::strikeLive(const session::Shot& shot, const char* source)
{
  session::StrikeOutcome outcome;
  {
    std::lock_guard<std::mutex> lock(table_mutex_);
    outcome = table_->strike(shot, toStamp(now()));
  }
  if (!outcome.success)
    return outcome;
  const ros::Time stamp = toRosTime(outcome.stamp);
  cue_publisher_.publish(cueStickMarker(outcome.cue, parameters_.table_frame, stamp, kCueMarkerLifetime));
  ExecutedShot played;
  played.header.stamp = stamp;
  played.header.frame_id = parameters_.table_frame;
  played.source = source;
  played.requested = toShotMsg(shot);
  played.executed = toShotMsg(outcome.executed);
  played.noise = parameters_.table.noise_enabled;
  played.time_to_rest = outcome.time_to_rest;
  played.num_events = static_cast<uint32_t>(outcome.num_events);
  shot_publisher_.publish(played);
  return outcome;
}

bool TableNode::onStrike(Strike::Request& request, Strike::Response& response)
{
  const Shot shot = shotOf(request);
  const session::StrikeOutcome outcome = strikeLive(toSessionShot(shot), "strike");
  answer(outcome, response);
  response.executed = outcome.success ? toShotMsg(outcome.executed) : shot;
  response.stamp = toRosTime(outcome.stamp);
  response.time_to_rest = outcome.time_to_rest;
  response.num_events = static_cast<uint32_t>(outcome.num_events);
  response.ball_velocity = toVector3(outcome.ball_velocity);
  response.ball_angular_velocity = toVector3(outcome.ball_angular_velocity);
  return true;
}

std::string TableNode::cueInTableFrame(const geometry_msgs::PoseStamped& pose, physics::CueStick& cue)
{
  const auto& q = pose.pose.orientation;
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (!(std::abs(norm - 1) < 1e-3))
    return "cue.pose.orientation must be a unit quaternion (its norm is " + std::to_string(norm) + ")";
  const auto& p = pose.pose.position;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    return "cue.pose.position must be finite";
  if (pose.header.frame_id.empty())
    return "cue.header.frame_id is empty: give the frame of the cue pose";
  geometry_msgs::PoseStamped in_table = pose;
  if (pose.header.frame_id != parameters_.table_frame)
  {
    try
    {
      const geometry_msgs::TransformStamped t = tf_buffer_->lookupTransform(
          parameters_.table_frame, pose.header.frame_id, ros::Time(0), ros::Duration(parameters_.tf_timeout));
      tf2::doTransform(pose, in_table, t);
    }
    catch (const tf2::TransformException& e)
    {
      return "cannot transform the cue pose from '" + pose.header.frame_id + "' to '" + parameters_.table_frame +
             "' (waited ~tf_timeout = " + std::to_string(parameters_.tf_timeout) + " s): " + e.what();
    }
  }
  const auto& r = in_table.pose.orientation;
  cue.tip = physics::Vec3<double>(in_table.pose.position.x, in_table.pose.position.y, in_table.pose.position.z);
  cue.axis = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized() * physics::Vec3<double>::UnitX();
  return "";
}

bool TableNode::onStrikeCue(StrikeCue::Request& request, StrikeCue::Response& response)
{
  response.success = false;
  physics::CueStick cue;
  response.message = cueInTableFrame(request.cue, cue);  // outside the lock: it may wait for tf
  if (!response.message.empty())
    return true;
  session::StrikeOutcome outcome;
  session::Shot aimed;
  {
    std::lock_guard<std::mutex> lock(table_mutex_);
    outcome = table_->strikeWithCue(cue, request.speed, toStamp(now()), aimed);
  }
  answer(outcome, response);
  response.shot = toShotMsg(aimed);
  if (!outcome.success)
    return true;
  response.executed = toShotMsg(outcome.executed);
  response.stamp = toRosTime(outcome.stamp);
  response.time_to_rest = outcome.time_to_rest;
  response.num_events = static_cast<uint32_t>(outcome.num_events);
  cue_publisher_.publish(cueStickMarker(outcome.cue, parameters_.table_frame, response.stamp, kCueMarkerLifetime));
  ExecutedShot played;
  played.header.stamp = response.stamp;
  played.header.frame_id = parameters_.table_frame;
  played.source = "strike_cue";
  played.requested = response.shot;
  played.executed = response.executed;
  played.noise = parameters_.table.noise_enabled;
  played.time_to_rest = outcome.time_to_rest;
  played.num_events = response.num_events;
  played.cue = request.cue;
  shot_publisher_.publish(played);
  return true;
}

bool TableNode::onPredict(Predict::Request& request, Predict::Response& response)
{
  heavy_done_ = true;
  session::PredictionStart start;
  std::string why = session::whyBadSamplePeriod(request.sample_period);
  if (why.empty())
  {
    std::lock_guard<std::mutex> lock(table_mutex_);
    why = table_->predictionStart(toBallInputs(request.balls), toStamp(now()), start);
  }
  if (!why.empty())
  {
    response.prediction.executed = request.shot;
    response.prediction.message = why;
    return true;
  }
  const session::PredictionOptions options{request.sample_period, request.noise ? &parameters_.table.noise : nullptr,
                                           request.seed};
  const session::ShotPrediction prediction =
      session::predictShot(*start.engine, start.table, toSessionShot(request.shot), options, parameters_.table.limits);
  response.prediction =
      toPredictionMsg(prediction, start.engine->table(), request.sample_period, parameters_.table_frame);
  if (prediction.success)
    preview_publisher_.publish(previewMarkers(*start.engine, start.table, request.shot.ball_id,
                                              prediction.executed.strike, parameters_.table_frame));
  return true;
}

bool TableNode::onPredictBatch(PredictBatch::Request& request, PredictBatch::Response& response)
{
  heavy_done_ = true;
  session::PredictionStart start;
  std::string why = session::whyBadSamplePeriod(request.sample_period);
  if (why.empty() && request.shots.size() > parameters_.table.limits.max_batch_shots)
    why = "shots: " + std::to_string(request.shots.size()) +
          " shots, at most ~max_batch_shots = " + std::to_string(parameters_.table.limits.max_batch_shots);
  if (why.empty())
  {
    std::lock_guard<std::mutex> lock(table_mutex_);
    why = table_->predictionStart(toBallInputs(request.balls), toStamp(now()), start);
  }
  std::vector<session::Shot> shots;
  shots.reserve(request.shots.size());
  for (const auto& s : request.shots)
    shots.push_back(toSessionShot(s));
  const session::PredictionOptions options{request.sample_period, request.noise ? &parameters_.table.noise : nullptr,
                                           request.seed};
  std::vector<session::ShotPrediction> predictions;
  if (why.empty())
    predictions =
        session::predictBatch(*start.engine, start.table, shots, options, parameters_.table.limits, *pool_, why);
  response.success = why.empty();
  response.message = why;
  if (!why.empty())
    return true;
  std::size_t succeeded = 0;
  response.predictions.reserve(predictions.size());
  for (auto& p : predictions)
  {
    succeeded += p.success;
    response.predictions.push_back(
        toPredictionMsg(p, start.engine->table(), request.sample_period, parameters_.table_frame));
    p = session::ShotPrediction();  // the message holds it now
  }
  response.message = std::to_string(succeeded) + " of " + std::to_string(request.shots.size()) +
                     " shots predicted on " + std::to_string(pool_->size()) + " threads";
  return true;
}

bool TableNode::onRack(Rack::Request& request, Rack::Response& response)
{
  session::RackRequest rack;
  rack.layout = request.layout;
  rack.ids.assign(request.ids.begin(), request.ids.end());
  for (const auto& p : request.positions)
    rack.positions.emplace_back(p.x, p.y);
  rack.jitter = request.jitter;
  rack.seed = request.seed;
  std::lock_guard<std::mutex> lock(table_mutex_);
  answer(table_->rack(rack, toStamp(now())), response);
  return true;
}

bool TableNode::onReset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response)
{
  std::lock_guard<std::mutex> lock(table_mutex_);
  answer(table_->reset(toStamp(now())), response);
  return true;
}

bool TableNode::onSetState(SetState::Request& request, SetState::Response& response)
{
  std::lock_guard<std::mutex> lock(table_mutex_);
  const ros::Time stamp = now();
  answer(table_->setState(toBallInputs(request.balls), toStamp(stamp)), response);
  response.stamp = stamp;
  return true;
}

bool TableNode::onPlaceBall(PlaceBall::Request& request, PlaceBall::Response& response)
{
  std::lock_guard<std::mutex> lock(table_mutex_);
  const ros::Time stamp = now();
  answer(table_->placeBall(toBallInput(request.ball), toStamp(stamp)), response);
  response.stamp = stamp;
  return true;
}

bool TableNode::onRemoveBall(RemoveBall::Request& request, RemoveBall::Response& response)
{
  std::lock_guard<std::mutex> lock(table_mutex_);
  const ros::Time stamp = now();
  answer(table_->removeBall(request.ball_id, toStamp(stamp)), response);
  response.stamp = stamp;
  return true;
}

bool TableNode::onPause(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response)
{
  std::lock_guard<std::mutex> lock(table_mutex_);
  answer(table_->pause(request.data, toStamp(now())), response);
  return true;
}

bool TableNode::onStep(Step::Request& request, Step::Response& response)
{
  std::lock_guard<std::mutex> lock(table_mutex_);
  const ros::Time stamp = now();
  answer(table_->step(request.duration, toStamp(stamp)), response);
  response.stamp = stamp;
  return true;
}

}  // namespace cue_sim
