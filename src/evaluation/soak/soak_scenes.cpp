// The campaign's random scenes: tables, models, coefficients across their accepted ranges, racks
// and placements that touch cushions, jaws and other balls, strikes over every speed, elevation and
// English, and tables where everything moves at once.
#include <algorithm>
#include <cmath>
#include <mutex>
#include <random>

#include "cue_sim/evaluation/soak.hpp"
#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"

namespace cue_sim
{
namespace evaluation
{
namespace
{
/// Draws of one scene: seeded from (seed, k) by SplitMix64, so that scenes do not depend on one
/// another or on the order they are made in.
class Draws
{
public:
  Draws(std::uint64_t seed, long k) : engine_(mix(mix(seed) ^ static_cast<std::uint64_t>(k))) {}

  double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }  ///< [0, 1)
  double uniform(double low, double high) { return low + (high - low) * unit(); }
  double logUniform(double low, double high) { return low * std::pow(high / low, unit()); }
  bool chance(double p) { return unit() < p; }
  int integer(int low, int high) { return low + static_cast<int>(unit() * (high - low + 1)); }
  template <typename T>
  const T& pick(const std::vector<T>& items)
  {
    return items[static_cast<std::size_t>(unit() * static_cast<double>(items.size()))];
  }

private:
  static std::uint64_t mix(std::uint64_t x)
  {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
  }
  std::mt19937_64 engine_;
};

/// The bundled tables, read once.
const std::map<std::string, std::shared_ptr<const physics::TableModel>>& bundledTables()
{
  static std::once_flag once;
  static std::map<std::string, std::shared_ptr<const physics::TableModel>> tables;
  std::call_once(once, [] {
    for (const std::string& name : tableNames())
      tables[name] = std::make_shared<const physics::TableModel>(tableFromUrdfFile(tableUrdfPath(name)));
  });
  return tables;
}

/// A coefficient across its range: its default half the time; else a bound (an eighth each) or
/// a value between them, uniform or log-uniform (so that small values are met as often as large).
double coefficient(Draws& draws, double low, double high, double default_value)
{
  if (draws.chance(0.5))
    return default_value;
  const double u = draws.unit();
  if (u < 0.125)
    return low;
  if (u < 0.25)
    return high;
  if (u < 0.6 || high <= 0)
    return draws.uniform(low, high);
  return draws.logUniform(std::max(low, high * 1e-4), high);
}

physics::PhysicsParams<double> drawParams(Draws& draws, const physics::TableModel& table)
{
  physics::PhysicsParams<double> p;
  const physics::PhysicsParams<double> defaults;
  for (const physics::ParamField& field : physics::physicsParamFields())
    if (!std::isnan(field.min))
      p.*field.member = coefficient(draws, field.min, field.max, defaults.*field.member);
  // A ball must fit on the table, and its nose height lies strictly between R and 2R.
  const double largest = std::min(1.0, 0.45 * std::min(table.clothLength(), table.clothWidth()));
  if (p.ball_radius > largest)
    p.ball_radius = draws.logUniform(1e-3, largest);
  const double share = draws.chance(0.5)   ? defaults.cushion_height / defaults.ball_radius - 1
                       : draws.chance(0.2) ? draws.pick(std::vector<double>{1e-9, 1e-6, 1 - 1e-6, 1 - 1e-9})
                                           : draws.uniform(0.0, 1.0);
  p.cushion_height = p.ball_radius * (1 + std::clamp(share, 1e-9, 1 - 1e-9));
  return p;
}

/// A place for one more ball: anywhere on the cloth or in a pocket's mouth, frozen to a cushion
/// (anywhere along it, or at one of its ends, a hair beyond or short of it), to a jaw, or to another
/// ball (exactly touching, or a hair off). Refused places are drawn again.
Eigen::Vector2d drawPlace(Draws& draws, const physics::TableModel& table, const physics::TableState<double>& state,
                          double R)
{
  const double hair = draws.pick(std::vector<double>{0.0, 0.0, 1e-12, 1e-9, 1e-6});
  const double angle = draws.uniform(-M_PI, M_PI);
  const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
  const double kind = draws.unit();
  if (kind < 0.15 && !table.segments().empty())
  {
    const auto& s = draws.pick(table.segments());
    double along = draws.unit() * s.length;
    if (draws.chance(0.3))  // at an end: where the cushion's line and its jaw meet
    {
      const double off = draws.logUniform(1e-15, 1e-3) * (draws.chance(0.7) ? 1.0 : -1.0);
      along = draws.chance(0.5) ? -off : s.length + off;
    }
    return s.start + along * s.direction + (R + hair) * s.normal;
  }
  if (kind < 0.25 && !table.circles().empty())
  {
    const auto& c = draws.pick(table.circles());
    return c.centre + (R + c.radius + hair) * direction;
  }
  if (kind < 0.45 && !state.balls.empty())
    return draws.pick(state.balls).r.head<2>() + (2 * R + hair) * direction;
  // The cloth and a ball's reach beyond it, so that the pockets' mouths are met too.
  const Eigen::Vector2d half(table.clothLength() / 2 + R, table.clothWidth() / 2 + R);
  return table.clothCentre() + Eigen::Vector2d(draws.uniform(-half.x(), half.x()), draws.uniform(-half.y(), half.y()));
}

/// `count` balls with ids from `first_id`, each where the engine lets it stand (as many as fit).
void placeBalls(Draws& draws, const physics::Engine<double>& engine, int count, int first_id,
                physics::TableState<double>& state)
{
  const double R = engine.params().ball_radius;
  for (int placed = 0, tries = 0; placed < count && tries < 60 * count; ++tries)
  {
    const physics::Ball<double> ball = sceneBall(first_id + placed, drawPlace(draws, engine.table(), state, R),
                                                 Eigen::Vector2d::Zero(), Eigen::Vector3d::Zero(), R);
    if (engine.whyNotPlaceable(state, ball).empty())
    {
      state.balls.push_back(ball);
      ++placed;
    }
  }
}

/// A rack (eight, nine or the cue ball alone, its gaps from frozen to loose), or balls placed one
/// by one: mostly a few, sometimes up to 200.
physics::TableState<double> drawBalls(Draws& draws, const physics::Engine<double>& engine)
{
  const double R = engine.params().ball_radius;
  physics::TableState<double> state;
  const double kind = draws.unit();
  if (kind < 0.35)
  {
    physics::RackOptions rack;
    rack.gap = draws.pick(std::vector<double>{0.0, 1e-9, 1e-5, 2e-4, 1e-3});
    rack.jitter = draws.chance(0.5) ? draws.uniform(0.0, rack.gap / 2) : 0.0;
    rack.seed = static_cast<unsigned>(draws.integer(0, 1 << 30));
    state = physics::rackLayout<double>(draws.pick(std::vector<std::string>{"eight", "nine", "empty"}), engine.table(),
                                        R, rack);
    if (engine.whyInvalid(state).empty())
    {
      if (draws.chance(0.3))
        placeBalls(draws, engine, draws.integer(1, 6), 16, state);
      return state;
    }
    state.balls.clear();  // the rack does not fit balls this large: placed instead
  }
  const int count = kind < 0.7 ? draws.integer(1, 16) : kind < 0.9 ? draws.integer(17, 64) : draws.integer(65, 200);
  placeBalls(draws, engine, count, 0, state);
  return state;
}

/// A strike anywhere in its ranges: speeds from a millimetre a second to the hardest break,
/// level to vertical, any English the tip allows (its edge included).
physics::CueStrike<double> drawStrike(Draws& draws)
{
  physics::CueStrike<double> s;
  s.speed = draws.chance(0.05) ? physics::CueLimits::max_speed : draws.logUniform(1e-3, physics::CueLimits::max_speed);
  s.phi = draws.uniform(-M_PI, M_PI);
  s.theta = draws.chance(0.5)    ? 0.0
            : draws.chance(0.05) ? physics::CueLimits::max_elevation
                                 : draws.uniform(0.0, physics::CueLimits::max_elevation);
  if (draws.chance(0.6))
  {
    const double offset =
        draws.chance(0.1) ? physics::CueLimits::max_offset : physics::CueLimits::max_offset * std::sqrt(draws.unit());
    const double angle = draws.uniform(-M_PI, M_PI);
    s.a = offset * std::cos(angle);
    s.b = offset * std::sin(angle);
    if (s.a * s.a + s.b * s.b > physics::CueLimits::max_offset * physics::CueLimits::max_offset)
      s.a = s.b = 0;  // rounding beyond the edge
  }
  return s;
}

/// Every ball, or some, sent off at once with any velocity and spin (as after a break).
void drawMotion(Draws& draws, double R, physics::TableState<double>& state)
{
  const double share = draws.uniform(0.1, 1.0);
  for (auto& b : state.balls)
    if (draws.chance(share))
    {
      const double speed = draws.logUniform(1e-4, 10.0), angle = draws.uniform(-M_PI, M_PI);
      const Eigen::Vector3d spin(draws.uniform(-1, 1), draws.uniform(-1, 1), draws.uniform(-1, 1));
      b = sceneBall(b.id, b.r.head<2>(), speed * Eigen::Vector2d(std::cos(angle), std::sin(angle)),
                    draws.logUniform(1e-3, 300.0) * spin, R);
    }
}
/// Balls in the air: a share thrown from where they stand, and perhaps one dropped onto another.
void drawFlights(Draws& draws, const physics::TableModel& table, double R, physics::TableState<double>& state)
{
  const double share = draws.uniform(0.1, 1.0);
  for (auto& b : state.balls)
    if (draws.chance(share))
    {
      const double speed = draws.logUniform(1e-3, 6.0), angle = draws.uniform(-M_PI, M_PI);
      b.r.z() = R + draws.uniform(0.0, 0.3);
      b.v = physics::Vec3<double>(speed * std::cos(angle), speed * std::sin(angle), draws.uniform(-3.0, 3.0));
      b.motion = physics::Motion::Airborne;
    }
  if (!state.balls.empty() && draws.chance(0.3))
  {
    // Dropped onto a ball: above it, within R of its centre, from up to 0.2 m.
    const physics::Ball<double> below = draws.pick(state.balls);
    int id = 0;
    for (const auto& b : state.balls)
      id = std::max(id, b.id + 1);
    physics::Ball<double> dropped;
    dropped.id = id;
    const double off = R * std::sqrt(draws.unit()), angle = draws.uniform(-M_PI, M_PI);
    dropped.r = below.r + physics::Vec3<double>(off * std::cos(angle), off * std::sin(angle),
                                                2 * R + 1e-6 + draws.uniform(0.0, 0.2));
    dropped.motion = physics::Motion::Airborne;
    bool clear = table.whyNotPlaceable(dropped.r.head<2>(), R).empty();
    for (const auto& b : state.balls)
      clear = clear && (b.r - dropped.r).norm() > 2 * R + 1e-7;
    if (clear)
      state.balls.push_back(dropped);
  }
}
}  // namespace

Scene soakScene(std::uint64_t seed, long k, bool airborne)
{
  Draws draws(seed, k);
  Scene scene;
  const auto& tables = bundledTables();
  std::vector<std::string> names;
  for (const auto& [name, table] : tables)
    names.push_back(name);
  scene.table_name = draws.pick(names);
  scene.table = tables.at(scene.table_name);
  scene.models.ball_ball = draws.pick(physics::ballBallModelNames());
  scene.models.cushion = draws.pick(physics::cushionModelNames());
  if (airborne)
  {
    scene.models.ball_table = draws.pick(physics::ballTableModelNames());
    scene.models.cue = draws.pick(physics::cueModelNames());
  }
  scene.params = drawParams(draws, *scene.table);
  const physics::Engine<double> engine(scene.table, scene.params, scene.models);
  scene.state = drawBalls(draws, engine);
  const bool moving = draws.chance(0.2);
  if (moving)
    drawMotion(draws, scene.params.ball_radius, scene.state);
  if (airborne && draws.chance(0.5))
    drawFlights(draws, *scene.table, scene.params.ball_radius, scene.state);
  if (!scene.state.balls.empty() && (!moving || draws.chance(0.5)))
  {
    Shot shot;
    shot.ball = draws.chance(0.7) && scene.state.indexOf(0) >= 0 ? 0 : draws.pick(scene.state.balls).id;
    shot.strike = drawStrike(draws);
    scene.shot = shot;
    // The cue strikes a ball on the cloth: a scene whose chosen ball flies has no shot.
    if (scene.state.balls[static_cast<std::size_t>(scene.state.indexOf(shot.ball))].airborne())
      scene.shot.reset();
  }
  return scene;
}

}  // namespace evaluation
}  // namespace cue_sim
