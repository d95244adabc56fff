// table_node through a real master: services, tf, markers and a real rosbag.
#include <cue_sim/Rack.h>
#include <cue_sim/Strike.h>
#include <cue_sim/TableState.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <std_srvs/Trigger.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "ros_conditions.hpp"
#include "shell_commands.hpp"
#include "table_client.hpp"

namespace
{
/// The latest transform of `frame` in the table frame stamped after `after`: what tf says once the
/// table as of `after` (a rack, a rest) has reached the buffer.
geometry_msgs::TransformStamped transformAfter(tf2_ros::Buffer& buffer, const std::string& frame,
                                               const ros::Time& after)
{
  geometry_msgs::TransformStamped latest;
  const bool seen = waitFor([&] {
    if (!buffer.canTransform("table", frame, ros::Time(0)))
      return false;
    latest = buffer.lookupTransform("table", frame, ros::Time(0));
    return latest.header.stamp > after;
  });
  EXPECT_TRUE(seen) << "no transform of " << frame << " stamped after " << after;
  return latest;
}

const double kRadius = 0.028575;
const double kMassRatio = 0.170097 / 0.567;

/// The table through TableClient (table_client.hpp), with this file's shorthands.
class TableNodeTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    ASSERT_TRUE(ros::service::waitForService("/table/reset", ros::Duration(kGenerousWait)));
    reset_ = nh_.serviceClient<std_srvs::Trigger>("/table/reset");
  }

  cue_sim::Rack::Response rack(const std::string& layout, const std::vector<int>& ids = {},
                               const std::vector<std::pair<double, double>>& xy = {})
  {
    return table_.rack(layout, ids, xy);
  }

  cue_sim::Strike::Response strike(int ball, double speed, double phi, double theta = 0, double a = 0, double b = 0)
  {
    return table_.strike(TableClient::shot(ball, speed, phi, theta, a, b));
  }

  /// The next ~state message published after now.
  cue_sim::TableStateConstPtr freshState() { return table_.freshState(); }
  void waitUntilAtRest(double timeout) { table_.atRest(timeout); }
  static std::map<int, cue_sim::BallState> byId(const cue_sim::TableState& s) { return TableClient::byId(s.balls); }

  void expectUnchanged(const cue_sim::TableState& before, const std::string& what)
  {
    const auto after = byId(*freshState());
    const auto was = byId(before);
    ASSERT_EQ(after.size(), was.size()) << what;
    for (const auto& [id, b] : was)
    {
      EXPECT_EQ(after.at(id).position.x, b.position.x) << what << ", ball " << id;
      EXPECT_EQ(after.at(id).position.y, b.position.y) << what << ", ball " << id;
      EXPECT_EQ(after.at(id).motion, b.motion) << what << ", ball " << id;
    }
  }

  ros::NodeHandle nh_;
  TableClient table_;
  ros::ServiceClient reset_;
};

TEST_F(TableNodeTest, MarkersArriveLatchedWithEveryLayer)
{
  ASSERT_TRUE(rack("eight").success);
  visualization_msgs::MarkerArrayConstPtr markers =
      ros::topic::waitForMessage<visualization_msgs::MarkerArray>("/table/markers", nh_, ros::Duration(10));
  ASSERT_TRUE(markers);
  ASSERT_FALSE(markers->markers.empty());
  EXPECT_EQ(markers->markers.front().action, visualization_msgs::Marker::DELETEALL);
  std::map<std::string, int> per_ns;
  for (const auto& m : markers->markers)
    if (m.action == visualization_msgs::Marker::ADD)
    {
      ++per_ns[m.ns];
      EXPECT_GT(m.color.a, 0.0f) << m.ns;
      EXPECT_NE(m.header.frame_id.front(), '/');
    }
  EXPECT_EQ(per_ns["cloth"], 1);
  EXPECT_EQ(per_ns["cushions"], 6);
  EXPECT_EQ(per_ns["pockets"], 6);
  EXPECT_EQ(per_ns["jaws"], 12);
  EXPECT_EQ(per_ns["balls"], 16);
  EXPECT_EQ(per_ns["stripes"], 7);
  EXPECT_EQ(per_ns["labels"], 32);  // each number twice, at the ball's poles
}

