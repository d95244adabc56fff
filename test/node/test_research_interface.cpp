// The research interface through a real master: ~predict and ~predict_batch against ~strike
// (bit for bit), ~events, execution noise, and refusals by field.
#include <cue_sim/Event.h>
#include <cue_sim/ExecutedShot.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <visualization_msgs/InteractiveMarkerFeedback.h>
#include <visualization_msgs/InteractiveMarkerInit.h>
#include <visualization_msgs/InteractiveMarkerUpdate.h>
#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <vector>

#include "cue_sim/physics/cue_aim.hpp"
#include "physics_of_msgs.hpp"
#include "table_client.hpp"

namespace
{
const double kRadius = 0.028575, kMuSlide = 0.2, kMuRoll = 0.01, kGravity = 9.81;

/// A few balls that a 1 m/s shot sends into each other and a cushion, and that rest within
/// about 8 s.
const std::vector<int> kIds = {0, 1, 2, 3};
const std::vector<std::pair<double, double>> kPositions = {{-0.6, 0.0}, {0.0, 0.02}, {0.15, -0.2}, {0.3, 0.25}};

void expectSameBalls(const std::vector<cue_sim::BallState>& got, const std::vector<cue_sim::BallState>& want,
                     const std::string& what)
{
  const auto g = TableClient::byId(got), w = TableClient::byId(want);
  ASSERT_EQ(g.size(), w.size()) << what;
  for (const auto& [id, b] : w)
  {
    const cue_sim::BallState& a = g.at(id);
    EXPECT_EQ(a.position.x, b.position.x) << what << ", ball " << id;
    EXPECT_EQ(a.position.y, b.position.y) << what << ", ball " << id;
    EXPECT_EQ(a.position.z, b.position.z) << what << ", ball " << id;
    EXPECT_EQ(a.velocity.x, b.velocity.x) << what << ", ball " << id;
    EXPECT_EQ(a.velocity.y, b.velocity.y) << what << ", ball " << id;
    EXPECT_EQ(a.motion, b.motion) << what << ", ball " << id;
    EXPECT_EQ(a.pocketed, b.pocketed) << what << ", ball " << id;
  }
}

void expectSameEvents(const std::vector<cue_sim::Event>& got, const std::vector<cue_sim::Event>& want,
                      const std::string& what)
{
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < want.size(); ++i)
  {
    EXPECT_EQ(got[i].kind, want[i].kind) << what << ", event " << i;
    EXPECT_EQ(got[i].ball_id, want[i].ball_id) << what << ", event " << i;
    EXPECT_EQ(got[i].other_ball_id, want[i].other_ball_id) << what << ", event " << i;
    EXPECT_EQ(got[i].obstacle, want[i].obstacle) << what << ", event " << i;
    EXPECT_EQ(got[i].shot_time, want[i].shot_time) << what << ", event " << i;
    EXPECT_EQ(got[i].ball_speed, want[i].ball_speed) << what << ", event " << i;
    EXPECT_EQ(got[i].other_speed, want[i].other_speed) << what << ", event " << i;
  }
}

class ResearchInterfaceTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    events_sub_ = nh_.subscribe<cue_sim::Event>("/table/events", 1000, [this](const cue_sim::EventConstPtr& e) {
      std::lock_guard<std::mutex> lock(mutex_);
      events_.push_back(*e);
    });
    ASSERT_TRUE(table_.rack("custom", kIds, kPositions).success);
  }

  /// The ~events stamped at or after `stamp`, once `count` of them have arrived (~events comes on
  /// a connection of its own: it may trail ~state at rest), or all there are after the deadline.
  std::vector<cue_sim::Event> eventsSince(const ros::Time& stamp, std::size_t count)
  {
    std::vector<cue_sim::Event> out;
    waitFor([&] {
      std::lock_guard<std::mutex> lock(mutex_);
      out.clear();
      for (const auto& e : events_)
        if (e.stamp >= stamp)
          out.push_back(e);
      return out.size() >= count;
    });
    return out;
  }

  ros::NodeHandle nh_;
  TableClient table_;
  std::mutex mutex_;
  std::vector<cue_sim::Event> events_;
  ros::Subscriber events_sub_;  // last: destroyed first, before what its callback uses
};

TEST_F(ResearchInterfaceTest, StrikeDoesExactlyWhatPredictSaidBitForBit)
{
  const cue_sim::TableState before = *table_.atRest(5);
  const cue_sim::Shot shot = TableClient::shot(0, 1.0, 0.05, 0.1, 0.2, -0.1);
  const cue_sim::Prediction prediction = table_.predict(shot);
  ASSERT_TRUE(prediction.success) << prediction.message;
  ASSERT_GE(prediction.events.size(), 6u);
  bool ball_ball = false, cushion = false;
  for (const auto& e : prediction.events)
  {
    ball_ball = ball_ball || e.kind == cue_sim::Event::BALL_BALL;
    cushion = cushion || e.kind == cue_sim::Event::BALL_CUSHION;
  }
  EXPECT_TRUE(ball_ball && cushion) << "the scene should have ball-ball and cushion events";

  // Predicting left the live table as it was.
  const cue_sim::TableState after_predict = *table_.freshState();
  EXPECT_FALSE(after_predict.moving);
  expectSameBalls(after_predict.balls, before.balls, "after ~predict");

  const cue_sim::Strike::Response struck = table_.strike(shot);
  ASSERT_TRUE(struck.success) << struck.message;
  EXPECT_EQ(struck.time_to_rest, prediction.time_to_rest);
  EXPECT_EQ(struck.num_events, prediction.events.size());
  EXPECT_EQ(struck.executed.speed, shot.speed);  // no noise by default
  EXPECT_EQ(struck.executed.a, shot.a);
  const cue_sim::TableState rest = *table_.atRest(prediction.time_to_rest + 10);
  expectSameBalls(rest.balls, prediction.final_balls, "live table at rest against the prediction");

  // ~events carried every event, stamped at the strike's stamp plus its shot time.
  const std::vector<cue_sim::Event> live = eventsSince(struck.stamp, prediction.events.size());
  expectSameEvents(live, prediction.events, "~events against the prediction");
  for (const auto& e : live)
    EXPECT_NEAR((e.stamp - struck.stamp).toSec(), e.shot_time, 1e-9);
}

