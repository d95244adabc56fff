// Simulation control through a real master, with use_sim_time: the node drives /clock as fast
// as possible; ~pause, ~step, ~set_state, ~place_ball, ~remove_ball; and a rosbag of a shot whose
// every ball transform is the engine's exact trajectory at its stamp, with the shot played in it.
#include <cue_sim/CameraGroundTruth.h>
#include <cue_sim/ExecutedShot.h>
#include <cue_sim/PlaceBall.h>
#include <cue_sim/RemoveBall.h>
#include <cue_sim/SetState.h>
#include <cue_sim/Step.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <rosgraph_msgs/Clock.h>
#include <std_srvs/SetBool.h>
#include <std_srvs/Trigger.h>
#include <tf2_msgs/TFMessage.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <thread>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"
#include "physics_of_msgs.hpp"
#include "shell_commands.hpp"
#include "table_client.hpp"

namespace
{
class SimControlTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    ASSERT_TRUE(ros::Time::isSimTime()) << "the launch file sets /use_sim_time";
    clock_sub_ = nh_.subscribe<rosgraph_msgs::Clock>("/clock", 100, [this](const rosgraph_msgs::ClockConstPtr& c) {
      std::lock_guard<std::mutex> lock(mutex_);
      clocks_.push_back(c->clock);
    });
    pause_ = nh_.serviceClient<std_srvs::SetBool>("/table/pause");
    step_ = nh_.serviceClient<cue_sim::Step>("/table/step");
    set_state_ = nh_.serviceClient<cue_sim::SetState>("/table/set_state");
    reset_ = nh_.serviceClient<std_srvs::Trigger>("/table/reset");
    ASSERT_TRUE(ros::service::waitForService("/table/step", ros::Duration(20)));
    pause(false);
  }

  void pause(bool on)
  {
    std_srvs::SetBool srv;
    srv.request.data = on;
    ASSERT_TRUE(pause_.call(srv));
    ASSERT_TRUE(srv.response.success);
  }

  cue_sim::Step::Response step(double duration)
  {
    cue_sim::Step srv;
    srv.request.duration = duration;
    EXPECT_TRUE(step_.call(srv));
    return srv.response;
  }

  cue_sim::SetState::Response setState(const std::vector<cue_sim::BallState>& balls)
  {
    cue_sim::SetState srv;
    srv.request.balls = balls;
    EXPECT_TRUE(set_state_.call(srv));
    return srv.response;
  }

  /// The node's engine, in this process: the table from robot_description, the node's parameters.
  cue_sim::physics::Engine<double> nodesEngine()
  {
    std::string urdf;
    EXPECT_TRUE(nh_.getParam("/robot_description", urdf));
    auto table = std::make_shared<const cue_sim::physics::TableModel>(cue_sim::tableFromUrdf(urdf));
    cue_sim::physics::PhysicsParams<double> params;
    for (const auto& field : cue_sim::physics::physicsParamFields())
      EXPECT_TRUE(nh_.getParam("/table/" + std::string(field.name), params.*field.member)) << field.name;
    cue_sim::physics::ModelChoice models;
    nh_.getParam("/table/ball_ball_model", models.ball_ball);
    nh_.getParam("/table/cushion_model", models.cushion);
    return cue_sim::physics::Engine<double>(table, params, models);
  }

  /// The balls of `rack` struck with `shot` on `engine`, at shot time 0.
  static cue_sim::physics::TableState<double> struckOnEngine(const cue_sim::physics::Engine<double>& engine,
                                                             const cue_sim::TableState& rack, const cue_sim::Shot& shot)
  {
    cue_sim::physics::TableState<double> state;
    for (const auto& b : rack.balls)
    {
      cue_sim::physics::Ball<double> ball;
      ball.id = b.id;
      ball.r = centreOf(b);
      state.balls.push_back(ball);
    }
    engine.strike(state, 0, strikeOfShot(shot));
    return state;
  }

  std::vector<ros::Time> clocks()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return clocks_;
  }

  ros::NodeHandle nh_;
  TableClient table_;
  ros::ServiceClient pause_, step_, set_state_, reset_;
  std::mutex mutex_;
  std::vector<ros::Time> clocks_;
  ros::Subscriber clock_sub_;  // last: destroyed first, before what its callback uses
};

