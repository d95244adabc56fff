// A robot's cue followed in tf (~cue/frame = cue_tip): strokes published as a frame in /tf, at
// 100 Hz and 1 kHz, each strike the ball as ~strike_cue strikes it for the cue's pose and speed at
// the touch (speed within 1 %, angles within 1 mrad, offsets within 0.01 R), and as the stroke was
// designed; hand-made poses with a tracker's jitter and gaps do too; a cue resting against the
// ball or creeping into it strikes nothing. The node is the real one, through a real master.
#include <cue_sim/CueContact.h>
#include <cue_sim/ExecutedShot.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/transform_broadcaster.h>

#include <cmath>
#include <functional>
#include <mutex>
#include <optional>
#include <random>
#include <vector>

#include "cue_sim/physics/cue_aim.hpp"
#include "table_client.hpp"

namespace
{
using cue_sim::physics::Ball;
using cue_sim::physics::CueStick;
using cue_sim::physics::CueStrike;
using cue_sim::physics::Vec3;

const cue_sim::physics::PhysicsParams<double> kParams;  // config/physics.yaml's, which the node loads
const double R = kParams.ball_radius;
/// Where the cue ball waits for each stroke, alone on the 7 ft table [m].
constexpr double kBallX = 0.3, kBallY = 0.1;

/// The node's tf rate (config/table_node.yaml).
constexpr double kPublishRate = 100.0;
/// The tolerances the issue sets for a strike from the followed cue against ~strike_cue's.
constexpr double kSpeedShare = 0.01;
constexpr double kAngle = 1e-3;   ///< [rad]
constexpr double kOffset = 0.01;  ///< [R]

Ball<double> cueBall()
{
  Ball<double> ball;
  ball.id = 0;
  ball.r = Vec3<double>(kBallX, kBallY, R);
  return ball;
}

/// A stroke through the cue at its touch: it waits `wait` s drawn back, accelerates uniformly for
/// `accelerate` s to touch at `speed`, and follows through, slowing to a stop over `follow` s.
struct Stroke
{
  CueStick touching;
  double speed = 1;
  double wait = 0.1, accelerate = 0.15, follow = 0.1;

  double touchTime() const { return wait + accelerate; }
  double duration() const { return touchTime() + follow + 0.05; }
  /// The tip's way along the axis from its place at the touch, `t` s from the start [m].
  double along(double t) const
  {
    const double drawn = 0.5 * speed * accelerate;
    if (t < wait)
      return -drawn;
    if (t < touchTime())
    {
      const double u = t - wait;
      return -drawn + 0.5 * (speed / accelerate) * u * u;
    }
    const double u = std::min(t - touchTime(), follow);
    return speed * u - 0.5 * (speed / follow) * u * u;
  }
  CueStick at(double t) const
  {
    CueStick cue = touching;
    cue.tip += cue.axis.normalized() * along(t);
    return cue;
  }
};

geometry_msgs::Pose poseOf(const CueStick& cue)
{
  geometry_msgs::Pose pose;
  pose.position.x = cue.tip.x();
  pose.position.y = cue.tip.y();
  pose.position.z = cue.tip.z();
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), cue.axis);
  pose.orientation.w = q.w();
  pose.orientation.x = q.x();
  pose.orientation.y = q.y();
  pose.orientation.z = q.z();
  return pose;
}

CueStrike<double> strikeOf(double speed, double phi, double theta, double a, double b)
{
  CueStrike<double> s;
  s.speed = speed;
  s.phi = phi;
  s.theta = theta;
  s.a = a;
  s.b = b;
  return s;
}

double angleBetween(double a, double b)
{
  return std::abs(std::remainder(a - b, 2 * M_PI));
}

