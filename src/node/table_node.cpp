#include "node/table_node.hpp"

#include <geometry_msgs/TransformStamped.h>
#include <pthread.h>
#include <rosgraph_msgs/Clock.h>
#include <sched.h>
#include <visualization_msgs/MarkerArray.h>

#include "cue_sim/TableState.h"
#include "cue_sim/table_description/urdf_table_loader.hpp"
#include "node/ros_conversions.hpp"
#include "node/table_markers.hpp"
#include "node/thread_priority.hpp"

namespace cue_sim
{
namespace
{
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

/// Threads answering the light services: a tf lookup for ~strike_cue may hold one of them for
/// up to ~tf_timeout while the other answers.
constexpr int kLightServiceThreads = 2;

/// ~markers goes out again this often, besides whenever the balls are placed anew: a bag then
/// holds the table's picture after the balls' first transforms wherever it is played from, and
/// rviz shows every ball on a replay (frame-locked markers that came before their frames are not
/// shown).
const ros::WallDuration kMarkerRefresh(1.0);

/// With sim time as fast as possible, /clock runs this many times the wall clock while no ball
/// moves, a step each publish period: a sim-time client's waits still pass at once, but tf, ~state
/// and /clock go out at the publish rate, not as fast as the loop turns. Still frames by the
/// thousand buried subscribers on a busy machine (a Python client fell two minutes behind ~state).
constexpr double kAtRestClockFactor = session::kMaxRealTimeFactor;

/// How far /clock moves in one turn of the sim-time loop, and whether the loop then waits a period.
struct ClockStep
{
  ros::Duration by;
  bool waits = true;
};

/// The step for `wall` elapsed since the last: at `factor` times the wall clock; as fast as
/// possible (`factor` 0), one `period` at once while balls move, at the wall clock's pace while
/// paused (a sim-time client never waits on the clock), kAtRestClockFactor times it at rest.
ClockStep simClockStep(double factor, bool paused, bool at_rest, const ros::WallDuration& wall,
                       const ros::WallDuration& period)
{
  if (factor > 0)
    return {ros::Duration(wall.toSec() * factor), true};
  if (paused)
    return {ros::Duration(wall.toSec()), true};
  if (at_rest)
    return {ros::Duration(wall.toSec() * kAtRestClockFactor), true};
  return {ros::Duration(period.toSec()), false};
}
}  // namespace

TableNode::TableNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node)
  : node_(node), private_node_(private_node)
{
  node_.setCallbackQueue(&queue_);
  private_node_.setCallbackQueue(&queue_);
  shared_.sim_time = ros::Time::isSimTime();
  parameters_ = readNodeParameters(node_, private_node_, shared_.sim_time);
  shared_.clock_factor = parameters_.real_time_factor;
  const NodeParameters& p = parameters_;
  std::shared_ptr<const physics::Engine<double>> engine;
  try
  {
    engine = std::make_shared<const physics::Engine<double>>(p.table_model, p.physics, p.models);
  }
  catch (const std::invalid_argument& e)
  {
    throw std::runtime_error(std::string("~ball_ball_model, ~cushion_model, ~ball_table_model, ~cue_model: ") +
                             e.what());
  }
  if (shared_.sim_time)
  {
    // This node's clock starts at the wall time (never 0) and only ever moves forward. The node
    // stamps with it directly; roscpp's own time follows it through /clock, never backwards.
    clock_publisher_ = node_.advertise<rosgraph_msgs::Clock>("/clock", 10);
    shared_.sim_now = ros::Time(ros::WallTime::now().sec, ros::WallTime::now().nsec);
  }
  try
  {
    shared_.live.emplace(engine, p.table, p.rack, toStamp(shared_.now()));
  }
  catch (const std::invalid_argument& e)
  {
    throw std::runtime_error("~" + std::string(e.what()));
  }
  state_publisher_ = private_node_.advertise<cue_sim::TableState>("state", 10);
  marker_publisher_ = private_node_.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
  event_publisher_ = private_node_.advertise<cue_sim::Event>("events", 1000);
  publishStaticFrames(p.urdf_xml);
  services_ = std::make_unique<TableServices>(private_node_, shared_, parameters_);
  games_ = std::make_unique<GameServices>(private_node_, shared_, parameters_);
  predictions_ = std::make_unique<PredictionServices>(private_node_, shared_, parameters_);
  reconfigure_ = std::make_unique<PhysicsReconfigure>(private_node_, shared_);
  startAimMarker();
  if (p.camera.enabled)
    camera_ = std::make_unique<CameraPublisher>(private_node_, p.camera, p.table_frame);
  if (!p.cue.frame.empty())
    followed_cue_ = std::make_unique<FollowedCue>(private_node_, shared_, parameters_, *services_);
  ROS_INFO("cue_sim: table '%s' (%zu cushions, %zu pockets), rack '%s', models %s/%s, tf at %.0f Hz",
           p.table_model->name().c_str(), p.table_model->segments().size(), p.table_model->pockets().size(),
           p.rack.c_str(), p.models.ball_ball.c_str(), p.models.cushion.c_str(), p.publish_rate);
}

