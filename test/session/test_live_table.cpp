// The live table without ROS: what table_node does with the table, and what it refuses. Each
// refusal must name the field and leave the table exactly as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cue_sim/physics/rack.hpp"
#include "live_table_fixtures.hpp"

namespace cue_sim
{
namespace session
{
namespace
{
using physics::Ball;
using physics::Engine;
using physics::PhysicsParams;

using fixtures::ballAt;
using fixtures::engineOn;
using fixtures::kSecond;
using fixtures::kStart;
using fixtures::shot;

/// Every number of every ball, bit for bit.
void expectSameBalls(const std::vector<Ball<double>>& a, const std::vector<Ball<double>>& b)
{
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    EXPECT_EQ(a[i].id, b[i].id);
    EXPECT_EQ(a[i].motion, b[i].motion) << "ball " << a[i].id;
    EXPECT_EQ(a[i].r, b[i].r) << "ball " << a[i].id;
    EXPECT_EQ(a[i].v, b[i].v) << "ball " << a[i].id;
    EXPECT_EQ(a[i].w, b[i].w) << "ball " << a[i].id;
  }
}

class LiveTableTest : public ::testing::Test
{
protected:
  LiveTableTest() : table_(engineOn("7ft"), LiveTableOptions(), "eight", kStart) {}
  LiveTable table_;
};

TEST_F(LiveTableTest, AStrikeFromRestIsItsPredictionBitForBit)
{
  PredictionStart start;
  ASSERT_EQ(table_.predictionStart({}, kStart, start), "");
  const Shot break_shot = shot(0, 8.0, 0.01, 0.1, 0.2);
  const ShotPrediction predicted = predictShot(*start.engine, start.table, break_shot, {});
  ASSERT_TRUE(predicted.success) << predicted.message;

  const Stamp struck_at = kStart + kSecond / 2;
  const StrikeOutcome outcome = table_.strike(break_shot, struck_at);
  ASSERT_TRUE(outcome.success) << outcome.message;
  EXPECT_EQ(outcome.stamp, struck_at);
  EXPECT_EQ(outcome.num_events, predicted.events.size());
  EXPECT_EQ(outcome.time_to_rest, predicted.time_to_rest);
  std::vector<StampedEvent> events;
  table_.advanceTo(struck_at + static_cast<Stamp>(std::ceil(predicted.time_to_rest * 1e9)) + kSecond, &events);
  EXPECT_TRUE(table_.motion().atRest());
  ASSERT_EQ(events.size(), predicted.events.size());
  for (std::size_t i = 0; i < events.size(); ++i)
  {
    EXPECT_EQ(events[i].event.time, predicted.events[i].time) << "event " << i;
    EXPECT_GE(events[i].stamp, struck_at);
    EXPECT_NEAR(static_cast<double>(events[i].stamp - struck_at) * 1e-9, predicted.events[i].time, 1e-9);
  }
  expectSameBalls(table_.motion().balls(), predicted.final_balls);
}

TEST_F(LiveTableTest, AStrikeStampedBeforeTheLatestStartsThenIfTheBallsRestedAndRefusedIfNot)
{
  // A robot's cue touched the ball 4 ms before the table heard of it: the shot starts at the
  // touch, physics time 0 there, exactly as if it had come then.
  const Stamp now = kStart + 3 * kSecond;
  table_.advanceTo(now);
  const Stamp touched = now - 4000000;
  const Shot gentle = shot(0, 1.0, 0.3);
  LiveTable told_at_once(engineOn("7ft"), LiveTableOptions(), "eight", kStart);
  const StrikeOutcome at_once = told_at_once.strike(gentle, touched);
  ASSERT_TRUE(at_once.success) << at_once.message;
  const StrikeOutcome late = table_.strike(gentle, touched);
  ASSERT_TRUE(late.success) << late.message;
  EXPECT_EQ(late.stamp, touched);
  EXPECT_EQ(table_.lastChange(), touched);
  const Stamp later = now + kSecond / 10;
  const std::vector<Ball<double>> seen_ahead = table_.ballsAt(later);
  table_.advanceTo(later);
  expectSameBalls(seen_ahead, table_.motion().balls());  // ballsAt looks ahead without moving the table
  told_at_once.advanceTo(later);
  expectSameBalls(table_.motion().balls(), told_at_once.motion().balls());

  // While the balls move, a strike stamped before the table's latest cannot be placed in their
  // motion; once they rest, one stamped before the last ball stopped is refused too, naming both
  // stamps, and the table is unchanged.
  LiveTableOptions moving_allowed;
  moving_allowed.allow_strike_while_moving = true;
  LiveTable moving(engineOn("7ft"), moving_allowed, "eight", kStart);
  ASSERT_TRUE(moving.strike(shot(0, 2.0, 0.0), kStart + kSecond).success);
  moving.advanceTo(kStart + 2 * kSecond);
  ASSERT_FALSE(moving.motion().atRest());
  const StrikeOutcome into_motion = moving.strike(shot(0, 1.0, 0.0), kStart + 2 * kSecond - 1000000);
  EXPECT_FALSE(into_motion.success);
  EXPECT_NE(into_motion.message.find("moving"), std::string::npos) << into_motion.message;

  table_.advanceTo(now + 60 * kSecond);
  ASSERT_TRUE(table_.motion().atRest());
  const Stamp rested = table_.lastChange();
  EXPECT_GT(rested, touched);
  EXPECT_LT(rested, now + 60 * kSecond);
  const std::vector<Ball<double>> before = table_.motion().balls();
  int in_play = -1;
  for (const auto& b : before)
    if (b.inPlay() && in_play < 0)
      in_play = b.id;
  ASSERT_GE(in_play, 0);
  const Shot nudge = shot(in_play, 0.2, 0.0);
  const StrikeOutcome stale = table_.strike(nudge, rested - 1);
  EXPECT_FALSE(stale.success);
  EXPECT_NE(stale.message.find("last change"), std::string::npos) << stale.message;
  table_.advanceTo(now + 61 * kSecond);
  expectSameBalls(table_.motion().balls(), before);
  const StrikeOutcome fresh = table_.strike(nudge, rested + 1);
  EXPECT_TRUE(fresh.success) << fresh.message;
}

TEST_F(LiveTableTest, RefusedRequestsNameTheFieldAndChangeNothing)
{
  const std::vector<Ball<double>> before = table_.motion().balls();
  const long layout = table_.motion().layoutVersion();
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();

  EXPECT_FALSE(table_.setRealTimeFactor(nan, kStart).success);
  EXPECT_FALSE(table_.setRealTimeFactor(inf, kStart).success);
  const Outcome zero = table_.setRealTimeFactor(0, kStart);
  EXPECT_FALSE(zero.success);
  EXPECT_NE(zero.message.find("real_time_factor"), std::string::npos) << zero.message;
  EXPECT_EQ(table_.options().real_time_factor, 1.0);

  EXPECT_FALSE(table_.strike(shot(0, nan, 0), kStart).success);
  EXPECT_FALSE(table_.strike(shot(0, 13, 0), kStart).success);
  EXPECT_FALSE(table_.strike(shot(16, 1, 0), kStart).success);

  BallInput fast = ballAt(0, 0, 0);
  fast.velocity = physics::Vec3<double>(1e308, 0, 0);
  Outcome set = table_.setState({fast}, kStart);
  EXPECT_FALSE(set.success);
  EXPECT_NE(set.message.find("balls[0].velocity"), std::string::npos) << set.message;
  fast.velocity = physics::Vec3<double>(nan, 0, 0);
  EXPECT_FALSE(table_.setState({fast}, kStart).success);
  fast.velocity = physics::Vec3<double>(1, 0, 0);
  fast.angular_velocity = physics::Vec3<double>(0, 0, 1e9);
  set = table_.setState({fast}, kStart);
  EXPECT_FALSE(set.success);
  EXPECT_NE(set.message.find("balls[0].angular_velocity"), std::string::npos) << set.message;
  set = table_.setState({ballAt(1, 0, 0), ballAt(1, 0.5, 0)}, kStart);
  EXPECT_FALSE(set.success);
  EXPECT_NE(set.message.find("balls[1].id = 1 appears twice"), std::string::npos) << set.message;
  EXPECT_FALSE(table_.setState({}, kStart).success);
  EXPECT_FALSE(table_.setState({ballAt(0, 5, 0)}, kStart).success) << "off the table";
  BallInput down = ballAt(0, 0, 0);
  down.velocity = physics::Vec3<double>(0, 0, -1);
  set = table_.setState({down}, kStart);
  EXPECT_FALSE(set.success);
  EXPECT_NE(set.message.find("balls[0].velocity.z = -1 m/s drives a ball on the cloth into the slate"),
            std::string::npos)
      << set.message;

  PhysicsParams<double> params;
  params.gravity = inf;
  Outcome physics = table_.setPhysics(params, {}, kStart);
  EXPECT_FALSE(physics.success);
  EXPECT_NE(physics.message.find("gravity"), std::string::npos) << physics.message;
  params = PhysicsParams<double>();
  physics::ModelChoice models;
  models.cushion = "no_such_model";
  EXPECT_FALSE(table_.setPhysics(params, models, kStart).success);

  RackRequest rack;
  rack.layout = "triangle";
  EXPECT_FALSE(table_.rack(rack, kStart).success);
  rack.layout = "eight";
  rack.jitter = 1.0;
  const Outcome jitter = table_.rack(rack, kStart);
  EXPECT_FALSE(jitter.success);
  EXPECT_NE(jitter.message.find("jitter"), std::string::npos) << jitter.message;
  rack = RackRequest();
  rack.layout = "custom";
  rack.ids = {0, 1};
  rack.positions = {{0, 0}, {0.01, 0}};
  EXPECT_FALSE(table_.rack(rack, kStart).success) << "overlapping";
  rack.ids = {0, 99};
  EXPECT_FALSE(table_.rack(rack, kStart).success);

  EXPECT_FALSE(table_.step(0.1, kStart).success) << "not paused";
  for (const auto& b : before)
    if (b.id == 0)
    {
      const Outcome onto = table_.placeBall(ballAt(5, b.r.x() + 0.01, b.r.y()), kStart);
      EXPECT_FALSE(onto.success);
      EXPECT_NE(onto.message.find("overlap"), std::string::npos) << onto.message;
    }
  EXPECT_FALSE(table_.removeBall(16, kStart).success);

  table_.advanceTo(kStart + kSecond);
  EXPECT_EQ(table_.motion().layoutVersion(), layout);
  expectSameBalls(table_.motion().balls(), before);
  EXPECT_TRUE(table_.motion().atRest());
}

// A ball given above the cloth is in the air there: it falls, bounces and comes to rest on the
// cloth; one over another ball falls onto it. A state read back from the table, heights and all,
// is taken again as it is.
TEST_F(LiveTableTest, ABallSetInTheAirFallsFromThere)
{
  const double R = PhysicsParams<double>().ball_radius;
  BallInput high = ballAt(0, -0.3, 0.1), over = ballAt(2, 0.3 + 0.3 * R, 0.1);
  high.position.z() = R + 0.2;
  high.velocity = physics::Vec3<double>(-0.5, 0, 1);  // away from the others
  over.position.z() = 5 * R;                          // above ball 1, off its top, with 2R between them
  const Outcome set = table_.setState({high, ballAt(1, 0.3, 0.1), over}, kStart);
  ASSERT_TRUE(set.success) << set.message;
  const auto at = [&](int id) {
    for (const auto& b : table_.motion().balls())
      if (b.id == id)
        return b;
    return Ball<double>();
  };
  EXPECT_EQ(at(0).motion, physics::Motion::Airborne);
  EXPECT_EQ(at(0).r, physics::Vec3<double>(-0.3, 0.1, R + 0.2));
  EXPECT_EQ(at(0).v, physics::Vec3<double>(-0.5, 0, 1));
  EXPECT_EQ(at(1).motion, physics::Motion::Stationary);
  EXPECT_EQ(at(2).motion, physics::Motion::Airborne);

  // Its state taken from the table mid-flight and set again: the same balls, bit for bit.
  table_.advanceTo(kStart + kSecond / 20);
  ASSERT_GT(at(0).r.z(), R);
  std::vector<BallInput> read_back;
  for (const auto& b : table_.motion().balls())
  {
    BallInput in;
    in.id = b.id;
    in.position = b.r;
    in.velocity = b.v;
    in.angular_velocity = b.w;
    read_back.push_back(in);
  }
  const std::vector<Ball<double>> mid_flight = table_.motion().balls();
  ASSERT_TRUE(table_.setState(read_back, kStart + kSecond / 20).success);
  expectSameBalls(table_.motion().balls(), mid_flight);

  table_.advanceTo(kStart + 20 * kSecond);
  EXPECT_TRUE(table_.motion().atRest());
  for (const auto& b : table_.motion().balls())
  {
    EXPECT_FALSE(b.airborne()) << "ball " << b.id;
    EXPECT_EQ(b.r.z(), R) << "ball " << b.id;
  }
  // Ball 2 came down on ball 1's side and knocked it from where it stood, away from itself.
  EXPECT_GT((at(1).r.head<2>() - Eigen::Vector2d(0.3, 0.1)).norm(), 1e-3);
  EXPECT_LT(at(1).r.x(), 0.3);
  EXPECT_GT(at(2).r.x(), 0.3 + 0.3 * R);
}

TEST_F(LiveTableTest, ALargeBallOnAnEmptyTableStillLetsTheTableBeRackedAgain)
{
  RackRequest empty;
  empty.layout = "empty";
  ASSERT_TRUE(table_.rack(empty, kStart).success);
  PhysicsParams<double> large;
  large.ball_radius = 0.1;
  large.cushion_height = 0.13;
  const Outcome set = table_.setPhysics(large, {}, kStart);
  ASSERT_TRUE(set.success) << set.message;
  RackRequest eight;
  eight.layout = "eight";
  const Outcome refused = table_.rack(eight, kStart);
  ASSERT_FALSE(refused.success);
  EXPECT_NE(refused.message.find("ball_radius 0.1"), std::string::npos) << refused.message;
  ASSERT_TRUE(table_.setPhysics(PhysicsParams<double>(), {}, kStart).success);
  const Outcome racked = table_.rack(eight, kStart);
  EXPECT_TRUE(racked.success) << racked.message;
  EXPECT_EQ(table_.motion().balls().size(), 16u);
}

TEST_F(LiveTableTest, OneBallIsPlacedMovedOrRemovedAndTheOthersStay)
{
  const std::vector<Ball<double>> before = table_.motion().balls();
  // Ball in hand: the cue ball moved behind the head string.
  const Outcome moved = table_.placeBall(ballAt(0, -0.6, 0.2), kStart);
  ASSERT_TRUE(moved.success) << moved.message;
  std::vector<Ball<double>> after = table_.motion().balls();
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t i = 0; i < after.size(); ++i)
  {
    if (after[i].id == 0)
      EXPECT_EQ(after[i].r, physics::Vec3<double>(-0.6, 0.2, before[i].r.z()));
    else
      EXPECT_EQ(after[i].r, before[i].r) << "ball " << after[i].id;
  }

