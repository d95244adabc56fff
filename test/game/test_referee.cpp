// The referee: every rule it applies, on shots played by the engine (scenes) where a shot can
// show it, on a shot's facts where only the ruleset's logic is at stake; spotting and ball in
// hand on the table's geometry; and thousands of random shots through whole games.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/game/referee.hpp"
#include "cue_sim/game/self_play.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "game_test_support.hpp"

using namespace cue_sim;
using namespace cue_sim::game;
using namespace cue_sim::game::test;

namespace
{
GameState eightBallAfterBreak(Group shooter_group)
{
  GameState s;
  s.rules = "eight_ball";
  s.break_shot = false;
  s.ball_in_hand = BallInHand::None;
  s.groups = {shooter_group, shooter_group == Group::Open     ? Group::Open
                             : shooter_group == Group::Solids ? Group::Stripes
                                                              : Group::Solids};
  return s;
}
}  // namespace

TEST(Referee, AScratchIsAFoulWithBallInHandAnywhere)
{
  // WPA 6.1: the cue ball rolled into the corner pocket it was aimed at.
  const Eigen::Vector2d corner = engine().table().pockets()[static_cast<std::size_t>(pocketNear({1, 0.5}))].centre;
  const ShotFacts f = play({ball(0, 0.5, 0.2), ball(3, -0.5, -0.3), ball(12, -0.6, 0.3)}, corner, 1.5);
  ASSERT_TRUE(f.scratch);
  const Ruling r = judge(eightBallAfterBreak(Group::Solids), {3, 8, 12}, f);
  EXPECT_TRUE(r.foul);
  EXPECT_EQ(r.rule, "WPA 6.1");
  EXPECT_EQ(r.ball_in_hand, BallInHand::Anywhere);
  EXPECT_EQ(r.next_player, 1);
  EXPECT_FALSE(r.continues);
}

TEST(Referee, HittingTheOpponentsBallFirstIsAFoul)
{
  // WPA 6.2: solids to shoot; the cue ball goes straight into the 12.
  const ShotFacts f = play({ball(0, -0.4, 0.0), ball(12, 0.0, 0.0), ball(3, 0.3, 0.3)}, {0.0, 0.0}, 1.0);
  ASSERT_EQ(f.first_contact, 12);
  const Ruling r = judge(eightBallAfterBreak(Group::Solids), {3, 8, 12}, f);
  EXPECT_TRUE(r.foul);
  EXPECT_EQ(r.rule, "WPA 6.2");
  EXPECT_NE(r.reason.find("ball 12"), std::string::npos) << r.reason;
  // On an open table the 8-ball may not be hit first either.
  ShotFacts eight;
  eight.first_contact = 8;
  eight.rail_after_contact = true;
  EXPECT_EQ(judge(eightBallAfterBreak(Group::Open), {3, 8, 12}, eight).rule, "WPA 6.2");
}

TEST(Referee, NoRailAfterContactIsAFoul)
{
  // WPA 6.3: a soft stun shot full on the 3, which stops short of every cushion.
  const ShotFacts f = play({ball(0, -0.3, 0.0), ball(3, -0.1, 0.0)}, {-0.1, 0.0}, 0.5);
  ASSERT_EQ(f.first_contact, 3);
  ASSERT_FALSE(f.rail_after_contact);
  ASSERT_TRUE(f.pocketed.empty());
  const Ruling r = judge(eightBallAfterBreak(Group::Solids), {3, 8}, f);
  EXPECT_TRUE(r.foul);
  EXPECT_EQ(r.rule, "WPA 6.3");
  // Harder, the 3 reaches the foot cushion: a legal miss, and the turn passes without a foul.
  const ShotFacts hard = play({ball(0, -0.3, 0.0), ball(3, -0.1, 0.0)}, {-0.1, 0.0}, 2.0);
  ASSERT_TRUE(hard.rail_after_contact);
  const Ruling miss = judge(eightBallAfterBreak(Group::Solids), {3, 8}, hard);
  EXPECT_FALSE(miss.foul) << miss.reason;
  EXPECT_EQ(miss.next_player, 1);
}

