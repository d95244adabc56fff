#include "node/followed_cue.hpp"

#include <tf2/exceptions.h>

#include <algorithm>

#include "node/ros_conversions.hpp"
#include "node/shot_markers.hpp"

namespace cue_sim
{
namespace
{
/// /tf messages that may wait for the follower's thread: a second of a 100 Hz robot, a tenth of a
/// second at 1 kHz. A follower that falls further behind loses the oldest, which the follower then
/// sees as a gap (~cue/max_gap) if it is long enough to matter.
constexpr uint32_t kTfQueue = 100;
/// The followed cue is drawn at most this often [s of wall time]: rviz needs no more, and a 1 kHz
/// frame would otherwise send a marker a millisecond.
const ros::WallDuration kDrawPeriod(1.0 / 30);
/// [s] the drawn cue vanishes this long after its frame stops moving (or is lost).
constexpr double kDrawnLifetime = 0.5;

geometry_msgs::Pose poseOf(const physics::CueStick& cue)
{
  geometry_msgs::Pose pose;
  pose.position = toPoint(cue.tip);
  pose.orientation = toQuaternion(Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), cue.axis));
  return pose;
}
}  // namespace

FollowedCue::FollowedCue(ros::NodeHandle& private_node, SharedTable& shared, const NodeParameters& parameters,
                         TableServices& services)
  : shared_(shared),
    parameters_(parameters),
    services_(services),
    follower_(parameters.cue.follower),
    epoch_(ros::Time::now()),
    node_(private_node.getNamespace())
{
  node_.setCallbackQueue(&queue_);
  contact_publisher_ = node_.advertise<cue_sim::CueContact>("cue_contacts", 100);
  const ros::TransportHints low_latency = ros::TransportHints().tcpNoDelay();
  tf_subscriber_ = node_.subscribe("/tf", kTfQueue, &FollowedCue::onTf, this, low_latency);
  tf_static_subscriber_ = node_.subscribe("/tf_static", kTfQueue, &FollowedCue::onTfStatic, this);
  spinner_ = std::make_unique<ros::AsyncSpinner>(1, &queue_);
  spinner_->start();
  ROS_INFO("cue_sim: following the cue frame '%s' in tf (strikes at %.3g m/s and more along the cue)",
           parameters.cue.frame.c_str(), parameters.cue.follower.min_speed);
}

FollowedCue::~FollowedCue()
{
  spinner_->stop();
  tf_subscriber_.shutdown();
  tf_static_subscriber_.shutdown();
}

bool FollowedCue::mayMoveTheCue(const geometry_msgs::TransformStamped& transform) const
{
  const std::string& prefix = parameters_.ball_frame_prefix;
  return transform.child_frame_id.compare(0, prefix.size(), prefix) != 0;
}

void FollowedCue::onTfStatic(const tf2_msgs::TFMessage::ConstPtr& message)
{
  for (const auto& t : message->transforms)
    buffer_.setTransform(t, "tf_static", true);
  sample();
}

void FollowedCue::onTf(const tf2_msgs::TFMessage::ConstPtr& message)
{
  bool inserted = false;
  for (const auto& t : message->transforms)
    if (mayMoveTheCue(t))
    {
      buffer_.setTransform(t, "tf", false);
      inserted = true;
    }
  if (inserted)
    sample();
}

void FollowedCue::sample()
{
  geometry_msgs::TransformStamped t;
  try
  {
    t = buffer_.lookupTransform(parameters_.table_frame, parameters_.cue.frame, ros::Time(0));
  }
  catch (const tf2::TransformException&)
  {
    return;  // the cue's frame is not (yet) connected to the table's
  }
  if (t.header.stamp <= last_sample_)
    return;
  last_sample_ = t.header.stamp;
  physics::CuePose pose;
  pose.stamp = secondsOf(t.header.stamp);
  const auto& p = t.transform.translation;
  const auto& q = t.transform.rotation;
  pose.cue.tip = physics::Vec3<double>(p.x, p.y, p.z);
  pose.cue.axis = Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized() * Eigen::Vector3d::UnitX();
  std::vector<physics::Ball<double>> balls;
  physics::PhysicsParams<double> params;
  {
    std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
    balls = shared_.live->ballsAt(toStamp(t.header.stamp));
    params = shared_.live->engine().params();
  }
  const session::CueStep step = follower_.observe(pose, balls, params);
  if (!step.note.empty() && step.note != last_note_)
    ROS_INFO("cue_sim: cue frame '%s': %s", parameters_.cue.frame.c_str(), step.note.c_str());
  last_note_ = step.note;
  if (step.contact)
    onContact(*step.contact);
  drawCue(pose.cue, t.header.stamp);
}

void FollowedCue::onContact(const session::CueContact& contact)
{
  cue_sim::CueContact report;
  report.header.stamp = timeOf(contact.stamp);
  report.header.frame_id = parameters_.table_frame;
  report.ball_id = contact.ball_id;
  report.point = toPoint(contact.point);
  report.velocity = toVector3(contact.velocity);
  report.speed = contact.speed;
  report.cue = poseOf(contact.cue);
  report.message = contact.refusal;
  if (contact.refusal.empty())
  {
    geometry_msgs::PoseStamped pose;
    pose.header = report.header;
    pose.pose = report.cue;
    session::Shot aimed;
    const session::StrikeOutcome outcome =
        services_.strikeWithCue(contact.cue, contact.speed, report.header.stamp, "cue_frame", pose, aimed);
    report.struck = outcome.success;
    report.message = outcome.message;
    if (outcome.success)
    {
      report.shot = toShotMsg(aimed);
      report.executed = toShotMsg(outcome.executed);
    }
  }
  contact_publisher_.publish(report);
  if (report.struck)
    ROS_INFO("cue_sim: cue frame '%s' struck ball %d at %.3f m/s: %s", parameters_.cue.frame.c_str(), contact.ball_id,
             contact.speed, report.message.c_str());
  else
    ROS_INFO("cue_sim: cue frame '%s' touched ball %d at %.3f m/s, no strike: %s", parameters_.cue.frame.c_str(),
             contact.ball_id, contact.speed, report.message.c_str());
}

void FollowedCue::drawCue(const physics::CueStick& cue, const ros::Time& stamp)
{
  const ros::WallTime now = ros::WallTime::now();
  if (now - drawn_ < kDrawPeriod)
    return;
  drawn_ = now;
  visualization_msgs::Marker marker = cueStickMarker(cue, parameters_.table_frame, stamp, kDrawnLifetime);
  marker.ns = "cue_frame";
  marker.color.a = 0.6f;  // see-through: a robot's own model of its cue shows through it
  services_.showCue(marker);
}

}  // namespace cue_sim