TEST_F(SimControlTest, TheClockRunsAheadOfTheWallNeverZeroAndNeverBackAcrossResets)
{
  ASSERT_TRUE(waitFor([&] { return !clocks().empty(); })) << "no /clock";
  // Sim time from this test's own /clock messages: roscpp's copy (ros::Time::now) comes through
  // another subscription and can still be 0 when the first message has reached this one.
  const ros::Time start = clocks().back();
  const ros::WallTime wall_start = ros::WallTime::now();
  ASSERT_TRUE(table_.rack("nine").success);
  std_srvs::Trigger reset;
  ASSERT_TRUE(reset_.call(reset));
  // A hundred clock messages more, whatever time the machine gives the node for them.
  const std::size_t before = clocks().size();
  ASSERT_TRUE(waitFor([&] { return clocks().size() > before + 100; })) << "the clock stalled";
  // As fast as possible: well over real time.
  EXPECT_GT((clocks().back() - start).toSec(), 3 * (ros::WallTime::now() - wall_start).toSec());
  const std::vector<ros::Time> seen = clocks();
  ASSERT_GT(seen.size(), 50u);
  EXPECT_GT(seen.front().toSec(), 1e9) << "the clock starts at the wall time, not 0";
  for (std::size_t i = 1; i < seen.size(); ++i)
    ASSERT_LT(seen[i - 1], seen[i]) << "clock message " << i;
}

TEST_F(SimControlTest, PauseFreezesThePhysicsWhileTheClockRunsAndAStepMovesItByTheDuration)
{
  EXPECT_FALSE(step(0.1).success) << "a step needs a paused table";
  ASSERT_TRUE(table_.rack("custom", {0, 1}, {{-0.5, 0.0}, {0.3, 0.0}}).success);
  pause(true);
  const cue_sim::Strike::Response struck = table_.strike(TableClient::shot(0, 1.0, 0.0));
  ASSERT_TRUE(struck.success) << struck.message;
  // The clock runs on while the table is paused (a sim-time client never waits on it), and
  // the struck ball waits at its spot.
  ASSERT_TRUE(waitFor([&] { return ros::Time::now() > struck.stamp + ros::Duration(0.15); }));
  const ros::Time later = ros::Time::now();
  EXPECT_GT(later, struck.stamp + ros::Duration(0.1));
  const cue_sim::TableStateConstPtr waiting = table_.stateAfter(later);
  EXPECT_EQ(TableClient::byId(waiting->balls).at(0).position.x, -0.5);

  const cue_sim::Step::Response stepped = step(0.25);
  ASSERT_TRUE(stepped.success) << stepped.message;
  EXPECT_GE(stepped.stamp, later);
  // The ~state from the step on has the cue ball 0.25 s into its shot, and stays there.
  const cue_sim::TableStateConstPtr after = table_.stateAfter(stepped.stamp);
  const cue_sim::TableStateConstPtr still = table_.stateAfter(after->header.stamp + ros::Duration(0.2));
  EXPECT_GT(still->header.stamp, after->header.stamp);
  EXPECT_TRUE(after->moving);
  const double x = TableClient::byId(after->balls).at(0).position.x;
  EXPECT_GT(x, -0.5 + 0.2);
  EXPECT_LT(x, -0.5 + 0.5);  // the cue ball leaves a 1 m/s cue at about 1.5 m/s
  EXPECT_EQ(TableClient::byId(still->balls).at(0).position.x, x);

  EXPECT_FALSE(step(0).success);
  const cue_sim::Step::Response too_long = step(61);
  EXPECT_FALSE(too_long.success);
  EXPECT_NE(too_long.message.find("duration"), std::string::npos) << too_long.message;
  pause(false);
  table_.atRest(30);
}

