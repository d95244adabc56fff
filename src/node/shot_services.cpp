// table_node's shot services: ~strike changes the live table; ~predict and ~predict_batch run
// the same shot on a copy. All three go through predictShot, so they agree bit for bit.
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <cmath>
#include <sstream>

#include "cue_sim/physics/cue_aim.hpp"
#include "node/ros_conversions.hpp"
#include "node/shot_markers.hpp"
#include "node/shot_prediction.hpp"
#include "node/table_node.hpp"

namespace cue_sim
{
std::string TableNode::predictionStart(const std::vector<BallState>& balls, physics::TableState<double>& start)
{
  if (balls.empty())
  {
    catchUp(ros::Time::now());
    if (!live_->atRest())
      return "the live table is moving: predict from it once it rests, or pass the balls to start from";
    start = atTimeZero(live_->state());
    return "";
  }
  std::string why = fromBallStateMsgs(balls, *table_, engine_->params().ball_radius, start);
  if (why.empty())
  {
    why = engine_->whyInvalid(start);
    if (!why.empty())
      why = "balls: " + why;
  }
  return why;
}

bool TableNode::onStrike(Strike::Request& request, Strike::Response& response)
{
  strikeLive(shotOf(request), ros::Time::now(), response);
  return true;
}

void TableNode::strikeLive(const Shot& shot, const ros::Time& stamp, Strike::Response& response)
{
  response.executed = shot;
  catchUp(stamp);
  std::string why = live_->whyNotStrikable(shot.ball_id, toCueStrike(shot));
  if (why.empty() && !live_->atRest() && !config_.allow_strike_while_moving)
    why = "balls are still moving (set ~allow_strike_while_moving to strike anyway)";
  if (!why.empty())
  {
    response.success = false;
    response.message = why;
    return;
  }
  // A strike from rest starts at physics time 0, like a prediction.
  if (live_->atRest())
    rebaseAtRest(stamp);
  const physics::CueStrike<double> executed = live_cue_.execute(toCueStrike(shot), engine_->params().ball_radius);
  response.executed = toShotMsg(shot.ball_id, executed);
  // Run the shot to rest on a copy first: it answers the request, and a shot the engine
  // cannot finish is refused before it touches the table.
  Prediction prediction =
      predictShot(*engine_, live_->state(), response.executed, {0, nullptr, 0, config_.table_frame});
  if (!prediction.success)
  {
    response.success = false;
    response.message = prediction.message;
    return;
  }
  const physics::Ball<double> before = live_->snapshot()[live_->state().indexOf(shot.ball_id)];
  cue_publisher_.publish(cueStickMarker(physics::cueStickFor(before, executed, engine_->params(), 0.005),
                                        config_.table_frame, stamp, 1.5));
  live_->strike(shot.ball_id, executed);
  snapshot_at_rest_ = false;
  const physics::Ball<double>& ball = live_->state().balls[live_->state().indexOf(shot.ball_id)];
  response.ball_velocity = toVector3(ball.v);
  response.ball_angular_velocity = toVector3(ball.w);
  response.success = true;
  response.stamp = stamp;
  response.time_to_rest = prediction.time_to_rest;
  response.num_events = static_cast<uint32_t>(prediction.events.size());
  std::ostringstream message;
  message << "struck ball " << shot.ball_id << " at " << stamp << "; " << prediction.message;
  response.message = message.str();
}

std::string TableNode::cueInTableFrame(const geometry_msgs::PoseStamped& pose, physics::CueStick& cue)
{
  const auto& q = pose.pose.orientation;
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (!(std::abs(norm - 1) < 1e-3))
    return "cue.pose.orientation must be a unit quaternion (its norm is " + std::to_string(norm) + ")";
  if (pose.header.frame_id.empty())
    return "cue.header.frame_id is empty: give the frame of the cue pose";
  geometry_msgs::PoseStamped in_table = pose;
  if (pose.header.frame_id != config_.table_frame)
  {
    if (!tf_buffer_)
    {
      tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
      tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_);
    }
    try
    {
      const geometry_msgs::TransformStamped t =
          tf_buffer_->lookupTransform(config_.table_frame, pose.header.frame_id, ros::Time(0), ros::Duration(1.0));
      tf2::doTransform(pose, in_table, t);
    }
    catch (const tf2::TransformException& e)
    {
      return "cannot transform the cue pose from '" + pose.header.frame_id + "' to '" + config_.table_frame +
             "': " + e.what();
    }
  }
  const auto& p = in_table.pose.position;
  const auto& r = in_table.pose.orientation;
  cue.tip = physics::Vec3<double>(p.x, p.y, p.z);
  cue.axis = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized() * physics::Vec3<double>::UnitX();
  return "";
}

bool TableNode::onStrikeCue(StrikeCue::Request& request, StrikeCue::Response& response)
{
  const ros::Time stamp = ros::Time::now();
  response.success = false;
  physics::CueStick cue;
  response.message = cueInTableFrame(request.cue, cue);
  if (!response.message.empty())
    return true;
  catchUp(stamp);
  physics::CueAim aim;
  response.message = physics::aimCue(live_->snapshot(), engine_->params(), cue, request.speed, aim);
  if (!response.message.empty())
    return true;
  response.shot = toShotMsg(aim.ball_id, aim.strike);
  Strike::Response struck;
  strikeLive(response.shot, stamp, struck);
  response.success = struck.success;
  response.message = struck.message;
  response.executed = struck.executed;
  response.stamp = struck.stamp;
  response.time_to_rest = struck.time_to_rest;
  response.num_events = struck.num_events;
  return true;
}

bool TableNode::onPredict(Predict::Request& request, Predict::Response& response)
{
  Prediction& prediction = response.prediction;
  physics::TableState<double> start;
  std::string why = whyBadSamplePeriod(request.sample_period);
  if (why.empty())
    why = predictionStart(request.balls, start);
  if (!why.empty())
  {
    prediction.executed = request.shot;
    prediction.message = why;
    return true;
  }
  const PredictionOptions options{request.sample_period, request.noise ? &config_.noise : nullptr, request.seed,
                                  config_.table_frame};
  prediction = predictShot(*engine_, start, request.shot, options);
  if (prediction.success)
    preview_publisher_.publish(
        previewMarkers(*engine_, start, request.shot.ball_id, toCueStrike(prediction.executed), config_.table_frame));
  return true;
}

bool TableNode::onPredictBatch(PredictBatch::Request& request, PredictBatch::Response& response)
{
  physics::TableState<double> start;
  std::string why = whyBadSamplePeriod(request.sample_period);
  if (why.empty())
    why = predictionStart(request.balls, start);
  if (!why.empty())
  {
    response.success = false;
    response.message = why;
    return true;
  }
  response.predictions.resize(request.shots.size());
  pool_->parallelFor(request.shots.size(), [&](std::size_t i) {
    const PredictionOptions options{request.sample_period, request.noise ? &config_.noise : nullptr, request.seed + i,
                                    config_.table_frame};
    response.predictions[i] = predictShot(*engine_, start, request.shots[i], options);
  });
  std::size_t succeeded = 0;
  for (const auto& p : response.predictions)
    succeeded += p.success;
  response.success = true;
  response.message = std::to_string(succeeded) + " of " + std::to_string(request.shots.size()) +
                     " shots predicted on " + std::to_string(pool_->size()) + " threads";
  return true;
}

}  // namespace cue_sim
