// A Simulation keeps its table and event search between calls (issue 15): advanced in any steps,
// copied half way, or edited, it must give bit for bit what one run gives, or what a fresh
// simulation of the edited table gives.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "cue_sim/physics/rack.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "scattered_scene.hpp"

using namespace cue_sim::physics;

namespace
{
struct ShotRun
{
  std::vector<Event<double>> events;
  TableState<double> state;
};

void expectSame(const ShotRun& got, const ShotRun& want, const std::string& what)
{
  ASSERT_EQ(got.events.size(), want.events.size()) << what;
  for (std::size_t i = 0; i < want.events.size(); ++i)
    ASSERT_TRUE(sameEvent(got.events[i], want.events[i]))
        << what << ", event " << i << ": " << eventKindName(got.events[i].kind) << " at " << got.events[i].time
        << ", want " << eventKindName(want.events[i].kind) << " at " << want.events[i].time;
  ASSERT_EQ(got.state.balls.size(), want.state.balls.size()) << what;
  for (std::size_t i = 0; i < want.state.balls.size(); ++i)
    EXPECT_TRUE(sameBall(got.state.balls[i], want.state.balls[i])) << what << ", ball " << want.state.balls[i].id;
}

/// A struck table and the engine it runs on.
struct Scene
{
  std::string name;
  std::shared_ptr<const Engine<double>> engine;
  TableState<double> start;
};

/// The 8-ball and 9-ball breaks (every pair looked at) and 80 scattered balls (the grid).
std::vector<Scene> scenes()
{
  const auto seven = std::make_shared<const TableModel>(TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137));
  const auto engine = std::make_shared<const Engine<double>>(seven, PhysicsParams<double>());
  std::vector<Scene> out;
  for (const std::string rack : {"eight", "nine"})
  {
    RackOptions options;
    options.gap = 2e-4;
    options.jitter = 1e-4;
    TableState<double> s = rackLayout<double>(rack, *seven, engine->params().ball_radius, options);
    CueStrike<double> cue;
    cue.speed = 7.0;
    cue.phi = 0.003;
    cue.b = 0.2;
    engine->strike(s, 0, cue);
    out.push_back({rack + "-ball break", engine, s});
  }
  const auto large = std::make_shared<const Engine<double>>(scaledTable(80), PhysicsParams<double>());
  out.push_back({"80 scattered balls", large, scatteredScene(*large, 80, 3)});
  return out;
}

ShotRun runToRest(const Scene& scene)
{
  Simulation<double> simulation(*scene.engine, scene.start);
  ShotRun run;
  const ShotResult<double> result = simulation.runToRest();
  EXPECT_TRUE(result.at_rest) << scene.name;
  run.events = result.events;
  run.state = simulation.state();
  return run;
}

/// Advances to each of `targets` in turn, copying the simulation where `copy_at` says, then on
/// until it rests.
ShotRun runInSteps(const Scene& scene, const std::vector<double>& targets, const std::vector<bool>& copy_at = {})
{
  Simulation<double> simulation(*scene.engine, scene.start);
  ShotRun run;
  double t = 0;
  for (std::size_t k = 0; k < targets.size(); ++k)
  {
    t = targets[k];
    simulation.advance(t, &run.events);
    if (k < copy_at.size() && copy_at[k])
      simulation = Simulation<double>(simulation);  // a copy finds its search afresh
  }
  while (!simulation.atRest())
    simulation.advance(t += 1.0, &run.events);
  run.state = simulation.state();
  return run;
}
}  // namespace