TableNode::~TableNode()
{
  followed_cue_.reset();  // it strikes through services_: gone before them
  if (spinner_)
    spinner_->stop();
}

void TableNode::startAimMarker()
{
  if (!parameters_.aim_marker)
    return;
  const auto strike = [this](const Shot& shot) {
    const session::StrikeOutcome outcome = services_->strike(toSessionShot(shot), "aim_marker");
    if (outcome.success)
      ROS_INFO("cue_sim: aim marker: %s", outcome.message.c_str());
    else
      ROS_WARN("cue_sim: aim marker: %s", outcome.message.c_str());
  };
  const auto predict = [this](const Shot& shot) {
    Predict::Request request;
    Predict::Response response;
    request.shot = shot;
    predictions_->onPredict(request, response);  // draws the paths on ~preview
    if (!response.prediction.success)
      ROS_WARN("cue_sim: aim marker: %s", response.prediction.message.c_str());
  };
  aim_marker_ = std::make_unique<AimMarker>(private_node_.resolveName("aim"), parameters_.table_frame,
                                            parameters_.physics.ball_radius, strike, predict);
}

void TableNode::publishStaticFrames(const std::string& urdf_xml)
{
  // world -> table, and every link of the table description for rviz's RobotModel.
  std::vector<geometry_msgs::TransformStamped> frames;
  const ros::Time now = shared_.now();
  frames.push_back(makeTransform(parameters_.world_frame, parameters_.table_frame, Eigen::Vector3d::Zero(),
                                 Eigen::Quaterniond::Identity(), now));
  for (const auto& link : fixedLinkTransforms(urdf_xml))
    frames.push_back(makeTransform(link.parent, link.child, link.translation, link.rotation, now));
  const CameraParameters& camera = parameters_.camera;
  if (camera.enabled && camera.publish_frame)
  {
    const camera::Pose pose = CameraPublisher::poseOf(camera);
    frames.push_back(makeTransform(parameters_.table_frame, camera.frame, pose.translation(),
                                   Eigen::Quaterniond(pose.linear()), now));
  }
  static_broadcaster_.sendTransform(frames);
}

void TableNode::run()
{
  // Services on their own threads from here on: this thread only publishes.
  spinner_ = std::make_unique<ros::AsyncSpinner>(kLightServiceThreads, &queue_);
  spinner_->start();
  // The balls' frames exist from the start, even on a table started paused.
  tick();
  if (!shared_.sim_time)
  {
    raisePublishingPriority();
    ros::Rate rate(parameters_.publish_rate);
    while (running())
    {
      tick();
      rate.sleep();
    }
    return;
  }
  // Sim time: the node drives /clock (simClockStep says how), ticking at every step.
  const ros::WallDuration period(1.0 / parameters_.publish_rate);
  ros::WallTime last = ros::WallTime::now();
  while (running())
  {
    const ros::WallTime wall = ros::WallTime::now();
    const bool waits = advanceSimClock(wall - last, period);
    last = wall;
    if (waits)
      period.sleep();
  }
}

