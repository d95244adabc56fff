// Results must not change when the engine is made faster (issue 5). The final states of many
// shots were recorded once in test/data/golden_shots.txt; every optimisation must reproduce
// them bit for bit, and the event queue of advance() must agree with the full scan of step().
//
// The file is rewritten only for a deliberate change of the physics, and that change is then
// named in the commit:
//   CUE_SIM_WRITE_GOLDEN=1 devel/lib/cue_sim/physics_tests --gtest_filter='Golden.*'
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/physics/scan.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "scattered_scene.hpp"

using namespace cue_sim::physics;

namespace
{
const std::string kGoldenFile = std::string(CUE_SIM_SOURCE_DIR) + "/test/data/golden_shots.txt";

struct GoldenShot
{
  std::string name;
  std::shared_ptr<const Engine<double>> engine;
  TableState<double> state;  // struck, ready to run
};

/// 150 shots: breaks of both racks at random speeds, angles and English on randomly uneven
/// racks, single shots among resting balls, carom shots, in both ball-ball models.
std::vector<GoldenShot> goldenShots()
{
  const auto pool = std::make_shared<const TableModel>(TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137));
  const auto carom = std::make_shared<const TableModel>(TableModel::carom("carom", 2.84, 1.42));
  const PhysicsParams<double> p;
  const auto frictional = std::make_shared<const Engine<double>>(pool, p);
  const auto frictionless = std::make_shared<const Engine<double>>(pool, p, ModelChoice{"frictionless", "simple"});
  const auto on_carom = std::make_shared<const Engine<double>>(carom, p);
  std::mt19937 random(5);  // fully specified: the same shots everywhere
  const auto unit = [&] { return static_cast<double>(random()) / 4294967296.0; };
  std::vector<GoldenShot> shots;
  for (int k = 0; k < 150; ++k)
  {
    GoldenShot shot;
    const int kind = k % 5;
    shot.engine = kind == 4 ? on_carom : (k % 3 == 2 ? frictionless : frictional);
    CueStrike<double> cue;
    cue.speed = 0.5 + 7.5 * unit();
    cue.phi = 0.1 * (unit() - 0.5);
    cue.theta = 0.2 * unit();
    cue.a = 0.6 * (unit() - 0.5);
    cue.b = 0.6 * (unit() - 0.5);
    if (cue.a * cue.a + cue.b * cue.b > 0.25)
      cue.a = cue.b = 0;
    RackOptions rack;
    rack.gap = 2e-4;
    rack.jitter = 1e-4;
    rack.seed = static_cast<unsigned>(k);
    if (kind <= 1)
      shot.state = rackLayout<double>(kind == 0 ? "eight" : "nine", shot.engine->table(), p.ball_radius, rack);
    else
    {
      // The cue ball and a few resting balls scattered at random, clear of each other.
      shot.state = rackLayout<double>("empty", shot.engine->table(), p.ball_radius);
      const double hx = shot.engine->table().clothLength() / 2 - 0.1, hy = shot.engine->table().clothWidth() / 2 - 0.1;
      for (int id = 1; shot.state.balls.size() < 6; ++id)
      {
        Ball<double> b;
        b.id = id;
        b.r = Vec3<double>((2 * unit() - 1) * hx, (2 * unit() - 1) * hy, p.ball_radius);
        shot.state.balls.push_back(b);
        if (!shot.engine->whyInvalid(shot.state).empty() || (b.r - shot.state.balls[0].r).norm() < 0.2)
          shot.state.balls.pop_back();
      }
      cue.phi = 2 * M_PI * unit();
    }
    shot.engine->strike(shot.state, 0, cue);
    shot.name = "shot " + std::to_string(k);
    shots.push_back(shot);
  }
  return shots;
}

/// One line per shot: events, the final time, and every ball's id, motion, pocket and centre,
/// each double written exactly (%a, hexadecimal).
std::string describe(const TableState<double>& s, std::size_t events)
{
  std::ostringstream out;
  char number[64];
  std::snprintf(number, sizeof number, "%a", s.time);
  out << events << ' ' << number;
  for (const auto& b : s.balls)
  {
    out << " | " << b.id << ' ' << static_cast<int>(b.motion) << ' ' << b.pocket;
    for (double x : {b.r.x(), b.r.y()})
    {
      std::snprintf(number, sizeof number, "%a", x);
      out << ' ' << number;
    }
  }
  return out.str();
}
}  // namespace

