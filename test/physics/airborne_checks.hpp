// What the tests of balls off the cloth share: tables, balls in the air, and a shot run event by
// event with every invariant checked, or by the full scan against the kept search.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/scan.hpp"
#include "cue_sim/physics/simulation.hpp"

namespace cue_sim
{
namespace physics
{
namespace testing
{
inline std::shared_ptr<const TableModel> sevenFoot()
{
  return std::make_shared<const TableModel>(TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137));
}

template <typename S = double>
Ball<S> inTheAir(int id, S x, S y, S height, const Vec3<S>& v = Vec3<S>::Zero(), const Vec3<S>& w = Vec3<S>::Zero())
{
  const PhysicsParams<S> p;
  Ball<S> b;
  b.id = id;
  b.r = Vec3<S>(x, y, p.ball_radius + height);
  b.v = v;
  b.w = w;
  settleMotion(b, p.ball_radius);
  return b;
}

/// The shot run event by event with a full scan, every invariant checked at each event and at
/// `samples` times between: returns the events. A ball in sustained contact moves by pieces that its
/// group's steps (taken silently by the scan before the next event) renew: the samples stop at the
/// first piece's end, and its energy counts as at its piece's start (Engine::energyAt), so the energy is
/// compared from one processed state to the next.
inline std::vector<Event<double>> runChecked(const Engine<double>& engine, TableState<double> s, int samples = 8)
{
  const PhysicsParams<double>& p = engine.params();
  const double R = p.ball_radius;
  const auto energy = [&](double t) { return engine.energyAt(s, t); };
  const auto check = [&](double t) {
    for (std::size_t i = 0; i < s.balls.size(); ++i)
    {
      if (!s.balls[i].inPlay())
        continue;
      const Ball<double> a = engine.ballAt(s, i, t);
      EXPECT_TRUE(isFinite(a.r) && isFinite(a.v) && isFinite(a.w)) << "ball " << a.id << " at " << t;
      EXPECT_GE(a.r.z(), R - 1e-12) << "ball " << a.id << " below the slate at t = " << t;
      if (a.airborne())  // between events too: a wall met late is a ball inside it for a while
        EXPECT_EQ(engine.table().whyInTheWalls(a.r, R, p.cushion_height), "") << "ball " << a.id << " at t = " << t;
      for (std::size_t j = i + 1; j < s.balls.size(); ++j)
      {
        if (s.balls[j].inPlay())
        {
          EXPECT_GE((a.r - engine.ballAt(s, j, t).r).norm(), 2 * R - 1e-9)
              << "balls " << a.id << " and " << s.balls[j].id << " overlap at t = " << t;
        }
      }
    }
  };
  std::vector<Event<double>> events;
  double last_time = s.time, last_energy = energy(s.time);
  for (int n = 0; n < 20000; ++n)
  {
    const Event<double> next = scanNextEvent(engine, s);
    if (!next.valid())
      break;
    double horizon = next.time;
    for (const Ball<double>& b : s.balls)
      if (b.supported())
        horizon = std::min(horizon, b.piece.until);
    for (int k = 1; k < samples; ++k)
    {
      const double t = last_time + (horizon - last_time) * k / samples;
      check(t);
      const double e = energy(t);
      EXPECT_LE(e, last_energy * (1 + 1e-12) + 1e-15) << "energy gained at t = " << t;
      last_energy = std::min(last_energy, e);
    }
    events.push_back(scanStep(engine, s));
    const double after = energy(next.time);
    EXPECT_LE(after, last_energy * (1 + 1e-12) + 1e-15)
        << eventKindName(next.kind) << " of ball " << next.ball << " gained energy at t = " << next.time;
    check(next.time);
    // Nowhere a ball on the table may not be (inside a cushion, under a rail), ever.
    EXPECT_EQ(engine.whyInvalid(s), "") << "after " << eventKindName(next.kind) << " at t = " << next.time;
    last_time = next.time;
    last_energy = after;
  }
  return events;
}

/// The shot run by a full scan, event by event, and by the kept search: the same events bit for
/// bit (kind, time, ball), checked; returns the scan's.
inline std::vector<Event<double>> keptSearchAgreesWithScan(const Engine<double>& engine, const TableState<double>& s)
{
  TableState<double> scanned = s;
  std::vector<Event<double>> by_scan;
  for (int n = 0; n < 5000; ++n)
  {
    const Event<double> e = scanStep(engine, scanned);
    if (!e.valid())
      break;
    by_scan.push_back(e);
  }
  TableState<double> kept = s;
  const ShotResult<double> run = simulateToRest(engine, kept);
  EXPECT_EQ(run.events.size(), by_scan.size());
  for (std::size_t i = 0; i < std::min(by_scan.size(), run.events.size()); ++i)
  {
    EXPECT_EQ(run.events[i].kind, by_scan[i].kind) << "event " << i;
    EXPECT_EQ(run.events[i].time, by_scan[i].time) << "event " << i;
    EXPECT_EQ(run.events[i].ball, by_scan[i].ball) << "event " << i;
  }
  return by_scan;
}

inline int countKind(const std::vector<Event<double>>& events, EventKind kind)
{
  int n = 0;
  for (const auto& e : events)
    n += e.kind == kind;
  return n;
}
}  // namespace testing
}  // namespace physics
}  // namespace cue_sim
