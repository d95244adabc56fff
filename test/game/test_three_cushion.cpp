// Three-cushion (UMB World Rules of Carom Billiard): the starting position, the count of cushions
// before the second ball, points, innings and the race, fouls (the wrong ball, a ball off the
// table, the starting stroke not on the red), the re-spotting of balls off the table or frozen
// together. Each rule on exact positions or a shot's facts; the count on a shot's events.
#include <gtest/gtest.h>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/game/self_play.hpp"
#include "cue_sim/physics/rack.hpp"
#include "game_test_support.hpp"

using namespace cue_sim;
using namespace cue_sim::game;
using namespace cue_sim::game::test;
using physics::Event;
using physics::EventKind;

namespace
{
constexpr int kWhite = 0, kYellow = 1, kRed = 2;

GameState threeCushion(int turn = 0, bool break_shot = false)
{
  GameState s;
  s.rules = "three_cushion";
  s.turn = turn;
  s.break_shot = break_shot;
  s.ball_in_hand = BallInHand::None;
  s.target = 40;
  return s;
}

ShotFacts caromOf(int cue, int first, int second, int cushions)
{
  ShotFacts f;
  f.cue_ball = cue;
  f.first_contact = first;
  f.second_contact = second;
  f.cushions_before_second = cushions;
  return f;
}

Event<double> event(EventKind kind, double time, int ball, int other = -1, int obstacle = -1)
{
  Event<double> e;
  e.kind = kind;
  e.time = time;
  e.ball = ball;
  e.other = other;
  e.obstacle = obstacle;
  return e;
}

Eigen::Vector2d at(const TableState<double>& s, int id)
{
  return s.balls[static_cast<std::size_t>(s.indexOf(id))].r.head<2>();
}

TableState<double> balls(const std::vector<Ball<double>>& list)
{
  TableState<double> s;
  s.balls = list;
  return s;
}
}  // namespace

TEST(ThreeCushion, TheStartingPositionPutsEachBallOnItsSpotAndTheBreakerOnTheStartingSpot)
{
  const TableModel& t = caromEngine().table();
  for (const int breaker : {0, 1})
  {
    GamePlay game(caromEngine(), "three_cushion", {"a", "b"}, gameRack(), breaker);
    const TableState<double>& s = game.table();
    ASSERT_EQ(s.balls.size(), 3u);
    EXPECT_EQ(game.cueBall(), breaker) << "each player strikes a ball of their own";
    EXPECT_EQ((at(s, kRed) - t.footSpot()).norm(), 0.0) << "the red on the top spot (Art. 23)";
    EXPECT_EQ((at(s, 1 - breaker) - t.headSpot()).norm(), 0.0) << "the other cue ball on the bottom spot";
    const Eigen::Vector2d start = at(s, breaker) - t.headSpot();
    EXPECT_NEAR(start.x(), 0.0, 1e-15);
    EXPECT_NEAR(std::abs(start.y()), 0.182, 1e-15) << "on the head string 18.2 cm from the bottom spot (Art. 13)";
    EXPECT_EQ(game.state().ball_in_hand, BallInHand::None);
    EXPECT_EQ(game.legalFirst(), std::vector<int>{kRed}) << "the starting stroke is on the red (Art. 23)";
    EXPECT_EQ(game.state().target, 40);
    EXPECT_EQ(game.state().innings[static_cast<std::size_t>(breaker)], 1);
    EXPECT_EQ(game.state().innings[static_cast<std::size_t>(1 - breaker)], 0);
  }
}

