// Contacts that begin touching (issue 29): a ball that starts touching a cushion and then moves
// into it meets it at the start of that motion, whatever the coefficients; checked on every
// cushion of both pool tables, at both its ends, for balls a hair beyond the end or beside it,
// drifting into the cushion by their velocity or by their slip, sampled every millisecond
// between the events: no ball is ever inside a cushion by more than 1e-9 m.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "invariants.hpp"

using namespace cue_sim::physics;

namespace
{
/// How deep a ball may be in a cushion [m]: the soak's tolerance.
constexpr double kPenetrationTolerance = 1e-9;
/// Samples between events [s].
constexpr double kSamplePeriod = 1e-3;

struct Coefficients
{
  std::string name;
  PhysicsParams<double> params;
};

/// The defaults, and the regime the held-out campaign met the defect in: a fully inelastic
/// cushion, a ball larger than the default and stronger gravity.
std::vector<Coefficients> coefficientSets()
{
  std::vector<Coefficients> sets;
  sets.push_back({"defaults", PhysicsParams<double>()});
  PhysicsParams<double> stiff;
  stiff.e_cushion = 0;
  stiff.ball_radius = 0.037;
  stiff.cushion_height = 1.28 * stiff.ball_radius;
  stiff.gravity = 25;
  sets.push_back({"e_cushion 0, R 37 mm, g 25", stiff});
  return sets;
}

/// The ball `beyond` past the end of `seg` (negative: beside it), `hair` off its line, moving back
/// along it at `speed`, into it at `into` of that speed, with spin `w`.
Ball<double> atTheEnd(const CushionSegment& seg, bool far_end, double beyond, double hair, double speed, double into,
                      const Vec3<double>& w, double R)
{
  const Eigen::Vector2d along = far_end ? seg.direction : Eigen::Vector2d(-seg.direction);
  const Eigen::Vector2d end = far_end ? Eigen::Vector2d(seg.start + seg.length * seg.direction) : seg.start;
  const Eigen::Vector2d c = end + beyond * along + (R + hair) * seg.normal;
  const Eigen::Vector2d v = -speed * along - into * speed * seg.normal;
  Ball<double> b;
  b.id = 0;
  b.r = Vec3<double>(c.x(), c.y(), R);
  b.v = Vec3<double>(v.x(), v.y(), 0);
  b.w = w;
  settleMotion(b, R);
  return b;
}

/// No spin, spin about the cushion's line (the slip turns the ball into it or off it), and side spin.
std::vector<Vec3<double>> spins(const CushionSegment& seg)
{
  return {Vec3<double>::Zero(), 30.0 * Vec3<double>(seg.direction.x(), seg.direction.y(), 0),
          -30.0 * Vec3<double>(seg.direction.x(), seg.direction.y(), 0), Vec3<double>(0, 0, 40)};
}

/// Runs the table to rest on the kept search; the deepest a ball went into a cushion at any event
/// or sample, and where.
double deepestAlongTheWay(const Engine<double>& engine, TableState<double> start, std::string& where)
{
  Simulation<double> live(engine, std::move(start));
  double deepest = 0;
  double t = live.time();
  for (int events = 0; !live.atRest() && events < 2000; ++events)
  {
    const Event<double> e = live.step();
    if (!e.valid())
      break;
    for (; t < e.time; t += kSamplePeriod)
    {
      const double depth = deepestCushionPenetration(engine, live.state(), t);
      if (depth > deepest)
      {
        deepest = depth;
        where = "at t = " + std::to_string(t) + " s, before the " + eventKindName(e.kind);
      }
    }
    const double depth = deepestCushionPenetration(engine, live.state(), e.time);
    if (depth > deepest)
    {
      deepest = depth;
      where = std::string("at the ") + eventKindName(e.kind) + ", t = " + std::to_string(e.time) + " s";
    }
  }
  EXPECT_TRUE(live.atRest()) << where;
  return deepest;
}
}  // namespace

TEST(FrozenContacts, ABallAtACushionsEndDriftingBackAlongItMeetsItAsItComesBeside)
{
  const std::vector<std::shared_ptr<const TableModel>> tables = {
      std::make_shared<const TableModel>(TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137)),
      std::make_shared<const TableModel>(TableModel::pool("9ft", 2.54, 1.27, 0.118, 0.137))};
  int scenes = 0, failures = 0;
  for (const auto& table : tables)
    for (const Coefficients& set : coefficientSets())
      for (const std::string& cushion : cushionModelNames())
      {
        ModelChoice models;
        models.cushion = cushion;
        const Engine<double> engine(table, set.params, models);
        const double R = set.params.ball_radius;
        for (const auto& seg : table->segments())
          for (const bool far_end : {false, true})
            for (const double beyond : {1e-15, 1e-12, 1e-9, 1e-8, 1e-6, 1e-5, 1e-4, 1e-3, -1e-9})
              for (const double hair : {0.0, 1e-15, 1e-12})
                for (const double into : {0.0, 1e-9, 1e-6})
                  for (const Vec3<double>& w : spins(seg))
                  {
                    TableState<double> state;
                    state.balls.push_back(atTheEnd(seg, far_end, beyond, hair, 1.5, into, w, R));
                    if (!engine.whyInvalid(state).empty())
                      continue;  // in the jaw's circle: not a place a ball can be
                    ++scenes;
                    std::string where;
                    const double deepest = deepestAlongTheWay(engine, state, where);
                    if (deepest > kPenetrationTolerance && ++failures <= 5)
                      ADD_FAILURE() << table->name() << ", " << set.name << ", " << cushion << ": "
                                    << (far_end ? "far" : "near") << " end, " << beyond << " m beyond, hair " << hair
                                    << ", into " << into << ", w (" << w.transpose() << "): " << deepest
                                    << " m inside a cushion " << where;
                  }
      }
  EXPECT_EQ(failures, 0) << "of " << scenes << " scenes";
  EXPECT_GT(scenes, 5000);
}
