// table_node's shot services: ~strike changes the live table; ~predict and ~predict_batch run
// the same shot on a copy. All three go through predictShot, so they agree bit for bit.
#include <sstream>

#include "node/ros_conversions.hpp"
#include "node/shot_prediction.hpp"
#include "node/table_node.hpp"

namespace cue_sim
{
namespace
{
/// Every ball referred to time 0, as at a strike from rest.
physics::TableState<double> atTimeZero(physics::TableState<double> state)
{
  state.time = state.event_time = 0;
  for (auto& b : state.balls)
    b.time = 0;
  return state;
}
}  // namespace

std::string TableNode::predictionStart(const std::vector<BallState>& balls, physics::TableState<double>& start)
{
  if (balls.empty())
  {
    catchUp(ros::Time::now());
    if (state_.anyMoving())
      return "the live table is moving: predict from it once it rests, or pass the balls to start from";
    start = atTimeZero(state_);
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
  const ros::Time stamp = ros::Time::now();
  Shot shot;
  shot.ball_id = request.ball_id;
  shot.speed = request.speed;
  shot.phi = request.phi;
  shot.theta = request.theta;
  shot.a = request.a;
  shot.b = request.b;
  response.executed = shot;
  catchUp(stamp);
  std::string why = engine_->whyNotStrikable(state_, request.ball_id, toCueStrike(shot));
  if (why.empty() && state_.anyMoving() && !config_.allow_strike_while_moving)
    why = "balls are still moving (set ~allow_strike_while_moving to strike anyway)";
  if (!why.empty())
  {
    response.success = false;
    response.message = why;
    return true;
  }
  // A strike from rest starts at physics time 0, like a prediction.
  if (!state_.anyMoving())
    rebaseAtRest(stamp);
  const physics::CueStrike<double> executed = live_cue_.execute(toCueStrike(shot), engine_->params().ball_radius);
  response.executed = toShotMsg(request.ball_id, executed);
  // Run the shot to rest on a copy first: it answers the request, and a shot the engine
  // cannot finish is refused before it touches the table.
  Prediction prediction = predictShot(*engine_, state_, response.executed, {0, nullptr, 0, config_.table_frame});
  if (!prediction.success)
  {
    response.success = false;
    response.message = prediction.message;
    return true;
  }
  engine_->strike(state_, request.ball_id, executed);
  snapshot_at_rest_ = false;
  const physics::Ball<double>& ball = state_.balls[state_.indexOf(request.ball_id)];
  response.ball_velocity = toVector3(ball.v);
  response.ball_angular_velocity = toVector3(ball.w);
  response.success = true;
  response.stamp = stamp;
  response.time_to_rest = prediction.time_to_rest;
  response.num_events = static_cast<uint32_t>(prediction.events.size());
  std::ostringstream message;
  message << "struck ball " << request.ball_id << " at " << stamp << "; " << prediction.message;
  response.message = message.str();
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