TEST(ThreeCushion, CushionsAreCountedUntilTheSecondBallAndOnlyTheCueBalls)
{
  // The yellow's cue ball: a cushion, the red, two cushions (one of them twice, and the red's own
  // cushion between, which does not count), then the white: three before the second ball. The
  // cushions after it do not count either.
  const std::vector<Event<double>> events = {
      event(EventKind::BallCushion, 0.1, kYellow, -1, 1), event(EventKind::BallBall, 0.2, kRed, kYellow),
      event(EventKind::BallCushion, 0.3, kRed, -1, 0),    event(EventKind::BallCushion, 0.4, kYellow, -1, 2),
      event(EventKind::BallCushion, 0.5, kYellow, -1, 2), event(EventKind::BallBall, 0.6, kRed, kYellow),
      event(EventKind::BallBall, 0.7, kYellow, kWhite),   event(EventKind::BallCushion, 0.8, kYellow, -1, 3),
  };
  const ShotFacts f = readShot(events, &caromEngine().table(), kYellow);
  EXPECT_EQ(f.cue_ball, kYellow);
  EXPECT_EQ(f.first_contact, kRed);
  EXPECT_EQ(f.second_contact, kWhite) << "the red met again is not a second ball";
  EXPECT_EQ(f.cushions_before_second, 3);
  // Without a second ball every cue-ball cushion counts, for the ruling's text.
  const ShotFacts one(readShot({events.begin(), events.begin() + 6}, &caromEngine().table(), kYellow));
  EXPECT_EQ(one.second_contact, -1);
  EXPECT_EQ(one.cushions_before_second, 3);
}

TEST(ThreeCushion, APointNeedsBothBallsAndThreeCushionsBeforeTheSecond)
{
  const GameState s = threeCushion(1);
  for (int cushions = 0; cushions <= 5; ++cushions)
  {
    const Ruling r = judge(s, {kWhite, kRed}, caromOf(kYellow, kRed, kWhite, cushions));
    EXPECT_FALSE(r.foul) << "a miss is no foul in three-cushion";
    EXPECT_EQ(r.rule, "UMB Art. 83");
    EXPECT_EQ(r.points, cushions >= 3 ? 1 : 0) << cushions;
    EXPECT_EQ(r.continues, cushions >= 3);
    EXPECT_EQ(r.next_player, cushions >= 3 ? 1 : 0);
  }
  const Ruling one_ball = judge(s, {kWhite, kRed}, caromOf(kYellow, kRed, -1, 6));
  EXPECT_EQ(one_ball.points, 0);
  EXPECT_NE(one_ball.reason.find("not the other object ball"), std::string::npos) << one_ball.reason;
  const Ruling none = judge(s, {kWhite, kRed}, caromOf(kYellow, -1, -1, 4));
  EXPECT_EQ(none.points, 0);
  EXPECT_FALSE(none.foul);
  // A third miss in a row loses nothing: WPA 6.14 is pool's.
  GameState three = s;
  three.consecutive_fouls = {0, 2};
  ShotFacts wrong = caromOf(kWhite, kRed, -1, 0);
  const Ruling third = judge(three, {kWhite, kRed}, wrong);
  EXPECT_TRUE(third.foul);
  EXPECT_FALSE(third.game_over);
}

TEST(ThreeCushion, PointsAddUpInningsCountTurnsAtTheTableAndTheTargetWins)
{
  GameState s = threeCushion(0);
  s.innings = {1, 0};
  const ShotFacts point = caromOf(kWhite, kRed, kYellow, 3);
  s = afterRuling(s, judge(s, {kYellow, kRed}, point));
  EXPECT_EQ(s.score, (std::array<int, 2>{1, 0}));
  EXPECT_EQ(s.turn, 0);
  EXPECT_EQ(s.innings, (std::array<int, 2>{1, 0})) << "a point continues the inning";
  s = afterRuling(s, judge(s, {kYellow, kRed}, caromOf(kWhite, kRed, -1, 2)));
  EXPECT_EQ(s.turn, 1);
  EXPECT_EQ(s.innings, (std::array<int, 2>{1, 1})) << "a miss passes the table: the other's inning begins";
  s.score = {39, 39};
  const Ruling win = judge(s, {kWhite, kRed}, caromOf(kYellow, kWhite, kRed, 4));
  EXPECT_TRUE(win.game_over);
  EXPECT_EQ(win.winner, 1);
  EXPECT_NE(win.reason.find("reaches 40 and wins"), std::string::npos) << win.reason;
  const std::array<int, 2> innings = s.innings;
  s = afterRuling(s, win);
  EXPECT_TRUE(s.over);
  EXPECT_EQ(s.score, (std::array<int, 2>{39, 40}));
  EXPECT_EQ(s.innings, innings) << "the winning point begins no one's inning";
}

