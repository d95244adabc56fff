// Self-play: whole games between two shot planners on the engine, with execution noise, each
// game recorded shot by shot. No ROS.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/physics/execution_noise.hpp"

namespace cue_sim
{
namespace game
{
/// What a player does on its turn: where it places the cue ball in hand, what it calls, and the
/// strike it plans (execution noise comes on top).
struct Choice
{
  bool place_cue_ball = false;                         ///< the ball is in hand: place it first, at cue_ball
  Eigen::Vector2d cue_ball = Eigen::Vector2d::Zero();  ///< [m] where, if place_cue_ball
  int ball = -1, pocket = -1;
  physics::CueStrike<double> strike;
};

/// A player: chooses the next shot of a game.
class Planner
{
public:
  virtual ~Planner() = default;
  virtual Choice choose(const GamePlay& game) const = 0;
};

/// The planner that fits the rules: a CaromPlanner where points are scored by caroms, a
/// PottingPlanner otherwise.
std::unique_ptr<Planner> plannerFor(const Rules& rules);

/// The open shots of the player to shoot: pairs of a ball it may hit first and a pocket whose
/// ghost-ball shot is cut at most PottingPlanner::kMaxCut with clear paths for the cue ball and the
/// object ball (with the cue ball in hand, a clear path for the object ball is enough).
int openShots(const GamePlay& game);

/// Chooses a shot by trying them. On a break: the cue ball on the break spot, 8 m/s at the apex.
/// Otherwise, for every ball it may hit first and every pocket, the ghost-ball aim (cut at most
/// kMaxCut) at two speeds; with the cue ball in hand it is placed straight behind the ghost ball.
/// Each candidate is played on a copy of the game without noise, and the best ruling wins: a won
/// game, then a legal pot (the shooter continues), then a shot without a foul. A pot that leaves
/// the shooter open shots (position) and a miss that leaves the opponent none (safety) count
/// kPositionWeight for each, up to kOpenShotsCounted; among equals the slower. With no candidate
/// it hits its first legal ball full at 2 m/s.
class PottingPlanner : public Planner
{
public:
  Choice choose(const GamePlay& game) const override;

  static constexpr double kMaxCut = 70 * 3.14159265358979323846 / 180;  ///< [rad]
  static constexpr double kBreakSpeed = 8.0;                            ///< [m/s]
  static constexpr double kPositionWeight = 5;                          ///< per open shot, against 100 for a pot
  static constexpr int kOpenShotsCounted = 10;                          ///< more open shots than this add nothing
  static constexpr int kInHandGrid = 4;    ///< places in hand tried per pot, on a grid over the region
  static constexpr int kInHandTrials = 2;  ///< places in hand played per pot, the first that stand
};

/// Searches cue-ball paths that make a point. Every candidate (kDirections headings round the
/// cue ball, at kSpeeds, with side spin kSide) is played on a copy of the game without noise;
/// a won game, then a point, then a shot without a foul is best, and among points the one whose
/// heading's neighbours score too (a wide window survives the cue's noise), then the slower. With no point
/// it plays the slowest shot without a foul that meets a ball (a safety of sorts).
class CaromPlanner : public Planner
{
public:
  Choice choose(const GamePlay& game) const override;

  static constexpr int kDirections = 180;                        ///< 2 degrees apart
  static constexpr std::array<double, 2> kSpeeds{3.0, 4.5};      ///< [m/s]
  static constexpr std::array<double, 3> kSide{-0.4, 0.0, 0.4};  ///< tip offset a [R]
};

/// One game as played: the table before each shot (the cue ball placed), the turn, and how it
/// ended.
struct GameRecord
{
  std::string rules;
  int index = 0;
  std::array<std::string, 2> players;
  unsigned rack_seed = 0;  ///< of its first rack (gameRack); each new rack takes the next
  int first_player = 0;    ///< who broke
  std::vector<physics::TableState<double>> before;
  std::vector<GameState> state_before;  ///< the game as each shot found it (its calls included)
  std::vector<Turn> turns;
  GameState end;
};

struct SelfPlayOptions
{
  std::string rules = "eight_ball";
  int games = 10;
  std::uint64_t seed = 0;
  int max_shots = 150;            ///< the cap: a game not over by then ends without a winner
  int target = 0;                 ///< the points that win where the game keeps a score; 0: the rules' default
  physics::ExecutionNoise noise;  ///< the tournaments' deviations by default
};

struct SelfPlaySummary
{
  int games = 0, finished = 0, capped = 0;
  std::array<int, 2> wins{0, 0};
  int shots = 0, fouls = 0;
  int points = 0, innings = 0;  ///< where the game keeps a score: points scored, innings played
  int penalty_points = 0;       ///< of those, given for fouls (snooker)
  int highest_break = 0;        ///< the most points one visit to the table scored
  std::vector<GameRecord> records;
};

/// Plays options.games games, plannerFor(rules) on both sides, the break alternating (player 0
/// breaks the even games). Each game racks with seeds of its own; the noise's seed is options.seed. `progress` is
/// called after each game.
SelfPlaySummary selfPlay(const physics::Engine<double>& engine, const SelfPlayOptions& options,
                         const std::function<void(const GameRecord&)>& progress = {});

}  // namespace game
}  // namespace cue_sim