TEST_F(TableNodeTest, StrikeMovesTheCueBallAlongItsHeadingInTf)
{
  ASSERT_TRUE(rack("empty").success);
  const ros::Time racked = ros::Time::now();
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  const auto start = transformAfter(buffer, "ball_0", racked).transform.translation;
  EXPECT_NEAR(start.z, kRadius, 1e-12);
  const double phi = 0.6, speed = 1.0;
  const auto response = strike(0, speed, phi);
  ASSERT_TRUE(response.success) << response.message;
  EXPECT_GT(response.time_to_rest, 1.0);
  EXPECT_GE(response.num_events, 2u);  // slide to roll, roll to stop
  EXPECT_NEAR(std::hypot(response.ball_velocity.x, response.ball_velocity.y), 2 * speed / (1 + kMassRatio), 1e-9);
  // 0.4 s after the strike the ball has run some 0.5 m straight along its heading, short of the
  // cushion (0.8 m away): as tf had it then, however late the buffer gets it.
  const ros::Time then = ros::Time::now() + ros::Duration(0.4);
  ASSERT_TRUE(waitFor([&] { return buffer.canTransform("table", "ball_0", then); }));
  const auto later = buffer.lookupTransform("table", "ball_0", then).transform.translation;
  const double dx = later.x - start.x, dy = later.y - start.y;
  EXPECT_GT(std::hypot(dx, dy), 0.2);
  EXPECT_NEAR(std::atan2(dy, dx), phi, 1e-9);
  // The world frame holds the table.
  EXPECT_TRUE(buffer.canTransform("world", "ball_0", ros::Time(0), ros::Duration(1)));
}

TEST_F(TableNodeTest, ARollingBallTurnsInTfByDistanceOverR)
{
  ASSERT_TRUE(rack("empty").success);
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  const auto racked = table_.atRest(kGenerousWait);
  const auto before = transformAfter(buffer, "ball_0", racked->header.stamp).transform;
  // A level cue 2R/5 above the centre: natural roll from the strike.
  const double phi = 0.6;
  const auto response = table_.strike(TableClient::shot(0, 0.25, phi, 0, 0, 0.4));
  ASSERT_TRUE(response.success) << response.message;
  const auto rested = table_.atRest(response.time_to_rest + kGenerousWait);
  const auto after = transformAfter(buffer, "ball_0", rested->header.stamp).transform;
  const auto quaternion = [](const geometry_msgs::Quaternion& q) { return Eigen::Quaterniond(q.w, q.x, q.y, q.z); };
  const Eigen::AngleAxisd turned(quaternion(after.rotation) * quaternion(before.rotation).inverse());
  const double distance =
      std::hypot(after.translation.x - before.translation.x, after.translation.y - before.translation.y);
  ASSERT_GT(distance, 0.1);
  const Eigen::Vector3d across(-std::sin(phi), std::cos(phi), 0);  // z x the heading
  EXPECT_NEAR(std::abs(turned.axis().dot(across)), 1.0, 1e-9);
  EXPECT_NEAR(std::remainder(turned.angle() * turned.axis().dot(across) - distance / kRadius, 2 * M_PI), 0.0, 1e-9)
      << "turned " << turned.angle() << " rad over " << distance << " m";
}

