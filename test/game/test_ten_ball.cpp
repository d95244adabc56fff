// 10-ball (WPA section 9): its rack, its break, called shots and wrongfully pocketed balls, the
// 10's spotting and the win on the called 10. Each rule on shots the engine plays where a shot can
// show it, on a shot's facts where only the ruleset's logic is at stake.
#include <gtest/gtest.h>

#include <algorithm>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/physics/rack.hpp"
#include "game_test_support.hpp"

using namespace cue_sim;
using namespace cue_sim::game;
using namespace cue_sim::game::test;

namespace
{
GameState tenBallAfterBreak(int called_ball = -1, int called_pocket = -1)
{
  GameState s;
  s.rules = "ten_ball";
  s.break_shot = false;
  s.ball_in_hand = BallInHand::None;
  s.called_ball = called_ball;
  s.called_pocket = called_pocket;
  return s;
}

ShotFacts hitThenPocketed(int first, const std::vector<int>& pocketed, const std::vector<int>& pockets)
{
  ShotFacts f;
  f.first_contact = first;
  f.pocketed = pocketed;
  f.pockets = pockets;
  f.rail_after_contact = true;
  return f;
}

/// A straight shot: the cue ball 0.4 m behind `object` on the line from it to the pocket nearest
/// `towards`, struck at the ghost ball. Sets `pocket` to that pocket.
std::vector<Ball<double>> lineUp(int id, const Eigen::Vector2d& object, const Eigen::Vector2d& towards, int& pocket,
                                 Eigen::Vector2d& ghost)
{
  pocket = pocketNear(towards);
  const Eigen::Vector2d along =
      (engine().table().pockets()[static_cast<std::size_t>(pocket)].centre - object).normalized();
  ghost = object - 2 * R() * along;
  const Eigen::Vector2d cue = object - 0.4 * along;
  return {ball(0, cue.x(), cue.y()), ball(id, object.x(), object.y())};
}
}  // namespace

TEST(TenBall, TheRackHasTheOneOnTheFootSpotTheTenInTheMiddleAndTwoAndThreeInTheBackCorners)
{
  // WPA 9.2: a triangle of the ten balls, the 1 at the apex on the foot spot, the 10 in the middle.
  const TableState<double> s = physics::rackLayout<double>("ten", engine().table(), R());
  ASSERT_EQ(s.balls.size(), 11u);
  std::vector<int> ids;
  for (const auto& b : s.balls)
    ids.push_back(b.id);
  std::sort(ids.begin(), ids.end());
  for (int id = 0; id <= 10; ++id)
    EXPECT_EQ(ids[static_cast<std::size_t>(id)], id);
  const auto at = [&](int id) { return s.balls[static_cast<std::size_t>(s.indexOf(id))].r.head<2>().eval(); };
  const Eigen::Vector2d foot = engine().table().footSpot();
  EXPECT_NEAR((at(1) - foot).norm(), 0, 1e-15);
  // The middle of the triangle: the centroid of its three corners (the 1, the 2 and the 3).
  const Eigen::Vector2d centroid = (at(1) + at(2) + at(3)) / 3;
  EXPECT_NEAR((at(10) - centroid).norm(), 0, 1e-12);
  double back = -1e9;
  for (const auto& b : s.balls)
    back = std::max(back, b.r.x());
  EXPECT_NEAR(at(2).x(), back, 1e-15);
  EXPECT_NEAR(at(3).x(), back, 1e-15);
  EXPECT_NEAR(std::abs(at(2).y() - foot.y()), std::abs(at(3).y() - foot.y()), 1e-12);
  EXPECT_GE(std::abs(at(2).y() - foot.y()), 3 * R());  // the back row's ends: three diameters apart
  for (std::size_t i = 0; i < s.balls.size(); ++i)
    for (std::size_t j = i + 1; j < s.balls.size(); ++j)
      EXPECT_GE((s.balls[i].r - s.balls[j].r).norm(), 2 * R());
  EXPECT_EQ(engine().whyInvalid(s), "");
}

TEST(TenBall, ALegalBreakCountsWhatItPocketsSpotsTheTenAndAllowsAPushOut)
{
  GameState s;
  s.rules = "ten_ball";
  // The 10 and the 4 down on a legal break: nothing is called on a break; the 4 counts, the 10 is
  // spotted, and the breaker continues (WPA 9.3, 9.8, 9.9).
  const Ruling r = judge(s, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, hitThenPocketed(1, {10, 4}, {1, 2}));
  EXPECT_FALSE(r.foul) << r.reason;
  EXPECT_FALSE(r.game_over);
  EXPECT_TRUE(r.continues);
  EXPECT_EQ(r.next_player, 0);
  EXPECT_EQ(r.respot, std::vector<int>{10});
  EXPECT_TRUE(r.push_out_next);
  EXPECT_NE(r.reason.find("WPA 9.9"), std::string::npos) << r.reason;
  // The 10 alone: still spotted, still the breaker's inning.
  const Ruling ten = judge(s, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, hitThenPocketed(1, {10}, {0}));
  EXPECT_TRUE(ten.continues);
  EXPECT_EQ(ten.respot, std::vector<int>{10});
  // Nothing down, four balls to a rail: legal, the turn passes, the push-out allowed.
  ShotFacts spread = hitThenPocketed(1, {}, {});
  spread.object_balls_to_rail = 5;
  const Ruling passed = judge(s, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, spread);
  EXPECT_FALSE(passed.foul);
  EXPECT_EQ(passed.next_player, 1);
  EXPECT_TRUE(passed.push_out_next);
  // The 2 first on the break: 6.2, the 10 it pockets spotted.
  const Ruling wrong = judge(s, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, hitThenPocketed(2, {10}, {0}));
  EXPECT_TRUE(wrong.foul);
  EXPECT_EQ(wrong.rule, "WPA 6.2");
  EXPECT_EQ(wrong.respot, std::vector<int>{10});
  EXPECT_FALSE(wrong.push_out_next);
}

