// The parts the live table is composed of, each on its own: the clock, the balls in motion, the
// edits and the game.
#include <gtest/gtest.h>

#include "cue_sim/physics/rack.hpp"
#include "live_table_fixtures.hpp"

namespace cue_sim
{
namespace session
{
namespace
{
using fixtures::engineOn;
using fixtures::kSecond;
using fixtures::kStart;

TEST(TableClock, MapsStampsToPhysicsTimeThroughPausesStepsAndFactors)
{
  TableClock clock(1.0, false, kStart);
  clock.restart(kStart);
  EXPECT_EQ(clock.at(kStart + kSecond / 2), 0.5);
  clock.setRealTimeFactor(2.0, kStart + kSecond);  // 1 s of physics so far, then twice as fast
  EXPECT_DOUBLE_EQ(clock.at(kStart + 2 * kSecond), 3.0);
  EXPECT_EQ(clock.whyNotStep(0.1), "not paused: a step advances a paused table (~pause first)");
  clock.pause(true, kStart + 2 * kSecond);
  EXPECT_DOUBLE_EQ(clock.at(kStart + 5 * kSecond), 3.0) << "paused: physics time stands";
  EXPECT_NE(clock.whyNotStep(0).find("duration must be in (0, 60] s, got 0"), std::string::npos);
  EXPECT_NE(clock.whyNotStep(61).find("got 61"), std::string::npos);
  ASSERT_EQ(clock.whyNotStep(0.25), "");
  clock.step(0.25, kStart + 5 * kSecond);
  EXPECT_DOUBLE_EQ(clock.at(kStart + 6 * kSecond), 3.25);
  clock.pause(false, kStart + 6 * kSecond);
  EXPECT_DOUBLE_EQ(clock.at(kStart + 7 * kSecond), 5.25) << "the factor outlasts the pause";
  EXPECT_NE(TableClock::whyBadFactor(0).find("real_time_factor must be in (0, 1000], got 0"), std::string::npos);
  EXPECT_NE(TableClock::whyBadFactor(1001).find("got 1001"), std::string::npos);
  EXPECT_EQ(TableClock::whyBadFactor(1000), "");
  clock.saw(kStart + 9 * kSecond);
  clock.saw(kStart + 8 * kSecond);
  EXPECT_EQ(clock.lastStamp(), kStart + 9 * kSecond) << "never back";
}

/// Ball by ball, every number.
void expectSameBalls(const std::vector<physics::Ball<double>>& a, const std::vector<physics::Ball<double>>& b)
{
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_TRUE(a[i].id == b[i].id && a[i].motion == b[i].motion && a[i].r == b[i].r && a[i].v == b[i].v &&
                a[i].w == b[i].w)
        << "ball " << a[i].id;
}

TEST(LiveBalls, ACopyMovesAsTheOriginalAndLeavesItWhereItWas)
{
  const auto engine = engineOn("7ft");
  LiveBalls balls(engine, true);
  balls.startFrom(physics::rackLayout<double>("eight", engine->table(), engine->params().ball_radius));
  physics::CueStrike<double> strike;
  strike.speed = 8.0;
  strike.phi = 0.002;
  balls.strike(0, strike);
  balls.advance(0.05);
  balls.look();
  const std::vector<physics::Ball<double>> at_50ms = balls.balls();

  LiveBalls copy = balls;  // what the camera takes
  std::vector<physics::Event<double>> copy_events, events;
  for (double t = 0.06; t < 0.5; t += 0.013)
  {
    copy.advance(t, &copy_events);
    copy.look();
  }
  expectSameBalls(balls.balls(), at_50ms);
  EXPECT_EQ(balls.time(), 0.05) << "the original is not advanced";
  for (double t = 0.06; t < 0.5; t += 0.013)
  {
    balls.advance(t, &events);
    balls.look();
  }
  expectSameBalls(copy.balls(), balls.balls());
  ASSERT_EQ(copy_events.size(), events.size());
  for (std::size_t i = 0; i < events.size(); ++i)
    EXPECT_EQ(copy_events[i].time, events[i].time);
  for (std::size_t i = 0; i < balls.orientations().size(); ++i)
    EXPECT_TRUE(copy.orientations()[i].isApprox(balls.orientations()[i], 0)) << "ball " << i;
}

TEST(LiveBalls, NewPhysicsWaitsForRestAndMovesTheBallsToTheirNewHeight)
{
  // Applied at rest, a larger ball sits higher: what tf shows must follow at once.
  LiveTable table(engineOn("7ft"), LiveTableOptions(), "empty", kStart);
  ASSERT_TRUE(table.placeBall(fixtures::ballAt(5, 0.4, 0.1), kStart).success);
  physics::PhysicsParams<double> larger;
  larger.ball_radius = 0.03;
  larger.cushion_height = 0.64 * 2 * larger.ball_radius;
  const Outcome at_rest = table.setPhysics(larger, {}, kStart + kSecond);
  ASSERT_TRUE(at_rest.success) << at_rest.message;
  EXPECT_EQ(at_rest.message, "new physics applied");
  for (const auto& b : table.motion().balls())
    EXPECT_EQ(b.r.z(), 0.03) << "ball " << b.id;

  // While a shot rolls, the physics it started with; the new ones once it rests.
  ASSERT_TRUE(table.strike(fixtures::shot(0, 3.0, 0.0), kStart + 2 * kSecond).success);
  const Outcome moving = table.setPhysics({}, {}, kStart + 2 * kSecond + kSecond / 10);
  ASSERT_TRUE(moving.success) << moving.message;
  EXPECT_EQ(moving.message, "new physics: applies when the balls rest");
  EXPECT_EQ(table.engine().params().ball_radius, 0.03);
  const long layout = table.motion().layoutVersion();
  table.advanceTo(kStart + 30 * kSecond);
  ASSERT_TRUE(table.motion().atRest());
  EXPECT_EQ(table.engine().params().ball_radius, physics::PhysicsParams<double>().ball_radius);
  EXPECT_GT(table.motion().layoutVersion(), layout) << "the table is drawn again";
  for (const auto& b : table.motion().balls())
  {
    if (b.inPlay())
    {
      EXPECT_EQ(b.r.z(), physics::PhysicsParams<double>().ball_radius) << "ball " << b.id;
    }
  }
}

TEST(TableEdits, RequestsAreCheckedInFullIntoWhatTheyMake)
{
  const auto engine = engineOn("7ft");
  TableEdits edits(1e-5);
  physics::TableState<double> rack;
  RackRequest request;
  request.layout = "nine";
  ASSERT_EQ(edits.whyNotRack(request, *engine, rack), "");
  EXPECT_EQ(rack.balls.size(), 10u);
  request.jitter = 1e-5;
  EXPECT_NE(edits.whyNotRack(request, *engine, rack).find("jitter must be in [0, rack_gap / 2]"), std::string::npos);
  edits.racked(physics::rackLayout<double>("nine", engine->table(), engine->params().ball_radius));
  EXPECT_EQ(edits.whyNotReset(*engine), "");
  physics::PhysicsParams<double> huge;
  huge.ball_radius = 0.1;
  huge.cushion_height = 0.15;
  const physics::Engine<double> large(engine->tableShared(), huge);
  EXPECT_NE(edits.whyNotReset(large).find("the last rack does not fit the physics now"), std::string::npos);
  physics::TableState<double> state;
  EXPECT_NE(edits.whyNotState({}, *engine, state).find("give at least one ball"), std::string::npos);
  EXPECT_EQ(TableEdits::whyNotRemovable(7, rack), "");
  EXPECT_EQ(TableEdits::whyNotRemovable(12, rack),
            "ball_id 12 is not on the table (on it: 0, 1, 2, 3, 4, 9, 5, 6, 7, 8)");
}

TEST(LiveGame, FreePlayUntilAGameStartsAndEveryChangeIsCounted)
{
  const auto engine = engineOn("7ft");
  LiveGame game;
  EXPECT_FALSE(game.on());
  EXPECT_EQ(game.whyNotFreeEdit(), "");
  GameRequest request;
  request.rules = "nine_ball";
  std::optional<game::GamePlay> started;
  request.breaker = 2;
  EXPECT_EQ(game.whyNotStart(request, *engine, started), "first_player must be 0 or 1, got 2");
  EXPECT_FALSE(started);
  request.breaker = 0;
  ASSERT_EQ(game.whyNotStart(request, *engine, started), "");
  EXPECT_EQ(game.version(), 0) << "checking starts nothing";
  game.start(std::move(*started));
  EXPECT_TRUE(game.on());
  EXPECT_EQ(game.version(), 1);
  EXPECT_NE(game.whyNotFreeEdit().find("a game of nine_ball is on"), std::string::npos);
  GameCall call;
  call.pocket = "no_such_pocket";
  EXPECT_NE(game.call(call, engine->table()).find("pocket must be one of"), std::string::npos);
  EXPECT_EQ(game.version(), 1) << "a refused call changes nothing";
  EXPECT_EQ(game.end(), "nine_ball");
  EXPECT_FALSE(game.on());
  EXPECT_EQ(game.version(), 2);
}

}  // namespace
}  // namespace session
}  // namespace cue_sim