TEST_F(TableNodeTest, EveryBallInOneTfMessageWithStrictlyIncreasingStamps)
{
  ASSERT_TRUE(rack("eight").success);
  std::mutex mutex;
  std::vector<tf2_msgs::TFMessage> messages;
  ros::Subscriber sub = nh_.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessageConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!m->transforms.empty() && m->transforms[0].child_frame_id.rfind("ball_", 0) == 0)
      messages.push_back(*m);
  });
  ASSERT_TRUE(strike(0, 3.0, 0.0).success);
  // A second of them at 100 Hz, however long the machine takes to deliver it.
  EXPECT_TRUE(waitFor([&] {
    std::lock_guard<std::mutex> lock(mutex);
    return messages.size() > 100;
  }));
  sub.shutdown();
  std::lock_guard<std::mutex> lock(mutex);
  ASSERT_GT(messages.size(), 50u);  // 100 Hz
  ros::Time last;
  for (const auto& m : messages)
  {
    EXPECT_EQ(m.transforms.size(), 16u);
    EXPECT_GT(m.transforms[0].header.stamp, last);
    last = m.transforms[0].header.stamp;
    std::set<std::string> frames;
    for (const auto& t : m.transforms)
    {
      frames.insert(t.child_frame_id);
      EXPECT_EQ(t.header.frame_id, "table");
      EXPECT_EQ(t.header.stamp, last);
    }
    EXPECT_EQ(frames.size(), 16u);
  }
  waitUntilAtRest(20);
}

TEST_F(TableNodeTest, BadStrikesAreRefusedAndChangeNothing)
{
  ASSERT_TRUE(rack("nine").success);
  const auto before = *freshState();
  struct Case
  {
    int ball;
    double speed, phi, theta, a, b;
    std::string field;
  };
  const std::vector<Case> cases = {
      {0, NAN, 0, 0, 0, 0, "speed"},       {0, -1.0, 0, 0, 0, 0, "speed"},
      {0, 0.0, 0, 0, 0, 0, "speed"},       {0, 12.5, 0, 0, 0, 0, "speed"},
      {0, INFINITY, 0, 0, 0, 0, "speed"},  {0, 2.0, NAN, 0, 0, 0, "phi"},
      {0, 2.0, INFINITY, 0, 0, 0, "phi"},  {0, 2.0, 0, -0.1, 0, 0, "theta"},
      {0, 2.0, 0, 2.0, 0, 0, "theta"},     {0, 2.0, 0, 0, 0.4, 0.4, "sqrt(a^2 + b^2)"},
      {0, 2.0, 0, 0, NAN, 0, "a and b"},   {12, 2.0, 0, 0, 0, 0, "ball_id 12 is not on the table"},
      {-1, 2.0, 0, 0, 0, 0, "ball_id -1"},
  };
  for (const auto& c : cases)
  {
    const auto r = strike(c.ball, c.speed, c.phi, c.theta, c.a, c.b);
    EXPECT_FALSE(r.success) << c.field;
    EXPECT_NE(r.message.find(c.field), std::string::npos) << "message '" << r.message << "' should name " << c.field;
  }
  expectUnchanged(before, "after bad strikes");
}

TEST_F(TableNodeTest, StrikeWhileMovingIsRefused)
{
  ASSERT_TRUE(rack("empty").success);
  ASSERT_TRUE(strike(0, 1.0, 0.0).success);
  const auto r = strike(0, 1.0, 3.0);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("still moving"), std::string::npos) << r.message;
  waitUntilAtRest(20);
}

TEST_F(TableNodeTest, PocketedBallCannotBeStruckAndRestsBelowTheCloth)
{
  // Ball 3 a short way from the foot-left corner, shot straight in.
  const double hx = 1.9812 / 2, hy = 0.9906 / 2;
  ASSERT_TRUE(rack("custom", {0, 3}, {{-0.5, 0.0}, {hx - 0.2, hy - 0.2}}).success);
  const auto r = strike(3, 1.5, M_PI / 4);
  ASSERT_TRUE(r.success) << r.message;
  waitUntilAtRest(10);
  const auto balls = byId(*freshState());
  EXPECT_TRUE(balls.at(3).pocketed);
  EXPECT_EQ(balls.at(3).pocket, "pocket_foot_ypos");
  EXPECT_LT(balls.at(3).position.z, 0.0);
  const auto before = *freshState();
  const auto again = strike(3, 1.0, 0.0);
  EXPECT_FALSE(again.success);
  EXPECT_NE(again.message.find("pocketed"), std::string::npos) << again.message;
  expectUnchanged(before, "after striking a pocketed ball");
}

