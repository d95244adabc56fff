// Snooker (WPBSA Official Rules): the table's markings against Section 1's millimetres, the rack,
// the ball on through a frame (a red, then a colour, then the colours in order), scores and the
// colours' re-spotting, fouls and their values, the free ball, the D, and the end of the frame
// with a re-spotted black on a tie. Each rule on exact positions or a shot's facts.
#include <gtest/gtest.h>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/physics/snooker_markings.hpp"
#include "game_test_support.hpp"

using namespace cue_sim;
using namespace cue_sim::game;
using namespace cue_sim::game::test;
using physics::SnookerColour;
using physics::SnookerMarkings;

namespace
{
constexpr int kCue = 0, kYellow = 16, kGreen = 17, kBrown = 18, kBlue = 19, kPink = 20, kBlack = 21;
constexpr double kLength = 3.569, kWidth = 1.778;  // the standard playing area [m]
constexpr double kBottom = -kLength / 2, kTop = kLength / 2;

double Rs()
{
  return snookerEngine().params().ball_radius;
}

Ball<double> snookerBall(int id, double x, double y)
{
  Ball<double> b;
  b.id = id;
  b.r = Vec3<double>(x, y, Rs());
  return b;
}

GameState snooker(int turn = 0)
{
  GameState s;
  s.rules = "snooker";
  s.turn = turn;
  s.break_shot = false;
  s.ball_in_hand = BallInHand::None;
  return s;
}

ShotFacts facts(int first, std::vector<int> pocketed = {})
{
  ShotFacts f;
  f.first_contact = first;
  f.pocketed = std::move(pocketed);
  return f;
}

/// All 15 reds and the six colours: the table at the start.
std::vector<int> fullTable()
{
  std::vector<int> ids;
  for (int id = 1; id <= kBlack; ++id)
    ids.push_back(id);
  return ids;
}

std::vector<int> coloursFrom(int lowest)
{
  std::vector<int> ids;
  for (int id = lowest; id <= kBlack; ++id)
    ids.push_back(id);
  return ids;
}
}  // namespace

TEST(Snooker, TheMarkingsAreWhereTheRulesPutThem)
{
  const SnookerMarkings m = physics::snookerMarkings(*snookerTable());
  EXPECT_NEAR(m.baulk_line_x - kBottom, 0.737, 1e-12) << "29 in from the bottom cushion";
  EXPECT_NEAR(m.d_radius, 0.292, 1e-12) << "11 1/2 in";
  EXPECT_NEAR(kTop - m.spotOf(SnookerColour::Black).x(), 0.324, 1e-12) << "the black spot, 12 3/4 in from the top";
  EXPECT_NEAR(m.spotOf(SnookerColour::Blue).norm(), 0.0, 1e-12) << "the blue on the centre spot";
  EXPECT_NEAR(m.spotOf(SnookerColour::Pink).x(), kTop / 2, 1e-12) << "the pink midway to the top cushion";
  EXPECT_EQ(m.spotOf(SnookerColour::Brown), m.d_centre) << "the brown on the middle of the baulk line";
  // Viewed from baulk (looking along +x), the yellow is on the right (-y), the green on the left,
  // both at the D's corners on the baulk line.
  EXPECT_NEAR(m.spotOf(SnookerColour::Yellow).y(), -0.292, 1e-12);
  EXPECT_NEAR(m.spotOf(SnookerColour::Green).y(), 0.292, 1e-12);
  EXPECT_EQ(m.spotOf(SnookerColour::Yellow).x(), m.baulk_line_x);
  // The D: the half disc in baulk, its lines included.
  EXPECT_TRUE(m.inD(m.d_centre));
  EXPECT_TRUE(m.inD(m.spotOf(SnookerColour::Yellow)));
  EXPECT_TRUE(m.inD(m.d_centre + Eigen::Vector2d(-m.d_radius, 0)));
  EXPECT_FALSE(m.inD(m.d_centre + Eigen::Vector2d(0.001, 0))) << "past the baulk line";
  EXPECT_FALSE(m.inD(m.d_centre + Eigen::Vector2d(-0.2, 0.25))) << "in baulk, outside the semicircle";
  // A 10 ft table is marked in proportion.
  const SnookerMarkings small = physics::snookerMarkings(TableModel::pool("10ft", 3.048, 1.524, 0.089, 0.083));
  EXPECT_NEAR(small.baulk_line_x + 3.048 / 2, 0.737 * 3.048 / kLength, 1e-12);
  EXPECT_NEAR(small.d_radius, 0.292 * 1.524 / kWidth, 1e-12);
}

