// Scene files (YAML) for the `simulate` program: a table, physics, balls and an optional shot.
// The format is documented in README.md, "Scene files".
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "cue_sim/game/game_state.hpp"
#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/physics/cue_strike.hpp"
#include "cue_sim/physics/physics_params.hpp"
#include "cue_sim/physics/table_model.hpp"
#include "cue_sim/physics/table_state.hpp"

namespace cue_sim
{
/// Thrown for a scene that cannot be used; what() names the key and the allowed values.
class SceneError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

struct Shot
{
  int ball = 0;
  physics::CueStrike<double> strike;
  bool push_out = false;  ///< declared a push-out (a game of nine_ball, the shot after the break)
};

struct Scene
{
  std::string table_name = "7ft";  ///< as the scene names it: a bundled table or a URDF file
  std::shared_ptr<const physics::TableModel> table;
  physics::PhysicsParams<double> params;
  physics::ModelChoice models;
  physics::TableState<double> state;
  std::optional<Shot> shot;
  std::optional<double> duration;  ///< [s]; absent: run to rest
  /// A game the shot is played in (the scene's `game:` block): `simulate` then rules on the shot.
  std::optional<game::GameState> game;
};

/// Reads physics coefficients and model names from a YAML map (keys of config/physics.yaml);
/// keys it does not know are an error.
void applyPhysicsYaml(const std::string& yaml_text, physics::PhysicsParams<double>& params,
                      physics::ModelChoice& models);

Scene loadScene(const std::string& yaml_text);
Scene loadSceneFile(const std::string& path);

/// A ball as a scene file places it: its centre at `position` on the cloth, with a velocity
/// along it and a spin; its motion state follows from them.
physics::Ball<double> sceneBall(int id, const Eigen::Vector2d& position, const Eigen::Vector2d& velocity,
                                const Eigen::Vector3d& angular_velocity, double radius);

/// A ball anywhere: its centre at `position` (z from the slate; z = radius is on the cloth,
/// higher is in the air), moving at `velocity`; its motion state follows from them.
physics::Ball<double> sceneBallInSpace(int id, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                                       const Eigen::Vector3d& angular_velocity, double radius);

/// The scene as a scene file that loads back to exactly this scene: the table by its name, every
/// coefficient and model, every ball and the shot, each number to 17 significant digits (the
/// rack, if any, written out ball by ball). `comment` heads it, each line after '# '.
std::string sceneYaml(const Scene& scene, const std::string& comment = "");

}  // namespace cue_sim