TEST_F(ResearchInterfaceTest, PredictFromGivenBallsMatchesTheClosedFormAndSamplesTheTrajectory)
{
  // One ball, struck level through its centre along +x: it slides, then rolls to rest
  // (PHYSICS.md): tau_slide = 2 v0 / (7 mu_s g); then |5/7 v0|^2 / (2 mu_r g) of rolling.
  cue_sim::BallState ball;
  ball.id = 0;
  ball.position.x = -0.8;
  ball.position.y = 0.1;
  const double period = 0.01;
  const cue_sim::Prediction p = table_.predict(TableClient::shot(0, 0.4, 0.0), {ball}, period);
  ASSERT_TRUE(p.success) << p.message;
  ASSERT_EQ(p.final_balls.size(), 1u);
  ASSERT_FALSE(p.samples.empty());
  const double v0 = p.samples[0].balls[0].velocity.x;
  ASSERT_GT(v0, 0.3);
  const double t_slide = 2 * v0 / (7 * kMuSlide * kGravity), v_roll = 5.0 / 7.0 * v0;
  const double distance =
      v0 * t_slide - 0.5 * kMuSlide * kGravity * t_slide * t_slide + v_roll * v_roll / (2 * kMuRoll * kGravity);
  EXPECT_NEAR(p.final_balls[0].position.x, -0.8 + distance, 1e-12);
  EXPECT_EQ(p.final_balls[0].position.y, 0.1);  // nothing turns it
  EXPECT_NEAR(p.time_to_rest, t_slide + v_roll / (kMuRoll * kGravity), 1e-12);
  ASSERT_EQ(p.events.size(), 2u);
  EXPECT_EQ(p.events[0].kind, cue_sim::Event::SLIDE_TO_ROLL);
  EXPECT_EQ(p.events[1].kind, cue_sim::Event::ROLL_TO_STOP);
  EXPECT_NEAR(p.events[0].shot_time, t_slide, 1e-12);
  EXPECT_NEAR(p.events[0].ball_speed, v_roll, 1e-12);

  // Samples every 10 ms from the strike, on the same closed form.
  EXPECT_EQ(p.samples.size(), static_cast<std::size_t>(std::floor(p.time_to_rest / period)) + 1);
  for (std::size_t k = 0; k < p.samples.size(); ++k)
  {
    const double t = k * period;
    double x = -0.8;
    if (t <= t_slide)
      x += v0 * t - 0.5 * kMuSlide * kGravity * t * t;
    else
      x += v0 * t_slide - 0.5 * kMuSlide * kGravity * t_slide * t_slide + v_roll * (t - t_slide) -
           0.5 * kMuRoll * kGravity * (t - t_slide) * (t - t_slide);
    ASSERT_NEAR(p.samples[k].balls[0].position.x, x, 1e-12) << "sample " << k;
  }
  // The live table was not touched: it still has the four balls of the rack.
  EXPECT_EQ(table_.freshState()->balls.size(), kIds.size());
}

TEST_F(ResearchInterfaceTest, PredictBatchGivesWhatPredictGivesShotByShot)
{
  std::vector<cue_sim::Shot> shots;
  for (int k = 0; k < 7; ++k)
    shots.push_back(TableClient::shot(0, 0.5 + 0.6 * k, -0.3 + 0.1 * k, 0.05 * k, 0.05 * (k - 3), 0.04 * (3 - k)));
  shots.push_back(TableClient::shot(0, 20.0, 0.0));  // too fast: refused alone
  shots.push_back(TableClient::shot(9, 1.0, 0.0));   // no ball 9 in this rack
  const cue_sim::PredictBatch::Response batch = table_.predictBatch(shots);
  ASSERT_TRUE(batch.success) << batch.message;
  ASSERT_EQ(batch.predictions.size(), shots.size());
  for (std::size_t i = 0; i < 7; ++i)
  {
    const cue_sim::Prediction alone = table_.predict(shots[i]);
    const cue_sim::Prediction& in_batch = batch.predictions[i];
    ASSERT_TRUE(in_batch.success) << in_batch.message;
    EXPECT_EQ(in_batch.time_to_rest, alone.time_to_rest) << "shot " << i;
    expectSameBalls(in_batch.final_balls, alone.final_balls, "shot " + std::to_string(i));
    expectSameEvents(in_batch.events, alone.events, "shot " + std::to_string(i));
  }
  EXPECT_FALSE(batch.predictions[7].success);
  EXPECT_NE(batch.predictions[7].message.find("speed"), std::string::npos) << batch.predictions[7].message;
  EXPECT_FALSE(batch.predictions[8].success);
  EXPECT_NE(batch.predictions[8].message.find("ball_id 9"), std::string::npos) << batch.predictions[8].message;
}