TEST(Simulation, AdvancingInAnyStepsGivesOneRunBitForBit)
{
  std::mt19937 random(15);
  const auto unit = [&] { return static_cast<double>(random()) / 4294967296.0; };
  for (const Scene& scene : scenes())
  {
    const ShotRun whole = runToRest(scene);
    ASSERT_GT(whole.events.size(), 50u) << scene.name;
    // Even steps, as the node's tick: 1 kHz and 100 Hz.
    for (const double period : {1e-3, 1e-2})
    {
      std::vector<double> targets;
      for (double t = period; t < whole.events.back().time + period; t += period)
        targets.push_back(t);
      expectSame(runInSteps(scene, targets), whole, scene.name + ", steps of " + std::to_string(period) + " s");
    }
    // Exactly on the event times (each twice), and back in time (which changes nothing).
    std::vector<double> on_events;
    for (const auto& e : whole.events)
      on_events.insert(on_events.end(), {e.time, e.time, e.time / 2});
    expectSame(runInSteps(scene, on_events), whole, scene.name + ", on the events' times");
    // Uneven steps from a microsecond to a second, copied now and then.
    std::vector<double> uneven;
    std::vector<bool> copies;
    for (double t = 0; t < whole.events.back().time;)
    {
      uneven.push_back(t += std::pow(10.0, -6 + 6 * unit()));
      copies.push_back(unit() < 0.1);
    }
    expectSame(runInSteps(scene, uneven, copies), whole, scene.name + ", uneven steps and copies");
    // One step past the end.
    expectSame(runInSteps(scene, {1e6}), whole, scene.name + ", one step");
  }
}

namespace
{
/// A place where a ball of the engine's fits in the state now, found on a lattice over the cloth.
Vec3<double> freePlace(const Simulation<double>& simulation)
{
  const Engine<double>& engine = simulation.engine();
  const double R = engine.params().ball_radius;
  const double hx = engine.table().clothLength() / 2 - 2 * R, hy = engine.table().clothWidth() / 2 - 2 * R;
  Ball<double> probe;
  probe.id = 1000;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 20; ++j)
    {
      probe.r = Vec3<double>(-hx + 2 * hx * (i + 0.5) / 40, -hy + 2 * hy * (j + 0.5) / 20, R);
      if (simulation.whyNotPlaceable(probe).empty())
        return probe.r;
    }
  ADD_FAILURE() << "no free place";
  return probe.r;
}

/// The edits a live table takes half way through a shot.
enum class Edit
{
  StrikeAMovingBall,
  PlaceANewBall,
  MoveABall,
  RemoveABall,
  RemoveTheLastBall,
};

void edit(Simulation<double>& simulation, Edit what)
{
  const TableState<double>& s = simulation.state();
  const double R = simulation.engine().params().ball_radius;
  int moving = -1;
  for (std::size_t i = 0; i < s.balls.size() && moving < 0; ++i)
    if (s.balls[i].translating())
      moving = static_cast<int>(i);
  ASSERT_GE(moving, 0);
  switch (what)
  {
    case Edit::StrikeAMovingBall: {
      CueStrike<double> cue;
      cue.speed = 3.0;
      cue.phi = 1.0;
      cue.a = 0.2;
      simulation.strike(s.balls[moving].id, cue);
      break;
    }
    case Edit::PlaceANewBall: {
      Ball<double> b;
      b.id = 1000;
      b.r = freePlace(simulation);
      b.v = Vec3<double>(1.5, -0.7, 0);
      b.w = Vec3<double>(0, 0, 30);
      simulation.place(b);
      break;
    }
    case Edit::MoveABall: {
      Ball<double> b = s.balls[moving];
      b.r = freePlace(simulation);
      b.v = Vec3<double>(-0.8, 0.4, 0);
      b.w = Vec3<double>(-0.4 / R, -0.8 / R, 0);  // rolling
      simulation.place(b);
      break;
    }
    case Edit::RemoveABall:
      simulation.remove(s.balls[moving].id);
      break;
    case Edit::RemoveTheLastBall:
      simulation.remove(s.balls.back().id);
      break;
  }
}
}  // namespace

TEST(Simulation, EditsGiveWhatAFreshSimulationOfTheEditedTableGives)
{
  for (const Scene& scene : scenes())
    for (const Edit what :
         {Edit::StrikeAMovingBall, Edit::PlaceANewBall, Edit::MoveABall, Edit::RemoveABall, Edit::RemoveTheLastBall})
    {
      const std::string name = scene.name + ", edit " + std::to_string(static_cast<int>(what));
      Simulation<double> live(*scene.engine, scene.start);
      live.advance(0.35);
      edit(live, what);
      ASSERT_EQ(scene.engine->whyInvalid(live.state()), "") << name;
      Simulation<double> fresh(*scene.engine, live.state());
      ShotRun kept, found;
      kept.events = live.runToRest().events;
      kept.state = live.state();
      found.events = fresh.runToRest().events;
      found.state = fresh.state();
      ASSERT_FALSE(found.events.empty()) << name;
      expectSame(kept, found, name + ", against a fresh simulation of the edited table");
    }
}