void TableNode::raisePublishingPriority()
{
  // tf before anything else the machine does. The loop sleeps every period and a tick takes well
  // under a millisecond, so it cannot starve the rest. Without the grant, as before.
  if (raiseThisThreadToRealTime())
    ROS_INFO("cue_sim: the publishing thread runs at real-time priority %d (SCHED_FIFO)", kPublishingRealTimePriority);
  else
    ROS_DEBUG("cue_sim: no real-time priority for the publishing thread; it runs at the normal one");
}

bool TableNode::advanceSimClock(const ros::WallDuration& wall, const ros::WallDuration& period)
{
  rosgraph_msgs::Clock clock;
  ClockStep step;
  {
    // The step is chosen and taken under one lock: a strike cannot land between a look at the
    // resting table and a step of a thousand periods, which would skip its shot's frames.
    std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
    const session::LiveTable& table = *shared_.live;
    step = simClockStep(shared_.clock_factor, table.clock().paused(), table.motion().atRest(), wall, period);
    if (step.by <= ros::Duration(0))
      return step.waits;
    shared_.sim_now += step.by;
    clock.clock = shared_.sim_now;
  }
  clock_publisher_.publish(clock);
  tick();
  return step.waits;
}

void TableNode::tick()
{
  std::vector<session::StampedEvent> events;
  std::vector<physics::Ball<double>> balls;
  std::vector<Eigen::Quaterniond> orientations;
  bool at_rest = false;
  long layout = 0;
  ros::Time stamp;
  {
    // The stamp is taken under the lock, as the services take theirs: no request can come
    // between it and the table it shows.
    std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
    stamp = shared_.clock();
    if (stamp <= shared_.last_published)
      return;  // tf must never see the same stamp twice (TF_REPEATED_DATA)
    session::LiveTable& table = *shared_.live;
    table.advanceTo(toStamp(stamp), &events);
    balls = table.motion().balls();
    orientations = table.motion().orientations();
    at_rest = table.motion().atRest();
    layout = table.motion().layoutVersion();
    if (layout != preview_layout_ || table.motion().strikeCount() != preview_strikes_)
    {
      predictions_->clearPreview();  // the table moved on: the preview is stale
      preview_layout_ = layout;
      preview_strikes_ = table.motion().strikeCount();
    }
    if (layout != markers_drawn_ || ros::WallTime::now() - markers_sent_ > kMarkerRefresh)
      publishMarkers(table);
    games_->publishIfChanged(table, stamp);
    if (camera_ && camera_->due(stamp))
      camera_->take(table, stamp);
    shared_.last_published = stamp;
  }
  const physics::TableModel& table = *parameters_.table_model;
  for (const auto& e : events)
    event_publisher_.publish(toEventMsg(e.event, table, toRosTime(e.stamp), e.event.time));
  std::vector<geometry_msgs::TransformStamped> transforms;
  transforms.reserve(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i)
    transforms.push_back(makeTransform(parameters_.table_frame,
                                       parameters_.ball_frame_prefix + std::to_string(balls[i].id), balls[i].r,
                                       orientations[i], stamp));
  tf_broadcaster_.sendTransform(transforms);
  state_publisher_.publish(toTableStateMsg(balls, table, stamp, parameters_.table_frame));
  // The aim marker waits at the cue ball once everything rests.
  if (!at_rest)
    aim_placed_at_ = -1;
  else if (aim_marker_ && aim_placed_at_ != layout)
  {
    aim_placed_at_ = layout;
    for (const auto& b : balls)
      if (b.id == 0 && b.inPlay())
        aim_marker_->place(b.r.head<2>());
  }
}

void TableNode::publishMarkers(const session::LiveTable& table)
{
  const physics::PhysicsParams<double>& params = table.engine().params();
  physics::TableState<double> state;
  state.balls = table.motion().balls();
  marker_publisher_.publish(tableMarkers(table.table(), state, params.ball_radius, params.cushion_height,
                                         {parameters_.table_frame, parameters_.ball_frame_prefix}));
  markers_drawn_ = table.motion().layoutVersion();
  markers_sent_ = ros::WallTime::now();
}

}  // namespace cue_sim