TEST_F(ResearchInterfaceTest, NoiseIsReproducibleFromItsSeedAndReportsTheShotExecuted)
{
  const cue_sim::Shot shot = TableClient::shot(0, 1.0, 0.0, 0.2, 0.1, 0.1);
  const cue_sim::Prediction first = table_.predict(shot, {}, 0, true, 5);
  const cue_sim::Prediction again = table_.predict(shot, {}, 0, true, 5);
  const cue_sim::Prediction other = table_.predict(shot, {}, 0, true, 6);
  ASSERT_TRUE(first.success && again.success && other.success);
  EXPECT_NE(first.executed.phi, shot.phi);
  EXPECT_NE(first.executed.speed, shot.speed);
  EXPECT_EQ(first.executed.phi, again.executed.phi);
  EXPECT_EQ(first.executed.b, again.executed.b);
  expectSameBalls(again.final_balls, first.final_balls, "the same seed");
  EXPECT_NE(other.executed.phi, first.executed.phi);
  // The noisy shot is the executed one: predicting it without noise gives the same numbers.
  const cue_sim::Prediction replay = table_.predict(first.executed);
  EXPECT_EQ(replay.time_to_rest, first.time_to_rest);
  expectSameBalls(replay.final_balls, first.final_balls, "the executed shot without noise");
}

TEST_F(ResearchInterfaceTest, TheNoisyTableStrikesWithNoiseAndSaysHow)
{
  TableClient noisy("/noisy_table");
  ASSERT_TRUE(noisy.rack("custom", kIds, kPositions).success);
  const cue_sim::TableState start = *noisy.atRest(5);
  const cue_sim::Shot shot = TableClient::shot(0, 1.0, 0.0);
  const cue_sim::Strike::Response struck = noisy.strike(shot);
  ASSERT_TRUE(struck.success) << struck.message;
  EXPECT_NE(struck.executed.phi, shot.phi);
  EXPECT_NE(struck.executed.speed, shot.speed);
  // What it reports is what it did: the executed shot, predicted from the same balls.
  const cue_sim::Prediction p = noisy.predict(struck.executed, start.balls);
  ASSERT_TRUE(p.success) << p.message;
  EXPECT_EQ(p.time_to_rest, struck.time_to_rest);
  EXPECT_EQ(p.events.size(), struck.num_events);
}

TEST_F(ResearchInterfaceTest, BadPredictionsAreRefusedByFieldAndChangeNothing)
{
  const cue_sim::TableState before = *table_.atRest(5);
  const cue_sim::Shot fine = TableClient::shot(0, 1.0, 0.0);
  cue_sim::Prediction p = table_.predict(fine, {}, 1e-5);
  EXPECT_FALSE(p.success);
  EXPECT_NE(p.message.find("sample_period"), std::string::npos) << p.message;
  p = table_.predict(TableClient::shot(0, 1.0, 0.0, 0, 0.6, 0));
  EXPECT_FALSE(p.success);
  EXPECT_NE(p.message.find("a and b"), std::string::npos) << p.message;

  cue_sim::BallState a, b;
  a.id = 0;
  b.id = 1;
  b.position.x = 0.01;  // overlaps ball 0
  p = table_.predict(fine, {a, b});
  EXPECT_FALSE(p.success);
  EXPECT_NE(p.message.find("balls:"), std::string::npos) << p.message;
  b.id = 16;
  b.position.x = 0.5;
  p = table_.predict(fine, {a, b});
  EXPECT_FALSE(p.success);
  EXPECT_NE(p.message.find("balls[1].id"), std::string::npos) << p.message;
  b.id = 1;
  b.velocity.z = -0.1;  // into the slate
  p = table_.predict(fine, {a, b});
  EXPECT_FALSE(p.success);
  EXPECT_NE(p.message.find("balls[1].velocity.z = -0.1"), std::string::npos) << p.message;
  b.velocity.z = 0;
  b.position.x = 5;  // off the table
  p = table_.predict(fine, {a, b});
  EXPECT_FALSE(p.success);
  EXPECT_NE(p.message.find("balls:"), std::string::npos) << p.message;

  const auto batch = table_.predictBatch({fine}, {a, b});
  EXPECT_FALSE(batch.success);
  EXPECT_NE(batch.message.find("balls:"), std::string::npos) << batch.message;
  expectSameBalls(table_.freshState()->balls, before.balls, "after refused predictions");

  // While the live table moves, it is not a start for a prediction.
  ASSERT_TRUE(table_.strike(fine).success);
  p = table_.predict(fine);
  EXPECT_FALSE(p.success);
  EXPECT_NE(p.message.find("moving"), std::string::npos) << p.message;
}

/// A cue pose in the table frame that makes `shot` on a ball at `centre` (cueStickFor), its
/// tip `gap` metres short.
geometry_msgs::PoseStamped cuePose(const cue_sim::BallState& ball, const cue_sim::Shot& shot, double gap)
{
  cue_sim::physics::Ball<double> b;
  b.r = centreOf(ball);
  const cue_sim::physics::CueStick cue =
      cue_sim::physics::cueStickFor(b, strikeOfShot(shot), cue_sim::physics::PhysicsParams<double>(), gap);
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), cue.axis);
  geometry_msgs::PoseStamped pose;
  pose.header.frame_id = "table";
  pose.pose.position.x = cue.tip.x();
  pose.pose.position.y = cue.tip.y();
  pose.pose.position.z = cue.tip.z();
  pose.pose.orientation.x = q.x();
  pose.pose.orientation.y = q.y();
  pose.pose.orientation.z = q.z();
  pose.pose.orientation.w = q.w();
  return pose;
}

