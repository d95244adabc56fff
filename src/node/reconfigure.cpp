// dynamic_reconfigure of table_node: physics coefficients and contact models take effect
// between shots (a shot in flight finishes with the physics it started with, so that it stays
// what its prediction said); the real-time factor at once. Invalid values are refused with the
// reason, and the last valid configuration stays.
#include <dynamic_reconfigure/Config.h>

#include "node/table_node.hpp"

namespace cue_sim
{
std::string TableNode::engineFor(const TableNodeConfig& config,
                                 std::shared_ptr<const physics::Engine<double>>& engine) const
{
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  physics::PhysicsParams<double> params = engine_->params();
  for (const auto& field : physics::physicsParamFields())
    for (const auto& value : message.doubles)
      if (value.name == field.name)
        params.*field.member = value.value;
  std::string why = params.validate();
  if (!why.empty())
    return why;
  physics::ModelChoice models;
  models.ball_ball = config.ball_ball_model;
  models.cushion = config.cushion_model;
  try
  {
    engine = std::make_shared<const physics::Engine<double>>(table_, params, models, engine_->limits());
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  // A larger ball must still fit where the balls are.
  why = engine->whyInvalid(live_->state());
  if (!why.empty())
    return "the balls on the table would not fit: " + why;
  return "";
}

void TableNode::onReconfigure(TableNodeConfig& config, uint32_t level)
{
  if (config.real_time_factor == 0 && !sim_time_)
  {
    ROS_ERROR("cue_sim: real_time_factor 0 (as fast as possible) needs use_sim_time; kept %g",
              applied_config_.real_time_factor);
    config.real_time_factor = applied_config_.real_time_factor;
  }
  if (config.real_time_factor != config_.real_time_factor)
  {
    config_.real_time_factor = config.real_time_factor;
    if (!sim_time_ && !paused_)
      clock_.setRate(ros::Time::now(), config_.real_time_factor);
  }
  std::shared_ptr<const physics::Engine<double>> engine;
  const std::string why = engineFor(config, engine);
  if (!why.empty())
  {
    ROS_ERROR("cue_sim: physics not changed: %s", why.c_str());
    const double rtf = config.real_time_factor;
    config = applied_config_;
    config.real_time_factor = rtf;
    applied_config_ = config;
    return;
  }
  applied_config_ = config;
  pending_engine_ = std::move(engine);
  catchUp(ros::Time::now());  // applies it if the balls rest
  if (pending_engine_)
    ROS_INFO("cue_sim: new physics (level %u) applies when the balls rest", level);
}

void TableNode::applyPendingPhysics()
{
  if (!pending_engine_ || !live_->atRest())
    return;
  engine_ = std::move(pending_engine_);
  live_->setEngine(engine_);
  publishMarkers();  // the ball radius or cushion height may have changed
}

}  // namespace cue_sim