TEST_F(TableNodeTest, BadRacksAreRefusedAndChangeNothing)
{
  ASSERT_TRUE(rack("nine").success);
  const auto before = *freshState();
  struct Case
  {
    std::string layout;
    std::vector<int> ids;
    std::vector<std::pair<double, double>> xy;
    std::string words;
  };
  const std::vector<Case> cases = {
      {"eleven", {}, {}, "layout must be one of"},
      {"custom", {0, 1}, {{0, 0}}, "same length"},
      {"custom", {0, 1}, {{0, 0}, {kRadius, 0}}, "overlap"},
      {"custom", {0}, {{5.0, 0}}, "off the cloth"},
      {"custom", {0}, {{NAN, 0}}, "finite"},
      {"custom", {16}, {{0, 0}}, "not in [0, 15]"},
      {"custom", {0, 0}, {{0, 0}, {0.3, 0}}, "twice"},
      {"custom", {0}, {{1.9812 / 2 - 0.03, 0.9906 / 2 - 0.03}}, "pocket"},
      {"eight", {1}, {{0, 0}}, "'custom' only"},
  };
  for (const auto& c : cases)
  {
    const auto r = rack(c.layout, c.ids, c.xy);
    EXPECT_FALSE(r.success) << c.words;
    EXPECT_NE(r.message.find(c.words), std::string::npos) << "message '" << r.message << "' should say " << c.words;
  }
  expectUnchanged(before, "after bad racks");
}

TEST_F(TableNodeTest, ResetReturnsToTheLastRack)
{
  ASSERT_TRUE(rack("custom", {0, 5}, {{-0.3, 0.1}, {0.4, -0.2}}).success);
  const auto racked = *freshState();
  ASSERT_TRUE(strike(0, 2.0, 1.0).success);
  ASSERT_TRUE(freshState()->moving) << "reset from a table in motion";
  std_srvs::Trigger srv;
  ASSERT_TRUE(reset_.call(srv));
  EXPECT_TRUE(srv.response.success);
  expectUnchanged(racked, "after reset");
  EXPECT_FALSE(freshState()->moving);
}

TEST_F(TableNodeTest, RosbagOfABreakHoldsAllSixteenBallFrames)
{
  ASSERT_TRUE(rack("eight").success);
  const std::string bag_path = std::string(CUE_SIM_TEST_DIR) + "/break_test.bag";
  {
    // The real record.launch, as a user runs it, from before the break until it has rested and
    // rosbag has received a good while of tf after that.
    BagRecording recording(bag_path, std::string(CUE_SIM_TEST_DIR) + "/record_test.log");
    ASSERT_TRUE(connectedTo("/record", "/tf"));
    ASSERT_TRUE(connectedTo("/record", "/tf_static"));
    ASSERT_TRUE(strike(0, 8.0, 0.0).success);
    table_.atRest(kGenerousWait);
    const long received = messagesReceivedBy("/record", "/tf");
    ASSERT_TRUE(receivedBy("/record", "/tf", received + 20));
  }
  rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
  std::map<std::string, std::vector<double>> x_of_frame;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(std::string("/tf"))))
    if (const auto tf = m.instantiate<tf2_msgs::TFMessage>())
      for (const auto& t : tf->transforms)
        x_of_frame[t.child_frame_id].push_back(t.transform.translation.x);
  for (int id = 0; id <= 15; ++id)
  {
    const std::string frame = "ball_" + std::to_string(id);
    ASSERT_TRUE(x_of_frame.count(frame)) << frame << " missing from the bag";
    EXPECT_GT(x_of_frame[frame].size(), 100u) << frame;
  }
  // The cue ball moved during the recording, and so did the apex ball it hit.
  const auto moved = [&](const std::string& f) {
    const auto& xs = x_of_frame[f];
    return *std::max_element(xs.begin(), xs.end()) - *std::min_element(xs.begin(), xs.end());
  };
  EXPECT_GT(moved("ball_0"), 0.5);
  EXPECT_GT(moved("ball_1"), 0.01);  // it meets balls 11 and 5 at once and mostly stops
  rosbag::View statics(bag, rosbag::TopicQuery(std::string("/tf_static")));
  EXPECT_GT(statics.size(), 0u);
  bag.close();
}
/// Runs a table_node of its own (it must refuse to start), with private parameters `params`:
/// its exit status and what it printed.
std::pair<int, std::string> runTableNode(const std::string& name, const std::string& params)
{
  const std::string log = std::string(CUE_SIM_TEST_DIR) + "/" + name + ".log";
  const std::string command = "rosrun cue_sim table_node __name:=" + name + " " + params + " > " + log + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WEXITSTATUS(status), text.str()};
}