TEST(Referee, PottingAnOwnBallContinuesAndOnAnOpenTableChoosesTheGroup)
{
  // A straight pot of the 11 into the foot-right corner, on an open table: the shooter takes the
  // stripes (WPA 3.4) and shoots again.
  const Eigen::Vector2d corner = engine().table().pockets()[static_cast<std::size_t>(pocketNear({1, 0.5}))].centre;
  const Eigen::Vector2d object(0.6, 0.3);
  const Eigen::Vector2d from = object - 0.4 * (corner - object).normalized();
  const ShotFacts f = play({ball(0, from.x(), from.y()), ball(11, object.x(), object.y())}, object, 1.5);
  ASSERT_EQ(f.pocketed, std::vector<int>{11});
  ASSERT_FALSE(f.scratch);
  const Ruling r = judge(eightBallAfterBreak(Group::Open), {3, 8, 11}, f);
  EXPECT_FALSE(r.foul) << r.reason;
  EXPECT_TRUE(r.continues);
  EXPECT_EQ(r.next_player, 0);
  EXPECT_EQ(r.groups[0], Group::Stripes);
  EXPECT_EQ(r.groups[1], Group::Solids);
  EXPECT_EQ(r.rule, "WPA 3.4");
  // Called on another pocket, the same shot pockets the ball but not as called: the turn passes.
  GameState called = eightBallAfterBreak(Group::Open);
  called.called_ball = 11;
  called.called_pocket = (f.pockets[0] + 1) % 6;
  const Ruling off = judge(called, {3, 8, 11}, f);
  EXPECT_FALSE(off.foul);
  EXPECT_FALSE(off.continues);
  EXPECT_EQ(off.groups[0], Group::Open);
}

TEST(Referee, TheEightBallEarlyLosesAndLastLegallyWins)
{
  // The 8 potted straight while the shooter (solids) still has the 3: loss of the rack.
  const Eigen::Vector2d corner = engine().table().pockets()[static_cast<std::size_t>(pocketNear({1, 0.5}))].centre;
  const Eigen::Vector2d object(0.6, 0.3);
  const Eigen::Vector2d from = object - 0.4 * (corner - object).normalized();
  const ShotFacts f =
      play({ball(0, from.x(), from.y()), ball(8, object.x(), object.y()), ball(3, -0.6, -0.3)}, object, 1.5);
  ASSERT_EQ(f.pocketed, std::vector<int>{8});
  const Ruling early = judge(eightBallAfterBreak(Group::Solids), {3, 8}, f);
  EXPECT_TRUE(early.game_over);
  EXPECT_EQ(early.winner, 1);
  // With the solids cleared the same shot wins, called in that pocket or uncalled; called in
  // another pocket it loses.
  GameState cleared = eightBallAfterBreak(Group::Solids);
  const Ruling win = judge(cleared, {8}, f);
  EXPECT_TRUE(win.game_over);
  EXPECT_EQ(win.winner, 0) << win.reason;
  cleared.called_ball = 8;
  cleared.called_pocket = f.pockets[0];
  EXPECT_EQ(judge(cleared, {8}, f).winner, 0);
  cleared.called_pocket = (f.pockets[0] + 1) % 6;
  const Ruling wrong_pocket = judge(cleared, {8}, f);
  EXPECT_EQ(wrong_pocket.winner, 1);
  // The reason names both pockets as the table does.
  const auto& pockets = engine().table().pockets();
  EXPECT_NE(wrong_pocket.reason.find("dropped in " + pockets[static_cast<std::size_t>(f.pockets[0])].name),
            std::string::npos)
      << wrong_pocket.reason;
  EXPECT_NE(wrong_pocket.reason.find("not the called " + pockets[static_cast<std::size_t>(cleared.called_pocket)].name),
            std::string::npos)
      << wrong_pocket.reason;
  // Pocketing the 8 with a scratch loses even when it was the object ball.
  ShotFacts scratch = f;
  scratch.scratch = true;
  const Ruling foul = judge(eightBallAfterBreak(Group::Solids), {8}, scratch);
  EXPECT_TRUE(foul.game_over);
  EXPECT_EQ(foul.winner, 1);
}

