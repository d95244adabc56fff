// Invariants every event must keep, checked event by event (shared by the engine tests).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/scan.hpp"

namespace cue_sim
{
namespace physics
{
inline double totalEnergy(const Engine<double>& engine, const TableState<double>& s, double t)
{
  double e = 0;
  for (std::size_t i = 0; i < s.balls.size(); ++i)
    e += kineticEnergy(engine.ballAt(s, i, t), engine.params());
  return e;
}

inline double smallestGap(const Engine<double>& engine, const TableState<double>& s, double t)
{
  double gap = INFINITY;
  for (std::size_t i = 0; i < s.balls.size(); ++i)
    for (std::size_t j = i + 1; j < s.balls.size(); ++j)
      if (s.balls[i].inPlay() && s.balls[j].inPlay())
        gap = std::min(gap,
                       (engine.ballAt(s, i, t).r - engine.ballAt(s, j, t).r).norm() - 2 * engine.params().ball_radius);
  return gap;
}

/// Smallest gap between any ball in play and any straight or circular cushion at time t [m]:
/// negative inside a cushion, zero touching.
inline double smallestCushionGap(const Engine<double>& engine, const TableState<double>& s, double t)
{
  const double R = engine.params().ball_radius;
  double smallest = INFINITY;
  for (std::size_t i = 0; i < s.balls.size(); ++i)
  {
    if (!s.balls[i].inPlay())
      continue;
    const Eigen::Vector2d c = engine.ballAt(s, i, t).r.head<2>();
    for (const auto& seg : engine.table().segments())
    {
      const double along = (c - seg.start).dot(seg.direction);
      const double gap = (c - seg.start).dot(seg.normal) - R;
      if (along >= 0 && along <= seg.length && gap > -R)
        smallest = std::min(smallest, gap);
    }
    for (const auto& circle : engine.table().circles())
      smallest = std::min(smallest, (c - circle.centre).norm() - R - circle.radius);
  }
  return smallest;
}

/// Deepest penetration of any ball into any straight or circular cushion at time t [m].
inline double deepestCushionPenetration(const Engine<double>& engine, const TableState<double>& s, double t)
{
  return std::max(0.0, -smallestCushionGap(engine, s, t));
}

/// Runs a shot event by event and checks, at every event: momentum conserved at ball-ball
/// events, kinetic energy never gained, no two balls overlapping, nothing NaN. Returns the
/// number of events.
inline int checkInvariantsEventByEvent(const Engine<double>& engine, TableState<double>& s, int max_events = 5000)
{
  const double m = engine.params().ball_mass;
  int count = 0;
  for (;; ++count)
  {
    const Event<double> ev = scanNextEvent(engine, s);
    if (!ev.valid())
      break;
    EXPECT_LT(count, max_events) << "runaway events";
    if (count >= max_events)
      break;
    const double energy_before = totalEnergy(engine, s, ev.time);
    // A ball-ball event may be a simultaneous impact of a touching group: all balls' momentum.
    const auto momentum = [&] {
      Vec3<double> total = Vec3<double>::Zero();
      for (std::size_t i = 0; i < s.balls.size(); ++i)
        total += m * engine.ballAt(s, i, ev.time).v;
      return total;
    };
    const Vec3<double> momentum_before = momentum();
    std::vector<Vec3<double>> velocities_before;
    for (std::size_t i = 0; i < s.balls.size(); ++i)
      velocities_before.push_back(engine.ballAt(s, i, ev.time).v);
    const Event<double> done = scanStep(engine, s);
    EXPECT_EQ(done.time, ev.time);
    const double energy_after = totalEnergy(engine, s, ev.time);
    EXPECT_LE(energy_after, energy_before * (1 + 1e-12) + 1e-15) << eventKindName(ev.kind) << " at " << ev.time;
    // ... unless a cushion took part, pinning a ball of the group.
    // A model with the cloth's friction in the impact (mathavan2014) loses to it at most mu_slide
    // times the balls' vertical friction, itself at most mu_b times the impulses exchanged
    // (bounded here by twice the momentum each ball changed by).
    if (ev.kind == EventKind::BallBall && smallestCushionGap(engine, s, ev.time) > 1e-12)
    {
      double cloth = 0;
      if (engine.models().ball_ball == "mathavan2014")
      {
        const PhysicsParams<double>& p = engine.params();
        for (std::size_t i = 0; i < s.balls.size(); ++i)
          cloth += 2 * p.mu_slide * (p.mu_ball_a + p.mu_ball_b) * m *
                   (engine.ballAt(s, i, ev.time).v - velocities_before[i]).norm();
      }
      EXPECT_LE((momentum() - momentum_before).norm(), cloth + 1e-12 * (1 + momentum_before.norm()));
    }
    EXPECT_GT(smallestGap(engine, s, ev.time), -1e-9) << "overlap at t = " << ev.time;
    EXPECT_LT(deepestCushionPenetration(engine, s, ev.time), 1e-9) << "inside a cushion at t = " << ev.time;
    for (const auto& b : s.balls)
      EXPECT_TRUE(isFinite(b.r) && isFinite(b.v) && isFinite(b.w)) << "ball " << b.id;
  }
  return count;
}

}  // namespace physics
}  // namespace cue_sim