TEST(Snooker, TheRackPutsTheRedsBehindThePinkAndTheColoursOnTheirSpots)
{
  const SnookerMarkings m = physics::snookerMarkings(*snookerTable());
  physics::RackOptions options;
  options.gap = 1e-4;
  const auto rack = physics::rackLayout<double>("snooker", *snookerTable(), Rs(), options);
  ASSERT_EQ(rack.balls.size(), 22u);
  for (std::size_t k = 0; k < rack.balls.size(); ++k)
    EXPECT_EQ(rack.balls[k].id, static_cast<int>(k)) << "by id";
  EXPECT_EQ(snookerEngine().whyInvalid(rack), "");  // on the cloth, no two overlapping
  for (int colour = kYellow; colour <= kBlack; ++colour)
    EXPECT_EQ(rack.balls[static_cast<std::size_t>(colour)].r.head<2>(),
              m.spots[static_cast<std::size_t>(colour - kYellow)]);
  EXPECT_TRUE(m.inD(rack.balls[0].r.head<2>())) << "the cue ball in the D";
  // The apex red on the long string, as near the pink as the gap: not touching it.
  const Eigen::Vector2d pink = m.spotOf(SnookerColour::Pink), apex = rack.balls[1].r.head<2>();
  EXPECT_NEAR(apex.y(), 0, 1e-15);
  EXPECT_NEAR((apex - pink).norm() - 2 * Rs(), options.gap, 1e-12);
  for (int red = 1; red <= 15; ++red)
    EXPECT_GT(rack.balls[static_cast<std::size_t>(red)].r.x(), pink.x()) << red << ": behind the pink";
  // A game starts there, with the cue ball in hand in the D.
  GamePlay game(snookerEngine(), "snooker");
  EXPECT_EQ(game.state().ball_in_hand, BallInHand::InD);
  EXPECT_EQ(game.legalFirst().size(), 15u) << "the reds are on";
}

TEST(Snooker, ARedThenAColourThenTheNextRed)
{
  GameState s = snooker();
  const Ruling red = judge(s, fullTable(), facts(3, {3}));
  EXPECT_FALSE(red.foul);
  EXPECT_EQ(red.points, 1);
  EXPECT_TRUE(red.continues);
  EXPECT_TRUE(red.colour_next);
  EXPECT_TRUE(red.respot.empty()) << "a red is never re-spotted";
  EXPECT_EQ(judge(s, fullTable(), facts(3, {3, 7})).points, 2) << "each red potted counts";
  s = afterRuling(s, red);
  EXPECT_TRUE(s.colour_next);
  EXPECT_EQ(s.score[0], 1);
  std::vector<int> on_table = fullTable();
  on_table.erase(std::find(on_table.begin(), on_table.end(), 3));
  EXPECT_EQ(makeRules("snooker")->legalFirst(s, on_table), coloursFrom(kYellow)) << "any colour is on";
  // The colour met first is the one nominated: the blue, potted, 5 points and back on its spot.
  const Ruling blue = judge(s, on_table, facts(kBlue, {kBlue}));
  EXPECT_FALSE(blue.foul);
  EXPECT_EQ(blue.points, 5);
  EXPECT_TRUE(blue.continues);
  EXPECT_FALSE(blue.colour_next);
  EXPECT_EQ(blue.respot, std::vector<int>{kBlue});
  s = afterRuling(s, blue);
  EXPECT_EQ(s.score[0], 6);
  EXPECT_EQ(makeRules("snooker")->legalFirst(s, on_table).size(), 14u) << "the reds again";
  // Nothing potted: the turn passes, no foul.
  const Ruling safety = judge(s, on_table, facts(5));
  EXPECT_FALSE(safety.foul);
  EXPECT_EQ(safety.next_player, 1);
  EXPECT_EQ(safety.points + safety.penalty, 0);
}

