// One campaign shot run three ways, with the invariants checked at every event.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "cue_sim/evaluation/soak.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/scan.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "shot_ending.hpp"

namespace cue_sim
{
namespace evaluation
{
namespace
{
using physics::Ball;
using physics::Engine;
using physics::Event;
using physics::TableState;

/// How far a ball may be inside another, a cushion, a jaw or a pocket [m], and how much of the
/// kinetic energy rounding may add at an event: 1e-12 of it, and for each ball what a change of
/// its speed or its surface's speed by zeroSpeed (1.4e-14 m/s, below which the engine takes a
/// speed or a slip for zero and snaps it) makes, m zeroSpeed (|v| + R |w| + zeroSpeed) for each.
/// At a metre a second that is 5e-15 of the energy; it matters only for balls a thousand times
/// slower.
constexpr double kOverlapTolerance = 1e-9;
constexpr double kEnergyTolerance = 1e-12;

/// The invariants of the balls at one instant, and the energy since the last look: kinetic, and
/// the potential of a ball in the air, m g (z - R) (a falling ball gains speed, not energy).
class InvariantCheck
{
public:
  explicit InvariantCheck(const Engine<double>& engine) : engine_(engine) {}

  /// Looks at every ball at time t (the state's last event or later); records the first
  /// violation of each kind.
  void look(const TableState<double>& state, double t, const char* when, std::vector<Violation>& found)
  {
    balls_.clear();
    for (std::size_t i = 0; i < state.balls.size(); ++i)
      balls_.push_back(engine_.ballAt(state, i, t));
    const double energy = engine_.energyAt(state, t);
    for (const Ball<double>& b : balls_)
      if (!physics::isFinite(b.r) || !physics::isFinite(b.v) || !physics::isFinite(b.w))
        note(found, "nan", describe(when, t) + ": ball " + std::to_string(b.id) + " is not finite");
    const double zero = physics::zeroSpeed<double>(), R = engine_.params().ball_radius;
    double snapped = 0;
    for (const Ball<double>& b : balls_)
      snapped += 2 * engine_.params().ball_mass * zero * (b.v.norm() + R * b.w.norm() + zero);
    if (energy > last_energy_ * (1 + kEnergyTolerance) + snapped)
    {
      std::ostringstream why;
      why.precision(17);
      why << describe(when, t) << ": energy grew from " << last_energy_ << " J to " << energy << " J";
      note(found, "energy_gain", why.str());
    }
    last_energy_ = energy;
    lookForOverlaps(when, t, found);
    for (const Ball<double>& b : balls_)
      if (b.airborne() && b.r.z() < R - kOverlapTolerance)
        note(found, "below_slate", describe(when, t) + ": ball " + std::to_string(b.id) + " is below the slate");
    for (const Ball<double>& b : balls_)
      if (b.inPlay() && b.airborne())
      {
        const std::string where =
            engine_.table().whyInTheWalls(b.r, R, engine_.params().cushion_height, kOverlapTolerance);
        if (!where.empty())
          note(found, "off_table", describe(when, t) + ": ball " + std::to_string(b.id) + " " + where);
      }
    for (const Ball<double>& b : balls_)
      if (b.inPlay() && !b.airborne())  // a ball in the air may fly over a cushion or a pocket
      {
        const std::string where = engine_.table().whyNotPlaceable(b.r.head<2>(), R, kOverlapTolerance);
        if (!where.empty())
          note(found, "off_table", describe(when, t) + ": ball " + std::to_string(b.id) + ": " + where);
      }
  }

private:
  static std::string describe(const char* when, double t)
  {
    std::ostringstream out;
    out.precision(17);
    out << when << " t = " << t << " s";
    return out.str();
  }
  static void note(std::vector<Violation>& found, const std::string& kind, const std::string& detail)
  {
    for (const Violation& v : found)
      if (v.kind == kind)
        return;
    found.push_back({kind, detail});
  }
  /// Every pair closer than 2R: the balls in play sorted along x, each compared with those
  /// within 2R of it along x.
  void lookForOverlaps(const char* when, double t, std::vector<Violation>& found)
  {
    const double reach = 2 * engine_.params().ball_radius - kOverlapTolerance;
    order_.clear();
    for (std::size_t i = 0; i < balls_.size(); ++i)
      if (balls_[i].inPlay())
        order_.push_back(static_cast<int>(i));
    std::sort(order_.begin(), order_.end(), [&](int a, int b) { return balls_[a].r.x() < balls_[b].r.x(); });
    for (std::size_t m = 0; m < order_.size(); ++m)
      for (std::size_t l = m + 1; l < order_.size() && balls_[order_[l]].r.x() - balls_[order_[m]].r.x() < reach; ++l)
      {
        const Ball<double>& a = balls_[order_[m]];
        const Ball<double>& b = balls_[order_[l]];
        const double d = (a.r - b.r).norm();  // in space: a ball in the air passes over another
        if (d < reach)
        {
          std::ostringstream why;
          why.precision(17);
          why << describe(when, t) << ": balls " << a.id << " and " << b.id << " overlap by "
              << 2 * engine_.params().ball_radius - d << " m";
          note(found, "overlap", why.str());
        }
      }
  }

