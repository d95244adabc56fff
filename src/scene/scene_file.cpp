#include "cue_sim/scene/scene_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/game/referee.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"

namespace cue_sim
{
namespace
{
/// A scalar, or why not, naming the key and saying what it is instead.
template <typename T>
T scalar(const YAML::Node& node, const std::string& key, const char* what)
{
  try
  {
    if (node.IsScalar())
      return node.as<T>();
  }
  catch (const YAML::Exception&)
  {
  }
  std::ostringstream why;
  why << "'" << key << "' must be " << what;
  if (node.IsScalar())
    why << ", got '" << node.Scalar() << "'";
  else
    why << ", got a " << (node.IsSequence() ? "list" : node.IsMap() ? "map" : "null");
  if (node.Mark().line >= 0)
    why << " (line " << node.Mark().line + 1 << ")";
  throw SceneError(why.str());
}

double number(const YAML::Node& node, const std::string& key)
{
  const double x = scalar<double>(node, key, "a number");
  if (!std::isfinite(x))
    throw SceneError("'" + key + "' must be a finite number, got '" + node.Scalar() + "'");
  return x;
}

int integer(const YAML::Node& node, const std::string& key)
{
  return scalar<int>(node, key, "an integer");
}

std::string text(const YAML::Node& node, const std::string& key)
{
  return scalar<std::string>(node, key, "a name");
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

/// A list of two numbers (on the cloth: the height part is `height`) or three (in space).
Eigen::Vector3d planarOrSpatial(const YAML::Node& node, const std::string& key, double height)
{
  if (!node.IsSequence() || (node.size() != 2 && node.size() != 3))
    throw SceneError("'" + key + "' must be a list of 2 numbers (on the cloth) or 3 (in space)");
  Eigen::Vector3d v(0, 0, height);
  for (std::size_t i = 0; i < node.size(); ++i)
    v[static_cast<int>(i)] = number(node[i], key);
  return v;
}

/// Every key of the map known, and each once.
void onlyKeys(const YAML::Node& map, const std::string& where, const std::set<std::string>& known)
{
  if (!map.IsMap())
    throw SceneError(where + " must be a map of keys to values");
  std::set<std::string> seen;
  for (const auto& item : map)
  {
    const std::string key = text(item.first, "a key in " + where);
    if (!seen.insert(key).second)
      throw SceneError("key '" + key + "' appears twice in " + where);
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
  std::set<std::string> known = {"ball_ball_model", "cushion_model", "ball_table_model", "cue_model"};
  for (const auto& field : physics::physicsParamFields())
    known.insert(field.name);
  onlyKeys(node, "physics", known);
  for (const auto& field : physics::physicsParamFields())
    if (node[field.name])
      params.*field.member = number(node[field.name], field.name);
  const auto model = [&](const char* key, std::string& choice, const std::vector<std::string>& known) {
    if (!node[key])
      return;
    choice = text(node[key], key);
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
  model("ball_table_model", models.ball_table, physics::ballTableModelNames());
  model("cue_model", models.cue, physics::cueModelNames());
  const std::string why = params.validate();
  if (!why.empty())
    throw SceneError("physics: " + why);
}

/// A number written so that reading it back gives it exactly.
std::string exact(double x)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

template <typename Vector>
std::string exactList(const Vector& v)
{
  std::string out = "[";
  for (int i = 0; i < v.size(); ++i)
    out += (i ? ", " : "") + exact(v[i]);
  return out + "]";
}

physics::Ball<double> ballFrom(const YAML::Node& node, const std::string& where, double radius)
{
  onlyKeys(node, where, {"id", "position", "velocity", "angular_velocity"});
  if (!node["id"] || !node["position"])
    throw SceneError(where + " needs 'id' and 'position' ([x, y] in metres, or [x, y, z] off the cloth)");
  const Eigen::Vector3d position = planarOrSpatial(node["position"], where + ".position", radius);
  if (!(position.z() >= radius))
    throw SceneError(where + ".position: the centre's height z = " + exact(position.z()) +
                     " m is below the cloth's ball_radius = " + exact(radius) + " m");
  return sceneBallInSpace(
      integer(node["id"], where + ".id"), position,
      node["velocity"] ? planarOrSpatial(node["velocity"], where + ".velocity", 0.0) : Eigen::Vector3d::Zero(),
      node["angular_velocity"] ? vector<3>(node["angular_velocity"], where + ".angular_velocity")
                               : Eigen::Vector3d::Zero(),
      radius);
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

namespace
{
/// A value of `node[key]` among `names` (the enum's values in order).
template <typename Enum>
Enum choice(const YAML::Node& node, const std::string& key, const std::vector<std::string>& names)
{
  const std::string value = text(node, key);
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == value)
      return static_cast<Enum>(k);
  std::string known;
  for (const auto& n : names)
    known += (known.empty() ? "" : ", ") + n;
  throw SceneError(key + " must be one of " + known + ", got '" + value + "'");
}

/// Two values of a list of exactly two.
YAML::Node pairOf(const YAML::Node& node, const std::string& key)
{
  if (!node.IsSequence() || node.size() != 2)
    throw SceneError(key + " must be a list of two, one per player");
  return node;
}

bool flag(const YAML::Node& node, const std::string& key)
{
  bool value = false;
  if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value))
    throw SceneError(key + " must be true or false");
  return value;
}

/// The pocket a game block calls: by its URDF link name (pocket_foot_ypos), or by its index among
/// the table's pockets, which are in the order of their link names; -1 (or absent) for none.
int calledPocket(const YAML::Node& node, const physics::TableModel& table)
{
  if (!node)
    return -1;
  const int count = static_cast<int>(table.pockets().size());
  std::string names;
  for (const auto& p : table.pockets())
    names += (names.empty() ? "" : ", ") + p.name;
  const std::string why = "game.called_pocket must be a pocket of table '" + table.name() + "' by name (" + names +
                          ") or index (0 to " + std::to_string(count - 1) + ", in that order), or -1 for none; got '" +
                          (node.IsScalar() ? node.Scalar() : std::string("not a scalar")) + "'";
  if (!node.IsScalar())
    throw SceneError(why);
  int index = -1;
  if (YAML::convert<int>::decode(node, index))
  {
    if (index < -1 || index >= count)
      throw SceneError(why);
    return index;
  }
  if (!table.whyNoPocket(node.Scalar(), index).empty() || index < 0)
    throw SceneError(why);
  return index;
}

const std::vector<std::string> kGroupNames{"open", "solids", "stripes"};
const std::vector<std::string> kBallInHandNames{"none", "anywhere", "behind_head_string", "in_d"};

/// A pair of counts of a game block, each in [0, high].
std::array<int, 2> countsFrom(const YAML::Node& node, const std::string& field, int high)
{
  std::array<int, 2> counts{0, 0};
  for (std::size_t k = 0; k < 2; ++k)
  {
    const std::string name = field + "[" + std::to_string(k) + "]";
    counts[k] = integer(pairOf(node, field)[k], name);
    if (counts[k] < 0 || counts[k] > high)
      throw SceneError(name + " must be in [0, " + std::to_string(high) + "], got " + std::to_string(counts[k]));
  }
  return counts;
}

/// The scene's `game:` block: the rules, then each field of the state with a game just started
/// (player 0 to break; in pool the ball in hand behind the head string) as its default.
game::GameState gameFrom(const YAML::Node& node)
{
  onlyKeys(node, "game",
           {"rules", "players", "turn", "break", "groups", "called_ball", "called_pocket", "ball_in_hand", "fouls",
            "push_out_allowed", "score", "target", "innings", "colour_next", "free_ball"});
  game::GameState g;
  if (!node["rules"])
  {
    std::string known;
    for (const std::string& n : game::rulesNames())
      known += (known.empty() ? "" : ", ") + n;
    throw SceneError("game needs 'rules' (one of " + known + ")");
  }
  g.rules = text(node["rules"], "game.rules");
  std::unique_ptr<game::Rules> rules;
  try
  {
    rules = game::makeRules(g.rules);
  }
  catch (const std::invalid_argument& e)
  {
    throw SceneError(std::string("game.rules: ") + e.what());
  }
  if (node["players"])
    for (std::size_t k = 0; k < 2; ++k)
      g.players[k] = text(pairOf(node["players"], "game.players")[k], "game.players[" + std::to_string(k) + "]");
  if (node["turn"])
  {
    g.turn = integer(node["turn"], "game.turn");
    if (g.turn != 0 && g.turn != 1)
      throw SceneError("game.turn must be 0 or 1 (the player to shoot), got " + std::to_string(g.turn));
  }
  g.break_shot = node["break"] ? flag(node["break"], "game.break") : true;
  g.ball_in_hand = node["ball_in_hand"]
                       ? choice<game::BallInHand>(node["ball_in_hand"], "game.ball_in_hand", kBallInHandNames)
                       : (g.break_shot ? rules->ballInHandOnBreak() : game::BallInHand::None);
  if (!rules->needsPockets() && g.ball_in_hand != game::BallInHand::None)
    throw SceneError("game.ball_in_hand: " + g.rules + " has no ball in hand; it must be none");
  const bool in_d = rules->ballInHandOnBreak() == game::BallInHand::InD;  // snooker: the D or nowhere
  if (g.ball_in_hand != game::BallInHand::None && (g.ball_in_hand == game::BallInHand::InD) != in_d)
    throw SceneError("game.ball_in_hand: " + g.rules + " has the cue ball in hand " +
                     (in_d ? "only in the D: in_d or none" : "anywhere or behind the head string, not in_d"));
  if (node["groups"])
  {
    for (std::size_t k = 0; k < 2; ++k)
      g.groups[k] = choice<game::Group>(pairOf(node["groups"], "game.groups")[k],
                                        "game.groups[" + std::to_string(k) + "]", kGroupNames);
    const bool open = g.groups[0] == game::Group::Open, both_open = open && g.groups[1] == game::Group::Open;
    if ((open || g.groups[1] == game::Group::Open) ? !both_open : g.groups[0] == g.groups[1])
      throw SceneError("game.groups must be both open, or solids and stripes one each");
  }
  g.called_ball = node["called_ball"] ? integer(node["called_ball"], "game.called_ball") : -1;
  if (g.called_ball < -1 || g.called_ball > 15)
    throw SceneError("game.called_ball must be an object ball 1-15, or -1 for none; got " +
                     std::to_string(g.called_ball));
  if (node["fouls"])
    for (std::size_t k = 0; k < 2; ++k)
    {
      const int fouls = integer(pairOf(node["fouls"], "game.fouls")[k], "game.fouls[" + std::to_string(k) + "]");
      const int most = rules->threeFoulsLose() ? 2 : 1000000;  // a third loses the game, where it does
      if (fouls < 0 || fouls > most)
        throw SceneError("game.fouls[" + std::to_string(k) + "] must be in [0, " + std::to_string(most) +
                         "] (fouls in a row), got " + std::to_string(fouls));
      g.consecutive_fouls[k] = fouls;
    }
  g.push_out_allowed = node["push_out_allowed"] ? flag(node["push_out_allowed"], "game.push_out_allowed") : false;
  g.target = rules->defaultTarget();
  if (node["target"])
  {
    g.target = integer(node["target"], "game.target");
    const int high = game::GamePlay::kMaxTarget;
    if (rules->defaultTarget() == 0 ? g.target != 0 : (g.target < 1 || g.target > high))
      throw SceneError("game.target must be " +
                       (rules->defaultTarget() == 0 ? g.rules + "'s 0 (it keeps no score)"
                                                    : "in [1, " + std::to_string(high) + "]") +
                       ", got " + std::to_string(g.target));
  }
  if (node["score"])
  {
    if (!rules->keepsScore())
      throw SceneError("game.score: " + g.rules + " keeps no score");
    g.score = countsFrom(node["score"], "game.score", g.target > 0 ? g.target - 1 : 1000000);
  }
  if (node["innings"])
    g.innings = countsFrom(node["innings"], "game.innings", 1000000);
  // Snooker's: a colour on after a red, and a free ball after a foul that snookers.
  g.colour_next = node["colour_next"] ? flag(node["colour_next"], "game.colour_next") : false;
  g.free_ball = node["free_ball"] ? flag(node["free_ball"], "game.free_ball") : false;
  return g;
}
}  // namespace

Scene loadScene(const std::string& yaml_text)
{
  try
  {
    const YAML::Node root = YAML::Load(yaml_text);
    if (!root.IsMap())
      throw SceneError("a scene is a YAML map");
    onlyKeys(root, "the scene", {"table", "physics", "rack", "rack_gap", "balls", "shot", "duration", "game"});
    Scene scene;
    if (root["table"])
      scene.table_name = text(root["table"], "table");
    scene.table = std::make_shared<const physics::TableModel>(tableFromUrdfFile(tableUrdfPath(scene.table_name)));
    scene.params = physics::tableDefaults(*scene.table);  // the table's balls, unless physics: says
    if (root["physics"])
      applyPhysicsNode(root["physics"], scene.params, scene.models);
    const double R = scene.params.ball_radius;
    if (root["rack"])
    {
      physics::RackOptions options;
      if (root["rack_gap"])
        options.gap = number(root["rack_gap"], "rack_gap");
      try
      {
        scene.state = physics::rackLayout<double>(text(root["rack"], "rack"), *scene.table, R, options);
      }
      catch (const std::invalid_argument& e)
      {
        throw SceneError(std::string("rack: ") + e.what());
      }
    }
    if (root["balls"])
    {
      if (!root["balls"].IsSequence())
        throw SceneError("balls must be a list of balls");
      std::set<int> ids;
      for (std::size_t i = 0; i < root["balls"].size(); ++i)
      {
        const std::string where = "balls[" + std::to_string(i) + "]";
        const physics::Ball<double> b = ballFrom(root["balls"][i], where, R);
        if (!ids.insert(b.id).second)
          throw SceneError(where + ".id = " + std::to_string(b.id) + " appears twice in balls");
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
      onlyKeys(s, "shot", {"ball", "speed", "phi", "theta", "a", "b", "push_out"});
      Shot shot;
      shot.ball = s["ball"] ? integer(s["ball"], "shot.ball") : 0;
      if (!s["speed"])
        throw SceneError("shot needs 'speed' (the cue's speed V0 in m/s)");
      shot.strike.speed = number(s["speed"], "shot.speed");
      shot.strike.phi = s["phi"] ? number(s["phi"], "shot.phi") : 0.0;
      shot.strike.theta = s["theta"] ? number(s["theta"], "shot.theta") : 0.0;
      shot.strike.a = s["a"] ? number(s["a"], "shot.a") : 0.0;
      shot.strike.b = s["b"] ? number(s["b"], "shot.b") : 0.0;
      shot.push_out = s["push_out"] ? flag(s["push_out"], "shot.push_out") : false;
      const std::string why = physics::validateStrike(shot.strike);
      if (!why.empty())
        throw SceneError("shot: " + why);
      scene.shot = shot;
    }
    if (root["game"])
    {
      scene.game = gameFrom(root["game"]);
      scene.game->called_pocket = calledPocket(root["game"]["called_pocket"], *scene.table);
      const auto rules = game::makeRules(scene.game->rules);
      if (const std::string why = game::whyNotPlayableOn(*rules, scene.game->rules, *scene.table); !why.empty())
        throw SceneError("game.rules: " + why);
      if (scene.shot && !rules->strikable(scene.shot->ball))
        throw SceneError("shot.ball: ball " + std::to_string(scene.shot->ball) + " is not struck in a game of " +
                         scene.game->rules + "; the shooter's is " + std::to_string(rules->cueBall(scene.game->turn)));
      if (root["duration"])
        throw SceneError("duration: a game's shot is ruled on at rest; drop duration");
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

physics::Ball<double> sceneBall(int id, const Eigen::Vector2d& position, const Eigen::Vector2d& velocity,
                                const Eigen::Vector3d& angular_velocity, double radius)
{
  return sceneBallInSpace(id, Eigen::Vector3d(position.x(), position.y(), radius),
                          Eigen::Vector3d(velocity.x(), velocity.y(), 0.0), angular_velocity, radius);
}

physics::Ball<double> sceneBallInSpace(int id, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                                       const Eigen::Vector3d& angular_velocity, double radius)
{
  physics::Ball<double> b;
  b.id = id;
  b.r = position;
  b.v = velocity;
  b.w = angular_velocity;
  physics::settleMotion(b, radius);
  return b;
}

std::string sceneYaml(const Scene& scene, const std::string& comment)
{
  std::ostringstream out;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);)
    out << "# " << line << "\n";
  out << "table: " << YAML::Node(scene.table_name) << "\n";
  out << "physics:\n";
  for (const auto& field : physics::physicsParamFields())
    out << "  " << field.name << ": " << exact(scene.params.*field.member) << "\n";
  out << "  ball_ball_model: " << scene.models.ball_ball << "\n";
  out << "  cushion_model: " << scene.models.cushion << "\n";
  out << "  ball_table_model: " << scene.models.ball_table << "\n";
  out << "  cue_model: " << scene.models.cue << "\n";
  out << "balls:\n";
  for (const auto& b : scene.state.balls)
  {
    // A ball off the cloth is written with its height and vertical speed; one on it as [x, y].
    out << "  - {id: " << b.id
        << ", position: " << (b.airborne() ? exactList(b.r) : exactList(Eigen::Vector2d(b.r.head<2>())))
        << ", velocity: " << (b.airborne() ? exactList(b.v) : exactList(Eigen::Vector2d(b.v.head<2>())))
        << ", angular_velocity: " << exactList(b.w) << "}\n";
  }
  if (scene.shot)
  {
    const auto& s = scene.shot->strike;
    out << "shot: {ball: " << scene.shot->ball << ", speed: " << exact(s.speed) << ", phi: " << exact(s.phi)
        << ", theta: " << exact(s.theta) << ", a: " << exact(s.a) << ", b: " << exact(s.b)
        << (scene.shot->push_out ? ", push_out: true" : "") << "}\n";
  }
  if (scene.duration)
    out << "duration: " << exact(*scene.duration) << "\n";
  if (scene.game)
  {
    const game::GameState& g = *scene.game;
    const auto groups = [&](std::size_t k) { return kGroupNames[static_cast<std::size_t>(g.groups[k])]; };
    out << "game:\n  rules: " << g.rules << "\n  players: [" << YAML::Node(g.players[0]) << ", "
        << YAML::Node(g.players[1]) << "]\n  turn: " << g.turn << "\n  break: " << (g.break_shot ? "true" : "false")
        << "\n  groups: [" << groups(0) << ", " << groups(1) << "]\n  called_ball: " << g.called_ball
        << "\n  called_pocket: "
        << (g.called_pocket >= 0 ? scene.table->pockets()[static_cast<std::size_t>(g.called_pocket)].name
                                 : std::string("-1"))
        << "\n  ball_in_hand: " << kBallInHandNames[static_cast<std::size_t>(g.ball_in_hand)] << "\n  fouls: ["
        << g.consecutive_fouls[0] << ", " << g.consecutive_fouls[1]
        << "]\n  push_out_allowed: " << (g.push_out_allowed ? "true" : "false") << "\n";
    if (game::makeRules(g.rules)->keepsScore())
      out << "  target: " << g.target << "\n  score: [" << g.score[0] << ", " << g.score[1] << "]\n  innings: ["
          << g.innings[0] << ", " << g.innings[1] << "]\n";
    if (g.colour_next)
      out << "  colour_next: true\n";
    if (g.free_ball)
      out << "  free_ball: true\n";
  }
  return out.str();
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