TEST_F(SimControlTest, SetStatePlacesMovingBallsAndRefusesBadOnesByField)
{
  const cue_sim::TableState before = *table_.afterRack(table_.rack("custom", {0, 1}, {{-0.5, 0.0}, {0.3, 0.0}}));
  cue_sim::BallState cue, other;
  cue.id = 0;
  cue.position.x = -0.2;
  cue.velocity.x = 0.5;
  cue.angular_velocity.y = 0.5 / 0.028575;  // rolling
  other.id = 3;
  other.position.x = 0.4;
  other.position.y = 0.2;

  cue_sim::BallState overlapping = other;
  overlapping.position.x = -0.19;
  overlapping.position.y = 0;
  cue_sim::SetState::Response r = setState({cue, overlapping});
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("balls:"), std::string::npos) << r.message;
  cue_sim::BallState bad_id = other;
  bad_id.id = -1;
  r = setState({cue, bad_id});
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("balls[1].id"), std::string::npos) << r.message;
  cue_sim::BallState nan = other;
  nan.velocity.y = std::nan("");
  r = setState({nan});
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("finite"), std::string::npos) << r.message;
  EXPECT_EQ(TableClient::byId(table_.freshState()->balls).size(), TableClient::byId(before.balls).size());

  // Placed while paused, then stepped 0.1 s: the cue ball rolls on from where it was put.
  pause(true);
  r = setState({cue, other});
  ASSERT_TRUE(r.success) << r.message;
  const cue_sim::Step::Response stepped = step(0.1);
  ASSERT_TRUE(stepped.success) << stepped.message;
  EXPECT_GE(stepped.stamp, r.stamp);
  const auto placed = table_.stateAfter(stepped.stamp);
  pause(false);
  const auto balls = TableClient::byId(placed->balls);
  ASSERT_EQ(balls.size(), 2u);
  EXPECT_TRUE(placed->moving);
  EXPECT_EQ(balls.at(0).motion, cue_sim::BallState::ROLLING);
  // Rolling at 0.5 m/s, slowed by mu_r g: 0.1 s later it is 0.05 - mu_r g 0.1^2 / 2 further.
  EXPECT_NEAR(balls.at(0).position.x, -0.2 + 0.05 - 0.5 * 0.01 * 9.81 * 0.01, 1e-12);
  EXPECT_EQ(balls.at(3).motion, cue_sim::BallState::STATIONARY);
  table_.atRest(30);
}

TEST_F(SimControlTest, OneBallIsPlacedMovedOrRemovedAndTheOthersStay)
{
  // The state after the rack's own stamp (under sim time a state at rest stamped after this
  // client's clock could still be the previous test's table).
  const auto before = TableClient::byId(
      table_.afterRack(table_.rack("custom", {0, 1, 2}, {{-0.5, 0.0}, {0.3, 0.0}, {0.3, 0.2}}))->balls);
  ASSERT_EQ(before.size(), 3u);
  ros::ServiceClient place = nh_.serviceClient<cue_sim::PlaceBall>("/table/place_ball");
  ros::ServiceClient remove = nh_.serviceClient<cue_sim::RemoveBall>("/table/remove_ball");
  cue_sim::PlaceBall in_hand;
  in_hand.request.ball.id = 0;
  in_hand.request.ball.position.x = -0.7;
  in_hand.request.ball.position.y = 0.1;
  ASSERT_TRUE(place.call(in_hand));
  ASSERT_TRUE(in_hand.response.success) << in_hand.response.message;
  auto after = TableClient::byId(table_.stateAfter(in_hand.response.stamp)->balls);
  ASSERT_EQ(after.size(), 3u);
  EXPECT_EQ(after.at(0).position.x, -0.7);
  EXPECT_EQ(after.at(1).position.x, before.at(1).position.x);
  EXPECT_EQ(after.at(2).position.y, before.at(2).position.y);

  // On another ball, at 1e308 m/s, or with an unknown id: refused by field, nothing changes.
  cue_sim::PlaceBall bad = in_hand;
  bad.request.ball.position.x = 0.31;
  bad.request.ball.position.y = 0.0;
  ASSERT_TRUE(place.call(bad));
  EXPECT_FALSE(bad.response.success);
  EXPECT_NE(bad.response.message.find("overlap"), std::string::npos) << bad.response.message;
  bad = in_hand;
  bad.request.ball.velocity.x = 1e308;
  ASSERT_TRUE(place.call(bad));
  EXPECT_FALSE(bad.response.success);
  EXPECT_NE(bad.response.message.find("ball.velocity"), std::string::npos) << bad.response.message;
  cue_sim::RemoveBall unknown;
  unknown.request.ball_id = 7;
  ASSERT_TRUE(remove.call(unknown));
  EXPECT_FALSE(unknown.response.success);
  EXPECT_NE(unknown.response.message.find("not on the table"), std::string::npos) << unknown.response.message;

  cue_sim::RemoveBall take;
  take.request.ball_id = 2;
  ASSERT_TRUE(remove.call(take));
  ASSERT_TRUE(take.response.success) << take.response.message;
  after = TableClient::byId(table_.stateAfter(take.response.stamp)->balls);
  EXPECT_EQ(after.size(), 2u);
  EXPECT_EQ(after.count(2), 0u);
  EXPECT_EQ(after.at(0).position.x, -0.7);
}

