// What the referee's tests share: the 7 ft table and the carom table and their engines, balls at rest, a shot played
// by the engine and read, and a ruling on a shot's facts.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "cue_sim/game/referee.hpp"
#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/simulation.hpp"

namespace cue_sim
{
namespace game
{
namespace test
{
using physics::Ball;
using physics::CueStrike;
using physics::Engine;
using physics::PhysicsParams;
using physics::TableModel;
using physics::TableState;
using physics::Vec3;

inline std::shared_ptr<const TableModel> sevenFoot()
{
  static const auto table = std::make_shared<const TableModel>(TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137));
  return table;
}

inline const Engine<double>& engine()
{
  static const Engine<double> e(sevenFoot(), PhysicsParams<double>());
  return e;
}

inline std::shared_ptr<const TableModel> caromTable()
{
  static const auto table = std::make_shared<const TableModel>(TableModel::carom("carom", 2.84, 1.42));
  return table;
}

inline const Engine<double>& caromEngine()
{
  static const Engine<double> e(caromTable(), PhysicsParams<double>());
  return e;
}

/// The snooker table built in code: the WPBSA's playing area with the mouths of urdf/'s (its
/// knuckles all of the pool tables' 1 cm), played with 52.5 mm balls of 142 g.
inline std::shared_ptr<const TableModel> snookerTable()
{
  static const auto table = std::make_shared<const TableModel>(TableModel::pool("snooker", 3.569, 1.778, 0.089, 0.083));
  return table;
}

inline const Engine<double>& snookerEngine()
{
  static const Engine<double> e(snookerTable(), [] {
    PhysicsParams<double> p;
    p.ball_radius = 0.02625;
    p.ball_mass = 0.142;
    return p;
  }());
  return e;
}

/// The engine on the table `rules` is played on (rulesTable()).
inline const Engine<double>& engineFor(const std::string& rules)
{
  const std::string table = rulesTable(rules);
  return table == "carom" ? caromEngine() : table == "snooker" ? snookerEngine() : engine();
}

inline double R()
{
  return engine().params().ball_radius;
}

inline Ball<double> ball(int id, double x, double y)
{
  Ball<double> b;
  b.id = id;
  b.r = Vec3<double>(x, y, R());
  return b;
}

/// The pocket nearest to p.
inline int pocketNear(const Eigen::Vector2d& p)
{
  const auto& pockets = engine().table().pockets();
  int best = 0;
  for (std::size_t k = 1; k < pockets.size(); ++k)
    if ((pockets[k].centre - p).norm() < (pockets[static_cast<std::size_t>(best)].centre - p).norm())
      best = static_cast<int>(k);
  return best;
}

/// Plays `balls` (the cue ball among them) with a level centre-ball strike at `speed` towards
/// `target`, and reads the shot.
inline ShotFacts play(const std::vector<Ball<double>>& balls, const Eigen::Vector2d& target, double speed)
{
  TableState<double> s;
  s.balls = balls;
  const Eigen::Vector2d from = balls.front().r.head<2>();
  CueStrike<double> cue;
  cue.speed = speed;
  cue.phi = std::atan2(target.y() - from.y(), target.x() - from.x());
  engine().strike(s, 0, cue);
  return readShot(simulateToRest(engine(), s).events, &engine().table());
}

inline Ruling judge(const GameState& state, const std::vector<int>& on_table, const ShotFacts& facts,
                    bool push_out = false)
{
  return judgeShot(*makeRules(state.rules), state, on_table, Shot{facts, push_out});
}

}  // namespace test
}  // namespace game
}  // namespace cue_sim