TEST(Referee, ALegalBreakAndAnIllegalOne)
{
  for (const std::string rules : {"eight_ball", "nine_ball"})
  {
    SCOPED_TRACE(rules);
    GamePlay hard(engine(), rules);
    CueStrike<double> cue;
    cue.speed = 8;
    const Turn legal = hard.shoot(cue);
    EXPECT_TRUE(legal.facts.object_balls_to_rail >= 4 || !legal.facts.pocketed.empty());
    EXPECT_FALSE(legal.ruling.foul) << legal.ruling.reason;
    EXPECT_FALSE(legal.after.break_shot);

    GamePlay soft(engine(), rules);
    cue.speed = 0.6;  // into the rack's apex, too soft to drive four balls to a rail
    const Turn illegal = soft.shoot(cue);
    EXPECT_LT(illegal.facts.object_balls_to_rail, 4);
    EXPECT_TRUE(illegal.facts.pocketed.empty());
    EXPECT_EQ(illegal.ruling.next_player, 1);
    if (rules == "eight_ball")
    {
      // WPA 3.3(d): not a foul; re-racked, the incoming player breaks.
      EXPECT_FALSE(illegal.ruling.foul);
      EXPECT_TRUE(illegal.ruling.rerack);
      EXPECT_TRUE(illegal.after.break_shot);
      EXPECT_EQ(illegal.after.ball_in_hand, BallInHand::BehindHeadString);
      EXPECT_EQ(objectBallsOnTable(soft.table()).size(), 15u);
    }
    else
    {
      // WPA 2.3: a foul, ball in hand anywhere.
      EXPECT_TRUE(illegal.ruling.foul);
      EXPECT_EQ(illegal.ruling.rule, "WPA 2.3");
      EXPECT_EQ(illegal.after.ball_in_hand, BallInHand::Anywhere);
    }
  }
}

TEST(Referee, APushOutSuspendsWrongBallAndNoRail)
{
  // 9-ball, the shot after a legal break: rolling the cue ball away from every ball is a foul
  // (6.3) as a normal shot, and legal as a declared push-out; the other player then shoots.
  GameState s;
  s.rules = "nine_ball";
  s.break_shot = false;
  s.push_out_allowed = true;
  s.ball_in_hand = BallInHand::None;
  const ShotFacts nothing = play({ball(0, -0.5, 0.0), ball(1, 0.5, 0.3), ball(9, 0.6, -0.3)}, {-0.5, -0.4}, 0.5);
  ASSERT_LT(nothing.first_contact, 0);
  EXPECT_EQ(judge(s, {1, 9}, nothing).rule, "WPA 6.3");
  const Ruling push = judge(s, {1, 9}, nothing, true);
  EXPECT_FALSE(push.foul) << push.reason;
  EXPECT_EQ(push.rule, "WPA 2.4");
  EXPECT_EQ(push.next_player, 1);
  EXPECT_FALSE(push.push_out_next);
  // Not allowed (not the shot after the break), the same declaration is a normal shot.
  s.push_out_allowed = false;
  EXPECT_TRUE(judge(s, {1, 9}, nothing, true).foul);
  // A scratch on a push-out is still a foul; a 9 it pockets is spotted.
  ShotFacts scratch;
  scratch.scratch = true;
  scratch.pocketed = {9};
  scratch.pockets = {2};
  s.push_out_allowed = true;
  const Ruling foul = judge(s, {1, 9}, scratch, true);
  EXPECT_TRUE(foul.foul);
  EXPECT_EQ(foul.respot, std::vector<int>{9});
}

TEST(Referee, NineBallWinsOnTheNineAndSpotsItAfterAFoul)
{
  GameState s;
  s.rules = "nine_ball";
  s.break_shot = false;
  ShotFacts combo;  // the 1 first, then the 9 drops: a win (WPA 2.5)
  combo.first_contact = 1;
  combo.pocketed = {9};
  combo.pockets = {0};
  const Ruling win = judge(s, {1, 9}, combo);
  EXPECT_TRUE(win.game_over);
  EXPECT_EQ(win.winner, 0);
  ShotFacts wrong = combo;  // the 9 first: foul 6.2, the 9 spotted (2.6)
  wrong.first_contact = 9;
  const Ruling foul = judge(s, {1, 9}, wrong);
  EXPECT_TRUE(foul.foul);
  EXPECT_FALSE(foul.game_over);
  EXPECT_EQ(foul.respot, std::vector<int>{9});
}