TEST_F(SimControlTest, EveryBallTransformInTheBagIsTheExactTrajectoryAtItsStamp)
{
  const std::vector<int> ids = {0, 1, 2, 3};
  const cue_sim::TableState rack =
      *table_.afterRack(table_.rack("custom", ids, {{-0.6, 0.0}, {0.0, 0.02}, {0.15, -0.2}, {0.3, 0.25}}));
  ASSERT_EQ(rack.balls.size(), ids.size());
  const std::string bag_path = std::string(CUE_SIM_TEST_DIR) + "/sim_shot_test.bag";
  BagRecording recording(bag_path, std::string(CUE_SIM_TEST_DIR) + "/sim_record_test.log");
  // Rosbag connected to every topic the test reads from the bag before the strike (a fixed wait
  // was once too short on a loaded machine, and the strike missed the bag).
  for (const std::string topic : {"/tf", "/table/shots", "/table/markers"})
    ASSERT_TRUE(connectedTo("/record", topic)) << topic;
  const long shots_before = messagesReceivedBy("/record", "/table/shots");
  // The table's picture, sent again every second, must come after the bag's first transforms.
  ASSERT_TRUE(receivedBy("/record", "/tf", 1));
  const long markers_before = messagesReceivedBy("/record", "/table/markers");
  const cue_sim::Shot shot = TableClient::shot(0, 1.5, 0.05, 0.1, 0.2, -0.1);
  const cue_sim::Strike::Response struck = table_.strike(shot);
  ASSERT_TRUE(struck.success) << struck.message;
  table_.atRestAfter(struck.stamp, 60);
  // Rosbag has the shot, and tf from after the rest (a connection delivers in order).
  ASSERT_TRUE(receivedBy("/record", "/table/shots", shots_before + 1));
  // Two refreshes of the table's picture after the first transforms, a wall second apart: the
  // bag's times come from rosbag's own /clock, which here (as fast as possible) moves only every
  // few hundred transforms, so one refresh alone could share the first transforms' time.
  ASSERT_TRUE(receivedBy("/record", "/table/markers", markers_before + 2));
  const long tf_at_rest = messagesReceivedBy("/record", "/tf");
  ASSERT_TRUE(receivedBy("/record", "/tf", tf_at_rest + 20));
  recording.stop();

  // The same engine, in this process, and the shot on it.
  const cue_sim::physics::Engine<double> engine = nodesEngine();
  cue_sim::physics::TableState<double> state = struckOnEngine(engine, rack, shot);

  rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
  // The shot played is in the bag, as executed, at its stamp.
  std::size_t shots = 0;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(std::string("/table/shots"))))
  {
    const auto played = m.instantiate<cue_sim::ExecutedShot>();
    ASSERT_TRUE(played);
    if (played->header.stamp != struck.stamp)
      continue;
    ++shots;
    EXPECT_EQ(played->source, "strike");
    EXPECT_EQ(played->executed.speed, struck.executed.speed);
    EXPECT_EQ(played->executed.phi, struck.executed.phi);
    EXPECT_EQ(played->num_events, struck.num_events);
  }
  EXPECT_EQ(shots, 1u) << "the strike on /table/shots";
  // The table's picture comes again after the balls' first transforms: a replay from anywhere
  // shows every ball.
  ros::Time first_tf, last_markers;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(std::string("/tf"))))
  {
    first_tf = m.getTime();
    break;
  }
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(std::string("/table/markers"))))
    last_markers = m.getTime();
  EXPECT_GT(last_markers, first_tf);
  std::size_t compared = 0;
  double largest = 0, moved = 0;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(std::string("/tf"))))
  {
    const auto tf = m.instantiate<tf2_msgs::TFMessage>();
    if (!tf || tf->transforms.empty() || tf->transforms[0].header.stamp < struck.stamp)
      continue;
    const double t = (tf->transforms[0].header.stamp - struck.stamp).toSec();
    advance(engine, state, t);
    const auto balls = engine.snapshot(state);
    for (const auto& transform : tf->transforms)
    {
      ASSERT_EQ(transform.header.stamp, tf->transforms[0].header.stamp);
      const int id = std::stoi(transform.child_frame_id.substr(std::string("ball_").size()));
      const auto& exact = balls[state.indexOf(id)].r;
      const double error =
          std::hypot(transform.transform.translation.x - exact.x(), transform.transform.translation.y - exact.y());
      largest = std::max(largest, error);
      moved = std::max(moved, std::hypot(exact.x() - rack.balls[state.indexOf(id)].position.x,
                                         exact.y() - rack.balls[state.indexOf(id)].position.y));
      ++compared;
    }
  }
  bag.close();
  EXPECT_GT(compared, 4u * 100u) << "transforms of the four balls over the shot";
  EXPECT_GT(moved, 0.3);
  EXPECT_LE(largest, 1e-9) << "largest distance of a recorded pose from the exact trajectory [m]";
}
/// Ground truths of ~camera, kept from when it subscribes until it is destroyed.
class GroundTruths
{
public:
  explicit GroundTruths(ros::NodeHandle& nh)
    : sub_(nh.subscribe<cue_sim::CameraGroundTruth>("/table/camera/ground_truth", 1000,
                                                    [this](const cue_sim::CameraGroundTruthConstPtr& m) {
                                                      std::lock_guard<std::mutex> lock(mutex_);
                                                      truths_.push_back(*m);
                                                    }))
  {
  }
  bool connected()
  {
    return waitFor([&] { return sub_.getNumPublishers() > 0; });
  }
  std::vector<cue_sim::CameraGroundTruth> since(const ros::Time& stamp)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<cue_sim::CameraGroundTruth> out;
    std::copy_if(truths_.begin(), truths_.end(), std::back_inserter(out),
                 [&](const cue_sim::CameraGroundTruth& t) { return t.header.stamp >= stamp; });
    return out;
  }

