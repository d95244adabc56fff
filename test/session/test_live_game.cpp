// A game on the live table, without ROS: refereed strikes whose ruling is the core game's
// (game::GamePlay::shoot on the same position), taken when the balls rest; ball in hand and
// calls checked by the rules; free edits refused while a game is on. Each refusal names the
// field and changes nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "live_table_fixtures.hpp"

namespace cue_sim
{
namespace session
{
namespace
{
using fixtures::ballAt;
using fixtures::engineOn;
using fixtures::kSecond;
using fixtures::kStart;

Shot cueShot(double speed, double phi)
{
  return fixtures::shot(0, speed, phi);
}

const physics::Pocket& pocketNamed(const physics::TableModel& table, const std::string& name)
{
  for (const auto& p : table.pockets())
    if (p.name == name)
      return p;
  throw std::runtime_error("no pocket " + name);
}

class LiveGameTest : public ::testing::Test
{
protected:
  LiveGameTest() : table_(engineOn("7ft"), LiveTableOptions(), "eight", kStart) {}

  /// Advances until the balls rest (a shot of a few seconds at most), returning when.
  Stamp runToRest(Stamp from)
  {
    Stamp t = from;
    for (int i = 0; i < 600 && (table_.game().pendingTurn() || !table_.motion().atRest()); ++i)
      table_.advanceTo(t += kSecond / 10);
    EXPECT_FALSE(table_.game().pendingTurn());
    return t;
  }

  /// A game from a position: the cue ball at `cue`, ball 1 elsewhere, the break played.
  void startFromPosition(const std::string& rules, const Eigen::Vector2d& cue, const Eigen::Vector2d& one)
  {
    GameRequest request;
    request.rules = rules;
    request.players = {"ann", "bob"};
    request.balls = {ballAt(0, cue.x(), cue.y()), ballAt(1, one.x(), one.y())};
    if (rules == "nine_ball")
      request.balls.push_back(ballAt(9, one.x(), one.y() + 0.2));
    const Outcome started = table_.startGame(request, kStart);
    ASSERT_TRUE(started.success) << started.message;
  }

