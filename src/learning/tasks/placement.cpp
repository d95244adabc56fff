#include "learning/tasks/placement.hpp"

#include "cue_sim/game/referee.hpp"

namespace cue_sim
{
namespace learning
{
namespace
{
/// Tries at drawing a free place for one ball before the whole table is drawn again.
constexpr int kPlacementTries = 1000;

bool placeAll(const physics::Engine<double>& engine, int count, Random& random, physics::TableState<double>& table)
{
  const double R = engine.params().ball_radius;
  Eigen::Vector2d low, high;
  game::inHandRegion(engine.table(), R, game::BallInHand::Anywhere, low, high);
  table = physics::TableState<double>();
  for (int id = 0; id <= count; ++id)
  {
    bool placed = false;
    for (int tries = 0; tries < kPlacementTries && !placed; ++tries)
    {
      const Eigen::Vector2d p(random.uniform(low.x(), high.x()), random.uniform(low.y(), high.y()));
      if (!game::whyNotInHand(engine.table(), R, table, p, game::BallInHand::Anywhere).empty())
        continue;
      physics::Ball<double> ball;
      ball.id = id;
      ball.r = Eigen::Vector3d(p.x(), p.y(), R);
      table.balls.push_back(ball);
      placed = true;
    }
    if (!placed)
      return false;
  }
  return true;
}
}  // namespace

physics::TableState<double> scatteredBalls(const physics::Engine<double>& engine, int count, Random& random)
{
  physics::TableState<double> table;
  while (!placeAll(engine, count, random, table))
  {
  }
  return table;
}

}  // namespace learning
}  // namespace cue_sim