TEST(ThreeCushion, FoulsEndTheInningWithoutAPoint)
{
  // The wrong ball (Art. 41): a point made with the opponent's ball does not count.
  const Ruling wrong = judge(threeCushion(0), {kYellow, kRed}, caromOf(kYellow, kWhite, kRed, 3));
  EXPECT_TRUE(wrong.foul);
  EXPECT_EQ(wrong.rule, "UMB Art. 41");
  EXPECT_EQ(wrong.points, 0);
  EXPECT_EQ(wrong.next_player, 1);
  // The starting stroke must meet the red first (Art. 23).
  const Ruling start = judge(threeCushion(0, true), {kYellow, kRed}, caromOf(kWhite, kYellow, kRed, 3));
  EXPECT_TRUE(start.foul);
  EXPECT_EQ(start.rule, "UMB Art. 23");
  EXPECT_TRUE(judge(threeCushion(0, true), {kYellow, kRed}, caromOf(kWhite, kRed, kYellow, 3)).points == 1);
  // A ball off the table (Art. 28): spotted, even on a point.
  ShotFacts off = caromOf(kWhite, kRed, kYellow, 3);
  off.off_table = {kRed};
  const Ruling jumped = judge(threeCushion(0), {kYellow, kRed}, off);
  EXPECT_TRUE(jumped.foul);
  EXPECT_EQ(jumped.rule, "UMB Art. 28");
  EXPECT_EQ(jumped.points, 0);
  EXPECT_EQ(jumped.respot, std::vector<int>{kRed});
  // The game takes a strike of either cue ball (the wrong one is the referee's to rule on) but
  // refuses one of the red.
  GamePlay game(caromEngine(), "three_cushion");
  CueStrike<double> cue;
  cue.speed = 2;
  EXPECT_NE(game.whyNotStrikable(kRed), "");
  EXPECT_THROW(game.shoot(cue, false, nullptr, kRed), std::invalid_argument);
  const Turn t = game.shoot(cue, false, nullptr, kYellow);
  EXPECT_EQ(t.ball, kYellow);
  EXPECT_EQ(t.ruling.rule, "UMB Art. 41");
  EXPECT_EQ(game.state().turn, 1);
}

TEST(ThreeCushion, BallsAreSpottedOnTheirSpotsOrOnTheSpotOfTheBallInTheWay)
{
  const TableModel& t = caromEngine().table();
  const auto rules = makeRules("three_cushion");
  // The red off the table, its spot free: back on the top spot.
  TableState<double> s = balls({ball(kWhite, 0.3, 0.3), ball(kYellow, -0.3, -0.2), ball(kRed, 0, 0)});
  s.balls[2].motion = physics::Motion::OffTable;
  rules->respot(t, R(), {kRed}, threeCushion(1), s);
  EXPECT_TRUE(s.balls[2].inPlay());
  EXPECT_EQ((at(s, kRed) - t.footSpot()).norm(), 0.0);
  // The yellow (the incoming shooter's) off the table, the white on its bottom spot: the yellow
  // goes on the white's spot, the centre spot.
  s = balls({ball(kWhite, t.headSpot().x(), t.headSpot().y()), ball(kYellow, 0, 0.4), ball(kRed, 0.5, 0.1)});
  s.balls[1].motion = physics::Motion::OffTable;
  rules->respot(t, R(), {kYellow}, threeCushion(1), s);
  EXPECT_EQ((at(s, kYellow) - t.clothCentre()).norm(), 0.0);
}