  LiveTable table_;
};

TEST_F(LiveGameTest, StartingAGameRacksForTheBreakAndRefusesFreeEdits)
{
  GameRequest request;
  request.rules = "eight_ball";
  request.players = {"ann", "bob"};
  request.breaker = 1;
  const Outcome started = table_.startGame(request, kStart);
  ASSERT_TRUE(started.success) << started.message;
  ASSERT_NE(table_.game().play(), nullptr);
  const game::GameState& state = table_.game().play()->state();
  EXPECT_EQ(state.turn, 1);
  EXPECT_TRUE(state.break_shot);
  EXPECT_EQ(state.ball_in_hand, game::BallInHand::BehindHeadString);
  EXPECT_EQ(table_.motion().balls().size(), 16u);
  // The cue ball stands behind the head string, not on it (WPA 8.1): where it is, it may be placed.
  const auto& cue =
      table_.game().play()->table().balls[static_cast<std::size_t>(table_.game().play()->table().indexOf(0))];
  EXPECT_LT(cue.r.x(), table_.table().headStringX());
  EXPECT_TRUE(table_.placeCueBall(cue.r.head<2>(), kStart).success);
  const Outcome on_string = table_.placeCueBall(table_.table().headSpot(), kStart);
  EXPECT_FALSE(on_string.success);
  EXPECT_NE(on_string.message.find("not on it (WPA 8.1"), std::string::npos) << on_string.message;

  const long version = table_.motion().layoutVersion();
  RackRequest rack;
  rack.layout = "nine";
  for (const Outcome& refused :
       {table_.rack(rack, kStart), table_.reset(kStart), table_.setState({ballAt(0, 0, 0)}, kStart),
        table_.placeBall(ballAt(0, -0.5, 0), kStart), table_.removeBall(3, kStart)})
  {
    EXPECT_FALSE(refused.success);
    EXPECT_NE(refused.message.find("a game of eight_ball is on"), std::string::npos) << refused.message;
  }
  const StrikeOutcome object_ball = table_.strike(
      [] {
        Shot s = cueShot(2, 0);
        s.ball_id = 5;
        return s;
      }(),
      kStart);
  EXPECT_FALSE(object_ball.success);
  EXPECT_NE(object_ball.message.find("ball_id: ball 5 is not struck in a game of eight_ball"), std::string::npos)
      << object_ball.message;
  EXPECT_EQ(table_.motion().layoutVersion(), version);
  EXPECT_EQ(table_.motion().balls().size(), 16u);
}

TEST_F(LiveGameTest, BadGameRequestsAreRefusedNamingTheField)
{
  GameRequest request;
  request.rules = "bagatelle";
  Outcome r = table_.startGame(request, kStart);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("eight_ball, nine_ball"), std::string::npos) << r.message;
  request.rules = "nine_ball";
  request.breaker = 2;
  r = table_.startGame(request, kStart);
  EXPECT_NE(r.message.find("first_player must be 0 or 1"), std::string::npos) << r.message;
  request.breaker = 0;
  request.players[1] = "";
  r = table_.startGame(request, kStart);
  EXPECT_NE(r.message.find("players[1]"), std::string::npos) << r.message;
  request.players[1] = "bob";
  request.balls = {ballAt(1, 0.3, 0.1)};
  r = table_.startGame(request, kStart);
  EXPECT_NE(r.message.find("cue ball"), std::string::npos) << r.message;
  BallInput pocketed_cue = ballAt(0, 0, 0);
  pocketed_cue.pocketed = true;
  pocketed_cue.pocket = table_.table().pockets().front().name;
  request.balls.push_back(pocketed_cue);
  r = table_.startGame(request, kStart);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("cue ball (id 0) on the cloth"), std::string::npos) << r.message;
  EXPECT_EQ(table_.game().play(), nullptr);
  EXPECT_FALSE(table_.callShot(GameCall{}, kStart).success);
  EXPECT_FALSE(table_.placeCueBall(Eigen::Vector2d(-0.5, 0), kStart).success);
  EXPECT_FALSE(table_.endGame(kStart).success);

  LiveTable carom(engineOn("carom"), LiveTableOptions(), "empty", kStart);
  request.balls.clear();
  r = carom.startGame(request, kStart);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("pockets"), std::string::npos) << r.message;
}

