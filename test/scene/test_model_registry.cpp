// The contact models are declared once (include/cue_sim/physics/contact_models.def): the C++
// registry, scene files, config/physics.yaml and the model table of doc/physics.md agree with it.
// config/TableNode.cfg reads the declarations itself.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/scene/scene_file.hpp"

using namespace cue_sim;

namespace
{
std::string fileText(const std::string& relative)
{
  std::ifstream f(std::string(CUE_SIM_SOURCE_DIR) + "/" + relative);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// The model names in doc/physics.md's "Models" table for one kind ("ball-ball", "ball-cushion"),
/// and which of them it marks "(default)".
std::set<std::string> readmeModels(const std::string& kind, std::string& marked_default)
{
  std::set<std::string> names;
  const std::regex row("\\| " + kind + " \\| `([a-z0-9_]+)`( \\(default\\))? \\|");
  const std::string readme = fileText("doc/physics.md");
  for (std::sregex_iterator it(readme.begin(), readme.end(), row), end; it != end; ++it)
  {
    names.insert((*it)[1]);
    if ((*it)[2].matched)
      marked_default = (*it)[1];
  }
  return names;
}
}  // namespace

TEST(ModelRegistry, EveryDeclaredModelIsMadeByNameAndTheFirstOfAKindIsTheDefault)
{
  for (const physics::ModelInfo& model : physics::contactModels())
  {
    SCOPED_TRACE(model.name);
    const std::string kind = model.kind;
    EXPECT_TRUE(kind == "ball_ball" || kind == "cushion" || kind == "ball_table" || kind == "cue");
    EXPECT_GT(std::string(model.summary).size(), 20u);
    EXPECT_GT(std::string(model.reference).size(), 5u);
    // dynamic_reconfigure's generator refuses quotes in the descriptions TableNode.cfg makes of these.
    EXPECT_EQ(std::string(model.reference).find_first_of("'\""), std::string::npos) << model.reference;
    if (kind == "ball_ball")
      EXPECT_NE(physics::makeBallBallModel<double>(model.name), nullptr);
    else if (kind == "cushion")
      EXPECT_NE(physics::makeCushionModel<long double>(model.name), nullptr);
    else if (kind == "ball_table")
      EXPECT_NE(physics::makeBallTableModel<double>(model.name), nullptr);
    else
      EXPECT_NE(physics::makeCueModel<long double>(model.name), nullptr);
    // Every coefficient it names is a declared physics parameter.
    std::istringstream words(model.coefficients);
    for (std::string word; words >> word;)
    {
      bool declared = false;
      for (const auto& field : physics::physicsParamFields())
        declared = declared || word == field.name;
      EXPECT_TRUE(declared) << word;
    }
  }
  EXPECT_EQ(physics::ModelChoice().ball_ball, physics::ballBallModelNames().front());
  EXPECT_EQ(physics::ModelChoice().cushion, physics::cushionModelNames().front());
  EXPECT_EQ(physics::ModelChoice().ball_table, physics::ballTableModelNames().front());
  EXPECT_EQ(physics::ModelChoice().cue, physics::cueModelNames().front());
  EXPECT_EQ(physics::ModelChoice("", "", "", "planar").cue, "planar");
  EXPECT_THROW(physics::makeBallTableModel<double>("rubber"), std::invalid_argument);
  EXPECT_THROW(physics::makeCueModel<double>("rubber"), std::invalid_argument);
}

TEST(ModelRegistry, TheReadmeTableListsEveryModelAndMarksTheDefaults)
{
  std::string ball_ball_default, cushion_default, ball_table_default;
  const auto ball_ball = physics::ballBallModelNames(), cushion = physics::cushionModelNames();
  const auto ball_table = physics::ballTableModelNames(), cue = physics::cueModelNames();
  std::string cue_default;
  EXPECT_EQ(readmeModels("ball-ball", ball_ball_default), std::set<std::string>(ball_ball.begin(), ball_ball.end()));
  EXPECT_EQ(readmeModels("ball-cushion", cushion_default), std::set<std::string>(cushion.begin(), cushion.end()));
  EXPECT_EQ(ball_ball_default, ball_ball.front());
  EXPECT_EQ(cushion_default, cushion.front());
  EXPECT_EQ(readmeModels("ball-table", ball_table_default),
            std::set<std::string>(ball_table.begin(), ball_table.end()));
  EXPECT_EQ(ball_table_default, ball_table.front());
  EXPECT_EQ(readmeModels("cue", cue_default), std::set<std::string>(cue.begin(), cue.end()));
  EXPECT_EQ(cue_default, cue.front());
}

TEST(ModelRegistry, PhysicsYamlAndSceneFilesTakeEveryModel)
{
  // config/physics.yaml names each model of its kind on the model's line.
  const std::string yaml = fileText("config/physics.yaml");
  for (const physics::ModelInfo& model : physics::contactModels())
  {
    const std::regex line("\\n" + std::string(model.kind) + "_model: [^\\n]*\\b" + model.name + "\\b");
    EXPECT_TRUE(std::regex_search(yaml, line)) << model.name;
    const Scene scene = loadScene("physics: {" + std::string(model.kind) + "_model: " + model.name +
                                  "}\nrack: nine\nshot: {speed: 1}\n");
    const std::string kind = model.kind;
    const std::string& chosen = kind == "cushion"      ? scene.models.cushion
                                : kind == "ball_table" ? scene.models.ball_table
                                : kind == "cue"        ? scene.models.cue
                                                       : scene.models.ball_ball;
    EXPECT_EQ(chosen, model.name);
  }
}