TEST(Snooker, AFoulGivesTheOpponentTheValueOfTheBallsConcernedAndAtLeastFour)
{
  const GameState s = snooker();
  struct Case
  {
    const char* what;
    ShotFacts f;
    int penalty;
  };
  ShotFacts in_off = facts(3, {3});
  in_off.scratch = true;
  ShotFacts off_table = facts(3);
  off_table.off_table = {kPink};
  const std::vector<Case> cases = {
      {"no ball met", facts(-1), 4},
      {"the green met first with reds on", facts(kGreen), 4},
      {"the black met first with reds on", facts(kBlack), 7},
      {"a red met first and the pink potted", facts(3, {kPink}), 6},
      {"a red potted, the cue ball in off", in_off, 4},
      {"the pink forced off the table", off_table, 6},
  };
  for (const Case& c : cases)
  {
    const Ruling r = judge(s, fullTable(), c.f);
    EXPECT_TRUE(r.foul) << c.what;
    EXPECT_EQ(r.penalty, c.penalty) << c.what;
    EXPECT_EQ(r.points, 0) << c.what << ": nothing scores on a foul";
    EXPECT_EQ(r.next_player, 1) << c.what;
    EXPECT_FALSE(r.colour_next) << c.what;
    EXPECT_FALSE(r.game_over) << c.what;
    const GameState after = afterRuling(s, r);
    EXPECT_EQ(after.score[1], c.penalty) << c.what << ": the points go to the opponent";
    EXPECT_EQ(after.score[0], 0) << c.what;
  }
  EXPECT_NE(judge(s, fullTable(), facts(-1)).reason.find("no miss is called"), std::string::npos);
  EXPECT_EQ(judge(s, fullTable(), in_off).ball_in_hand, BallInHand::InD) << "in off: in hand in the D";
  EXPECT_EQ(judge(s, fullTable(), facts(kBlack)).ball_in_hand, BallInHand::None) << "played where it lies";
  EXPECT_EQ(judge(s, fullTable(), facts(3, {kPink})).respot, std::vector<int>{kPink}) << "a colour comes back";
  // After a red, the colour nominated (met first) is the ball on: potting another is a foul of
  // the higher value.
  GameState colour = snooker();
  colour.colour_next = true;
  const Ruling wrong = judge(colour, fullTable(), facts(kBlue, {kBlue, kPink}));
  EXPECT_TRUE(wrong.foul);
  EXPECT_EQ(wrong.penalty, 6);
  EXPECT_EQ(wrong.respot, (std::vector<int>{kPink, kBlue})) << "both back, the higher first";
  EXPECT_TRUE(judge(colour, fullTable(), facts(4)).foul) << "a red met first when a colour is on";
  // Three fouls in a row lose nothing in snooker.
  GameState third = snooker();
  third.consecutive_fouls = {2, 0};
  EXPECT_FALSE(judgeShot(*makeRules("snooker"), third, fullTable(), Shot{facts(-1)}).game_over);
}

TEST(Snooker, WithTheRedsGoneTheColoursAreTakenInOrderAndStayDown)
{
  GameState s = snooker();
  const std::vector<int> colours = coloursFrom(kYellow);
  EXPECT_EQ(makeRules("snooker")->legalFirst(s, colours), std::vector<int>{kYellow});
  const Ruling yellow = judge(s, colours, facts(kYellow, {kYellow}));
  EXPECT_FALSE(yellow.foul);
  EXPECT_EQ(yellow.points, 2);
  EXPECT_TRUE(yellow.respot.empty()) << "the yellow stays down";
  EXPECT_FALSE(yellow.colour_next);
  const Ruling green_first = judge(s, colours, facts(kGreen));
  EXPECT_TRUE(green_first.foul);
  EXPECT_EQ(green_first.penalty, 4);
  const Ruling pink_potted = judge(s, colours, facts(kYellow, {kPink}));
  EXPECT_TRUE(pink_potted.foul);
  EXPECT_EQ(pink_potted.penalty, 6);
  EXPECT_EQ(pink_potted.respot, std::vector<int>{kPink});
  // The colour after the last red is re-spotted, and the yellow is on next.
  GameState after_last_red = snooker();
  after_last_red.colour_next = true;
  const Ruling black = judge(after_last_red, colours, facts(kBlack, {kBlack}));
  EXPECT_EQ(black.points, 7);
  EXPECT_EQ(black.respot, std::vector<int>{kBlack});
  EXPECT_EQ(makeRules("snooker")->legalFirst(afterRuling(after_last_red, black), colours), std::vector<int>{kYellow});
}