private:
  std::mutex mutex_;
  std::vector<cue_sim::CameraGroundTruth> truths_;
  ros::Subscriber sub_;  // last: shut down first, before what its callback uses
};

TEST_F(SimControlTest, TheCameraFollowsSimTimeAndItsGroundTruthIsTheExactTrajectory)
{
  // With sim time as fast as possible, ~camera/ground_truth (alone: no pixels drawn) comes at
  // ~camera/rate of sim time or slower, never two frames within half a period, each ball's
  // position at its stamp (the exposure's middle) the exact trajectory's.
  const std::vector<int> ids = {0, 1, 2, 3};
  const cue_sim::TableState rack =
      *table_.afterRack(table_.rack("custom", ids, {{-0.6, 0.0}, {0.0, 0.02}, {0.15, -0.2}, {0.3, 0.25}}));
  GroundTruths truths(nh_);
  ASSERT_TRUE(truths.connected());
  const cue_sim::Shot shot = TableClient::shot(0, 1.5, 0.05, 0.1, 0.2, -0.1);
  const cue_sim::Strike::Response struck = table_.strike(shot);
  ASSERT_TRUE(struck.success) << struck.message;
  table_.atRestAfter(struck.stamp, 60);
  double rate = 0, exposure = 0;
  ASSERT_TRUE(nh_.getParam("/table/camera/rate", rate));
  ASSERT_TRUE(nh_.getParam("/table/camera/exposure", exposure));
  // Over ten frames opened after the strike, however fast the sim runs against the camera's
  // thread, which yields to the node's publishing thread (as fast as possible, most come after
  // the rest).
  const ros::Time opened_after = struck.stamp + ros::Duration(exposure / 2);
  ASSERT_TRUE(waitFor([&] { return truths.since(opened_after).size() > 10; })) << "frames since the strike";

  const cue_sim::physics::Engine<double> engine = nodesEngine();
  cue_sim::physics::TableState<double> state = struckOnEngine(engine, rack, shot);
  std::size_t compared = 0;
  double largest = 0;
  ros::Time previous;
  for (const auto& truth : truths.since(struck.stamp))
  {
    // A frame's exposure is drawn from the table as it is when the exposure opens: a strike that
    // lands inside one shows from the next frame on. Frames opened after the strike are exact.
    if (truth.header.stamp < opened_after)
      continue;
    if (!previous.isZero())
    {
      EXPECT_GE((truth.header.stamp - previous).toSec(), 0.5 / rate) << "never two frames within half a period";
    }
    previous = truth.header.stamp;
    advance(engine, state, (truth.header.stamp - struck.stamp).toSec());
    const auto balls = engine.snapshot(state);
    ASSERT_EQ(truth.balls.size(), ids.size());
    for (const auto& b : truth.balls)
    {
      const auto& exact = balls[state.indexOf(b.id)].r;
      largest = std::max(largest, std::hypot(b.position.x - exact.x(), b.position.y - exact.y()));
      EXPECT_TRUE(b.visible) << "ball " << b.id;
      ++compared;
    }
  }
  const double seconds = (previous - struck.stamp).toSec();
  const double frames = static_cast<double>(compared) / ids.size();
  std::printf(
      "camera under sim time: %.0f frames in %.2f s of the shot, largest distance from the exact "
      "trajectory %.2e m\n",
      frames, seconds, largest);
  EXPECT_GT(frames, 10) << "frames of the shot";
  EXPECT_LE(frames, seconds * rate + 1) << "no more frames than the rate makes";
  EXPECT_LE(largest, 1e-9) << "largest distance of a ground-truth position from the exact trajectory [m]";
}
}  // namespace
