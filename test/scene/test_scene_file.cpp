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
  physics::PhysicsParams<double> from_yaml;
  for (const auto& field : physics::physicsParamFields())
    from_yaml.*field.member = -1;
  physics::ModelChoice models;
  models.ball_ball = models.cushion = "";
  applyPhysicsYaml(readConfig(), from_yaml, models);
  const physics::PhysicsParams<double> defaults;
  for (const auto& field : physics::physicsParamFields())
    EXPECT_NEAR(from_yaml.*field.member, defaults.*field.member, 1e-9 * std::abs(defaults.*field.member)) << field.name;
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

TEST(SceneFile, BadScenesNameTheProblem)
{
  EXPECT_NE(errorOf("table: 7ft\nfoo: 1\n").find("unknown key 'foo'"), std::string::npos);
  EXPECT_NE(errorOf("physics: {mu_slid: 0.2}\n").find("unknown key 'mu_slid'"), std::string::npos);
  EXPECT_NE(errorOf("physics: {e_ball: 1.5}\n").find("e_ball must be in [0, 1]"), std::string::npos);
  EXPECT_NE(errorOf("table: 6ft\n").find("unknown table '6ft'"), std::string::npos);
  EXPECT_NE(errorOf("rack: ten\n").find("unknown rack 'ten'"), std::string::npos);
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