TEST(TenBall, ASoftBreakOnTheTableIsAFoulUnderNineThree)
{
  // WPA 9.3(b): nothing pocketed and fewer than four balls to a rail; the engine plays it.
  GamePlay soft(engine(), "ten_ball");
  physics::CueStrike<double> cue;
  cue.speed = 0.6;
  const Turn t = soft.shoot(cue);
  ASSERT_LT(t.facts.object_balls_to_rail, 4);
  ASSERT_TRUE(t.facts.pocketed.empty());
  EXPECT_EQ(t.facts.first_contact, 1);
  EXPECT_TRUE(t.ruling.foul);
  EXPECT_EQ(t.ruling.rule, "WPA 9.3");
  EXPECT_EQ(t.after.ball_in_hand, BallInHand::Anywhere);
  EXPECT_EQ(t.after.turn, 1);
  EXPECT_FALSE(t.after.push_out_allowed);
}

TEST(TenBall, TheCalledBallInTheCalledPocketContinuesAndOthersStayDownButTheTen)
{
  // The engine pots the 1 in the pocket it was lined up on.
  int pocket = -1;
  Eigen::Vector2d ghost;
  const std::vector<Ball<double>> balls = lineUp(1, {0.55, 0.25}, {1, 0.5}, pocket, ghost);
  const ShotFacts potted = play(balls, ghost, 1.5);
  ASSERT_EQ(potted.pocketed, std::vector<int>{1});
  ASSERT_EQ(potted.pockets, std::vector<int>{pocket});
  const Ruling made = judge(tenBallAfterBreak(1, pocket), {1, 5, 10}, potted);
  EXPECT_FALSE(made.foul) << made.reason;
  EXPECT_EQ(made.rule, "WPA 9.5");
  EXPECT_TRUE(made.continues);
  EXPECT_EQ(made.next_player, 0);
  EXPECT_TRUE(made.respot.empty());
  // Called in another pocket: pocketed wrongfully (9.7), no foul, it stays down, the turn passes
  // with the cue ball where it lies.
  const int other = (pocket + 1) % static_cast<int>(engine().table().pockets().size());
  const Ruling elsewhere = judge(tenBallAfterBreak(1, other), {1, 5, 10}, potted);
  EXPECT_FALSE(elsewhere.foul);
  EXPECT_EQ(elsewhere.rule, "WPA 9.7");
  EXPECT_FALSE(elsewhere.continues);
  EXPECT_EQ(elsewhere.next_player, 1);
  EXPECT_EQ(elsewhere.ball_in_hand, BallInHand::None);
  EXPECT_TRUE(elsewhere.respot.empty());
  // Nothing called: a safety (9.6), so the 1 is pocketed wrongfully too.
  const Ruling safety = judge(tenBallAfterBreak(), {1, 5, 10}, potted);
  EXPECT_FALSE(safety.foul);
  EXPECT_EQ(safety.rule, "WPA 9.7");
  EXPECT_EQ(safety.next_player, 1);
  EXPECT_NE(safety.reason.find("WPA 9.6"), std::string::npos) << safety.reason;
  // A ball called without a pocket is no call.
  EXPECT_EQ(judge(tenBallAfterBreak(1, -1), {1, 5, 10}, potted).rule, "WPA 9.7");
  // The called 1 and, uncalled, the 5 and the 10: the shooter continues, the 5 stays down and the
  // 10 is spotted (9.9).
  const Ruling more = judge(tenBallAfterBreak(1, 2), {1, 5, 10}, hitThenPocketed(1, {5, 1, 10}, {0, 2, 4}));
  EXPECT_TRUE(more.continues);
  EXPECT_FALSE(more.game_over);
  EXPECT_EQ(more.respot, std::vector<int>{10});
  EXPECT_NE(more.reason.find("ball 5 also pocketed"), std::string::npos) << more.reason;
}

