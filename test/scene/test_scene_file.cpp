// Scene files: defaults agree with config/physics.yaml, and bad scenes name the bad key.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "cue_sim/scene/scene_file.hpp"

using namespace cue_sim;

namespace
{
std::string readConfig()
{
  std::ifstream f(std::string(CUE_SIM_SOURCE_DIR) + "/config/physics.yaml");
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string errorOf(const std::string& scene)
{
  try
  {
    loadScene(scene);
  }
  catch (const SceneError& e)
  {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(SceneFile, ConfigPhysicsYamlHoldsTheBuiltInDefaults)
{
  // The node reads config/physics.yaml, simulate falls back to the compiled defaults: both
  // must describe the same physics.
  // The ball's radius and mass are not in it: they are the table's (its URDF's `balls` link),
  // and a value in the file would override every table's.
  const physics::PhysicsParams<double> defaults;
  const auto isBall = [](const physics::ParamField& field) {
    return std::string(field.name) == "ball_radius" || std::string(field.name) == "ball_mass";
  };
  physics::PhysicsParams<double> from_yaml;
  for (const auto& field : physics::physicsParamFields())
    if (!isBall(field))
      from_yaml.*field.member = -1;
  from_yaml.ball_radius = 0.0262;  // a sentinel ball the file must leave alone
  from_yaml.ball_mass = 0.15;
  physics::ModelChoice models;
  models.ball_ball = models.cushion = "";
  applyPhysicsYaml(readConfig(), from_yaml, models);
  for (const auto& field : physics::physicsParamFields())
  {
    if (!isBall(field))
    {
      EXPECT_NEAR(from_yaml.*field.member, defaults.*field.member, 1e-9 * std::abs(defaults.*field.member))
          << field.name;
    }
  }
  EXPECT_EQ(from_yaml.ball_radius, 0.0262);
  EXPECT_EQ(from_yaml.ball_mass, 0.15);
  EXPECT_EQ(models.ball_ball, physics::ModelChoice().ball_ball);
  EXPECT_EQ(models.cushion, physics::ModelChoice().cushion);
  // rosparam reads the file as YAML 1.1, where a number with an exponent and no point (1e-5)
  // is a string, and the node refuses a coefficient that is not a number.
  const std::regex exponent_without_point("\\n[a-z_]+: *[-+]?[0-9]+[eE][-+]?[0-9]+");
  EXPECT_FALSE(std::regex_search(readConfig(), exponent_without_point));
}

TEST(SceneFile, ReadsTableRackBallsAndShot)
{
  const Scene s = loadScene(R"(
table: 9ft
physics: {mu_roll: 0.012, e_ball: 0.9}
rack: nine
balls:
  - {id: 0, position: [-0.5, 0.1]}
  - {id: 12, position: [0.2, -0.3], velocity: [0.5, 0], angular_velocity: [0, 0, 3]}
shot: {ball: 0, speed: 4.5, phi: 0.1}
duration: 1.5
)");
  EXPECT_EQ(s.table->name(), "cue_sim_table_9ft");
  EXPECT_DOUBLE_EQ(s.params.mu_roll, 0.012);
  EXPECT_DOUBLE_EQ(s.params.e_ball, 0.9);
  EXPECT_EQ(s.state.balls.size(), 11u);  // nine-ball rack plus ball 12
  EXPECT_DOUBLE_EQ(s.state.balls[s.state.indexOf(0)].r.x(), -0.5);
  EXPECT_EQ(s.state.balls[s.state.indexOf(12)].motion, physics::Motion::Sliding);
  ASSERT_TRUE(s.shot.has_value());
  EXPECT_DOUBLE_EQ(s.shot->strike.speed, 4.5);
  EXPECT_DOUBLE_EQ(*s.duration, 1.5);
}

// A ball off the cloth: [x, y, z] places its centre z above the slate, [vx, vy, vz] throws it;
// written back with its height, and a ball on the cloth still as [x, y].
TEST(SceneFile, ABallInTheAirIsReadWithItsHeightAndWrittenBackSo)
{
  const Scene s = loadScene(R"(
table: 7ft
balls:
  - {id: 0, position: [-0.5, 0.1]}
  - {id: 1, position: [0.2, -0.3, 0.25], velocity: [0.5, 0, 1.5]}
  - {id: 2, position: [0.4, 0.3, 0.028575], velocity: [0, 0, 2]}
)");
  const physics::Ball<double>&cloth = s.state.balls[0], &high = s.state.balls[1], &rising = s.state.balls[2];
  EXPECT_EQ(cloth.motion, physics::Motion::Stationary);
  EXPECT_EQ(cloth.r.z(), s.params.ball_radius);
  EXPECT_EQ(high.motion, physics::Motion::Airborne);
  EXPECT_EQ(high.r, physics::Vec3<double>(0.2, -0.3, 0.25));
  EXPECT_EQ(high.v, physics::Vec3<double>(0.5, 0, 1.5));
  EXPECT_EQ(rising.motion, physics::Motion::Airborne);  // on the slate, leaving it
  const std::string yaml = sceneYaml(s);
  EXPECT_NE(yaml.find("{id: 0, position: [-0.5, 0.10000000000000001], velocity: [0, 0]"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("{id: 1, position: [0.20000000000000001, -0.29999999999999999, 0.25], velocity: [0.5, 0, 1.5]"),
            std::string::npos)
      << yaml;
  const Scene back = loadScene(yaml);
  for (std::size_t i = 0; i < s.state.balls.size(); ++i)
  {
    EXPECT_EQ(back.state.balls[i].r, s.state.balls[i].r) << i;
    EXPECT_EQ(back.state.balls[i].v, s.state.balls[i].v) << i;
    EXPECT_EQ(back.state.balls[i].motion, s.state.balls[i].motion) << i;
  }
  EXPECT_NE(errorOf("balls: [{id: 0, position: [0, 0, 0.01]}]\n")
                .find("balls[0].position: the centre's height z = 0.01 m is below the cloth's ball_radius"),
            std::string::npos);
  EXPECT_NE(
      errorOf("balls: [{id: 0, position: [0, 0, 0.1, 2]}]\n").find("must be a list of 2 numbers (on the cloth) or 3"),
      std::string::npos);
}

TEST(SceneFile, BadScenesNameTheProblem)
{
  EXPECT_NE(errorOf("table: 7ft\nfoo: 1\n").find("unknown key 'foo'"), std::string::npos);
  EXPECT_NE(errorOf("physics: {mu_slid: 0.2}\n").find("unknown key 'mu_slid'"), std::string::npos);
  EXPECT_NE(errorOf("physics: {e_ball: 1.5}\n").find("e_ball must be in [0, 1]"), std::string::npos);
  EXPECT_NE(errorOf("table: 6ft\n").find("unknown table '6ft'"), std::string::npos);
  EXPECT_NE(errorOf("rack: eleven\n").find("unknown rack 'eleven'"), std::string::npos);
  EXPECT_NE(errorOf("physics: {cushion_model: rubber}\n")
                .find("cushion_model 'rubber' is unknown (known: han2005, mathavan2010, stronge2018, simple)"),
            std::string::npos);
  EXPECT_NE(errorOf("balls: [{id: 0, position: [1]}]\n").find("'balls[0].position' must be a list of 2"),
            std::string::npos);
  EXPECT_NE(errorOf("shot: {speed: -2}\n").find("speed must be in (0, 12]"), std::string::npos);
  EXPECT_NE(errorOf("shot: {phi: 1}\n").find("needs 'speed'"), std::string::npos);
  EXPECT_NE(errorOf("duration: -1\n").find("duration"), std::string::npos);
}

TEST(SceneFile, NonNumbersDuplicatesAndWrongTypesAreRefusedByKey)
{
  EXPECT_NE(errorOf("balls: [{id: 0, position: [0, 0], velocity: [.nan, 0]}]\n")
                .find("'balls[0].velocity' must be a finite number, got '.nan'"),
            std::string::npos);
  EXPECT_NE(errorOf("shot: {speed: .inf}\n").find("'shot.speed' must be a finite number"), std::string::npos);
  EXPECT_NE(errorOf("balls: [{id: one, position: [0, 0]}]\n").find("'balls[0].id' must be an integer, got 'one'"),
            std::string::npos);
  EXPECT_NE(errorOf("table: [7ft]\n").find("'table' must be a name, got a list"), std::string::npos);
  EXPECT_NE(errorOf("rack: eight\nrack: nine\n").find("key 'rack' appears twice in the scene"), std::string::npos);
  EXPECT_NE(errorOf("physics: {mu_roll: 0.01, mu_roll: 0.02}\n").find("key 'mu_roll' appears twice in physics"),
            std::string::npos);
  EXPECT_NE(errorOf("balls: [{id: 3, position: [0, 0]}, {id: 3, position: [0.3, 0]}]\n")
                .find("balls[1].id = 3 appears twice"),
            std::string::npos);
  EXPECT_NE(errorOf("balls: {id: 3}\n").find("balls must be a list"), std::string::npos);
}

TEST(SceneFile, AGameBlockDefaultsToAGameJustStartedAndRoundTrips)
{
  const cue_sim::Scene fresh = cue_sim::loadScene("rack: nine\ngame: {rules: nine_ball}\n");
  ASSERT_TRUE(fresh.game);
  EXPECT_EQ(fresh.game->rules, "nine_ball");
  EXPECT_EQ(fresh.game->turn, 0);
  EXPECT_TRUE(fresh.game->break_shot);
  EXPECT_EQ(fresh.game->ball_in_hand, cue_sim::game::BallInHand::BehindHeadString);
  EXPECT_EQ(fresh.game->called_ball, -1);
  const cue_sim::Scene set = cue_sim::loadScene(
      "rack: eight\nshot: {speed: 2, push_out: false}\n"
      "game: {rules: eight_ball, players: [ann, bob], turn: 1, break: false, groups: [stripes, solids],\n"
      "       called_ball: 3, called_pocket: 4, ball_in_hand: anywhere, fouls: [2, 1]}\n");
  ASSERT_TRUE(set.game);
  EXPECT_EQ(set.game->players[1], "bob");
  EXPECT_EQ(set.game->groups[0], cue_sim::game::Group::Stripes);
  EXPECT_EQ(set.game->ball_in_hand, cue_sim::game::BallInHand::Anywhere);
  EXPECT_EQ(set.game->consecutive_fouls[0], 2);
  const cue_sim::Scene back = cue_sim::loadScene(cue_sim::sceneYaml(set));
  ASSERT_TRUE(back.game);
  EXPECT_EQ(cue_sim::sceneYaml(back), cue_sim::sceneYaml(set));
}

TEST(SceneFile, ACalledPocketIsNamedByItsLinkOrItsIndexInLinkNameOrder)
{
  const auto called = [](const std::string& pocket) {
    return cue_sim::loadScene("rack: eight\ngame: {rules: eight_ball, called_ball: 3, called_pocket: " + pocket +
                              "}\n");
  };
  const cue_sim::Scene by_name = called("pocket_foot_ypos");
  ASSERT_TRUE(by_name.game);
  const auto& pockets = by_name.table->pockets();
  ASSERT_EQ(pockets.size(), 6u);
  for (std::size_t i = 1; i < pockets.size(); ++i)
    EXPECT_LT(pockets[i - 1].name, pockets[i].name) << "the index order is the link names' order";
  EXPECT_EQ(pockets[static_cast<std::size_t>(by_name.game->called_pocket)].name, "pocket_foot_ypos");
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(called(std::to_string(i)).game->called_pocket, i);
  EXPECT_EQ(called("1").game->called_pocket, by_name.game->called_pocket);
  EXPECT_EQ(called("-1").game->called_pocket, -1);
  // Written back by name.
  EXPECT_NE(cue_sim::sceneYaml(by_name).find("called_pocket: pocket_foot_ypos"), std::string::npos);
  EXPECT_EQ(cue_sim::loadScene(cue_sim::sceneYaml(by_name)).game->called_pocket, by_name.game->called_pocket);
}

TEST(SceneFile, BadGameBlocksNameTheKey)
{
  EXPECT_NE(errorOf("game: {turn: 0}\n").find("game needs 'rules'"), std::string::npos);
  EXPECT_NE(errorOf("game: {rules: bagatelle}\n").find("unknown rules 'bagatelle'"), std::string::npos);
  EXPECT_NE(errorOf("game: {rules: eight_ball, turn: 2}\n").find("game.turn must be 0 or 1"), std::string::npos);
  EXPECT_NE(errorOf("game: {rules: eight_ball, groups: [solids, open]}\n").find("game.groups"), std::string::npos);
  EXPECT_NE(errorOf("game: {rules: eight_ball, fouls: [3, 0]}\n").find("game.fouls[0] must be in [0, 2]"),
            std::string::npos);
  EXPECT_NE(errorOf("game: {rules: eight_ball, called_pocket: 6}\n").find("game.called_pocket"), std::string::npos);
  // Snooker: the cue ball in hand only in the D, fouls in a row without end, a frame's score with
  // no target; and pool without the D.
  EXPECT_NE(errorOf("table: snooker\ngame: {rules: snooker, ball_in_hand: anywhere}\n").find("only in the D"),
            std::string::npos);
  EXPECT_NE(errorOf("game: {rules: nine_ball, ball_in_hand: in_d}\n").find("not in_d"), std::string::npos);
  const auto frame = cue_sim::loadScene(
      "table: snooker\nrack: snooker\ngame: {rules: snooker, break: false, ball_in_hand: none, fouls: [5, 0], "
      "score: [40, 72], colour_next: true}\n");
  EXPECT_EQ(frame.game->consecutive_fouls[0], 5);
  EXPECT_EQ(frame.game->score[1], 72);
  EXPECT_TRUE(frame.game->colour_next);
  EXPECT_FALSE(frame.game->free_ball);
  const auto again = cue_sim::loadScene(cue_sim::sceneYaml(frame));  // written back as read
  EXPECT_EQ(again.game->score, frame.game->score);
  EXPECT_TRUE(again.game->colour_next);
  EXPECT_NE(errorOf("game: {rules: nine_ball, score: [1, 0]}\n").find("keeps no score"), std::string::npos);
  EXPECT_NE(errorOf("game: {rules: eight_ball, called_pocket: pocket_nowhere}\n")
                .find("game.called_pocket must be a pocket of table 'cue_sim_table_7ft' by name (pocket_foot_yneg, "
                      "pocket_foot_ypos, pocket_head_yneg, pocket_head_ypos, pocket_side_yneg, pocket_side_ypos) or "
                      "index (0 to 5, in that order), or -1 for none; got 'pocket_nowhere'"),
            std::string::npos);
  EXPECT_NE(errorOf("game: {rules: eight_ball, ball_in_hand: kitchen}\n").find("game.ball_in_hand must be one of"),
            std::string::npos);
  EXPECT_NE(errorOf("game: {rules: eight_ball, break: maybe}\n").find("game.break must be true or false"),
            std::string::npos);
  EXPECT_NE(errorOf("rack: eight\nshot: {ball: 3, speed: 1}\ngame: {rules: eight_ball}\n")
                .find("shot.ball: ball 3 is not struck in a game of eight_ball"),
            std::string::npos);
  EXPECT_NE(errorOf("game: {rules: eight_ball, colour: red}\n").find("unknown key 'colour'"), std::string::npos);
}

// A scene plays with its table's balls (issue 34) unless its physics: block names others.
TEST(SceneFile, TheTablesBallsUnlessPhysicsSaysOtherwise)
{
  const Scene snooker = loadScene("table: snooker\nrack: empty\n");
  EXPECT_EQ(snooker.params.ball_radius, 0.02625);
  EXPECT_EQ(snooker.params.ball_mass, 0.142);
  const Scene carom = loadScene("table: carom\nrack: carom\n");
  EXPECT_EQ(carom.params.ball_radius, 0.03075);
  for (const auto& b : carom.state.balls)
    EXPECT_EQ(b.r.z(), 0.03075);  // placed with the table's ball
  const Scene overridden = loadScene("table: snooker\nphysics: {ball_radius: 0.028575}\n");
  EXPECT_EQ(overridden.params.ball_radius, 0.028575);
  EXPECT_EQ(overridden.params.ball_mass, 0.142);
  EXPECT_EQ(loadScene("table: 7ft\n").params.ball_radius, physics::PhysicsParams<double>().ball_radius);
}