class FollowedCueTest : public ::testing::Test
{
protected:
  FollowedCueTest()
  {
    tf_sub_ = nh_.subscribe<tf2_msgs::TFMessage>("/tf", 10000, [this](const tf2_msgs::TFMessageConstPtr& m) {
      for (const auto& t : m->transforms)
        if (t.child_frame_id == "ball_0")
        {
          std::lock_guard<std::mutex> lock(mutex_);
          ticks_.push_back(t.header.stamp);
        }
    });
    contacts_sub_ =
        nh_.subscribe<cue_sim::CueContact>("/table/cue_contacts", 100, [this](const cue_sim::CueContactConstPtr& m) {
          std::lock_guard<std::mutex> lock(mutex_);
          contacts_.push_back(*m);
        });
    shots_sub_ =
        nh_.subscribe<cue_sim::ExecutedShot>("/table/shots", 100, [this](const cue_sim::ExecutedShotConstPtr& m) {
          std::lock_guard<std::mutex> lock(mutex_);
          shots_.push_back(*m);
        });
    EXPECT_TRUE(waitFor([&] { return contacts_sub_.getNumPublishers() > 0 && shots_sub_.getNumPublishers() > 0; }));
  }

  /// The cue ball alone at its place, at rest; returns the stamp it was placed at.
  ros::Time placeCueBall()
  {
    const cue_sim::Rack::Response racked = table_.rack("custom", {0}, {{kBallX, kBallY}});
    table_.afterRack(racked);
    return racked.stamp;
  }

  /// Publishes the cue frame `cue(t)` at `rate` for `duration` s (t from the start), stamped with
  /// the time of publication, skipping instants where `cue` gives nothing (a gap); the tip's
  /// position gets Gaussian noise of `jitter` [m] a coordinate.
  void play(const std::function<std::optional<CueStick>(double)>& cue, double duration, double rate, double jitter = 0,
            unsigned seed = 1)
  {
    std::mt19937 random(seed);
    std::normal_distribution<double> noise(0.0, jitter);
    const ros::Time start = ros::Time::now();
    ros::Rate pace(rate);
    for (ros::Time now = start; (now - start).toSec() < duration; now = ros::Time::now())
    {
      const std::optional<CueStick> at = cue((now - start).toSec());
      if (at)
      {
        geometry_msgs::TransformStamped t;
        t.header.stamp = now;
        t.header.frame_id = "table";
        t.child_frame_id = "cue_tip";
        const geometry_msgs::Pose pose = poseOf(*at);
        t.transform.translation.x = pose.position.x + (jitter > 0 ? noise(random) : 0.0);
        t.transform.translation.y = pose.position.y + (jitter > 0 ? noise(random) : 0.0);
        t.transform.translation.z = pose.position.z + (jitter > 0 ? noise(random) : 0.0);
        t.transform.rotation = pose.orientation;
        broadcaster_.sendTransform(t);
      }
      pace.sleep();
    }
  }

  /// The first contact reported stamped after `after`.
  std::optional<cue_sim::CueContact> contactAfter(const ros::Time& after)
  {
    std::optional<cue_sim::CueContact> found;
    waitFor([&] {
      std::lock_guard<std::mutex> lock(mutex_);
      for (const auto& c : contacts_)
        if (c.header.stamp > after)
        {
          found = c;
          return true;
        }
      return false;
    });
    return found;
  }