  const Engine<double>& engine_;
  std::vector<Ball<double>> balls_;
  std::vector<int> order_;
  double last_energy_ = INFINITY;
};

bool sameEvent(const Event<double>& a, const Event<double>& b)
{
  return a.time == b.time && a.kind == b.kind && a.ball == b.ball && a.other == b.other && a.obstacle == b.obstacle;
}

bool sameBall(const Ball<double>& a, const Ball<double>& b)
{
  return a.id == b.id && a.motion == b.motion && a.time == b.time && a.r == b.r && a.v == b.v && a.w == b.w &&
         a.pocket == b.pocket;
}

/// Empty if the events and final balls are those of the first run, bit for bit; else the first
/// difference. A shot stopped by its time limit is compared event by event only: the first run
/// may have stopped between events of the same instant.
std::string difference(const std::vector<Event<double>>& events, const TableState<double>& state,
                       const std::vector<Event<double>>& reference, const TableState<double>& reference_state,
                       bool at_rest)
{
  std::ostringstream why;
  why.precision(17);
  const std::size_t common = std::min(events.size(), reference.size());
  for (std::size_t i = 0; i < common; ++i)
    if (!sameEvent(events[i], reference[i]))
    {
      why << "event " << i << ": " << physics::eventKindName(events[i].kind) << " of ball " << events[i].ball
          << " at t = " << events[i].time << " s, where the first run had " << physics::eventKindName(reference[i].kind)
          << " of ball " << reference[i].ball << " at t = " << reference[i].time << " s";
      return why.str();
    }
  if (!at_rest)
    return {};
  if (events.size() != reference.size())
  {
    why << events.size() << " events, where the first run had " << reference.size();
    return why.str();
  }
  for (std::size_t i = 0; i < state.balls.size(); ++i)
    if (!sameBall(state.balls[i], reference_state.balls[i]))
    {
      why << "ball " << state.balls[i].id << " ends elsewhere: (" << state.balls[i].r.x() << ", "
          << state.balls[i].r.y() << "), where the first run left it at (" << reference_state.balls[i].r.x() << ", "
          << reference_state.balls[i].r.y() << ")";
      return why.str();
    }
  return {};
}

/// The same shot advanced in uneven steps (from a millisecond to a third of a second, in a
/// fixed pattern), and continued by a copy of the simulation half way: the events up to `last` (and,
/// if the first run came to rest, the steps after them).
void runStepped(const Engine<double>& engine, const TableState<double>& struck, double last, bool at_rest,
                std::vector<Event<double>>& events, TableState<double>& state)
{
  physics::Simulation<double> simulation(engine, struck);
  double t = struck.time;
  for (int k = 0; t < last && !simulation.atRest(); ++k)
  {
    t = std::min(last, t + 1e-3 * std::pow(1.7, k % 12));
    simulation.advance(t, &events);
    if (k == 7)
      simulation = physics::Simulation<double>(simulation);  // a copy finds its search afresh
  }
  simulation.advance(last, &events);
  // The steps of a group that comes to rest after the last event (an event found instead is one
  // the first run did not have).
  if (at_rest)
  {
    const Event<double> e = simulation.step();
    if (e.valid())
      events.push_back(e);
  }
  state = simulation.state();
}

/// The same shot by the full scan of every ball and pair, for as many events as the first run had
/// (and, if that came to rest, the steps after them).
void runScanned(const Engine<double>& engine, const TableState<double>& struck, std::size_t count, bool at_rest,
                std::vector<Event<double>>& events, TableState<double>& state)
{
  state = struck;
  while (events.size() < count)
  {
    const Event<double> e = scanStep(engine, state);
    if (!e.valid())
      break;
    events.push_back(e);
  }
  // The steps of a group that comes to rest after the last event (an event found instead is one
  // the first run did not have).
  if (!at_rest)
    return;
  const Event<double> e = scanStep(engine, state);
  if (e.valid())
    events.push_back(e);
}
}  // namespace

SceneCheck checkScene(const Scene& scene, bool full_scan)
{
  SceneCheck check;
  try
  {
    physics::EngineLimits limits;
    limits.max_shot_time = SoakLimits::max_shot_time;
    limits.max_events = SoakLimits::max_events;
    const Engine<double> engine(scene.table, scene.params, scene.models, limits);
    std::string why = engine.whyInvalid(scene.state);
    if (why.empty() && scene.shot)
      why = engine.whyNotStrikable(scene.state, scene.shot->ball, scene.shot->strike);
    if (!why.empty())
    {
      check.violations.push_back({"invalid_start", why});
      return check;
    }
    physics::Simulation<double> simulation(engine, scene.state);
    if (scene.shot)
      simulation.strike(scene.shot->ball, scene.shot->strike);
    const TableState<double> struck = simulation.state();

    // 1. Event by event, every invariant after every event.
    InvariantCheck invariants(engine);
    invariants.look(simulation.state(), simulation.time(), "at the start,", check.violations);
    std::vector<Event<double>> events;
    const double end = struck.time + stoppingTime(struck, scene.params);
    try
    {
      while (!simulation.atRest())
      {
        const Event<double> e = simulation.step(end);
        if (!e.valid())
          break;
        events.push_back(e);
        invariants.look(simulation.state(), e.time, physics::eventKindName(e.kind), check.violations);
      }
    }
    catch (const physics::EventLimitError& e)
    {
      // A shot that cannot end by physics may meet the event limit before its stopping time (a
      // frictionless cloth's balls meeting the cushions for 1e5 s); one whose last events were
      // a storm at one instant, or that could have ended, broke the limit.
      check.events = static_cast<long>(events.size());
      std::vector<double> times;
      times.reserve(events.size());
      for (const Event<double>& event : events)
        times.push_back(event.time);
      check.endless = endlessByPhysics(simulation.state(), scene.params);
      if (check.endless.empty() || endsInAStorm(times))
      {
        check.endless.clear();
        check.violations.push_back({"event_limit", e.what()});
      }
      else
        check.endless += " (the event limit came first, at t = " + std::to_string(simulation.time()) + " s)";
      return check;
    }
    check.events = static_cast<long>(events.size());
    check.at_rest = simulation.atRest();
    // Still moving when every ball must have stopped: a ball whose coefficients never stop it, or a
    // shot that does not end.
    if (!check.at_rest)
    {
      check.endless = endlessByPhysics(simulation.state(), scene.params);
      if (check.endless.empty())
      {
        std::ostringstream why;
        why << "still moving at t = " << end << " s, by when every ball must have stopped";
        check.violations.push_back({"still_moving", why.str()});
      }
    }
    // A shot ends in a state the engine, and so `simulate`, accepts as a scene.
    if (check.at_rest)
    {
      const std::string refused = engine.whyInvalid(simulation.state());
      if (!refused.empty())
        check.violations.push_back({"invalid_end", "the balls at rest are refused as a scene: " + refused});
    }
    const double last = events.empty() ? struck.time : events.back().time;

    // 2. In steps, with a copy half way.
    std::vector<Event<double>> stepped_events;
    TableState<double> stepped;
    runStepped(engine, struck, last, check.at_rest, stepped_events, stepped);
    why = difference(stepped_events, stepped, events, simulation.state(), check.at_rest);
    if (!why.empty())
      check.violations.push_back({"not_repeatable", "advanced in steps: " + why});

    // 3. The full scan.
    if (full_scan)
    {
      std::vector<Event<double>> scanned_events;
      TableState<double> scanned;
      runScanned(engine, struck, events.size(), check.at_rest, scanned_events, scanned);
      why = difference(scanned_events, scanned, events, simulation.state(), check.at_rest);
      if (!why.empty())
        check.violations.push_back({"scan_mismatch", "the full scan: " + why});
      check.scanned = true;
    }
  }
  catch (const std::exception& e)
  {
    check.violations.push_back({"error", e.what()});
  }
  return check;
}

}  // namespace evaluation
}  // namespace cue_sim
