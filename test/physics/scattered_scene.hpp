// Balls scattered at random on a pool table scaled to their number, all sent off at once with
// random speeds and spins, as after a break (shared by the event search tests).
#pragma once

#include <cmath>
#include <memory>
#include <random>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/motion.hpp"

namespace cue_sim
{
namespace physics
{
/// A 7-ft table scaled so that `count` balls have the room 16 have on it.
inline std::shared_ptr<const TableModel> scaledTable(int count)
{
  const double scale = std::sqrt(std::max(count, 16) / 16.0);
  return std::make_shared<const TableModel>(TableModel::pool("scaled", 1.9812 * scale, 0.9906 * scale, 0.118, 0.137));
}

/// `count` balls clear of each other and of the cushions, each sent off at 0.5 to 2 m/s with
/// spins up to 20 rad/s about every axis (from `seed`).
inline TableState<double> scatteredScene(const Engine<double>& engine, int count, unsigned seed)
{
  const double R = engine.params().ball_radius;
  std::mt19937 random(seed);
  const auto unit = [&] { return static_cast<double>(random()) / 4294967296.0; };
  const TableModel& table = engine.table();
  TableState<double> state;
  while (static_cast<int>(state.balls.size()) < count)
  {
    Ball<double> b;
    b.id = static_cast<int>(state.balls.size());
    b.r = Vec3<double>((2 * unit() - 1) * (table.clothLength() / 2 - 2 * R),
                       (2 * unit() - 1) * (table.clothWidth() / 2 - 2 * R), R);
    if (engine.whyNotPlaceable(state, b).empty())
      state.balls.push_back(b);
  }
  for (auto& b : state.balls)
  {
    const double speed = 0.5 + 1.5 * unit(), heading = 2 * M_PI * unit();
    b.v = Vec3<double>(speed * std::cos(heading), speed * std::sin(heading), 0);
    b.w = Vec3<double>((unit() - 0.5) * 40, (unit() - 0.5) * 40, (unit() - 0.5) * 40);
    settleMotion(b, R);
  }
  return state;
}

/// Whether two balls are the same bit for bit.
inline bool sameBall(const Ball<double>& a, const Ball<double>& b)
{
  return a.id == b.id && a.motion == b.motion && a.time == b.time && a.r == b.r && a.v == b.v && a.w == b.w &&
         a.pocket == b.pocket;
}

/// Whether two events are the same bit for bit (what happened, to whom, when).
inline bool sameEvent(const Event<double>& a, const Event<double>& b)
{
  return a.time == b.time && a.kind == b.kind && a.ball == b.ball && a.other == b.other && a.obstacle == b.obstacle;
}

}  // namespace physics
}  // namespace cue_sim