// The live table's ruling and the table it leaves are the core game's on the same position,
// bit for bit: the node referees exactly as `simulate` and self-play do.
TEST_F(LiveGameTest, ABreakIsRuledAsTheCoreGameRulesItAndTakenAtRest)
{
  GameRequest request;
  request.rules = "eight_ball";
  request.seed = 3;
  ASSERT_TRUE(table_.startGame(request, kStart).success);
  game::GamePlay core = *table_.game().play();

  const Stamp struck_at = kStart + kSecond;
  const StrikeOutcome outcome = table_.strike(cueShot(8, 0.002), struck_at);
  ASSERT_TRUE(outcome.success) << outcome.message;
  ASSERT_TRUE(outcome.refereed);
  ASSERT_TRUE(table_.game().pendingTurn());
  const game::Turn expected = core.shoot(cueShot(8, 0.002).strike);
  EXPECT_EQ(outcome.ruling.reason, expected.ruling.reason);
  EXPECT_EQ(outcome.ruling.foul, expected.ruling.foul);
  EXPECT_EQ(outcome.ruling.next_player, expected.ruling.next_player);
  EXPECT_NE(outcome.message.find(expected.ruling.reason), std::string::npos);

  // While the balls roll the game waits: no call, no placement, no strike.
  table_.advanceTo(struck_at + kSecond / 10);
  ASSERT_FALSE(table_.motion().atRest());
  EXPECT_FALSE(table_.callShot(GameCall{}, struck_at + kSecond / 10).success);
  EXPECT_FALSE(table_.placeCueBall(Eigen::Vector2d(-0.6, 0), struck_at + kSecond / 10).success);
  const StrikeOutcome moving = table_.strike(cueShot(1, 0), struck_at + kSecond / 10);
  EXPECT_FALSE(moving.success);
  EXPECT_NE(moving.message.find("still moving"), std::string::npos) << moving.message;
  EXPECT_EQ(table_.game().play()->state().shots, 0);

  runToRest(struck_at);
  ASSERT_TRUE(table_.game().lastTurn());
  EXPECT_EQ(table_.game().lastTurn()->ruling.reason, expected.ruling.reason);
  EXPECT_EQ(table_.game().play()->state().shots, 1);
  EXPECT_EQ(table_.game().play()->state().turn, core.state().turn);
  EXPECT_EQ(table_.game().play()->state().ball_in_hand, core.state().ball_in_hand);
  const auto& live = table_.game().play()->table().balls;
  const auto& reference = core.table().balls;
  ASSERT_EQ(live.size(), reference.size());
  for (std::size_t i = 0; i < live.size(); ++i)
  {
    EXPECT_EQ(live[i].id, reference[i].id);
    EXPECT_EQ(live[i].r, reference[i].r) << "ball " << live[i].id;
    EXPECT_EQ(live[i].pocket, reference[i].pocket) << "ball " << live[i].id;
  }
  // What the live table shows is the game's table.
  for (const auto& b : table_.motion().balls())
  {
    if (b.inPlay())
    {
      EXPECT_EQ(b.r, live[static_cast<std::size_t>(table_.game().play()->table().indexOf(b.id))].r);
    }
  }
}

TEST_F(LiveGameTest, AScratchGivesTheOpponentBallInHandWhichTheRulesPlace)
{
  const physics::TableModel& model = table_.table();
  const Eigen::Vector2d pocket = pocketNamed(model, "pocket_foot_ypos").centre;
  const Eigen::Vector2d cue = model.clothCentre() + Eigen::Vector2d(0.4, 0.1);
  startFromPosition("eight_ball", cue, model.clothCentre() + Eigen::Vector2d(-0.5, -0.3));
  const double phi = std::atan2(pocket.y() - cue.y(), pocket.x() - cue.x());
  const StrikeOutcome outcome = table_.strike(cueShot(1.5, phi), kStart + kSecond);
  ASSERT_TRUE(outcome.success) << outcome.message;
  EXPECT_TRUE(outcome.ruling.foul);
  EXPECT_EQ(outcome.ruling.next_player, 1);
  EXPECT_EQ(outcome.ruling.ball_in_hand, game::BallInHand::Anywhere);
  runToRest(kStart + kSecond);

  // The cue ball is back on the cloth, in hand for bob, anywhere.
  const game::GameState& state = table_.game().play()->state();
  EXPECT_EQ(state.turn, 1);
  EXPECT_EQ(state.consecutive_fouls[0], 1);
  EXPECT_EQ(state.ball_in_hand, game::BallInHand::Anywhere);
  ASSERT_GE(table_.game().play()->table().indexOf(0), 0);
  const long version = table_.game().version();
  const Eigen::Vector2d one = model.clothCentre() + Eigen::Vector2d(-0.5, -0.3);
  const Outcome on_ball = table_.placeCueBall(one + Eigen::Vector2d(0.02, 0), kStart + 20 * kSecond);
  EXPECT_FALSE(on_ball.success);
  EXPECT_NE(on_ball.message.find("overlap"), std::string::npos) << on_ball.message;
  const Outcome off_table = table_.placeCueBall(Eigen::Vector2d(5, 0), kStart + 20 * kSecond);
  EXPECT_FALSE(off_table.success);
  EXPECT_EQ(table_.game().version(), version);

  const Eigen::Vector2d foot = model.clothCentre() + Eigen::Vector2d(0.6, -0.2);  // past the head string: anywhere
  const Outcome placed = table_.placeCueBall(foot, kStart + 20 * kSecond);
  ASSERT_TRUE(placed.success) << placed.message;
  bool found = false;
  for (const auto& b : table_.motion().balls())
    if (b.id == 0)
    {
      found = true;
      EXPECT_DOUBLE_EQ(b.r.x(), foot.x());
      EXPECT_DOUBLE_EQ(b.r.y(), foot.y());
      EXPECT_TRUE(b.inPlay());
    }
  EXPECT_TRUE(found);
  EXPECT_GT(table_.game().version(), version);
}

