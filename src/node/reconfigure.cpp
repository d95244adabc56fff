// dynamic_reconfigure of table_node: physics coefficients and contact models take effect
// between shots (a shot in flight finishes with the physics it started with, so that it stays
// what its prediction said); the real-time factor at once. An invalid change is refused with
// the reason, and the last valid configuration stays (and is what the server reports back).
#include <dynamic_reconfigure/Config.h>

#include <cmath>
#include <sstream>

#include "node/ros_conversions.hpp"
#include "node/table_node.hpp"

namespace cue_sim
{
std::string TableNode::applyConfig(const TableNodeConfig& config)
{
  const double factor = config.real_time_factor;
  if (!(factor >= 0 && factor <= session::kMaxRealTimeFactor))
  {
    std::ostringstream why;
    why << "real_time_factor must be in [0, " << session::kMaxRealTimeFactor << "], got " << factor;
    return why.str();
  }
  if (factor == 0 && !sim_time_)
    return "real_time_factor 0 (as fast as possible) needs use_sim_time";
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  std::lock_guard<std::mutex> lock(table_mutex_);
  physics::PhysicsParams<double> params = table_->engine().params();
  for (const auto& field : physics::physicsParamFields())
    for (const auto& value : message.doubles)
      if (value.name == field.name)
        params.*field.member = value.value;
  physics::ModelChoice models;
  models.ball_ball = config.ball_ball_model;
  models.cushion = config.cushion_model;
  const ros::Time stamp = now();
  const session::Outcome physics = table_->setPhysics(params, models, toStamp(stamp));
  if (!physics.success)
    return physics.message;
  if (sim_time_)
    clock_factor_ = factor;  // /clock runs at it; physics follows /clock
  else
    table_->setRealTimeFactor(factor, toStamp(stamp));
  ROS_INFO("cue_sim: %s", physics.message.c_str());
  return "";
}

void TableNode::onReconfigure(TableNodeConfig& config, uint32_t)
{
  const std::string why = applyConfig(config);
  if (why.empty())
  {
    applied_config_ = config;
    return;
  }
  ROS_ERROR("cue_sim: configuration not changed: %s", why.c_str());
  config = applied_config_;
}

}  // namespace cue_sim