TEST(Simulation, RefusedEditsChangeNothing)
{
  const Scene scene = scenes().front();
  Simulation<double> live(*scene.engine, scene.start);
  live.advance(0.2);
  const TableState<double> before = live.state();
  const double R = scene.engine->params().ball_radius;
  Ball<double> on_top = before.balls[3];
  on_top.id = 99;
  on_top.r.x() += R;  // overlaps ball 3
  EXPECT_THROW(live.place(on_top), std::invalid_argument);
  Ball<double> behind_pocket = on_top;
  behind_pocket.r = Vec3<double>(0.12, 0.51, R);  // past the cushion line, beside the side pocket
  EXPECT_NE(live.whyNotPlaceable(behind_pocket).find("off the cloth"), std::string::npos)
      << live.whyNotPlaceable(behind_pocket);
  EXPECT_THROW(live.place(behind_pocket), std::invalid_argument);
  EXPECT_THROW(live.remove(42), std::invalid_argument);
  CueStrike<double> too_hard;
  too_hard.speed = 50;
  EXPECT_THROW(live.strike(0, too_hard), std::invalid_argument);
  ASSERT_EQ(live.state().balls.size(), before.balls.size());
  for (std::size_t i = 0; i < before.balls.size(); ++i)
    EXPECT_TRUE(sameBall(live.state().balls[i], before.balls[i]));
  // And the shot goes on as if nothing had been asked.
  Simulation<double> untouched(*scene.engine, scene.start);
  untouched.advance(0.2);
  const ShotResult<double> a = live.runToRest(), b = untouched.runToRest();
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i)
    EXPECT_TRUE(sameEvent(a.events[i], b.events[i])) << i;
}

TEST(Simulation, StepEndsWhereNothingWillEverHappen)
{
  // On a frictionless cloth a ball crawling at 1e-12 m/s meets nothing within the search's
  // horizon; its box is never drawn again and again (40 balls: the grid).
  PhysicsParams<double> p;
  p.mu_slide = p.mu_roll = p.mu_spin = 0;
  const Engine<double> engine(scaledTable(40), p);
  TableState<double> s = scatteredScene(engine, 40, 8);
  for (auto& b : s.balls)
  {
    b.v.setZero();
    b.w.setZero();
    settleMotion(b, p.ball_radius);
  }
  s.balls[5].v = Vec3<double>(1e-12, 0, 0);
  settleMotion(s.balls[5], p.ball_radius);
  Simulation<double> simulation(engine, s);
  EXPECT_FALSE(simulation.atRest());
  EXPECT_FALSE(simulation.step().valid());
  simulation.advance(1e6);
  EXPECT_FALSE(simulation.atRest());
}

TEST(Simulation, TheEventLimitStopsAShotAndAnEditStartsAnother)
{
  const Scene scene = scenes().front();
  EngineLimits limits;
  limits.max_events = 30;
  const Engine<double> limited(std::make_shared<const TableModel>(scene.engine->table()), scene.engine->params(),
                               scene.engine->models(), limits);
  const ShotRun whole = runToRest(scene);
  Simulation<double> simulation(limited, scene.start);
  std::vector<Event<double>> events;
  EXPECT_THROW(simulation.advance(10.0, &events), EventLimitError);
  ASSERT_EQ(events.size(), 30u);
  for (std::size_t i = 0; i < events.size(); ++i)
    EXPECT_TRUE(sameEvent(events[i], whole.events[i])) << i;
  EXPECT_THROW(simulation.advance(10.0), EventLimitError);  // still the same shot
  EXPECT_THROW(simulation.step(), EventLimitError);
  CueStrike<double> cue;
  cue.speed = 1.0;
  simulation.strike(0, cue);  // a new shot
  EXPECT_NO_THROW(simulation.step());
}