TEST_F(LiveGameTest, CallsNameARealPocketAndAPushOutOnlyAfterTheBreak)
{
  const physics::TableModel& model = table_.table();
  startFromPosition("nine_ball", model.clothCentre() + Eigen::Vector2d(-0.5, 0),
                    model.clothCentre() + Eigen::Vector2d(0.3, 0));
  GameCall call;
  call.ball = 1;
  call.pocket = "corner";
  Outcome r = table_.callShot(call, kStart);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("pocket_foot_ypos"), std::string::npos) << r.message;
  call.pocket = "pocket_foot_ypos";
  call.ball = 4;
  r = table_.callShot(call, kStart);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("not on the table"), std::string::npos) << r.message;
  call.ball = 1;
  call.push_out = true;
  r = table_.callShot(call, kStart);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("2.4"), std::string::npos) << r.message;
  EXPECT_EQ(table_.game().play()->state().called_ball, -1);
  call.push_out = false;
  r = table_.callShot(call, kStart);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(table_.game().play()->state().called_ball, 1);
  EXPECT_EQ(model.pockets()[static_cast<std::size_t>(table_.game().play()->state().called_pocket)].name,
            "pocket_foot_ypos");
}

TEST_F(LiveGameTest, AWonGameTakesNoMoreShotsAndEndingItFreesTheTable)
{
  const physics::TableModel& model = table_.table();
  // 9-ball with only the 9 left, straight in: potting it wins.
  const Eigen::Vector2d pocket = pocketNamed(model, "pocket_foot_ypos").centre;
  const Eigen::Vector2d along_bisector(-M_SQRT1_2, -M_SQRT1_2);
  const Eigen::Vector2d one = pocket + along_bisector * 0.3;
  const Eigen::Vector2d cue = pocket + along_bisector * 0.6;
  GameRequest request;
  request.rules = "nine_ball";
  request.balls = {ballAt(0, cue.x(), cue.y()), ballAt(9, one.x(), one.y())};
  ASSERT_TRUE(table_.startGame(request, kStart).success);
  const double phi = std::atan2(pocket.y() - cue.y(), pocket.x() - cue.x());
  const StrikeOutcome outcome = table_.strike(cueShot(1.5, phi), kStart + kSecond);
  ASSERT_TRUE(outcome.success) << outcome.message;
  EXPECT_FALSE(outcome.ruling.foul) << outcome.ruling.reason;
  EXPECT_TRUE(outcome.ruling.game_over) << outcome.ruling.reason;
  EXPECT_EQ(outcome.ruling.winner, 0);
  const Stamp rest = runToRest(kStart + kSecond);
  EXPECT_TRUE(table_.game().play()->state().over);
  const StrikeOutcome after = table_.strike(cueShot(1, 0), rest + kSecond);
  EXPECT_FALSE(after.success);
  EXPECT_NE(after.message.find("the game is over: player 1 won"), std::string::npos) << after.message;
  const std::size_t balls = table_.motion().balls().size();
  ASSERT_TRUE(table_.endGame(rest + kSecond).success);
  EXPECT_EQ(table_.game().play(), nullptr);
  EXPECT_EQ(table_.motion().balls().size(), balls);
  EXPECT_TRUE(table_.strike(cueShot(1, 0), rest + 2 * kSecond).success);
  RackRequest rack;
  rack.layout = "nine";
  EXPECT_TRUE(table_.rack(rack, rest + 10 * kSecond).success);
}