TEST_F(ResearchInterfaceTest, StrikeCueFindsTheBallAndTheStrikeFromThePoseInAnyFrame)
{
  const cue_sim::TableState rack = *table_.atRest(5);
  const auto balls = TableClient::byId(rack.balls);
  const cue_sim::Shot planned = TableClient::shot(0, 1.0, 0.2, 0.15, 0.2, -0.1);
  geometry_msgs::PoseStamped pose = cuePose(balls.at(0), planned, 0.03);

  // The same pose in a robot's frame: the table seen from a base 1 m along x, 2 m along y,
  // 0.5 m down, turned a quarter turn about z.
  tf2_ros::StaticTransformBroadcaster broadcaster;
  geometry_msgs::TransformStamped base;
  base.header.stamp = ros::Time::now();
  base.header.frame_id = "table";
  base.child_frame_id = "robot_base";
  base.transform.translation.x = 1;
  base.transform.translation.y = 2;
  base.transform.translation.z = -0.5;
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  base.transform.rotation.x = turn.x();
  base.transform.rotation.y = turn.y();
  base.transform.rotation.z = turn.z();
  base.transform.rotation.w = turn.w();
  broadcaster.sendTransform(base);
  const Eigen::Vector3d tip_table(pose.pose.position.x, pose.pose.position.y, pose.pose.position.z);
  const Eigen::Vector3d tip_base = turn.inverse() * (tip_table - Eigen::Vector3d(1, 2, -0.5));
  const Eigen::Quaterniond q_table(pose.pose.orientation.w, pose.pose.orientation.x, pose.pose.orientation.y,
                                   pose.pose.orientation.z);
  const Eigen::Quaterniond q_base = turn.inverse() * q_table;
  geometry_msgs::PoseStamped in_base = pose;
  in_base.header.frame_id = "robot_base";
  in_base.pose.position.x = tip_base.x();
  in_base.pose.position.y = tip_base.y();
  in_base.pose.position.z = tip_base.z();
  in_base.pose.orientation.x = q_base.x();
  in_base.pose.orientation.y = q_base.y();
  in_base.pose.orientation.z = q_base.z();
  in_base.pose.orientation.w = q_base.w();

  // The node waits ~tf_timeout for a frame, not for it to appear: a robot asks again once its
  // base frame is on tf. Until then every call is refused and changes nothing.
  cue_sim::StrikeCue::Response struck = table_.strikeCue(in_base, 1.0);
  waitFor(
      [&] {
        if (struck.success || struck.message.find("cannot transform") == std::string::npos)
          return true;
        struck = table_.strikeCue(in_base, 1.0);
        return false;
      },
      kGenerousWait, 0.05);
  ASSERT_TRUE(struck.success) << struck.message;
  EXPECT_EQ(struck.shot.ball_id, 0);
  EXPECT_NEAR(struck.shot.phi, planned.phi, 1e-9);
  EXPECT_NEAR(struck.shot.theta, planned.theta, 1e-9);
  EXPECT_NEAR(struck.shot.a, planned.a, 1e-9);
  EXPECT_NEAR(struck.shot.b, planned.b, 1e-9);
  EXPECT_EQ(struck.executed.phi, struck.shot.phi);  // no noise on this table
  // It struck what it says: that shot predicted from the same balls takes the same time.
  const cue_sim::Prediction p = table_.predict(struck.executed, rack.balls);
  ASSERT_TRUE(p.success) << p.message;
  EXPECT_EQ(p.time_to_rest, struck.time_to_rest);
  EXPECT_EQ(p.events.size(), struck.num_events);
  // The cue stick is shown along the stroke, its tip at the ball.
  const auto cue = ros::topic::waitForMessage<visualization_msgs::Marker>("/table/cue", ros::Duration(kGenerousWait));
  ASSERT_TRUE(cue);
  EXPECT_EQ(cue->type, visualization_msgs::Marker::CYLINDER);
  const Eigen::Quaterniond q(cue->pose.orientation.w, cue->pose.orientation.x, cue->pose.orientation.y,
                             cue->pose.orientation.z);
  const Eigen::Vector3d tip = Eigen::Vector3d(cue->pose.position.x, cue->pose.position.y, cue->pose.position.z) +
                              q * Eigen::Vector3d::UnitZ() * (cue->scale.z / 2);
  const auto& b0 = balls.at(0).position;
  EXPECT_NEAR((tip - Eigen::Vector3d(b0.x, b0.y, b0.z)).norm(), kRadius + 0.005, 2e-3);
  table_.atRest(30);
}

TEST_F(ResearchInterfaceTest, StrikeCueRefusesMissesMiscuesBlockedCuesAndUnknownFrames)
{
  const cue_sim::TableState rack = *table_.atRest(5);
  const auto balls = TableClient::byId(rack.balls);
  const geometry_msgs::PoseStamped good = cuePose(balls.at(0), TableClient::shot(0, 1, 0.0), 0.03);
  geometry_msgs::PoseStamped pose = good;
  pose.pose.position.y += 0.1;  // beside the ball
  EXPECT_NE(table_.strikeCue(pose, 1).message.find("meets no ball"), std::string::npos);
  pose = good;
  pose.pose.position.y -= 0.8 * kRadius;  // inside it, but too far out for the tip
  EXPECT_NE(table_.strikeCue(pose, 1).message.find("miscue"), std::string::npos);
  pose = good;
  pose.header.frame_id = "nowhere";
  EXPECT_NE(table_.strikeCue(pose, 1).message.find("cannot transform"), std::string::npos);
  pose = good;
  pose.pose.orientation.w = 0;
  EXPECT_NE(table_.strikeCue(pose, 1).message.find("unit quaternion"), std::string::npos);
  EXPECT_NE(table_.strikeCue(good, 13).message.find("speed"), std::string::npos);
  // Ball 1 struck away from ball 0, along their line: the shaft passes through ball 0.
  const cue_sim::Shot backwards = TableClient::shot(1, 1, std::atan2(0.02, 0.6));
  EXPECT_NE(table_.strikeCue(cuePose(balls.at(1), backwards, 0.01), 1).message.find("shaft passes through ball 0"),
            std::string::npos);
  expectSameBalls(table_.freshState()->balls, rack.balls, "after refused cue strikes");
}

