// The live table turns its balls as they move: a ball that rolls all the way turns by
// distance / R about the axis across its path, however often the table is looked at; a break
// turns the same whatever the ticks.
#include <gtest/gtest.h>

#include <cmath>

#include "live_table_fixtures.hpp"

namespace cue_sim
{
namespace session
{
namespace
{
using namespace fixtures;

/// The table advanced to rest in ticks of `tick` [s] from the strike at kStart.
void toRest(LiveTable& table, double tick)
{
  for (Stamp now = kStart; !table.motion().atRest() && now < kStart + 60 * kSecond;)
  {
    now += static_cast<Stamp>(tick * kSecond);
    table.advanceTo(now);
  }
  ASSERT_TRUE(table.motion().atRest());
}

double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
  return Eigen::AngleAxisd(a.inverse() * b).angle();
}
}  // namespace

TEST(BallOrientations, ABallStruckToRollTurnsByDistanceOverR)
{
  // A level cue 2R/5 above the centre (b = 0.4) sends the ball off in natural roll.
  LiveTable table(engineOn("7ft"), LiveTableOptions{}, "empty", kStart);
  const Eigen::Vector3d start = table.motion().balls().at(0).r;
  ASSERT_TRUE(table.strike(shot(0, 0.25, 0.0, 0.0, 0.4), kStart).success);
  ASSERT_EQ(table.motion().balls().at(0).motion, physics::Motion::Rolling) << "rolling from the strike";
  toRest(table, 0.01);
  const double distance = (table.motion().balls().at(0).r - start).norm();
  ASSERT_GT(distance, 0.1);
  const Eigen::AngleAxisd turned(table.motion().orientations().at(0));
  EXPECT_NEAR(std::abs(turned.axis().y()), 1.0, 1e-9) << "about +y, across a path along +x";
  const double radius = table.engine().params().ball_radius;
  EXPECT_NEAR(std::remainder(turned.angle() * turned.axis().y() - distance / radius, 2 * M_PI), 0.0, 1e-9);
}

TEST(BallOrientations, ABreakTurnsTheBallsTheSameWhateverTheTicks)
{
  std::vector<Eigen::Quaterniond> seen[2];
  const double ticks[2] = {0.001, 0.37};
  for (int k = 0; k < 2; ++k)
  {
    LiveTable table(engineOn("7ft"), LiveTableOptions{}, "eight", kStart);
    ASSERT_TRUE(table.strike(shot(0, 8.0, 0.002, 0.1, 0.2), kStart).success);
    toRest(table, ticks[k]);
    seen[k] = table.motion().orientations();
  }
  ASSERT_EQ(seen[0].size(), 16u);
  int turned = 0;
  for (std::size_t i = 0; i < seen[0].size(); ++i)
  {
    // Both are the Magnus integration's answers, on different substeps: they differ by its own
    // error, about 1e-9 rad a motion state (test_orientation.cpp), 4e-9 rad at most over this
    // break's hundreds of radians. A kink integrated across (the z-spin running out mid-state)
    // made it 2e-4.
    EXPECT_LT(angleBetween(seen[0][i], seen[1][i]), 1e-8) << "ball index " << i;
    turned += angleBetween(seen[0][i], Eigen::Quaterniond::Identity()) > 0.1;
  }
  EXPECT_GT(turned, 10) << "the balls that moved turned";
}

}  // namespace session
}  // namespace cue_sim
