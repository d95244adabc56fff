// calibration::predictTracks: a shot's balls at the instants asked are the live simulation's at
// those instants, bit for bit, on any number of threads; contacts are counted; bad requests are
// refused with the field named and leave the others unaffected.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "cue_sim/calibration/track_prediction.hpp"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "engine_7ft.hpp"

namespace cue_sim
{
namespace calibration
{
namespace
{
using physics::Engine;
using physics::TableState;

TrackRequest breakRequest(const Engine<double>& engine, double speed)
{
  TrackRequest r;
  r.start = physics::rackLayout<double>("eight", engine.table(), engine.params().ball_radius);
  r.strike = TrackStrike{0, {speed, 0.001, 0.0, 0.0, 0.1}};
  for (int k = 0; k <= 240; ++k)
    r.times.push_back(k / 60.0);  // 4 s at 60 Hz
  return r;
}

TEST(TrackPrediction, IsTheLiveSimulationAtEachInstantOnAnyThreads)
{
  const auto engine = engine7ft();
  std::vector<TrackRequest> requests{breakRequest(*engine, 8.0), breakRequest(*engine, 5.0)};
  physics::ThreadPool one(1), two(2);
  const std::vector<TrackPrediction> a = predictTracks(*engine, requests, one);
  const std::vector<TrackPrediction> b = predictTracks(*engine, requests, two);
  for (std::size_t i = 0; i < requests.size(); ++i)
  {
    ASSERT_TRUE(a[i].error.empty()) << a[i].error;
    EXPECT_EQ(a[i].positions, b[i].positions);
    TableState<double> state = requests[i].start;
    engine->strike(state, 0, requests[i].strike->cue);
    physics::Simulation<double> live(*engine, state);
    const std::size_t balls = state.balls.size();
    int pocketed = 0;
    for (std::size_t k = 0; k < requests[i].times.size(); ++k)
    {
      live.advance(requests[i].times[k]);
      const auto snapshot = live.snapshot();
      for (std::size_t j = 0; j < balls; ++j)
      {
        EXPECT_EQ(a[i].positions[(k * balls + j) * 2], snapshot[j].r.x());
        EXPECT_EQ(a[i].positions[(k * balls + j) * 2 + 1], snapshot[j].r.y());
        EXPECT_EQ(a[i].on_table[k * balls + j], snapshot[j].inPlay() ? 1 : 0);
        if (k + 1 == requests[i].times.size() && !snapshot[j].inPlay())
          ++pocketed;
      }
    }
    // A break meets the rack and the cushions; every pocketed ball is counted once.
    EXPECT_GT(a[i].contacts.ball_ball, 10);
    EXPECT_GT(a[i].contacts.cushion, 3);
    EXPECT_EQ(a[i].contacts.pocketed, pocketed);
  }
}

TEST(TrackPrediction, ABallInMotionNeedsNoStrike)
{
  const auto engine = engine7ft();
  TrackRequest r;
  physics::Ball<double> ball;
  ball.r = {-0.5, 0.0, engine->params().ball_radius};
  ball.v = {2.0, 0.0, 0.0};
  ball.motion = physics::Motion::Sliding;
  r.start.balls.push_back(ball);
  r.times = {0.0, 0.05, 0.5};
  physics::ThreadPool pool(1);
  const TrackPrediction p = predictTracks(*engine, {r}, pool).front();
  ASSERT_TRUE(p.error.empty()) << p.error;
  EXPECT_EQ(p.positions[0], -0.5);
  // Sliding friction alone slows it: it has gone less far than at 2 m/s, and on.
  EXPECT_LT(p.positions[2], -0.5 + 2.0 * 0.05);
  EXPECT_GT(p.positions[2], -0.5 + 0.9 * 2.0 * 0.05);
  EXPECT_GT(p.positions[4], p.positions[2]);
}

/// The cue ball at 3 m/s straight into a standing ball 0.3 m away: a full hit.
TrackRequest headOn(const Engine<double>& engine, double exposure, std::vector<double> times)
{
  TrackRequest r;
  const double radius = engine.params().ball_radius;
  r.start.balls.resize(2);
  r.start.balls[0].id = 0;
  r.start.balls[0].r = {-0.3, 0.0, radius};
  r.start.balls[1].id = 1;
  r.start.balls[1].r = {0.0, 0.0, radius};
  r.strike = TrackStrike{0, {3.0, 0.0, 0.0, 0.0, 0.0}};
  r.times = std::move(times);
  r.exposure = exposure;
  return r;
}

TEST(TrackPrediction, AnExposureAveragesOnlyWhereSomethingHappensInIt)
{
  const auto engine = engine7ft();
  physics::ThreadPool pool(1);
  std::vector<double> times;
  for (int k = 1; k <= 125; ++k)
    times.push_back(k / 250.0);  // 250 Hz for half a second, the shutter open 97.5 % of it
  const TrackPrediction instant = predictTracks(*engine, {headOn(*engine, 0.0, times)}, pool).front();
  const TrackPrediction smeared = predictTracks(*engine, {headOn(*engine, 0.0039, times)}, pool).front();
  ASSERT_TRUE(instant.error.empty() && smeared.error.empty()) << instant.error << smeared.error;
  ASSERT_EQ(instant.contacts.ball_ball, 1);
  int differ = 0, at_contact = 0;
  for (std::size_t k = 0; k < times.size(); ++k)
  {
    const bool same = smeared.positions[4 * k] == instant.positions[4 * k] &&
                      smeared.positions[4 * k + 2] == instant.positions[4 * k + 2];
    if (!same && ++differ == 1)
    {
      // The first is the contact within this frame's exposure: the struck ball's x is convex in
      // time there (it starts), so its mean over the shutter is ahead of its middle, by at most
      // v e / 8.
      EXPECT_GT(smeared.positions[4 * k + 2], instant.positions[4 * k + 2]);
      EXPECT_LE(smeared.positions[4 * k + 2] - instant.positions[4 * k + 2], 3.0 * 0.0039 / 8);
      ++at_contact;
    }
  }
  // The contact, the balls' slides ending (a kink in their deceleration: micrometres) and the
  // object ball's cushion, a few frames: everywhere else the middle is the mean to the second order, and is taken.
  EXPECT_EQ(at_contact, 1);
  EXPECT_LE(differ, 6);
}

TEST(TrackPrediction, BadRequestsAreRefusedNamingTheFieldAndTheOthersRun)
{
  const auto engine = engine7ft();
  TrackRequest backwards = breakRequest(*engine, 6.0);
  backwards.times = {0.0, 0.2, 0.1};
  TrackRequest nan_time = breakRequest(*engine, 6.0);
  nan_time.times[3] = std::nan("");
  TrackRequest refused_strike = breakRequest(*engine, 6.0);
  refused_strike.strike->cue.a = 0.9;  // beyond the tip's largest offset
  TrackRequest overlapping = breakRequest(*engine, 6.0);
  overlapping.start.balls[1].r = overlapping.start.balls[2].r;
  TrackRequest long_exposure = breakRequest(*engine, 6.0);
  long_exposure.exposure = 0.02;  // frames at 60 Hz are 16.7 ms apart
  TrackRequest negative_exposure = breakRequest(*engine, 6.0);
  negative_exposure.exposure = -0.001;
  const TrackRequest good = breakRequest(*engine, 6.0);
  physics::ThreadPool pool(2);
  const auto p = predictTracks(
      *engine, {backwards, nan_time, refused_strike, overlapping, good, long_exposure, negative_exposure}, pool);
  EXPECT_EQ(p[5].error.rfind("exposure", 0), 0u) << p[5].error;
  EXPECT_EQ(p[6].error.rfind("exposure", 0), 0u) << p[6].error;
  EXPECT_EQ(p[0].error.rfind("times[2]", 0), 0u) << p[0].error;
  EXPECT_EQ(p[1].error.rfind("times[3]", 0), 0u) << p[1].error;
  EXPECT_EQ(p[2].error.rfind("strike", 0), 0u) << p[2].error;
  EXPECT_EQ(p[3].error.rfind("start", 0), 0u) << p[3].error;
  for (int i = 0; i < 4; ++i)
    EXPECT_TRUE(p[i].positions.empty());
  EXPECT_TRUE(p[4].error.empty());
  EXPECT_EQ(p[4].positions.size(), good.times.size() * good.start.balls.size() * 2);
}

}  // namespace
}  // namespace calibration
}  // namespace cue_sim