TEST_F(ResearchInterfaceTest, PredictShowsThePathsOfTheBallsThatMoveUntilTheyRest)
{
  const cue_sim::TableState rack = *table_.atRest(5);
  const cue_sim::Prediction p = table_.predict(TableClient::shot(0, 1.0, 0.05, 0.1, 0.2, -0.1));
  ASSERT_TRUE(p.success) << p.message;
  // Published before ~predict answers, and latched: a new subscriber gets this prediction's.
  const auto preview =
      ros::topic::waitForMessage<visualization_msgs::MarkerArray>("/table/preview", ros::Duration(kGenerousWait));
  ASSERT_TRUE(preview);
  ASSERT_FALSE(preview->markers.empty());
  EXPECT_EQ(preview->markers[0].action, visualization_msgs::Marker::DELETEALL);
  const auto start = TableClient::byId(rack.balls), end = TableClient::byId(p.final_balls);
  std::size_t moved = 0;
  for (const auto& [id, b] : end)
    moved += b.position.x != start.at(id).position.x || b.position.y != start.at(id).position.y;
  ASSERT_EQ(preview->markers.size(), 1 + moved);
  for (std::size_t k = 1; k < preview->markers.size(); ++k)
  {
    const auto& line = preview->markers[k];
    EXPECT_EQ(line.type, visualization_msgs::Marker::LINE_STRIP);
    ASSERT_GT(line.points.size(), 10u);
    EXPECT_EQ(line.points.front().x, start.at(line.id).position.x) << "ball " << line.id;
    EXPECT_EQ(line.points.back().x, end.at(line.id).position.x) << "ball " << line.id;
    EXPECT_EQ(line.points.back().y, end.at(line.id).position.y) << "ball " << line.id;
  }
}

/// Every message on ~preview, as rviz sees them.
class PreviewWatcher
{
public:
  explicit PreviewWatcher(ros::NodeHandle& nh)
    : sub_(nh.subscribe<visualization_msgs::MarkerArray>("/table/preview", 10,
                                                         [this](const visualization_msgs::MarkerArrayConstPtr& m) {
                                                           std::lock_guard<std::mutex> lock(mutex_);
                                                           last_ = *m;
                                                           ++count_;
                                                         }))
  {
  }
  /// Waits until the latest message draws paths (more than its DELETEALL), or is only a
  /// DELETEALL: true once it does as asked.
  bool becomes(bool draws_paths)
  {
    return waitFor([&] {
      std::lock_guard<std::mutex> lock(mutex_);
      return count_ > 0 && !last_.markers.empty() && (last_.markers.size() > 1) == draws_paths;
    });
  }

private:
  std::mutex mutex_;
  visualization_msgs::MarkerArray last_;
  int count_ = 0;
  ros::Subscriber sub_;
};

TEST_F(ResearchInterfaceTest, APreviewLeavesTheScreenWhenTheTableMovesOn)
{
  // From a cleared preview (a rack clears it), each step turns it the other way.
  PreviewWatcher preview(nh_);
  ASSERT_TRUE(table_.rack("eight").success);
  ASSERT_TRUE(preview.becomes(false)) << "racked: no preview";
  table_.atRest(5);
  const cue_sim::Shot shot = TableClient::shot(0, 1.5, 0.3);
  const cue_sim::Prediction first = table_.predict(shot);
  ASSERT_TRUE(first.success) << first.message;
  EXPECT_TRUE(preview.becomes(true)) << "a prediction draws its paths";
  ASSERT_TRUE(table_.strike(shot).success);
  EXPECT_TRUE(preview.becomes(false)) << "struck: the preview is cleared";
  table_.atRest(30);
  ASSERT_TRUE(table_.rack("eight").success);  // the cue ball back, whatever the shot did
  table_.atRest(5);

  for (const std::string edit : {"rack", "reset"})
  {
    const cue_sim::Prediction again = table_.predict(shot);
    ASSERT_TRUE(again.success) << edit << ": " << again.message;
    EXPECT_TRUE(preview.becomes(true));
    if (edit == "rack")
      ASSERT_TRUE(table_.rack("eight").success);
    else
    {
      std_srvs::Trigger reset;
      ASSERT_TRUE(ros::service::call("/table/reset", reset) && reset.response.success);
    }
    EXPECT_TRUE(preview.becomes(false)) << edit << ": the preview is cleared";
    table_.atRest(5);
  }
}

/// Sets doubles and strings of a node's dynamic_reconfigure; answers the configuration after.
dynamic_reconfigure::Config reconfigure(const std::string& node, const std::map<std::string, double>& doubles,
                                        const std::map<std::string, std::string>& strings = {})
{
  dynamic_reconfigure::Reconfigure srv;
  for (const auto& [name, value] : doubles)
  {
    dynamic_reconfigure::DoubleParameter p;
    p.name = name;
    p.value = value;
    srv.request.config.doubles.push_back(p);
  }
  for (const auto& [name, value] : strings)
  {
    dynamic_reconfigure::StrParameter p;
    p.name = name;
    p.value = value;
    srv.request.config.strs.push_back(p);
  }
  EXPECT_TRUE(ros::service::call(node + "/set_parameters", srv));
  return srv.response.config;
}