  std::vector<cue_sim::CueContact> contactsAfter(const ros::Time& after)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<cue_sim::CueContact> out;
    for (const auto& c : contacts_)
      if (c.header.stamp > after)
        out.push_back(c);
    return out;
  }

  std::vector<cue_sim::ExecutedShot> cueFrameShotsAfter(const ros::Time& after)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<cue_sim::ExecutedShot> out;
    for (const auto& s : shots_)
      if (s.source == "cue_frame" && s.header.stamp > after)
        out.push_back(s);
    return out;
  }

  /// Plays `stroke` at `rate` and checks its strike against the designed one and against what
  /// ~strike_cue gives for the cue's pose and speed at the touch.
  void expectStrike(const Stroke& stroke, const CueStrike<double>& designed, double rate, double jitter = 0,
                    const std::function<bool(double)>& gap = nullptr)
  {
    SCOPED_TRACE(::testing::Message() << "speed " << designed.speed << ", theta " << designed.theta << ", a "
                                      << designed.a << ", b " << designed.b << " at " << rate << " Hz");
    const ros::Time placed = placeCueBall();
    play(
        [&](double t) -> std::optional<CueStick> {
          if (gap && gap(t))
            return std::nullopt;
          return stroke.at(t);
        },
        stroke.duration(), rate, jitter);
    const std::optional<cue_sim::CueContact> contact = contactAfter(placed);
    ASSERT_TRUE(contact) << "no touch reported";
    ASSERT_TRUE(contact->struck) << contact->message;
    EXPECT_EQ(contact->ball_id, 0);
    EXPECT_NEAR(contact->speed, designed.speed, kSpeedShare * designed.speed);
    EXPECT_TRUE(waitFor([&] { return cueFrameShotsAfter(placed).size() == 1; })) << "one ~shots from cue_frame";

    // ~strike_cue, for the cue at the touch and its speed there.
    placeCueBall();
    geometry_msgs::PoseStamped at_touch;
    at_touch.header.frame_id = "table";
    at_touch.pose = poseOf(cueStickFor(cueBall(), designed, kParams, 1e-6));
    const cue_sim::StrikeCue::Response asked = table_.strikeCue(at_touch, designed.speed);
    ASSERT_TRUE(asked.success) << asked.message;
    const cue_sim::Shot& expected = asked.shot;
    EXPECT_EQ(contact->shot.ball_id, expected.ball_id);
    EXPECT_NEAR(contact->shot.speed, expected.speed, kSpeedShare * expected.speed);
    EXPECT_LT(angleBetween(contact->shot.phi, expected.phi), kAngle);
    EXPECT_NEAR(contact->shot.theta, expected.theta, kAngle);
    EXPECT_NEAR(contact->shot.a, expected.a, kOffset);
    EXPECT_NEAR(contact->shot.b, expected.b, kOffset);
    // And the stroke as designed.
    EXPECT_LT(angleBetween(contact->shot.phi, designed.phi), kAngle);
    EXPECT_NEAR(contact->shot.theta, designed.theta, kAngle);
    EXPECT_NEAR(contact->shot.a, designed.a, kOffset);
    EXPECT_NEAR(contact->shot.b, designed.b, kOffset);
  }

  static Stroke strokeFor(const CueStrike<double>& strike)
  {
    Stroke stroke;
    stroke.touching = cueStickFor(cueBall(), strike, kParams, 0.0);
    stroke.speed = strike.speed;
    return stroke;
  }

  ros::NodeHandle nh_;
  TableClient table_;
  tf2_ros::TransformBroadcaster broadcaster_;
  /// The node's tf ticks stamped in [from, to), and the longest time between two of them.
  std::pair<std::size_t, double> ticksBetween(const ros::Time& from, const ros::Time& to)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::size_t n = 0;
    double gap = 0;
    for (std::size_t i = 0; i < ticks_.size(); ++i)
      if (ticks_[i] >= from && ticks_[i] < to)
      {
        ++n;
        if (i > 0 && ticks_[i - 1] >= from)
          gap = std::max(gap, (ticks_[i] - ticks_[i - 1]).toSec());
      }
    return {n, gap};
  }

  ros::Subscriber contacts_sub_, shots_sub_, tf_sub_;
  std::vector<ros::Time> ticks_;
  std::mutex mutex_;
  std::vector<cue_sim::CueContact> contacts_;
  std::vector<cue_sim::ExecutedShot> shots_;
};

/// Over the range of speed, elevation and offsets.
const std::vector<CueStrike<double>> kStrikes = {
    strikeOf(0.5, 0.4, 0.0, 0.0, 0.0),   strikeOf(2.0, -1.2, 0.1, 0.3, 0.2), strikeOf(4.0, 2.5, 0.25, -0.35, 0.1),
    strikeOf(6.0, 0.0, 0.05, 0.0, -0.4), strikeOf(1.2, -2.8, 0.5, 0.2, 0.3),
};

TEST_F(FollowedCueTest, StrokesAt100HzStrikeAsStrikeCueDoesForTheCueAtTheTouch)
{
  for (const auto& s : kStrikes)
    expectStrike(strokeFor(s), s, 100.0);
}

