#include "node/table_node.hpp"

#include <geometry_msgs/TransformStamped.h>
#include <rosgraph_msgs/Clock.h>
#include <visualization_msgs/MarkerArray.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "cue_sim/TableState.h"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"
#include "node/ros_conversions.hpp"
#include "node/table_markers.hpp"

namespace cue_sim
{
using physics::Ball;
using PhysicsState = physics::TableState<double>;

namespace
{
std::string readFile(const std::string& path)
{
  std::ifstream file(path);
  if (!file)
    throw std::runtime_error("cannot read URDF file '" + path + "'");
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

geometry_msgs::TransformStamped makeTransform(const std::string& parent, const std::string& child,
                                              const Eigen::Vector3d& p, const Eigen::Quaterniond& q,
                                              const ros::Time& stamp)
{
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation = toVector3(p);
  t.transform.rotation = toQuaternion(q);
  return t;
}
}  // namespace

physics::TableState<double> atTimeZero(physics::TableState<double> state)
{
  state.time = state.event_time = 0;
  state.events_this_instant = 0;
  for (auto& b : state.balls)
    b.time = 0;
  return state;
}

TableNode::TableNode(ros::NodeHandle& node, ros::NodeHandle& private_node)
{
  private_node.param("publish_rate", config_.publish_rate, config_.publish_rate);
  private_node.param("allow_strike_while_moving", config_.allow_strike_while_moving, false);
  private_node.param("table_frame", config_.table_frame, config_.table_frame);
  private_node.param("world_frame", config_.world_frame, config_.world_frame);
  private_node.param("rack", config_.initial_rack, config_.initial_rack);
  private_node.param("rack_gap", config_.rack_gap, config_.rack_gap);
  private_node.param("ball_frame_prefix", config_.ball_frame_prefix, config_.ball_frame_prefix);
  private_node.param("real_time_factor", config_.real_time_factor, config_.real_time_factor);
  private_node.param("paused", paused_, false);
  if (!(config_.publish_rate > 0 && config_.publish_rate <= 10000))
    throw std::runtime_error("~publish_rate must be in (0, 10000] Hz");
  sim_time_ = ros::Time::isSimTime();
  if (!(config_.real_time_factor >= 0 && config_.real_time_factor <= 1000))
    throw std::runtime_error("~real_time_factor must be in [0, 1000] (0: as fast as possible, with use_sim_time)");
  if (config_.real_time_factor == 0 && !sim_time_)
    throw std::runtime_error(
        "~real_time_factor 0 (as fast as possible) needs use_sim_time: the node then drives /clock");
  for (const std::string* frame : {&config_.table_frame, &config_.world_frame, &config_.ball_frame_prefix})
    if (frame->empty() || frame->front() == '/')
      throw std::runtime_error("frame ids must be non-empty and without a leading '/', got '" + *frame + "'");
  if (!(config_.rack_gap >= 0 && config_.rack_gap < 0.01))
    throw std::runtime_error("~rack_gap must be in [0, 0.01) m");
  loadNoise(private_node);

  physics::PhysicsParams<double> params;
  for (const auto& field : physics::physicsParamFields())
    private_node.param(field.name, params.*field.member, params.*field.member);
  const std::string why = params.validate();
  if (!why.empty())
    throw std::runtime_error("physics parameter ~" + why);
  physics::ModelChoice models;
  private_node.param("ball_ball_model", models.ball_ball, models.ball_ball);
  private_node.param("cushion_model", models.cushion, models.cushion);

  loadTable(node, private_node);
  engine_ = std::make_shared<const physics::Engine<double>>(table_, params, models);  // throws for unknown models

  PhysicsState rack;
  try
  {
    physics::RackOptions options;
    options.gap = config_.rack_gap;
    rack = physics::rackLayout<double>(config_.initial_rack, *table_, params.ball_radius, options);
  }
  catch (const std::invalid_argument& e)
  {
    throw std::runtime_error(std::string("~rack: ") + e.what());
  }
  const std::string invalid = engine_->whyInvalid(rack);
  if (!invalid.empty())
    throw std::runtime_error("~rack '" + config_.initial_rack + "' does not fit table '" + table_->name() +
                             "': " + invalid);

  state_publisher_ = private_node.advertise<cue_sim::TableState>("state", 10);
  marker_publisher_ = private_node.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
  event_publisher_ = private_node.advertise<cue_sim::Event>("events", 1000);
  cue_publisher_ = private_node.advertise<visualization_msgs::Marker>("cue", 1, true);
  preview_publisher_ = private_node.advertise<visualization_msgs::MarkerArray>("preview", 1, true);
  if (sim_time_)
  {
    // This node's clock starts at the wall time (never 0) and only ever moves forward.
    clock_publisher_ = node.advertise<rosgraph_msgs::Clock>("/clock", 10);
    sim_now_ = ros::Time(ros::WallTime::now().sec, ros::WallTime::now().nsec);
    ros::Time::setNow(sim_now_);
  }
  pool_ = std::make_unique<physics::ThreadPool>();
  live_.emplace(engine_, physics::TableState<double>());
  if (!sim_time_)
    clock_.setRate(ros::Time::now(), paused_ ? 0 : config_.real_time_factor);
  setRack(rack, ros::Time::now());
  applied_config_ = TableNodeConfig::__getDefault__();
  reconfigure_ = std::make_unique<dynamic_reconfigure::Server<TableNodeConfig>>(private_node);
  reconfigure_->setCallback([this](TableNodeConfig& config, uint32_t level) { onReconfigure(config, level); });
  startAimMarker(private_node);
  services_ = {
      private_node.advertiseService("strike", &TableNode::onStrike, this),
      private_node.advertiseService("strike_cue", &TableNode::onStrikeCue, this),
      private_node.advertiseService("predict", &TableNode::onPredict, this),
      private_node.advertiseService("predict_batch", &TableNode::onPredictBatch, this),
      private_node.advertiseService("rack", &TableNode::onRack, this),
      private_node.advertiseService("reset", &TableNode::onReset, this),
      private_node.advertiseService("set_state", &TableNode::onSetState, this),
      private_node.advertiseService("pause", &TableNode::onPause, this),
      private_node.advertiseService("step", &TableNode::onStep, this),
  };
  ROS_INFO("cue_sim: table '%s' (%zu cushions, %zu pockets), rack '%s', models %s/%s, tf at %.0f Hz",
           table_->name().c_str(), table_->segments().size(), table_->pockets().size(), config_.initial_rack.c_str(),
           models.ball_ball.c_str(), models.cushion.c_str(), config_.publish_rate);
}

void TableNode::loadNoise(ros::NodeHandle& private_node)
{
  // Off by default; the deviations default to those of the computational pool tournaments.
  physics::ExecutionNoise& noise = config_.noise;
  private_node.param("noise/enabled", config_.noise_enabled, false);
  private_node.param("noise/speed", noise.speed, noise.speed);
  private_node.param("noise/phi", noise.phi, noise.phi);
  private_node.param("noise/theta", noise.theta, noise.theta);
  private_node.param("noise/a", noise.a, noise.a);
  private_node.param("noise/b", noise.b, noise.b);
  private_node.param("noise/seed", config_.noise_seed, 0);
  const std::string why = noise.validate();
  if (!why.empty())
    throw std::runtime_error("~" + why);
  if (config_.noise_seed < 0)
    throw std::runtime_error("~noise/seed must be >= 0");
  live_cue_ = physics::NoisyCue(config_.noise_enabled ? noise : physics::ExecutionNoise::none(),
                                static_cast<std::uint64_t>(config_.noise_seed));
}

void TableNode::startAimMarker(ros::NodeHandle& private_node)
{
  bool enabled = true;
  private_node.param("aim_marker", enabled, enabled);
  if (!enabled)
    return;
  const auto strike = [this](const Shot& shot) {
    Strike::Response response;
    strikeLive(shot, ros::Time::now(), response);
    if (response.success)
      ROS_INFO("cue_sim: aim marker: %s", response.message.c_str());
    else
      ROS_WARN("cue_sim: aim marker: %s", response.message.c_str());
  };
  const auto predict = [this](const Shot& shot) {
    Predict::Request request;
    Predict::Response response;
    request.shot = shot;
    onPredict(request, response);  // draws the paths on ~preview
    if (!response.prediction.success)
      ROS_WARN("cue_sim: aim marker: %s", response.prediction.message.c_str());
  };
  aim_marker_ = std::make_unique<AimMarker>(private_node.resolveName("aim"), config_.table_frame,
                                            engine_->params().ball_radius, strike, predict);
}

void TableNode::loadTable(ros::NodeHandle& node, ros::NodeHandle& private_node)
{
  // The table comes from ~urdf_file, else the robot_description parameter, else ~table by name.
  std::string urdf_file, urdf_xml, table_name = "7ft";
  private_node.param("urdf_file", urdf_file, urdf_file);
  private_node.param("table", table_name, table_name);
  try
  {
    if (!urdf_file.empty())
      urdf_xml = readFile(urdf_file);
    else if (!node.getParam("robot_description", urdf_xml))
      urdf_xml = readFile(tableUrdfPath(table_name));
    table_ = std::make_shared<const physics::TableModel>(tableFromUrdf(urdf_xml, config_.table_frame));
    publishStaticFrames(urdf_xml);
  }
  catch (const TableDescriptionError& e)
  {
    throw std::runtime_error(std::string("table description: ") + e.what());
  }
}

void TableNode::publishStaticFrames(const std::string& urdf_xml)
{
  // world -> table, and every link of the table description for rviz's RobotModel.
  std::vector<geometry_msgs::TransformStamped> frames;
  const ros::Time now = ros::Time::now();
  frames.push_back(makeTransform(config_.world_frame, config_.table_frame, Eigen::Vector3d::Zero(),
                                 Eigen::Quaterniond::Identity(), now));
  for (const auto& link : fixedLinkTransforms(urdf_xml))
    frames.push_back(makeTransform(link.parent, link.child, link.translation, link.rotation, now));
  static_broadcaster_.sendTransform(frames);
}

double TableNode::catchUp(const ros::Time& stamp)
{
  const double now = std::max(clock_.at(stamp), live_->time());
  if (live_->atRest())
  {
    live_->advance(now);  // nothing moves: no physics to do
    applyPendingPhysics();
    return now;
  }
  std::vector<physics::Event<double>> events;
  try
  {
    live_->advance(now, &events);
  }
  catch (const physics::EventLimitError& e)
  {
    // Not reachable for strikes (they are simulated to rest first); kept so that the node
    // never dies on a pathological state. The state is left at its last event, and the shot
    // goes on with a new allowance of events at the next tick.
    ROS_ERROR_THROTTLE(1.0, "cue_sim: %s", e.what());
    live_->reset(live_->state());
  }
  for (const auto& e : events)
    event_publisher_.publish(toEventMsg(e, *table_, clock_.stampOf(e.time, stamp), e.time));
  applyPendingPhysics();  // between shots only
  return now;
}

void TableNode::rebaseAtRest(const ros::Time& stamp)
{
  clock_.restart(stamp);
  live_->reset(atTimeZero(live_->state()));
}

void TableNode::run()
{
  // The balls' frames exist from the start, even on a table started paused.
  tick(ros::Time::now());
  if (!sim_time_)
  {
    ros::Rate rate(config_.publish_rate);
    while (ros::ok())
    {
      ros::spinOnce();
      tick(ros::Time::now());
      rate.sleep();
    }
    return;
  }
  // Sim time: the clock moves at real_time_factor x wall time, or one publish period per
  // loop without waiting (as fast as possible), and not at all while paused.
  const ros::WallDuration period(1.0 / config_.publish_rate);
  ros::WallTime last = ros::WallTime::now();
  while (ros::ok())
  {
    ros::spinOnce();
    const ros::WallTime wall = ros::WallTime::now();
    if (!paused_)
      advanceSimClock(config_.real_time_factor == 0 ? ros::Duration(period.toSec())
                                                    : ros::Duration((wall - last).toSec() * config_.real_time_factor));
    last = wall;
    if (paused_ || config_.real_time_factor > 0)
      period.sleep();
  }
}

void TableNode::advanceSimClock(const ros::Duration& by)
{
  if (by <= ros::Duration(0))
    return;
  sim_now_ += by;
  ros::Time::setNow(sim_now_);
  rosgraph_msgs::Clock clock;
  clock.clock = sim_now_;
  clock_publisher_.publish(clock);
  tick(sim_now_);
}

void TableNode::tick(const ros::Time& stamp)
{
  if (stamp <= last_stamp_)
    return;  // tf must never see the same stamp twice (TF_REPEATED_DATA)
  catchUp(stamp);
  // Balls at rest are where they were: no physics at all until something moves them.
  if (!live_->atRest() || !snapshot_at_rest_)
  {
    snapshot_ = live_->snapshot();
    snapshot_at_rest_ = live_->atRest();
    // The aim marker waits at the cue ball once everything rests.
    const int cue = live_->state().indexOf(0);
    if (snapshot_at_rest_ && aim_marker_ && cue >= 0 && snapshot_[cue].inPlay())
      aim_marker_->place(snapshot_[cue].r.head<2>());
  }
  const std::vector<Ball<double>>& balls = snapshot_;
  std::vector<geometry_msgs::TransformStamped> transforms;
  transforms.reserve(balls.size());
  for (const auto& b : balls)
    transforms.push_back(makeTransform(config_.table_frame, config_.ball_frame_prefix + std::to_string(b.id), b.r,
                                       Eigen::Quaterniond::Identity(), stamp));
  tf_broadcaster_.sendTransform(transforms);
  state_publisher_.publish(toTableStateMsg(balls, *table_, stamp, config_.table_frame));
  last_stamp_ = stamp;
}

void TableNode::setRack(PhysicsState rack, const ros::Time& stamp)
{
  clock_.restart(stamp);
  live_->reset(atTimeZero(rack));
  snapshot_at_rest_ = false;
  last_rack_ = rack;
  publishMarkers();
}

void TableNode::publishMarkers()
{
  marker_publisher_.publish(tableMarkers(*table_, live_->state(), engine_->params().ball_radius,
                                         engine_->params().cushion_height,
                                         {config_.table_frame, config_.ball_frame_prefix}));
}

}  // namespace cue_sim