double doubleOf(const dynamic_reconfigure::Config& config, const std::string& name)
{
  for (const auto& p : config.doubles)
    if (p.name == name)
      return p.value;
  ADD_FAILURE() << name << " is not in the configuration";
  return std::nan("");
}

std::string stringOf(const dynamic_reconfigure::Config& config, const std::string& name)
{
  for (const auto& p : config.strs)
    if (p.name == name)
      return p.value;
  ADD_FAILURE() << name << " is not in the configuration";
  return "";
}

/// Time to rest [s] of one ball struck level through its centre, by the closed form.
double restTime(const cue_sim::Prediction& p, double mu_roll)
{
  const double v0 = p.samples.at(0).balls.at(0).velocity.x;
  return 2 * v0 / (7 * kMuSlide * kGravity) + 5.0 / 7.0 * v0 / (mu_roll * kGravity);
}

TEST_F(ResearchInterfaceTest, ReconfigureStartsFromTheNodesParametersAndChangesPhysicsBetweenShots)
{
  // The noisy table was started with mu_roll 0.015 (its launch parameters), not the default.
  EXPECT_EQ(doubleOf(reconfigure("/noisy_table", {}), "mu_roll"), 0.015);
  const dynamic_reconfigure::Config start = reconfigure("/table", {});
  EXPECT_EQ(doubleOf(start, "mu_roll"), kMuRoll);
  EXPECT_EQ(doubleOf(start, "mu_slide"), kMuSlide);
  EXPECT_EQ(stringOf(start, "ball_ball_model"), "frictional");

  cue_sim::BallState lone;
  lone.id = 0;
  lone.position.x = -0.8;
  const cue_sim::Shot gentle = TableClient::shot(0, 0.3, 0.0);
  // At rest, a change applies at once.
  EXPECT_EQ(doubleOf(reconfigure("/table", {{"mu_roll", 0.02}}), "mu_roll"), 0.02);
  cue_sim::Prediction p = table_.predict(gentle, {lone}, 0.01);
  ASSERT_TRUE(p.success) << p.message;
  EXPECT_NEAR(p.time_to_rest, restTime(p, 0.02), 1e-12);

  // During a shot, the shot finishes with the physics it started with.
  const cue_sim::Shot shot = TableClient::shot(0, 1.0, 0.05, 0.1, 0.2, -0.1);
  const cue_sim::Prediction planned = table_.predict(shot);
  ASSERT_TRUE(table_.strike(shot).success);
  reconfigure("/table", {{"mu_roll", kMuRoll}});
  const cue_sim::TableState rest = *table_.atRest(planned.time_to_rest + 10);
  expectSameBalls(rest.balls, planned.final_balls, "a shot during a reconfiguration");
  p = table_.predict(gentle, {lone}, 0.01);
  EXPECT_NEAR(p.time_to_rest, restTime(p, kMuRoll), 1e-12);

  // A value that is not a number, or out of a range that depends on the others, is refused, and
  // the last valid one stays; one beyond its declared range is clamped to it by
  // dynamic_reconfigure, as rqt's sliders show it.
  EXPECT_EQ(doubleOf(reconfigure("/table", {{"mu_slide", std::nan("")}}), "mu_slide"), kMuSlide);
  EXPECT_EQ(doubleOf(reconfigure("/table", {{"real_time_factor", std::nan("")}}), "real_time_factor"), 1.0);
  EXPECT_EQ(doubleOf(reconfigure("/table", {{"cushion_height", 0.5}}), "cushion_height"), 0.036576);
  EXPECT_EQ(table_.predict(gentle, {lone}, 0.01).time_to_rest, p.time_to_rest);
  EXPECT_EQ(doubleOf(reconfigure("/table", {{"e_ball", 1.5}}), "e_ball"), 1.0);
  EXPECT_EQ(doubleOf(reconfigure("/table", {{"gravity", std::numeric_limits<double>::infinity()}}), "gravity"), 30);
  reconfigure("/table", {{"e_ball", 0.95}, {"gravity", kGravity}});
  // The node is alive and strikes after all of it.
  const cue_sim::Strike::Response alive = table_.strike(gentle);
  EXPECT_TRUE(alive.success) << alive.message;
  table_.atRest(20);

  // Another model gives other physics; back again, the same as before.
  ASSERT_TRUE(table_.rack("custom", kIds, kPositions).success);
  const cue_sim::Prediction frictional = table_.predict(shot);
  EXPECT_EQ(stringOf(reconfigure("/table", {}, {{"ball_ball_model", "frictionless"}}), "ball_ball_model"),
            "frictionless");
  EXPECT_NE(table_.predict(shot).time_to_rest, frictional.time_to_rest);
  reconfigure("/table", {}, {{"ball_ball_model", "frictional"}});
  EXPECT_EQ(table_.predict(shot).time_to_rest, frictional.time_to_rest);
}

