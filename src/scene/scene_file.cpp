#include "cue_sim/scene/scene_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"

namespace cue_sim
{
namespace
{
double number(const YAML::Node& node, const std::string& key)
{
  try
  {
    return node.as<double>();
  }
  catch (const YAML::Exception&)
  {
    throw SceneError("'" + key + "' must be a number");
  }
}

template <int N>
Eigen::Matrix<double, N, 1> vector(const YAML::Node& node, const std::string& key)
{
  if (!node.IsSequence() || node.size() != N)
    throw SceneError("'" + key + "' must be a list of " + std::to_string(N) + " numbers");
  Eigen::Matrix<double, N, 1> v;
  for (int i = 0; i < N; ++i)
    v[i] = number(node[i], key);
  return v;
}

void onlyKeys(const YAML::Node& map, const std::string& where, const std::set<std::string>& known)
{
  for (const auto& item : map)
  {
    const std::string key = item.first.as<std::string>();
    if (!known.count(key))
    {
      std::string list;
      for (const auto& k : known)
        list += (list.empty() ? "" : ", ") + k;
      throw SceneError("unknown key '" + key + "' in " + where + " (known: " + list + ")");
    }
  }
}

void applyPhysicsNode(const YAML::Node& node, physics::PhysicsParams<double>& params, physics::ModelChoice& models)
{
  if (!node.IsMap())
    throw SceneError("physics must be a map of coefficient names to values");
  std::set<std::string> known = {"ball_ball_model", "cushion_model"};
  for (const auto& field : physics::physicsParamFields())
    known.insert(field.name);
  onlyKeys(node, "physics", known);
  for (const auto& field : physics::physicsParamFields())
    if (node[field.name])
      params.*field.member = number(node[field.name], field.name);
  const auto model = [&](const char* key, std::string& choice, const std::vector<std::string>& known) {
    if (!node[key])
      return;
    choice = node[key].as<std::string>();
    if (std::find(known.begin(), known.end(), choice) == known.end())
    {
      std::string list;
      for (const auto& k : known)
        list += (list.empty() ? "" : ", ") + k;
      throw SceneError(std::string(key) + " '" + choice + "' is unknown (known: " + list + ")");
    }
  };
  model("ball_ball_model", models.ball_ball, physics::ballBallModelNames());
  model("cushion_model", models.cushion, physics::cushionModelNames());
  const std::string why = params.validate();
  if (!why.empty())
    throw SceneError("physics: " + why);
}

physics::Ball<double> ballFrom(const YAML::Node& node, double radius)
{
  onlyKeys(node, "balls", {"id", "position", "velocity", "angular_velocity"});
  if (!node["id"] || !node["position"])
    throw SceneError("every ball needs 'id' and 'position' ([x, y] in metres)");
  physics::Ball<double> b;
  b.id = node["id"].as<int>();
  const Eigen::Vector2d xy = vector<2>(node["position"], "position");
  b.r = Eigen::Vector3d(xy.x(), xy.y(), radius);
  if (node["velocity"])
    b.v.head<2>() = vector<2>(node["velocity"], "velocity");
  if (node["angular_velocity"])
    b.w = vector<3>(node["angular_velocity"], "angular_velocity");
  physics::settleMotion(b, radius);
  return b;
}
}  // namespace

void applyPhysicsYaml(const std::string& yaml_text, physics::PhysicsParams<double>& params,
                      physics::ModelChoice& models)
{
  try
  {
    applyPhysicsNode(YAML::Load(yaml_text), params, models);
  }
  catch (const YAML::Exception& e)
  {
    throw SceneError(std::string("physics YAML: ") + e.what());
  }
}

Scene loadScene(const std::string& yaml_text)
{
  try
  {
    const YAML::Node root = YAML::Load(yaml_text);
    if (!root.IsMap())
      throw SceneError("a scene is a YAML map");
    onlyKeys(root, "the scene", {"table", "physics", "rack", "rack_gap", "balls", "shot", "duration"});
    Scene scene;
    if (root["physics"])
      applyPhysicsNode(root["physics"], scene.params, scene.models);
    const std::string table = root["table"] ? root["table"].as<std::string>() : "7ft";
    scene.table = std::make_shared<const physics::TableModel>(tableFromUrdfFile(tableUrdfPath(table)));
    const double R = scene.params.ball_radius;
    if (root["rack"])
    {
      physics::RackOptions options;
      if (root["rack_gap"])
        options.gap = number(root["rack_gap"], "rack_gap");
      try
      {
        scene.state = physics::rackLayout<double>(root["rack"].as<std::string>(), *scene.table, R, options);
      }
      catch (const std::invalid_argument& e)
      {
        throw SceneError(std::string("rack: ") + e.what());
      }
    }
    if (root["balls"])
    {
      for (const auto& node : root["balls"])
      {
        const physics::Ball<double> b = ballFrom(node, R);
        const int index = scene.state.indexOf(b.id);
        if (index >= 0)
          scene.state.balls[index] = b;
        else
          scene.state.balls.push_back(b);
      }
    }
    if (root["shot"])
    {
      const YAML::Node s = root["shot"];
      onlyKeys(s, "shot", {"ball", "speed", "phi", "theta", "a", "b"});
      Shot shot;
      shot.ball = s["ball"] ? s["ball"].as<int>() : 0;
      if (!s["speed"])
        throw SceneError("shot needs 'speed' (the cue's speed V0 in m/s)");
      shot.strike.speed = number(s["speed"], "speed");
      shot.strike.phi = s["phi"] ? number(s["phi"], "phi") : 0.0;
      shot.strike.theta = s["theta"] ? number(s["theta"], "theta") : 0.0;
      shot.strike.a = s["a"] ? number(s["a"], "a") : 0.0;
      shot.strike.b = s["b"] ? number(s["b"], "b") : 0.0;
      const std::string why = physics::validateStrike(shot.strike);
      if (!why.empty())
        throw SceneError("shot: " + why);
      scene.shot = shot;
    }
    if (root["duration"])
    {
      scene.duration = number(root["duration"], "duration");
      if (!(*scene.duration >= 0) || !std::isfinite(*scene.duration))
        throw SceneError("duration must be a finite time >= 0 in seconds");
    }
    return scene;
  }
  catch (const YAML::Exception& e)
  {
    throw SceneError(std::string("scene YAML: ") + e.what());
  }
  catch (const TableDescriptionError& e)
  {
    throw SceneError(std::string("table: ") + e.what());
  }
}

Scene loadSceneFile(const std::string& path)
{
  std::ifstream file(path);
  if (!file)
    throw SceneError("cannot read scene file '" + path + "'");
  std::stringstream text;
  text << file.rdbuf();
  return loadScene(text.str());
}

}  // namespace cue_sim