TEST_F(LiveGameTest, APushOutCalledAfterALegalBreakIsRuledAsOne)
{
  // Racks until a break is legal and leaves the game on (the 9 not down).
  Stamp t = kStart;
  bool ready = false;
  for (std::uint32_t seed = 0; seed < 10 && !ready; ++seed)
  {
    GameRequest request;
    request.rules = "nine_ball";
    request.seed = seed;
    ASSERT_TRUE(table_.startGame(request, t).success);
    const Eigen::Vector2d cue = table_.game()
                                    .play()
                                    ->table()
                                    .balls[static_cast<std::size_t>(table_.game().play()->table().indexOf(0))]
                                    .r.head<2>();
    const Eigen::Vector2d foot = table_.table().footSpot();
    ASSERT_TRUE(table_.strike(cueShot(8, std::atan2(foot.y() - cue.y(), foot.x() - cue.x())), t + kSecond).success);
    t = runToRest(t + kSecond) + kSecond;
    ready = table_.game().play()->state().push_out_allowed && !table_.game().play()->state().over;
  }
  ASSERT_TRUE(ready) << "no legal 9-ball break in 10 racks";
  GameCall push;
  push.push_out = true;
  const Outcome called = table_.callShot(push, t);
  ASSERT_TRUE(called.success) << called.message;
  EXPECT_TRUE(table_.game().pushOutCalled());
  const int shooter = table_.game().play()->state().turn;
  // A soft roll towards the middle of the table: no scratch (a scratch stays a foul, WPA 2.4).
  const Eigen::Vector2d cue = table_.game()
                                  .play()
                                  ->table()
                                  .balls[static_cast<std::size_t>(table_.game().play()->table().indexOf(0))]
                                  .r.head<2>();
  const Eigen::Vector2d middle = table_.table().clothCentre();
  const StrikeOutcome pushed =
      table_.strike(cueShot(0.3, std::atan2(middle.y() - cue.y(), middle.x() - cue.x())), t + kSecond);
  ASSERT_TRUE(pushed.success) << pushed.message;
  EXPECT_EQ(pushed.ruling.rule, "WPA 2.4") << pushed.ruling.reason;
  runToRest(t + kSecond);
  EXPECT_FALSE(table_.game().pushOutCalled());
  EXPECT_FALSE(table_.game().play()->state().push_out_allowed);  // only the shot right after the break
  EXPECT_FALSE(pushed.ruling.foul) << pushed.ruling.reason;
  EXPECT_EQ(table_.game().play()->state().turn, 1 - shooter);  // the simulator's choice after a push-out
}

TEST_F(LiveGameTest, EndingAGameMidShotLetsTheBallsRollOnUnrefereed)
{
  GameRequest request;
  request.rules = "eight_ball";
  ASSERT_TRUE(table_.startGame(request, kStart).success);
  ASSERT_TRUE(table_.strike(cueShot(8, 0.002), kStart + kSecond).success);
  const Stamp mid = kStart + kSecond + kSecond / 2;
  table_.advanceTo(mid);
  ASSERT_FALSE(table_.motion().atRest());
  const std::vector<physics::Ball<double>> rolling = table_.motion().balls();
  ASSERT_TRUE(table_.endGame(mid).success);
  EXPECT_EQ(table_.game().play(), nullptr);
  EXPECT_FALSE(table_.game().pendingTurn());
  EXPECT_FALSE(table_.motion().atRest());
  ASSERT_EQ(table_.motion().balls().size(), rolling.size());
  for (std::size_t i = 0; i < rolling.size(); ++i)
  {
    EXPECT_EQ(table_.motion().balls()[i].r, rolling[i].r) << "ball " << rolling[i].id;
    EXPECT_EQ(table_.motion().balls()[i].v, rolling[i].v) << "ball " << rolling[i].id;
  }
  runToRest(mid);
  EXPECT_TRUE(table_.motion().atRest());
}

}  // namespace
}  // namespace session
}  // namespace cue_sim
