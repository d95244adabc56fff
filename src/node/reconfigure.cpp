#include "node/reconfigure.hpp"

#include <dynamic_reconfigure/Config.h>

#include <sstream>

#include "node/ros_conversions.hpp"

namespace cue_sim
{
PhysicsReconfigure::PhysicsReconfigure(ros::NodeHandle& private_node, SharedTable& shared)
  : shared_(shared), applied_(TableNodeConfig::__getDefault__()), server_(private_node)
{
  server_.setCallback([this](TableNodeConfig& config, uint32_t level) { onReconfigure(config, level); });
}

std::string PhysicsReconfigure::apply(const TableNodeConfig& config)
{
  const double factor = config.real_time_factor;
  if (!(factor >= 0 && factor <= session::kMaxRealTimeFactor))
  {
    std::ostringstream why;
    why << "real_time_factor must be in [0, " << session::kMaxRealTimeFactor << "], got " << factor;
    return why.str();
  }
  if (factor == 0 && !shared_.sim_time)
    return "real_time_factor 0 (as fast as possible) needs use_sim_time";
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
  session::LiveTable& table = *shared_.live;
  physics::PhysicsParams<double> params = table.engine().params();
  for (const auto& field : physics::physicsParamFields())
    for (const auto& value : message.doubles)
      if (value.name == field.name)
        params.*field.member = value.value;
  physics::ModelChoice models;
  models.ball_ball = config.ball_ball_model;
  models.cushion = config.cushion_model;
  models.ball_table = config.ball_table_model;
  models.cue = config.cue_model;
  const session::Stamp now = toStamp(shared_.now());
  const session::Outcome physics = table.setPhysics(params, models, now);
  if (!physics.success)
    return physics.message;
  if (shared_.sim_time)
    shared_.clock_factor = factor;  // /clock runs at it; physics follows /clock
  else
    table.setRealTimeFactor(factor, now);
  ROS_INFO("cue_sim: %s", physics.message.c_str());
  return "";
}

void PhysicsReconfigure::onReconfigure(TableNodeConfig& config, uint32_t)
{
  const std::string why = apply(config);
  if (why.empty())
  {
    applied_ = config;
    return;
  }
  ROS_ERROR("cue_sim: configuration not changed: %s", why.c_str());
  config = applied_;
}

}  // namespace cue_sim