TEST_F(FollowedCueTest, StrokesAt1kHzStrikeAsStrikeCueDoesForTheCueAtTheTouch)
{
  const ros::Time from = ros::Time::now();
  for (const auto& s : kStrikes)
    expectStrike(strokeFor(s), s, 1000.0);
  // Following 1 kHz of the cue's tf, the node's own tf keeps its rate (the node-load test's bounds).
  const ros::Time to = ros::Time::now() - ros::Duration(0.1);
  ASSERT_TRUE(waitFor([&] { return ticksBetween(to, to + ros::Duration(1)).first > 0; }));
  const auto [ticks, gap] = ticksBetween(from, to);
  const double rate = ticks / (to - from).toSec();
  EXPECT_GT(rate, 0.9 * kPublishRate) << "tf ticks per second while following";
  EXPECT_LT(rate, 1.1 * kPublishRate);
  EXPECT_LT(gap, 5.0 / kPublishRate) << "the longest pause of tf while following [s]";
}

TEST_F(FollowedCueTest, HandMadePosesWithJitterAndGapsStillStrikeAsDesigned)
{
  // 0.05 mm of a tracker's noise on the tip, a 0.2 s gap (beyond ~cue/max_gap) while the cue
  // waits, and one sample in five missing all along.
  const CueStrike<double> designed = strikeOf(3.0, 1.0, 0.15, -0.2, 0.25);
  Stroke stroke = strokeFor(designed);
  stroke.wait = 0.45;
  std::mt19937 random(7);
  std::vector<bool> dropped(100000);
  for (std::size_t i = 0; i < dropped.size(); ++i)
    dropped[i] = random() % 5 == 0;
  expectStrike(stroke, designed, 1000.0, 5e-5, [&](double t) {
    return (t > 0.1 && t < 0.3) || dropped[static_cast<std::size_t>(t * 1e4) % dropped.size()];
  });
}

TEST_F(FollowedCueTest, ACueRestingAgainstTheBallOrCreepingIntoItStrikesNothing)
{
  const CueStrike<double> aim = strikeOf(1.0, 0.7, 0.0, 0.1, 0.0);
  const CueStick touching = cueStickFor(cueBall(), aim, kParams, 0.0);
  const Vec3<double> back = -touching.axis.normalized();
  const ros::Time placed = placeCueBall();
  // Resting 0.05 mm short of the ball with 0.05 mm of jitter, for a second at 1 kHz.
  play(
      [&](double) -> std::optional<CueStick> {
        CueStick cue = touching;
        cue.tip += back * 5e-5;
        return cue;
      },
      1.0, 1000.0, 5e-5);
  // Then drawn back 3 mm (clear of it: ~cue/rearm_distance) and creeping into it at 1 mm/s for
  // 4 s, 1 mm into where it stands: it touches, and is refused as slower than ~cue/min_speed.
  const ros::Time creeping = ros::Time::now();
  play(
      [&](double t) -> std::optional<CueStick> {
        CueStick cue = touching;
        cue.tip += back * (0.003 - 0.001 * t);
        return cue;
      },
      4.0, 1000.0);
  EXPECT_TRUE(cueFrameShotsAfter(placed).empty());
  for (const auto& c : contactsAfter(placed))
  {
    EXPECT_FALSE(c.struck) << c.message;
    EXPECT_LT(c.speed, 0.05) << "resting or creeping, under ~cue/min_speed";
  }
  ASSERT_TRUE(waitFor([&] { return !contactsAfter(creeping).empty(); })) << "the creeping touch is reported";
  const cue_sim::CueContact crept = contactsAfter(creeping).front();
  EXPECT_NEAR(crept.speed, 0.001, 0.0005);
  EXPECT_NE(crept.message.find("a strike needs"), std::string::npos) << crept.message;
  EXPECT_NEAR((crept.header.stamp - creeping).toSec(), 3.0, 0.1);
  const cue_sim::TableStateConstPtr state = table_.freshState();
  ASSERT_EQ(state->balls.size(), 1u);
  EXPECT_FALSE(state->moving);
  EXPECT_NEAR(state->balls[0].position.x, kBallX, 1e-9);
  EXPECT_NEAR(state->balls[0].position.y, kBallY, 1e-9);
}

}  // namespace