// Issue 33 on the node: with the sequential cue chosen at run time, a steep stroke jumps the cue
// ball over a ball a foot ahead. The prediction has its landings; the live table's tf carries its
// height and ~state its motion (AIRBORNE), and it comes back to the cloth at rest where the
// prediction said. The planar cue, chosen again, keeps the same stroke on the cloth.
TEST_F(ResearchInterfaceTest, AJumpShotFliesInTfWhenTheSequentialCueIsChosen)
{
  EXPECT_EQ(stringOf(reconfigure("/table", {}), "cue_model"), "planar");
  EXPECT_EQ(stringOf(reconfigure("/table", {}, {{"cue_model", "sequential"}}), "cue_model"), "sequential");
  ASSERT_TRUE(table_.rack("custom", {0, 1}, {{-0.6, 0.0}, {-0.6 + 0.3048, 0.0}}).success);
  table_.atRest(10);
  const cue_sim::Shot jump = TableClient::shot(0, 3.0, 0.0, 0.8);
  const cue_sim::Prediction planned = table_.predict(jump, {}, 0.005);
  ASSERT_TRUE(planned.success) << planned.message;
  int landings = 0;
  for (const auto& e : planned.events)
  {
    landings += e.kind == cue_sim::Event::BALL_SLATE && e.ball_id == 0;
    if (e.kind == cue_sim::Event::BALL_SLATE)
    {
      EXPECT_EQ(e.kind_name, "ball_slate");
    }
  }
  EXPECT_GT(landings, 3);
  // Its first event is its landing, and before it the samples have it beyond the other ball, in
  // the air: it flew over.
  ASSERT_EQ(planned.events.front().kind, cue_sim::Event::BALL_SLATE);
  bool beyond_in_the_air = false;
  for (std::size_t k = 0; k < planned.samples.size() && k * planned.sample_period < planned.events.front().shot_time;
       ++k)
    for (const auto& b : planned.samples[k].balls)
      beyond_in_the_air |= b.id == 0 && b.position.x > -0.6 + 0.3048 + 2 * kRadius && b.position.z > kRadius + 0.01;
  EXPECT_TRUE(beyond_in_the_air);

  std::mutex mutex;
  double highest = 0;
  bool airborne_seen = false;
  ros::Subscriber tf = nh_.subscribe<tf2_msgs::TFMessage>("/tf", 1000, [&](const tf2_msgs::TFMessageConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto& t : m->transforms)
      if (t.child_frame_id == "ball_0")
        highest = std::max(highest, t.transform.translation.z);
  });
  ros::Subscriber state =
      nh_.subscribe<cue_sim::TableState>("/table/state", 1000, [&](const cue_sim::TableStateConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        for (const auto& b : m->balls)
          airborne_seen |= b.id == 0 && b.motion == cue_sim::BallState::AIRBORNE;
      });
  ASSERT_TRUE(waitFor([&] { return tf.getNumPublishers() > 0 && state.getNumPublishers() > 0; }));
  const cue_sim::Strike::Response struck = table_.strike(jump);
  ASSERT_TRUE(struck.success) << struck.message;
  const cue_sim::TableState rest = *table_.atRestAfter(struck.stamp, planned.time_to_rest + 30);
  expectSameBalls(rest.balls, planned.final_balls, "the jump shot");
  {
    std::lock_guard<std::mutex> lock(mutex);
    // The flight's apex: (e_table V sin theta)^2 / 2g above the cloth, some 14 cm at this stroke;
    // tf at 100 Hz samples it within a few millimetres.
    EXPECT_GT(highest, kRadius + 0.08) << "the cue ball's highest transform";
    EXPECT_TRUE(airborne_seen);
  }
  for (const auto& b : rest.balls)
    EXPECT_NEAR(b.position.z, kRadius, 1e-12) << "ball " << b.id << " back on the cloth";

  EXPECT_EQ(stringOf(reconfigure("/table", {}, {{"cue_model", "planar"}}), "cue_model"), "planar");
  const cue_sim::Prediction level = table_.predict(jump);
  ASSERT_TRUE(level.success) << level.message;
  for (const auto& e : level.events)
    EXPECT_NE(e.kind, cue_sim::Event::BALL_SLATE);

  // Harder, the same stroke flies over the foot cushion: an OFF_TABLE event that says where it
  // lands, and the ball out of play (OFF_TABLE in ~state, no longer strikable) where it landed.
  reconfigure("/table", {}, {{"cue_model", "sequential"}});
  ASSERT_TRUE(table_.rack("custom", {0, 1}, {{-0.6, 0.0}, {-0.6 + 0.3048, 0.0}}).success);
  table_.atRest(10);
  const cue_sim::Shot off = TableClient::shot(0, 4.0, 0.0, 0.8);
  const cue_sim::Prediction flies = table_.predict(off);
  ASSERT_TRUE(flies.success) << flies.message;
  ASSERT_FALSE(flies.events.empty());
  const cue_sim::Event& gone = flies.events.back();
  EXPECT_EQ(gone.kind, cue_sim::Event::OFF_TABLE);
  EXPECT_EQ(gone.kind_name, "off_table");
  EXPECT_EQ(gone.ball_id, 0);
  EXPECT_TRUE(gone.obstacle == "rail" || gone.obstacle == "floor") << gone.obstacle;
  const cue_sim::Strike::Response flown = table_.strike(off);
  ASSERT_TRUE(flown.success) << flown.message;
  const cue_sim::TableState after = *table_.atRestAfter(flown.stamp, flies.time_to_rest + 30);
  expectSameBalls(after.balls, flies.final_balls, "the jump off the table");
  const cue_sim::BallState cue_ball = TableClient::byId(after.balls).at(0);
  EXPECT_EQ(cue_ball.motion, cue_sim::BallState::OFF_TABLE);
  EXPECT_TRUE(cue_ball.pocketed);
  EXPECT_EQ(cue_ball.pocket, "");
  EXPECT_GT(std::abs(cue_ball.position.x), 0.9906);  // beyond the foot cushion's nose
  const cue_sim::Strike::Response again = table_.strike(jump);
  EXPECT_FALSE(again.success);
  EXPECT_NE(again.message.find("off the table"), std::string::npos) << again.message;
  reconfigure("/table", {}, {{"cue_model", "planar"}});
}