TEST(TenBall, TheCalledTenWinsOnALegalShotEvenBeforeItIsTheLastBall)
{
  // The 3 first, the 10 into the called pocket (a combination): the rack is won (9.5, 9.8).
  const Ruling win = judge(tenBallAfterBreak(10, 4), {3, 7, 10}, hitThenPocketed(3, {10}, {4}));
  EXPECT_TRUE(win.game_over) << win.reason;
  EXPECT_EQ(win.winner, 0);
  EXPECT_FALSE(win.foul);
  // In another pocket than called: wrongfully pocketed, spotted, the turn passes.
  const Ruling wrong_pocket = judge(tenBallAfterBreak(10, 4), {3, 7, 10}, hitThenPocketed(3, {10}, {1}));
  EXPECT_FALSE(wrong_pocket.game_over);
  EXPECT_FALSE(wrong_pocket.foul);
  EXPECT_EQ(wrong_pocket.respot, std::vector<int>{10});
  EXPECT_EQ(wrong_pocket.next_player, 1);
  // The 7 first while the 3 is on the table: a foul (6.2), the 10 spotted, ball in hand.
  const Ruling foul = judge(tenBallAfterBreak(10, 4), {3, 7, 10}, hitThenPocketed(7, {10}, {4}));
  EXPECT_TRUE(foul.foul);
  EXPECT_FALSE(foul.game_over);
  EXPECT_EQ(foul.rule, "WPA 6.2");
  EXPECT_EQ(foul.respot, std::vector<int>{10});
  EXPECT_EQ(foul.ball_in_hand, BallInHand::Anywhere);
  // The called 10 with a scratch: a foul, not a win.
  ShotFacts scratch = hitThenPocketed(3, {10}, {4});
  scratch.scratch = true;
  const Ruling scratched = judge(tenBallAfterBreak(10, 4), {3, 7, 10}, scratch);
  EXPECT_TRUE(scratched.foul);
  EXPECT_FALSE(scratched.game_over);
  EXPECT_EQ(scratched.respot, std::vector<int>{10});
}

TEST(TenBall, APushOutSpotsTheTenWithoutPenaltyAndPassesTheTurn)
{
  GameState s = tenBallAfterBreak();
  s.push_out_allowed = true;
  ShotFacts f;  // the 10 first, and down: a foul (6.2) as a normal shot
  f.first_contact = 10;
  f.pocketed = {10};
  f.pockets = {3};
  EXPECT_TRUE(judge(s, {1, 10}, f).foul);
  const Ruling push = judge(s, {1, 10}, f, true);
  EXPECT_FALSE(push.foul) << push.reason;
  EXPECT_EQ(push.rule, "WPA 9.4");
  EXPECT_EQ(push.next_player, 1);
  EXPECT_EQ(push.respot, std::vector<int>{10});
  EXPECT_FALSE(push.game_over);
}

TEST(TenBall, AWrongfullyPocketedTenIsBackOnTheFootSpotAfterTheShot)
{
  // A combination the engine plays: the cue ball drives the 2 into the 10, which drops. The call
  // was the 2, so the 10 is pocketed wrongfully and the game spots it (WPA 9.7, 9.9, 1.4).
  const int pocket = pocketNear({1, 0.5});
  const Eigen::Vector2d mouth = engine().table().pockets()[static_cast<std::size_t>(pocket)].centre;
  const Eigen::Vector2d ten(0.55, 0.25), along = (mouth - ten).normalized();
  const Eigen::Vector2d two = ten - (2 * R() + 0.05) * along, cue = two - 0.3 * along;
  TableState<double> position;
  position.balls = {ball(0, cue.x(), cue.y()), ball(2, two.x(), two.y()), ball(10, ten.x(), ten.y())};
  GamePlay game(engine(), "ten_ball");
  ASSERT_EQ(game.setPosition(position, false), "");
  ASSERT_EQ(game.call(2, pocket), "");
  physics::CueStrike<double> strike;
  strike.speed = 2.5;
  strike.phi = std::atan2(along.y(), along.x());
  const Turn t = game.shoot(strike);
  ASSERT_EQ(t.facts.first_contact, 2);
  ASSERT_NE(std::find(t.facts.pocketed.begin(), t.facts.pocketed.end(), 10), t.facts.pocketed.end());
  EXPECT_FALSE(t.ruling.foul) << t.ruling.reason;
  EXPECT_FALSE(t.after.over);
  EXPECT_EQ(t.after.turn, 1);
  const auto& spotted = game.table().balls[static_cast<std::size_t>(game.table().indexOf(10))];
  EXPECT_TRUE(spotted.inPlay());
  EXPECT_NEAR((spotted.r.head<2>() - engine().table().footSpot()).norm(), 0, 1e-12);
}

TEST(TenBall, ItsDeclarationCallsShotsHoldsToThemAndAllowsAPushOut)
{
  const auto rules = makeRules("ten_ball");
  EXPECT_EQ(rules->rack(), "ten");
  EXPECT_TRUE(rules->callsShots());
  EXPECT_TRUE(rules->mustCall());
  EXPECT_TRUE(rules->pushOutAfterBreak());
  EXPECT_FALSE(rules->playsGroups());
  EXPECT_EQ(rulesTitle("ten_ball"), "10-ball");
  const std::vector<std::string> names = rulesNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "ten_ball"), names.end());
}