TEST(Golden, FinalStatesAreUnchanged)
{
  std::vector<std::string> lines;
  for (GoldenShot& shot : goldenShots())
  {
    const ShotResult<double> result = simulateToRest(*shot.engine, shot.state);
    ASSERT_TRUE(result.at_rest) << shot.name;
    lines.push_back(describe(shot.state, result.events.size()));
  }
  if (std::getenv("CUE_SIM_WRITE_GOLDEN"))
  {
    std::ofstream out(kGoldenFile);
    for (const auto& line : lines)
      out << line << '\n';
    GTEST_SKIP() << "wrote " << kGoldenFile;
  }
  std::ifstream in(kGoldenFile);
  ASSERT_TRUE(in.good()) << "cannot read " << kGoldenFile;
  std::string line;
  std::size_t k = 0;
  for (; std::getline(in, line); ++k)
  {
    ASSERT_LT(k, lines.size()) << "the golden file has more shots than the test";
    EXPECT_EQ(lines[k], line) << "shot " << k << " differs from the recorded result";
  }
  EXPECT_EQ(k, lines.size());
}

TEST(Golden, EventQueueAgreesWithFullScan)
{
  // advance() keeps candidates between events; step() scans every ball and pair afresh. Both
  // must process the same events and end in the same state, bit for bit.
  for (GoldenShot& shot : goldenShots())
  {
    TableState<double> scanned = shot.state;
    std::vector<Event<double>> scan_events;
    for (Event<double> e = scanStep(*shot.engine, scanned); e.valid(); e = scanStep(*shot.engine, scanned))
      scan_events.push_back(e);
    const ShotResult<double> queued = simulateToRest(*shot.engine, shot.state);
    ASSERT_EQ(queued.events.size(), scan_events.size()) << shot.name;
    for (std::size_t i = 0; i < scan_events.size(); ++i)
    {
      EXPECT_EQ(queued.events[i].time, scan_events[i].time) << shot.name << ", event " << i;
      EXPECT_EQ(queued.events[i].kind, scan_events[i].kind) << shot.name << ", event " << i;
      EXPECT_EQ(queued.events[i].ball, scan_events[i].ball) << shot.name << ", event " << i;
      EXPECT_EQ(queued.events[i].other, scan_events[i].other) << shot.name << ", event " << i;
    }
    EXPECT_EQ(describe(shot.state, 0), describe(scanned, 0)) << shot.name;
    if (HasFailure())
      break;
  }
}

TEST(Golden, GridAgreesWithFullScan)
{
  // Beyond 32 balls advance() keeps a grid and draws each ball's box a stretch at a time; the
  // events must still be those of the full scan, bit for bit. Balls scattered at random on a
  // table scaled to their number, all sent off at once, as in the bench's scaling scenes.
  for (const int count : {40, 100})
  {
    const Engine<double> engine(scaledTable(count), PhysicsParams<double>());
    const TableState<double> start = scatteredScene(engine, count, static_cast<unsigned>(count));
    TableState<double> scanned = start, queued = start;
    std::vector<Event<double>> scan_events;
    for (Event<double> e = scanStep(engine, scanned); e.valid(); e = scanStep(engine, scanned))
      scan_events.push_back(e);
    const ShotResult<double> result = simulateToRest(engine, queued);
    ASSERT_GT(scan_events.size(), static_cast<std::size_t>(2 * count)) << count << " balls";
    ASSERT_EQ(result.events.size(), scan_events.size()) << count << " balls";
    for (std::size_t i = 0; i < scan_events.size(); ++i)
    {
      ASSERT_EQ(result.events[i].time, scan_events[i].time) << count << " balls, event " << i;
      ASSERT_EQ(result.events[i].ball, scan_events[i].ball) << count << " balls, event " << i;
      ASSERT_EQ(result.events[i].other, scan_events[i].other) << count << " balls, event " << i;
    }
    EXPECT_EQ(describe(queued, 0), describe(scanned, 0)) << count << " balls";
  }
}