TEST(Snooker, TheFrameEndsOnTheBlackAndATieRespotsIt)
{
  GameState s = snooker(1);
  s.score = {60, 55};
  const Ruling win = judge(s, {kBlack}, facts(kBlack, {kBlack}));
  EXPECT_TRUE(win.game_over);
  EXPECT_EQ(win.winner, 1);
  EXPECT_TRUE(win.respot.empty());
  s.score = {60, 53};  // the black ties it at 60
  const Ruling tie = judge(s, {kBlack}, facts(kBlack, {kBlack}));
  EXPECT_FALSE(tie.game_over);
  EXPECT_EQ(tie.respot, std::vector<int>{kBlack});
  EXPECT_EQ(tie.ball_in_hand, BallInHand::InD);
  EXPECT_EQ(tie.next_player, 0);
  EXPECT_NE(tie.reason.find("re-spotted"), std::string::npos) << tie.reason;
  // After the re-spot, the next score or foul ends it.
  GameState again = afterRuling(s, tie);
  EXPECT_EQ(again.score[0], again.score[1]);
  const Ruling foul = judge(again, {kBlack}, facts(-1));
  EXPECT_TRUE(foul.game_over);
  EXPECT_EQ(foul.penalty, 7);
  EXPECT_EQ(foul.winner, 1);
  // A foul on the last black ends the frame, but a miss of the black with others left does not.
  EXPECT_FALSE(judge(snooker(), {kPink, kBlack}, facts(-1)).game_over);
  EXPECT_FALSE(judge(snooker(), {kBlack}, facts(kBlack)).game_over) << "no pot, no foul: the frame goes on";
}

TEST(Snooker, ColoursAreSpottedOnTheirOwnSpotTheHighestFreeOrTowardsTheTopCushion)
{
  const auto rules = makeRules("snooker");
  const TableModel& table = *snookerTable();
  const SnookerMarkings m = physics::snookerMarkings(table);
  const auto spot = [&](SnookerColour c) { return m.spotOf(c); };
  TableState<double> s;
  s.balls = {snookerBall(kCue, -1.2, 0.3), snookerBall(kPink, 0, 0.5), snookerBall(kBlack, 0, -0.5),
             snookerBall(kBlue, 0, 0.7)};
  for (auto& b : s.balls)
    if (b.id != kCue)
      b.motion = physics::Motion::Pocketed;
  // The pink's own spot is taken by a red: it goes on the black's spot, the highest free.
  s.balls.push_back(snookerBall(5, spot(SnookerColour::Pink).x(), spot(SnookerColour::Pink).y()));
  rules->respot(table, Rs(), {kPink}, snooker(), s);
  EXPECT_EQ(s.balls[1].r.head<2>(), spot(SnookerColour::Black));
  EXPECT_TRUE(s.balls[1].inPlay());
  // The black's spot is now taken by the pink, and reds stand on the other four: the black goes
  // as near its own spot as it stands, towards the top cushion.
  for (int c = 0; c < 6; ++c)
    if (c != static_cast<int>(SnookerColour::Black) && c != static_cast<int>(SnookerColour::Pink))
      s.balls.push_back(
          snookerBall(6 + c, m.spots[static_cast<std::size_t>(c)].x(), m.spots[static_cast<std::size_t>(c)].y()));
  rules->respot(table, Rs(), {kBlack}, snooker(), s);
  const Eigen::Vector2d black = s.balls[2].r.head<2>(), own = spot(SnookerColour::Black);
  EXPECT_NEAR(black.y(), own.y(), 1e-15);
  EXPECT_GT(black.x(), own.x()) << "towards the top cushion";
  EXPECT_NEAR(black.x() - own.x(), 2 * Rs(), Rs() / 32) << "as near its spot as it stands: by the pink";
  EXPECT_EQ(snookerEngine().whyInvalid(s), "");
}