  const Outcome removed = table_.removeBall(8, kStart);
  ASSERT_TRUE(removed.success) << removed.message;
  EXPECT_EQ(table_.motion().balls().size(), 15u);
  const Outcome again = table_.removeBall(8, kStart);
  EXPECT_FALSE(again.success);
  EXPECT_NE(again.message.find("not on the table"), std::string::npos) << again.message;
  // A re-spot: the 8 back on the foot spot, where it was.
  for (const auto& b : before)
    if (b.id == 8)
    {
      const Outcome respotted = table_.placeBall(ballAt(8, b.r.x(), b.r.y()), kStart);
      EXPECT_TRUE(respotted.success) << respotted.message;
    }
  EXPECT_EQ(table_.motion().balls().size(), 16u);
  // A ball placed moving rolls off from now.
  BallInput rolling = ballAt(0, -0.6, 0.2);
  rolling.velocity = physics::Vec3<double>(-0.5, 0, 0);
  ASSERT_TRUE(table_.placeBall(rolling, kStart).success);
  EXPECT_FALSE(table_.motion().atRest());
  table_.advanceTo(kStart + kSecond / 10);
  for (const auto& b : table_.motion().balls())
  {
    if (b.id == 0)
    {
      EXPECT_LT(b.r.x(), -0.6 - 0.04);
    }
  }
}

TEST_F(LiveTableTest, AJitteredRackIsSeededAndKeepsItsBallsApart)
{
  RackRequest rack;
  rack.layout = "eight";
  rack.jitter = table_.options().rack_gap / 2;
  rack.seed = 7;
  ASSERT_TRUE(table_.rack(rack, kStart).success);
  const std::vector<Ball<double>> first = table_.motion().balls();
  ASSERT_TRUE(table_.rack(rack, kStart).success);
  expectSameBalls(table_.motion().balls(), first);
  rack.seed = 8;
  ASSERT_TRUE(table_.rack(rack, kStart).success);
  int differ = 0;
  for (std::size_t i = 0; i < first.size(); ++i)
    differ += table_.motion().balls()[i].r != first[i].r;
  EXPECT_GT(differ, 10);
  EXPECT_EQ(table_.engine().whyInvalid(physics::TableState<double>{0, 0, 0, table_.motion().balls()}), "");
}

TEST_F(LiveTableTest, PauseStopsPhysicsAndAStepMovesItByExactlyTheDuration)
{
  ASSERT_TRUE(table_.strike(shot(0, 1.0, 0.3), kStart).success);
  ASSERT_TRUE(table_.pause(true, kStart + kSecond / 10).success);
  const std::vector<Ball<double>> paused = table_.motion().balls();
  table_.advanceTo(kStart + 5 * kSecond);
  expectSameBalls(table_.motion().balls(), paused);
  EXPECT_FALSE(table_.step(0, kStart + 5 * kSecond).success);
  EXPECT_FALSE(table_.step(61, kStart + 5 * kSecond).success);
  ASSERT_TRUE(table_.step(0.25, kStart + 5 * kSecond).success);

  // The same shot run without pausing, to 0.35 s.
  LiveTable reference(engineOn("7ft"), LiveTableOptions(), "eight", kStart);
  ASSERT_TRUE(reference.strike(shot(0, 1.0, 0.3), kStart).success);
  reference.advanceTo(kStart + 35 * kSecond / 100);
  for (std::size_t i = 0; i < paused.size(); ++i)
    EXPECT_NEAR((table_.motion().balls()[i].r - reference.motion().balls()[i].r).norm(), 0, 1e-12)
        << "ball " << paused[i].id;
}

TEST(PredictionLimits, ABatchOverALimitIsRefusedWithItsSizeBeforeAnyWork)
{
  const auto engine = engineOn("7ft");
  const physics::TableState<double> start =
      physics::atTimeZero(physics::rackLayout<double>("eight", engine->table(), engine->params().ball_radius));
  physics::ThreadPool pool(1);
  PredictionLimits limits;
  limits.max_batch_shots = 5;
  std::string why;
  EXPECT_TRUE(predictBatch(*engine, start, std::vector<Shot>(6, shot(0, 3, 0)), {}, limits, pool, why).empty());
  EXPECT_NE(why.find("6 shots, at most max_batch_shots = 5"), std::string::npos) << why;

  limits = PredictionLimits();
  limits.max_samples = 100;
  PredictionOptions sampled;
  sampled.sample_period = 0.01;
  const std::vector<Shot> shots(4, shot(0, 3, 0));
  EXPECT_TRUE(predictBatch(*engine, start, shots, sampled, limits, pool, why).empty());
  EXPECT_NE(why.find("at most max_samples = 100"), std::string::npos) << why;

  limits = PredictionLimits();
  limits.max_reply_bytes = 10000;
  EXPECT_TRUE(predictBatch(*engine, start, shots, sampled, limits, pool, why).empty());
  EXPECT_NE(why.find("at most max_reply_bytes = 10000"), std::string::npos) << why;

  limits = PredictionLimits();
  const std::vector<ShotPrediction> fits = predictBatch(*engine, start, shots, sampled, limits, pool, why);
  EXPECT_EQ(why, "");
  ASSERT_EQ(fits.size(), 4u);
  std::size_t bytes = 0;
  for (const auto& p : fits)
  {
    EXPECT_TRUE(p.success) << p.message;
    EXPECT_EQ(p.samples.size(), static_cast<std::size_t>(std::floor(p.time_to_rest / 0.01)) + 1);
    bytes += p.replyBytes();
  }
  EXPECT_LT(bytes, limits.max_reply_bytes);
}

TEST(LiveTableOptions, EveryOptionOutOfItsRangeIsRefusedByName)
{
  LiveTableOptions options;
  options.real_time_factor = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(LiveTable(engineOn("7ft"), options, "eight", kStart), std::invalid_argument);
  options = LiveTableOptions();
  options.rack_gap = -1;
  EXPECT_NE(options.whyInvalid().find("rack_gap"), std::string::npos);
  options = LiveTableOptions();
  options.noise.phi = -1;
  EXPECT_NE(options.whyInvalid(), "");
  options = LiveTableOptions();
  try
  {
    LiveTable(engineOn("7ft"), options, "eleven", kStart);
    ADD_FAILURE() << "an unknown rack was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("rack"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace session
}  // namespace cue_sim