TEST(Referee, AThirdFoulInARowLoses)
{
  for (const std::string& rules : rulesNames())
  {
    if (!makeRules(rules)->threeFoulsLose())
      continue;
    GameState s;
    s.rules = rules;
    s.break_shot = false;
    ShotFacts scratch;
    scratch.scratch = true;
    s.consecutive_fouls = {1, 0};
    EXPECT_FALSE(judge(s, {1, 3, 9}, scratch).game_over) << rules;
    s.consecutive_fouls = {2, 0};
    const Ruling third = judge(s, {1, 3, 9}, scratch);
    EXPECT_TRUE(third.game_over) << rules;
    EXPECT_EQ(third.winner, 1) << rules;
    EXPECT_EQ(third.rule, "WPA 6.14") << rules;
    // The count: a foul adds one, a legal shot clears it.
    GameState after = afterRuling(s, judge(s, {1, 3, 9}, ShotFacts{}));
    EXPECT_EQ(after.consecutive_fouls[0], 3) << rules;
  }
}

TEST(Referee, BallInHandBehindTheHeadStringIsOnlyThere)
{
  GamePlay game(engine(), "eight_ball");  // the break: behind the head string
  const double head = engine().table().headStringX();
  EXPECT_EQ(game.placeCueBall({head - 0.1, 0.2}), "");
  const std::string ahead = game.placeCueBall({head + 0.05, 0.2});
  EXPECT_NE(ahead.find("behind the head string"), std::string::npos) << ahead;
  EXPECT_NE(game.placeCueBall({head - 0.1, 0.9}), "");  // off the cloth
  EXPECT_NEAR(game.table().balls[static_cast<std::size_t>(game.table().indexOf(0))].r.x(), head - 0.1, 1e-15);
  // Anywhere after a foul, but never on another ball.
  TableState<double> s;
  s.balls = {ball(0, -0.5, 0), ball(5, 0.3, 0.1)};
  EXPECT_EQ(whyNotInHand(engine().table(), R(), s, {0.5, 0.1}, BallInHand::Anywhere), "");
  EXPECT_NE(whyNotInHand(engine().table(), R(), s, {0.3 + R(), 0.1}, BallInHand::Anywhere), "");
  EXPECT_NE(whyNotInHand(engine().table(), R(), s, {0.5, 0.1}, BallInHand::None), "");
}

TEST(Referee, SpottingOnAnOccupiedFootSpotFreezesBehindTheBallThere)
{
  // WPA 1.4: on the long string, as near the foot spot as it stands, behind it first.
  const Eigen::Vector2d spot = engine().table().footSpot();
  TableState<double> s;
  s.balls = {ball(0, -0.5, 0), ball(3, spot.x(), spot.y()), ball(9, 0, 0)};
  s.balls[2].motion = physics::Motion::Pocketed;
  s.balls[2].pocket = 1;
  spotBalls(engine().table(), R(), {9}, s);
  const Ball<double>& nine = s.balls[2];
  EXPECT_TRUE(nine.inPlay());
  EXPECT_EQ(nine.pocket, -1);
  EXPECT_NEAR(nine.r.y(), spot.y(), 1e-15);
  EXPECT_GT(nine.r.x(), spot.x());
  EXPECT_NEAR((nine.r - s.balls[1].r).norm(), 2 * R(), 1e-9);  // frozen to the 3
  // A free spot takes the ball on it.
  TableState<double> free;
  free.balls = {ball(0, -0.5, 0), ball(8, 0, 0)};
  spotBalls(engine().table(), R(), {8}, free);
  EXPECT_NEAR((free.balls[1].r.head<2>() - spot).norm(), 0, 1e-15);
}

TEST(Referee, UnknownRulesAreRefusedWithTheKnownOnes)
{
  try
  {
    makeRules("bagatelle");
    FAIL() << "no throw";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("eight_ball, nine_ball, ten_ball, three_cushion, snooker"), std::string::npos)
        << e.what();
  }
  // Pool on a table without pockets, and carom on one with them.
  EXPECT_THROW(GamePlay(caromEngine(), "nine_ball"), std::invalid_argument);
  EXPECT_THROW(GamePlay(engine(), "three_cushion"), std::invalid_argument);
}