TEST_F(TableNodeTest, BrokenTableDescriptionStopsTheNodeWithAReason)
{
  const std::string dir = CUE_SIM_TEST_DIR;
  const std::string no_cloth = dir + "/no_cloth.urdf";
  std::ofstream(no_cloth) << "<robot name='bad'><link name='table'/></robot>";
  const auto run = [&](const std::string& name, const std::string& file) {
    return runTableNode(name, "_urdf_file:=" + file);
  };
  const auto missing_file = run("no_file", dir + "/does_not_exist.urdf");
  EXPECT_EQ(missing_file.first, 1);
  EXPECT_NE(missing_file.second.find("cannot read URDF file"), std::string::npos) << missing_file.second;
  const auto missing_cloth = run("no_cloth", no_cloth);
  EXPECT_EQ(missing_cloth.first, 1);
  EXPECT_NE(missing_cloth.second.find("no link named 'cloth'"), std::string::npos) << missing_cloth.second;
}

TEST_F(TableNodeTest, MisspelledOrMistypedParametersStopTheNodeWithAReason)
{
  const auto run = [](const std::string& name, const std::string& params) {
    return runTableNode(name, "_table:=7ft " + params);
  };
  const auto misspelled = run("misspelled", "_publish_rte:=50");
  EXPECT_EQ(misspelled.first, 1);
  EXPECT_NE(misspelled.second.find("unknown parameter ~publish_rte (known: "), std::string::npos) << misspelled.second;
  const auto in_a_group = run("in_a_group", "_camera/widht:=640");
  EXPECT_EQ(in_a_group.first, 1);
  EXPECT_NE(in_a_group.second.find("unknown parameter ~camera/widht (known: "), std::string::npos) << in_a_group.second;
  const auto mistyped = run("mistyped", "_publish_rate:=fast");
  EXPECT_EQ(mistyped.first, 1);
  EXPECT_NE(mistyped.second.find("~publish_rate must be a number"), std::string::npos) << mistyped.second;
  const auto out_of_range = run("out_of_range", "_tf_timeout:=5.0");
  EXPECT_EQ(out_of_range.first, 1);
  EXPECT_NE(out_of_range.second.find("~tf_timeout must be in (0, 1] s, got 5"), std::string::npos)
      << out_of_range.second;
  const auto bad_limit = run("bad_limit", "_max_batch_shots:=0");
  EXPECT_EQ(bad_limit.first, 1);
  EXPECT_NE(bad_limit.second.find("~max_batch_shots must be in [1, 2147483647], got 0"), std::string::npos)
      << bad_limit.second;
  const auto no_queue = run("no_queue", "_camera/queue_size:=0");
  EXPECT_EQ(no_queue.first, 1);
  EXPECT_NE(no_queue.second.find("~camera/queue_size must be in [1, 1000] images, got 0"), std::string::npos)
      << no_queue.second;
}
}  // namespace
