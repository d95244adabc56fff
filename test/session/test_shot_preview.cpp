// A prediction runs its shot once: its samples and the preview's paths come from the trajectories
// that one run kept, and are exactly what a simulation of the shot shows at those times.
#include <gtest/gtest.h>

#include <algorithm>

#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "cue_sim/session/shot_preview.hpp"
#include "live_table_fixtures.hpp"

namespace cue_sim
{
namespace session
{
namespace
{
using fixtures::engineOn;

bool sameBall(const physics::Ball<double>& a, const physics::Ball<double>& b)
{
  return a.id == b.id && a.motion == b.motion && a.r == b.r && a.v == b.v && a.w == b.w;
}

struct Break
{
  std::shared_ptr<const physics::Engine<double>> engine = engineOn("7ft");
  physics::TableState<double> rack =
      physics::rackLayout<double>("eight", engine->table(), engine->params().ball_radius);
  Shot shot = fixtures::shot(0, 7.0, 0.01, 0.1, -0.2);
};

TEST(ShotPreview, APredictionSimulatesItsShotOnceForItsSamplesAndTrajectories)
{
  const Break b;
  PredictionOptions options;
  options.sample_period = 0.01;
  options.trajectories = true;
  const long before = physics::searchesStartedOnThisThread();
  const ShotPrediction prediction = predictShot(*b.engine, b.rack, b.shot, options);
  EXPECT_EQ(physics::searchesStartedOnThisThread() - before, 1) << "one run of the shot";
  ASSERT_TRUE(prediction.success) << prediction.message;
  ASSERT_EQ(prediction.trajectories.size(), b.rack.balls.size());

  // The reference: the shot struck and simulated to rest, then again advanced to every sample.
  physics::TableState<double> struck = b.rack;
  b.engine->strike(struck, 0, b.shot.strike);
  physics::TableState<double> to_rest = struck;
  const physics::ShotResult<double> result = simulateToRest(*b.engine, to_rest);
  ASSERT_EQ(prediction.events.size(), result.events.size());
  for (std::size_t i = 0; i < result.events.size(); ++i)
    EXPECT_EQ(prediction.events[i].time, result.events[i].time) << "event " << i;
  EXPECT_EQ(prediction.time_to_rest, result.duration);
  physics::Simulation<double> stepped(*b.engine, struck);
  ASSERT_GT(prediction.samples.size(), 50u);
  for (std::size_t k = 0; k < prediction.samples.size(); ++k)
  {
    stepped.advance(struck.time + static_cast<double>(k) * options.sample_period);
    const auto balls = stepped.snapshot();
    for (std::size_t i = 0; i < balls.size(); ++i)
      EXPECT_TRUE(sameBall(prediction.samples[k][i], balls[i])) << "sample " << k << ", ball " << balls[i].id;
  }
  // Every event's own instant too: a trajectory holds the events at that time.
  physics::Simulation<double> at_events(*b.engine, struck);
  for (const auto& e : result.events)
  {
    at_events.advance(e.time);
    const auto balls = at_events.snapshot();
    for (std::size_t i = 0; i < balls.size(); ++i)
      EXPECT_TRUE(sameBall(prediction.trajectories[i].at(e.time, b.engine->params()), balls[i]))
          << "ball " << balls[i].id << " at " << e.time;
  }
}

TEST(ShotPreview, PathsAreDrawnFromTheTrajectoriesWithoutRunningTheShot)
{
  const Break b;
  PredictionOptions options;
  options.trajectories = true;
  const ShotPrediction prediction = predictShot(*b.engine, b.rack, b.shot, options);
  ASSERT_TRUE(prediction.success);
  EXPECT_TRUE(prediction.samples.empty());
  const long before = physics::searchesStartedOnThisThread();
  const std::vector<PreviewPath> paths = previewPaths(prediction, b.engine->params());
  EXPECT_EQ(physics::searchesStartedOnThisThread(), before) << "drawing runs nothing";
  ASSERT_GT(paths.size(), 5u);
  for (const PreviewPath& path : paths)
  {
    const int i = b.rack.indexOf(path.id);
    ASSERT_GE(i, 0);
    EXPECT_EQ(path.points.front(), b.rack.balls[i].r.head<2>()) << "ball " << path.id << " starts where it rests";
    const physics::Ball<double>& last = prediction.final_balls[i];
    if (last.inPlay())
    {
      EXPECT_EQ(path.points.back(), last.r.head<2>()) << "ball " << path.id << " ends where it comes to rest";
    }
    // Each change of the ball's motion on the cloth is a corner of its path.
    for (const auto& piece : prediction.trajectories[i].pieces)
    {
      if (piece.ball.inPlay())
      {
        EXPECT_NE(std::find(path.points.begin(), path.points.end(),
                            physics::evolve(piece.ball, piece.start, b.engine->params()).r.head<2>()),
                  path.points.end())
            << "ball " << path.id << " at " << piece.start;
      }
    }
  }
  // Balls that do not move have no path.
  for (std::size_t i = 0; i < b.rack.balls.size(); ++i)
  {
    if (prediction.trajectories[i].pieces.size() == 1)
    {
      EXPECT_TRUE(
          std::none_of(paths.begin(), paths.end(), [&](const PreviewPath& p) { return p.id == b.rack.balls[i].id; }));
    }
  }
  // Without trajectories (a batch, a strike's own run) nothing is kept, and nothing is drawn.
  EXPECT_TRUE(predictShot(*b.engine, b.rack, b.shot, {}).trajectories.empty());
  EXPECT_TRUE(previewPaths(predictShot(*b.engine, b.rack, b.shot, {}), b.engine->params()).empty());
}

}  // namespace
}  // namespace session
}  // namespace cue_sim