TEST(Referee, RandomGamesConserveBallsStayValidAndEnd)
{
  // Random strikes (ball in hand placed at random where allowed, half of them aimed at a legal
  // ball) through 150 whole games of each ruleset, on its table: after every shot each ball is on
  // the table or pocketed, exactly once; the cue ball is back on the cloth; the state is valid;
  // the scores are the points ruled; and every game ends within 300 shots (a carom game's race
  // is to 1 point here, which about 1 random strike in 100 makes: within 1000 shots).
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(0, 1);
  int games = 0, shots = 0, fouls = 0;
  for (const std::string& rules : rulesNames())
    for (int g = 0; g < 150; ++g, ++games)
    {
      GamePlay game(engineFor(rules), rules);
      if (game.rules().defaultTarget() > 0)
        ASSERT_EQ(game.setTarget(1), "");
      const std::size_t total = game.table().balls.size();
      std::array<int, 2> points{0, 0};
      // Snooker's frame takes at least 21 pots, and its pockets are tight: 2000.
      const int limit = rules == "snooker" ? 2000 : game.rules().needsPockets() ? 300 : 1000;
      int n = 0;
      for (; n < limit && !game.state().over; ++n, ++shots)
      {
        const TableModel& t = engineFor(rules).table();
        if (game.state().ball_in_hand != BallInHand::None)
          for (int attempt = 0; attempt < 50; ++attempt)
          {
            const Eigen::Vector2d p = t.clothCentre() + Eigen::Vector2d((unit(rng) - 0.5) * t.clothLength(),
                                                                        (unit(rng) - 0.5) * t.clothWidth());
            if (game.placeCueBall(p).empty())
              break;
          }
        CueStrike<double> cue;
        cue.speed = 0.5 + 5 * unit(rng);
        cue.phi = 2 * M_PI * unit(rng);
        // Aim at a legal ball half the time, so that balls go down.
        const std::vector<int> legal = game.legalFirst();
        const auto& cue_ball = game.table().balls[static_cast<std::size_t>(game.table().indexOf(game.cueBall()))];
        if (!legal.empty() && unit(rng) < 0.5)
        {
          const auto& target = game.table().balls[static_cast<std::size_t>(game.table().indexOf(legal.front()))];
          cue.phi = std::atan2(target.r.y() - cue_ball.r.y(), target.r.x() - cue_ball.r.x()) + 0.05 * (unit(rng) - 0.5);
          // Where only a called ball counts (10-ball), it is called, in a pocket drawn at random.
          if (game.rules().mustCall() && !game.state().break_shot)
          {
            ASSERT_EQ(game.call(legal.front(), static_cast<int>(unit(rng) * 6)), "");
          }
        }
        const Turn turn = game.shoot(cue, game.state().push_out_allowed && unit(rng) < 0.3);
        fouls += turn.ruling.foul;
        points[static_cast<std::size_t>(turn.player)] += turn.ruling.points;
        points[static_cast<std::size_t>(1 - turn.player)] += turn.ruling.penalty;
        ASSERT_EQ(game.state().score, points);
        ASSERT_FALSE(turn.ruling.reason.empty());
        ASSERT_FALSE(turn.ruling.rule.empty());
        ASSERT_EQ(game.table().balls.size(), total);
        std::size_t on = 0, down = 0;
        for (const auto& b : game.table().balls)
          (b.inPlay() ? on : down) += 1;
        ASSERT_EQ(on + down, total);
        if (!game.state().over)
        {
          ASSERT_TRUE(game.table().balls[static_cast<std::size_t>(game.table().indexOf(game.cueBall()))].inPlay());
          ASSERT_FALSE(game.table().anyMoving());
          if (!game.rules().needsPockets())  // carom: every ball back on the table
            ASSERT_EQ(on, total);
        }
        const GameState& st = game.state();
        ASSERT_TRUE(st.turn == 0 || st.turn == 1);
        ASSERT_TRUE((st.groups[0] == Group::Open) == (st.groups[1] == Group::Open));
        ASSERT_TRUE(st.groups[0] == Group::Open || st.groups[0] != st.groups[1]);
        if (game.rules().threeFoulsLose())
        {
          for (const int count : st.consecutive_fouls)
            ASSERT_TRUE(count < 3 || (count == 3 && st.over));
        }
        if (st.over)
        {
          ASSERT_TRUE(st.winner == 0 || st.winner == 1);
        }
      }
      EXPECT_TRUE(game.state().over) << rules << " game " << g << " still going after " << n << " shots";
    }
  EXPECT_EQ(games, 150 * static_cast<int>(rulesNames().size()));
  EXPECT_GT(shots, 2000);
  EXPECT_GT(fouls, 0);
  std::cout << games << " games, " << shots << " shots, " << fouls << " fouls\n";
}