TEST(ThreeCushion, ACueBallFrozenToABallIsRespottedBeforeTheShot)
{
  const TableModel& t = caromEngine().table();
  const auto rules = makeRules("three_cushion");
  // The white (to shoot) touching the red: the red to the top spot, the white to the bottom spot;
  // the yellow stays.
  const Eigen::Vector2d red(0.4, -0.1);
  TableState<double> s =
      balls({ball(kWhite, red.x() - 2 * R(), red.y()), ball(kYellow, -0.5, 0.3), ball(kRed, red.x(), red.y())});
  GameState state = threeCushion(0);
  const std::string why = rules->beforeShot(t, R(), state, s);
  EXPECT_NE(why.find("UMB Art. 27"), std::string::npos) << why;
  EXPECT_EQ((at(s, kRed) - t.footSpot()).norm(), 0.0);
  EXPECT_EQ((at(s, kWhite) - t.headSpot()).norm(), 0.0);
  EXPECT_EQ((at(s, kYellow) - Eigen::Vector2d(-0.5, 0.3)).norm(), 0.0);
  // Balls 1 mm apart are not touching; nor is the other player's ball frozen to the red.
  s = balls({ball(kWhite, red.x() - 2 * R() - 1e-3, red.y()), ball(kYellow, red.x(), red.y() + 2 * R()),
             ball(kRed, red.x(), red.y())});
  const TableState<double> before = s;
  EXPECT_EQ(rules->beforeShot(t, R(), state, s), "");
  for (std::size_t k = 0; k < s.balls.size(); ++k)
    EXPECT_EQ(s.balls[k].r, before.balls[k].r);
}

TEST(ThreeCushion, ThePlannersPointIsThreeCushionImpactsOfTheCueBallBeforeItsSecondBall)
{
  // From the starting position, without noise, the carom planner finds a point; the shot's events
  // show the cue ball at each counted cushion on a cushion line, and its two ball contacts at two
  // balls' distance from each object ball.
  GamePlay game(caromEngine(), "three_cushion");
  const Choice c = CaromPlanner().choose(game);
  TableState<double> shot = game.table();
  caromEngine().strike(shot, kWhite, c.strike);
  TableState<double> state = shot;
  const auto events = simulateToRest(caromEngine(), state).events;
  const ShotFacts f = readShot(events, &caromEngine().table(), kWhite);
  ASSERT_GE(f.second_contact, 0);
  ASSERT_GE(f.cushions_before_second, 3);
  const TableModel& t = caromEngine().table();
  TableState<double> replay = shot;
  int cushions = 0;
  for (const auto& e : events)
  {
    physics::advance(caromEngine(), replay, e.time);
    const std::vector<Ball<double>> now = caromEngine().snapshot(replay);
    const auto where = [&](int id) {
      return Eigen::Vector2d(now[static_cast<std::size_t>(replay.indexOf(id))].r.head<2>());
    };
    const Eigen::Vector2d p = where(kWhite);
    if (e.kind == EventKind::BallCushion && e.ball == kWhite)
    {
      const double to_long = std::abs(std::abs(p.x()) - t.clothLength() / 2);
      const double to_short = std::abs(std::abs(p.y()) - t.clothWidth() / 2);
      EXPECT_NEAR(std::min(to_long, to_short), R(), 1e-6) << "a cushion impact one radius from the cloth's edge";
      ++cushions;
    }
    if (e.kind == EventKind::BallBall && (e.ball == kWhite || e.other == kWhite))
    {
      EXPECT_NEAR((p - where(e.ball == kWhite ? e.other : e.ball)).norm(), 2 * R(), 1e-6);
      if ((e.ball == kWhite ? e.other : e.ball) == f.second_contact)
        break;
    }
  }
  EXPECT_EQ(cushions, f.cushions_before_second);
  EXPECT_EQ(game.shoot(c.strike).ruling.points, 1);
}