TEST(Snooker, AFoulThatLeavesTheIncomingPlayerSnookeredGivesAFreeBall)
{
  const auto rules = makeRules("snooker");
  const TableModel& table = *snookerTable();
  // One red left, hidden from the cue ball behind the blue: after a foul, a free ball.
  TableState<double> s;
  s.balls = {snookerBall(kCue, -0.6, 0), snookerBall(kBlue, 0, 0), snookerBall(1, 0.6, 0)};
  GameState after_foul = snooker(1);
  after_foul.last_shot_foul = true;
  const std::string said = rules->beforeShot(table, Rs(), after_foul, s);
  EXPECT_TRUE(after_foul.free_ball) << said;
  EXPECT_NE(said.find("free ball"), std::string::npos) << said;
  EXPECT_EQ(rules->legalFirst(after_foul, {1, kBlue}), (std::vector<int>{1, kBlue})) << "any ball may be nominated";
  // The blue, nominated by being met first, potted: it counts as a red (1), comes back, and a
  // colour is on next.
  const Ruling free_ball = judge(after_foul, {1, kBlue}, facts(kBlue, {kBlue}));
  EXPECT_FALSE(free_ball.foul) << free_ball.reason;
  EXPECT_EQ(free_ball.points, 1);
  EXPECT_EQ(free_ball.respot, std::vector<int>{kBlue});
  EXPECT_TRUE(free_ball.colour_next);
  // No foul before, or the red in sight past the blue's edge: no free ball.
  GameState fair = snooker(1);
  EXPECT_EQ(rules->beforeShot(table, Rs(), fair, s), "");
  EXPECT_FALSE(fair.free_ball);
  s.balls[2].r.y() = 0.2;  // both edges of the red clear of the blue
  GameState seen = snooker(1);
  seen.last_shot_foul = true;
  EXPECT_EQ(rules->beforeShot(table, Rs(), seen, s), "");
  EXPECT_FALSE(seen.free_ball);
  // Only one edge clear is still snookered (WPBSA: both extreme edges).
  s.balls[2].r.y() = 2 * Rs();
  GameState half = snooker(1);
  half.last_shot_foul = true;
  rules->beforeShot(table, Rs(), half, s);
  EXPECT_TRUE(half.free_ball);
}

TEST(Snooker, TheCueBallInHandGoesInTheD)
{
  const TableModel& table = *snookerTable();
  const SnookerMarkings m = physics::snookerMarkings(table);
  TableState<double> s;
  s.balls = {snookerBall(kBrown, m.d_centre.x(), m.d_centre.y())};
  EXPECT_EQ(whyNotInHand(table, Rs(), s, m.d_centre + Eigen::Vector2d(-0.1, 0.15), BallInHand::InD), "");
  const std::string beyond = whyNotInHand(table, Rs(), s, m.d_centre + Eigen::Vector2d(0.05, 0.1), BallInHand::InD);
  EXPECT_NE(beyond.find("in the D"), std::string::npos) << beyond;
  EXPECT_NE(whyNotInHand(table, Rs(), s, m.d_centre + Eigen::Vector2d(-0.25, 0.25), BallInHand::InD), "");
  EXPECT_NE(whyNotInHand(table, Rs(), s, m.d_centre + Eigen::Vector2d(-Rs(), 0), BallInHand::InD), "")
      << "on the brown";
  Eigen::Vector2d low, high;
  ASSERT_TRUE(inHandRegion(table, Rs(), BallInHand::InD, low, high));
  EXPECT_NEAR(high.x(), m.baulk_line_x, 1e-12);
  EXPECT_NEAR(low.x(), m.baulk_line_x - m.d_radius, 1e-12);
  // A game: the break is played from the D; an in-off brings the cue ball back into it.
  GamePlay game(snookerEngine(), "snooker");
  EXPECT_NE(game.placeCueBall(m.d_centre + Eigen::Vector2d(0.1, 0)), "");
  EXPECT_EQ(game.placeCueBall(m.d_centre + Eigen::Vector2d(-0.1, -0.1)), "");
  // The cue ball sent into a bottom corner pocket, nothing met: a foul of 4, and the incoming
  // player has it in hand in the D, where the game has put it.
  TableState<double> position;
  position.balls = {snookerBall(kCue, kBottom + 0.3, -kWidth / 2 + 0.3), snookerBall(1, 0.5, 0.2),
                    snookerBall(kBlack, m.spotOf(SnookerColour::Black).x(), 0)};
  ASSERT_EQ(game.setPosition(position, false), "");
  CueStrike<double> strike;
  strike.speed = 2;
  strike.phi = std::atan2(-1.0, -1.0);  // along the diagonal into the corner
  const Turn turn = game.shoot(strike);
  ASSERT_TRUE(turn.facts.scratch) << turn.ruling.reason;
  EXPECT_TRUE(turn.ruling.foul);
  EXPECT_EQ(turn.ruling.penalty, 4);
  EXPECT_EQ(game.state().score[1], 4);
  EXPECT_EQ(game.state().ball_in_hand, BallInHand::InD);
  const Ball<double>& back = game.table().balls[static_cast<std::size_t>(game.table().indexOf(kCue))];
  EXPECT_TRUE(back.inPlay());
  EXPECT_TRUE(m.inD(back.r.head<2>()));
}