TEST(SelfPlay, PlannersFinishTheirGamesWithNoise)
{
  // The potting planner on both sides, the tournaments' execution noise: every game ends, by a
  // win far more often than by the shot cap, and the tallies add up.
  for (const std::string& rules : rulesNames())
  {
    SelfPlayOptions options;
    options.rules = rules;
    options.games = 10;
    options.seed = 3;
    options.target = makeRules(rules)->defaultTarget() > 0 ? 5 : 0;  // a short race
    int reported = 0;
    const SelfPlaySummary s = selfPlay(engineFor(rules), options, [&](const GameRecord& r) {
      ++reported;
      EXPECT_TRUE(r.end.over);
      EXPECT_EQ(r.turns.size(), r.before.size());
      EXPECT_EQ(static_cast<int>(r.turns.size()), r.end.shots);
      // The scores are the rulings' points; a race is won at its target; every turn at the table
      // is an inning: one for the breaker, and one more each time the table passes (not when the
      // game ends).
      std::array<int, 2> points{0, 0}, innings{0, 0};
      innings[static_cast<std::size_t>(r.first_player)] = 1;
      for (const Turn& t : r.turns)
      {
        points[static_cast<std::size_t>(t.player)] += t.ruling.points;
        points[static_cast<std::size_t>(1 - t.player)] += t.ruling.penalty;
        if (t.ruling.next_player != t.player && !t.ruling.game_over)
          ++innings[static_cast<std::size_t>(t.ruling.next_player)];
      }
      EXPECT_EQ(r.end.score, points) << rules;
      EXPECT_EQ(r.end.innings, innings) << rules;
      if (r.end.target > 0 && r.end.winner >= 0)
      {
        EXPECT_EQ(r.end.score[static_cast<std::size_t>(r.end.winner)], r.end.target) << rules;
        EXPECT_LT(r.end.score[static_cast<std::size_t>(1 - r.end.winner)], r.end.target) << rules;
      }
    });
    EXPECT_EQ(reported, 10) << rules;
    EXPECT_EQ(s.games, 10);
    EXPECT_EQ(s.finished + s.capped, 10);
    EXPECT_EQ(s.wins[0] + s.wins[1], s.finished);
    EXPECT_GE(s.finished, 9) << rules;
    int shots = 0;
    for (const auto& r : s.records)
      shots += static_cast<int>(r.turns.size());
    EXPECT_EQ(shots, s.shots);
    // The same seed plays the same games.
    const SelfPlaySummary again = selfPlay(engineFor(rules), options);
    EXPECT_EQ(again.shots, s.shots) << rules;
    EXPECT_EQ(again.wins, s.wins) << rules;
  }
}

TEST(SelfPlay, TheShotCapEndsAGameWithoutAWinnerAndSaysSo)
{
  GamePlay game(engine(), "nine_ball");
  game.setShotCap(2);
  CueStrike<double> soft;
  soft.speed = 0.6;
  game.shoot(soft);  // an illegal break: a foul, the game goes on
  const auto& cue = game.table().balls[static_cast<std::size_t>(game.table().indexOf(0))];
  soft.phi = std::atan2(-cue.r.y(), -1 - cue.r.x());  // away from the balls: another foul
  const Turn capped = game.shoot(soft);
  EXPECT_TRUE(capped.ruling.game_over);
  EXPECT_EQ(capped.ruling.winner, -1);
  EXPECT_NE(capped.ruling.reason.find("cap of 2 shots"), std::string::npos) << capped.ruling.reason;
  EXPECT_TRUE(game.state().over);
  EXPECT_THROW(game.shoot(soft), std::invalid_argument);
}

