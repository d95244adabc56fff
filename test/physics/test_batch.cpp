// Batch prediction on all cores gives, shot for shot, exactly what running the shots one by
// one gives (issue 5); the thread pool runs every index once and passes errors on.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <memory>
#include <random>
#include <stdexcept>

#include "cue_sim/physics/batch.hpp"
#include "cue_sim/physics/rack.hpp"

using namespace cue_sim::physics;

TEST(ThreadPool, RunsEveryIndexOnceAndRethrows)
{
  ThreadPool pool(3);
  EXPECT_EQ(pool.size(), 3u);
  for (std::size_t count : {0u, 1u, 7u, 1000u})
  {
    std::vector<std::atomic<int>> hits(count);
    pool.parallelFor(count, [&](std::size_t i) { ++hits[i]; });
    for (std::size_t i = 0; i < count; ++i)
      EXPECT_EQ(hits[i], 1) << i;
  }
  std::atomic<int> ran{0};
  EXPECT_THROW(pool.parallelFor(50,
                                [&](std::size_t i) {
                                  ++ran;
                                  if (i == 17)
                                    throw std::runtime_error("shot 17");
                                }),
               std::runtime_error);
  EXPECT_EQ(ran, 50) << "the rest of the loop still runs";
  pool.parallelFor(5, [](std::size_t) {});  // and the pool is still usable
}

TEST(Batch, EqualsShotsRunOneByOne)
{
  const auto table = std::make_shared<const TableModel>(TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137));
  const Engine<double> engine(table, PhysicsParams<double>());
  RackOptions rack;
  rack.gap = 2e-4;
  rack.jitter = 1e-4;
  rack.seed = 11;
  const TableState<double> start = rackLayout<double>("eight", *table, engine.params().ball_radius, rack);
  std::mt19937 random(3);
  const auto unit = [&] { return static_cast<double>(random()) / 4294967296.0; };
  std::vector<BatchShot<double>> shots(300);
  for (auto& shot : shots)
  {
    shot.cue.speed = 1.0 + 7.0 * unit();
    shot.cue.phi = 0.05 * (unit() - 0.5);
    shot.cue.a = 0.4 * (unit() - 0.5);
    shot.cue.b = 0.4 * (unit() - 0.5);
  }
  shots[5].cue.speed = 0;  // refused: speed out of range
  shots[9].ball_id = 42;   // refused: no such ball
  ThreadPool pool(2);
  const std::vector<ShotOutcome<double>> batch = simulateBatch(engine, start, shots, pool);
  ASSERT_EQ(batch.size(), shots.size());
  EXPECT_NE(batch[5].error.find("speed"), std::string::npos) << batch[5].error;
  EXPECT_NE(batch[9].error.find("42"), std::string::npos) << batch[9].error;
  for (std::size_t i = 0; i < shots.size(); ++i)
  {
    TableState<double> alone = start;
    ShotResult<double> result;
    const std::string why = engine.whyNotStrikable(alone, shots[i].ball_id, shots[i].cue);
    if (why.empty())
    {
      engine.strike(alone, shots[i].ball_id, shots[i].cue);
      result = simulateToRest(engine, alone);
    }
    EXPECT_EQ(batch[i].error, why) << "shot " << i;
    ASSERT_EQ(batch[i].result.events.size(), result.events.size()) << "shot " << i;
    for (std::size_t e = 0; e < result.events.size(); ++e)
      EXPECT_EQ(batch[i].result.events[e].time, result.events[e].time) << "shot " << i << ", event " << e;
    EXPECT_EQ(batch[i].result.duration, result.duration) << "shot " << i;
    ASSERT_EQ(batch[i].state.balls.size(), alone.balls.size());
    for (std::size_t b = 0; b < alone.balls.size(); ++b)
    {
      EXPECT_EQ(batch[i].state.balls[b].r, alone.balls[b].r) << "shot " << i << ", ball " << b;
      EXPECT_EQ(batch[i].state.balls[b].motion, alone.balls[b].motion) << "shot " << i << ", ball " << b;
    }
  }
}