TEST_F(ResearchInterfaceTest, TheAimMarkerFiresTheShotItShows)
{
  const cue_sim::TableState rack = *table_.atRest(5);
  const auto cue_ball = TableClient::byId(rack.balls).at(0).position;
  // rviz's side of the conversation: the marker as the server sends it, and the user's drag
  // and menu click as feedback.
  const auto full = ros::topic::waitForMessage<visualization_msgs::InteractiveMarkerInit>("/table/aim/update_full",
                                                                                          ros::Duration(kGenerousWait));
  ASSERT_TRUE(full);
  ASSERT_EQ(full->markers.size(), 1u);
  // Nothing rviz would complete with a text of the empty description, or draw as an empty text.
  EXPECT_TRUE(full->markers[0].description.empty());
  EXPECT_FALSE(full->markers[0].menu_entries.empty()) << "Strike and Predict, on a right-click";
  for (const auto& control : full->markers[0].controls)
  {
    EXPECT_NE(control.interaction_mode, visualization_msgs::InteractiveMarkerControl::MENU) << control.name;
    EXPECT_FALSE(control.markers.empty()) << control.name;
    for (const auto& m : control.markers)
      EXPECT_TRUE(m.type != visualization_msgs::Marker::TEXT_VIEW_FACING || !m.text.empty()) << control.name;
  }
  EXPECT_NEAR(full->markers[0].pose.position.x, cue_ball.x + 0.5, 1e-12) << "the default aim: 2 m/s along +x";
  EXPECT_NEAR(full->markers[0].pose.position.y, cue_ball.y, 1e-12);
  ros::Publisher feedback = nh_.advertise<visualization_msgs::InteractiveMarkerFeedback>("/table/aim/feedback", 10);
  ASSERT_TRUE(waitFor([&] { return feedback.getNumSubscribers() > 0; }));
  // The server's updates: the drag has taken effect once the marker stands at the handle.
  std::mutex update_mutex;
  bool at_handle = false;
  ros::Subscriber updates = nh_.subscribe<visualization_msgs::InteractiveMarkerUpdate>(
      "/table/aim/update", 10, [&](const visualization_msgs::InteractiveMarkerUpdateConstPtr& u) {
        std::lock_guard<std::mutex> lock(update_mutex);
        for (const auto& m : u->markers)
          at_handle |= std::abs(m.pose.position.x - (cue_ball.x + 0.2)) < 1e-9 &&
                       std::abs(m.pose.position.y - (cue_ball.y + 0.1)) < 1e-9;
      });
  ASSERT_TRUE(waitFor([&] { return updates.getNumPublishers() > 0; }));
  visualization_msgs::InteractiveMarkerFeedback f;
  f.header.frame_id = "table";
  f.client_id = "/test";
  f.marker_name = "aim";
  f.control_name = "aim";
  f.event_type = visualization_msgs::InteractiveMarkerFeedback::POSE_UPDATE;
  f.pose.position.x = cue_ball.x + 0.2;
  f.pose.position.y = cue_ball.y + 0.1;
  f.pose.orientation.w = 1;
  feedback.publish(f);
  ASSERT_TRUE(waitFor([&] {
    std::lock_guard<std::mutex> lock(update_mutex);
    return at_handle;
  })) << "the marker did not follow the drag";
  // What the marker aims: heading to the handle, 4 m/s per metre of arrow.
  const Eigen::Vector2d aim =
      Eigen::Vector2d(f.pose.position.x, f.pose.position.y) - Eigen::Vector2d(cue_ball.x, cue_ball.y);
  const cue_sim::Shot aimed = TableClient::shot(0, std::min(12.0, 4.0 * aim.norm()), std::atan2(aim.y(), aim.x()));
  const cue_sim::Prediction planned = table_.predict(aimed);
  ASSERT_TRUE(planned.success) << planned.message;

  // The strike is on ~shots, with who fired it: wait for it before waiting for the balls to rest.
  std::mutex shots_mutex;
  std::vector<cue_sim::ExecutedShot> shots;
  ros::Subscriber shots_sub =
      nh_.subscribe<cue_sim::ExecutedShot>("/table/shots", 10, [&](const cue_sim::ExecutedShotConstPtr& m) {
        std::lock_guard<std::mutex> lock(shots_mutex);
        shots.push_back(*m);
      });
  const ros::Time clicked = ros::Time::now();
  f.event_type = visualization_msgs::InteractiveMarkerFeedback::MENU_SELECT;
  f.control_name = "aim";  // right-clicked on the handle
  f.menu_entry_id = 1;     // "Strike"
  feedback.publish(f);
  const auto fired = [&] {
    std::lock_guard<std::mutex> lock(shots_mutex);
    for (const auto& s : shots)
      if (s.source == "aim_marker" && s.header.stamp >= clicked)
        return true;
    return false;
  };
  ASSERT_TRUE(waitFor(fired)) << "the aim marker's strike on /table/shots";
  table_.atRest(planned.time_to_rest + 10);
  expectSameEvents(eventsSince(clicked, planned.events.size()), planned.events, "the shot fired from the aim marker");
  shots_sub.shutdown();
}
}  // namespace