TEST(SelfPlay, OpenShotsCountClearPotsAndNotBlockedOnes)
{
  // 9-ball after the break, the 1 alone with the cue ball straight behind it on the line to the
  // foot-right corner: that pot is open. A ball on the line to the pocket closes it, and so does
  // one between the cue ball and the ghost ball.
  const Eigen::Vector2d pocket = engine().table().pockets()[static_cast<std::size_t>(pocketNear({1, 0.5}))].centre;
  const Eigen::Vector2d object(0.5, 0.2), along = (pocket - object).normalized();
  const auto openWith = [&](std::vector<Ball<double>> extra) {
    TableState<double> s;
    s.balls = {ball(0, object.x() - 0.4 * along.x(), object.y() - 0.4 * along.y()), ball(1, object.x(), object.y())};
    s.balls.insert(s.balls.end(), extra.begin(), extra.end());
    GamePlay game(engine(), "nine_ball");
    EXPECT_EQ(game.setPosition(s, false), "");
    return openShots(game);
  };
  const int open = openWith({});
  EXPECT_GE(open, 1);
  const Eigen::Vector2d on_line = object + 0.2 * along, in_front = object - 0.2 * along;
  EXPECT_EQ(openWith({ball(5, on_line.x(), on_line.y())}), open - 1);
  EXPECT_LT(openWith({ball(5, in_front.x(), in_front.y())}), open);
}

// WPA 6.1 and 6.5: a ball driven off the table is a foul, and each game says what is spotted.
// Ball 3 flies over the ypos cushion in a real run of the engine and lands on the rail.
TEST(Referee, ABallDrivenOffTheTableIsAFoulAndEachGameSaysWhatIsSpotted)
{
  TableState<double> s;
  s.balls = {ball(0, -0.5, 0.0), ball(3, 0.2, 0.3), ball(8, 0.5, -0.2), ball(12, -0.6, 0.3)};
  s.balls[1].r.z() = 0.12;
  s.balls[1].v = Vec3<double>(0, 2, 0);
  physics::settleMotion(s.balls[1], R());
  const ShotFacts f = readShot(simulateToRest(engine(), s).events, &engine().table());
  ASSERT_EQ(f.off_table, std::vector<int>{3});
  EXPECT_EQ(s.balls[1].motion, physics::Motion::OffTable);

  const Ruling r = judge(eightBallAfterBreak(Group::Solids), {3, 8, 12}, f);
  EXPECT_TRUE(r.foul);
  EXPECT_EQ(r.rule, "WPA 6.5");
  EXPECT_EQ(r.ball_in_hand, BallInHand::Anywhere);
  EXPECT_EQ(r.respot, std::vector<int>{3});
  // Spotted, it stands on the long string again, in play.
  physics::TableState<double> after = s;
  spotBalls(engine().table(), R(), r.respot, after);
  EXPECT_TRUE(after.balls[1].inPlay());
  EXPECT_EQ(engine().whyInvalid(after), "");

  ShotFacts eight;  // the 8 off the table after the break loses the rack
  eight.first_contact = 3;
  eight.off_table = {8};
  const Ruling lost = judge(eightBallAfterBreak(Group::Solids), {3, 8, 12}, eight);
  EXPECT_TRUE(lost.game_over);
  EXPECT_EQ(lost.winner, 1);

  ShotFacts cue;  // the cue ball off the table: 6.1
  cue.first_contact = 3;
  cue.cue_ball_off_table = true;
  const Ruling scratch = judge(eightBallAfterBreak(Group::Solids), {3, 8, 12}, cue);
  EXPECT_TRUE(scratch.foul);
  EXPECT_EQ(scratch.rule, "WPA 6.1");

  GameState nine;
  nine.rules = "nine_ball";
  nine.break_shot = false;
  ShotFacts nine_off;  // 9-ball spots the 9 (WPA 2.6), and no other ball driven off
  nine_off.first_contact = 1;
  nine_off.off_table = {4, 9};
  const Ruling spotted = judge(nine, {1, 4, 9}, nine_off);
  EXPECT_TRUE(spotted.foul);
  EXPECT_EQ(spotted.rule, "WPA 6.5");
  EXPECT_EQ(spotted.respot, std::vector<int>{9});
}
