// A moving cue's first touch of a ball between two samples of its pose: closed-form cases (head
// on, off centre, grazing, creeping), and the strike at the touch agreeing with aimCue's for the
// cue that made it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "cue_sim/physics/cue_sweep.hpp"
#include "resting_ball.hpp"

using namespace cue_sim::physics;

namespace
{
const PhysicsParams<double> kParams;
const double R = kParams.ball_radius;
const double r_tip = kParams.cue_tip_radius;

/// A level cue along +x whose tip's end is at (x, y, R) at `stamp`.
CuePose levelCue(double stamp, double x, double y)
{
  CuePose pose;
  pose.stamp = stamp;
  pose.cue.tip = Vec3<double>(x, y, R);
  pose.cue.axis = Vec3<double>(1, 0, 0);
  return pose;
}

/// The cue moved back along its axis by `distance`.
CueStick backedOff(CueStick cue, double distance)
{
  cue.tip -= cue.axis.normalized() * distance;
  return cue;
}
}  // namespace

TEST(CueSweep, AHeadOnStrokeTouchesWhenTheTipsEndReachesTheBall)
{
  // 5 m/s over 10 ms, the tip's end 20 mm short of the ball at the first sample.
  const std::vector<Ball<double>> balls = {restingBall(3, 0, 0)};
  const auto touch = firstTouch(levelCue(1.0, -R - 0.02, 0), levelCue(1.01, -R + 0.03, 0), balls, kParams);
  ASSERT_TRUE(touch);
  EXPECT_EQ(touch->ball_id, 3);
  EXPECT_NEAR(touch->fraction, 0.4, 1e-12);
  EXPECT_NEAR(touch->stamp, 1.004, 1e-12);
  EXPECT_NEAR(touch->cue.tip.x(), -R, 1e-15);
  EXPECT_NEAR((tipCentre(touch->cue, kParams) - balls[0].r).norm(), R + r_tip, 1e-15);
}

TEST(CueSweep, AnOffCentreStrokeTouchesWhereTheTipsSphereMeetsTheBall)
{
  // The axis passes d to the shooter's right (-y for a stroke along +x): the spheres touch when
  // their centres are R + r_tip apart, sqrt((R + r_tip)^2 - d^2) back along the axis.
  const double d = 0.3 * (R + r_tip);
  const std::vector<Ball<double>> balls = {restingBall(0, 0, 0)};
  const auto touch = firstTouch(levelCue(0, -0.1, -d), levelCue(0.05, 0.0, -d), balls, kParams);
  ASSERT_TRUE(touch);
  const double centre_x = -std::sqrt((R + r_tip) * (R + r_tip) - d * d);
  EXPECT_NEAR(tipCentre(touch->cue, kParams).x(), centre_x, 1e-15);
  EXPECT_NEAR(touch->fraction, (centre_x + r_tip + 0.1) / 0.1, 1e-12);
  // The strike there: right English of 0.3 R on the ball's face, as aimCue has it.
  CueAim aim;
  ASSERT_EQ(aimCue(balls, kParams, backedOff(touch->cue, 1e-9), 2.0, aim), "");
  EXPECT_EQ(aim.ball_id, 0);
  EXPECT_NEAR(aim.strike.a, 0.3, 1e-12);
  EXPECT_NEAR(aim.strike.b, 0.0, 1e-12);
}

TEST(CueSweep, NoTouchShortOfTheBallBesideItBehindItOrMovingAway)
{
  const std::vector<Ball<double>> balls = {restingBall(0, 0, 0)};
  // Short: the tip's end stops 1 um before the ball.
  EXPECT_FALSE(firstTouch(levelCue(0, -0.1, 0), levelCue(0.01, -R - 1e-6, 0), balls, kParams));
  // Beside: the sphere passes a nanometre clear.
  const double clear = R + r_tip + 1e-9;
  EXPECT_FALSE(firstTouch(levelCue(0, -0.1, clear), levelCue(0.01, 0.1, clear), balls, kParams));
  // ... and a nanometre into it grazes it, at its side.
  const auto graze = firstTouch(levelCue(0, -0.1, clear - 2e-9), levelCue(0.01, 0.1, clear - 2e-9), balls, kParams);
  ASSERT_TRUE(graze);
  EXPECT_NEAR(tipCentre(graze->cue, kParams).x(), 0.0, 1e-3);
  // Behind the cue, and a cue drawn back from the ball.
  EXPECT_FALSE(firstTouch(levelCue(0, 0.1, 0), levelCue(0.01, 0.2, 0), balls, kParams));
  EXPECT_FALSE(firstTouch(levelCue(0, -R - 0.01, 0), levelCue(0.01, -R - 0.05, 0), balls, kParams));
  // Standing still.
  EXPECT_FALSE(firstTouch(levelCue(0, -R - 0.01, 0), levelCue(0.01, -R - 0.01, 0), balls, kParams));
}

TEST(CueSweep, ATipAlreadyAgainstOrInABallDoesNotTouchItAgain)
{
  const std::vector<Ball<double>> balls = {restingBall(0, 0, 0), restingBall(1, 0.2, 0)};
  // Resting against ball 0 and pushed on: no touch of ball 0 (the follower reports the push).
  EXPECT_FALSE(firstTouch(levelCue(0, -R, 0), levelCue(0.01, -R + 0.001, 0), balls, kParams));
  // In ball 0 and stroked on to ball 1: ball 1 is touched.
  const auto touch = firstTouch(levelCue(0, -R + 0.01, 0), levelCue(0.1, 0.3, 0), balls, kParams);
  ASSERT_TRUE(touch);
  EXPECT_EQ(touch->ball_id, 1);
}

TEST(CueSweep, TheNearerOfTwoBallsInLineIsTouchedFirstAndAPocketedOneNot)
{
  std::vector<Ball<double>> balls = {restingBall(0, 0.3, 0), restingBall(1, 0.1, 0)};
  auto touch = firstTouch(levelCue(0, -0.1, 0), levelCue(0.2, 0.5, 0), balls, kParams);
  ASSERT_TRUE(touch);
  EXPECT_EQ(touch->ball_id, 1);
  balls[1].motion = Motion::Pocketed;
  touch = firstTouch(levelCue(0, -0.1, 0), levelCue(0.2, 0.5, 0), balls, kParams);
  ASSERT_TRUE(touch);
  EXPECT_EQ(touch->ball_id, 0);
}

TEST(CueSweep, ACreepingTipIsFoundAsExactlyAsAFastOne)
{
  // 1 mm/s sampled at 1 kHz: a micrometre a sample, the touch 0.4 of the way.
  const std::vector<Ball<double>> balls = {restingBall(0, 0.7, 0.4)};
  const double start = 0.7 - R - 0.4e-6;
  const auto touch = firstTouch(levelCue(2.0, start, 0.4), levelCue(2.001, start + 1e-6, 0.4), balls, kParams);
  ASSERT_TRUE(touch);
  EXPECT_NEAR(touch->fraction, 0.4, 1e-8);
  EXPECT_NEAR(touch->stamp, 2.0004, 1e-11);
}

TEST(CueSweep, TheCueBetweenTwoPosesIsEachPoseAtItsEnd)
{
  CuePose from = levelCue(0, -0.2, 0.01), to = levelCue(0.01, -0.15, 0.02);
  to.cue.axis = Vec3<double>(std::cos(0.1), std::sin(0.1), -0.05);
  for (const auto& [fraction, pose] : {std::pair<double, CuePose>{0.0, from}, {1.0, to}})
  {
    const CueStick cue = cueBetween(from, to, fraction, kParams);
    EXPECT_NEAR((cue.tip - pose.cue.tip).norm(), 0, 1e-15);
    EXPECT_NEAR((cue.axis - pose.cue.axis.normalized()).norm(), 0, 1e-15);
  }
}

TEST(CueSweep, APoseThatIsNotOneTouchesNothing)
{
  const std::vector<Ball<double>> balls = {restingBall(0, 0, 0)};
  CuePose bad = levelCue(0, -0.1, 0);
  bad.cue.axis = Vec3<double>::Zero();
  EXPECT_FALSE(firstTouch(bad, levelCue(0.01, 0.1, 0), balls, kParams));
  bad = levelCue(0, -0.1, 0);
  bad.cue.tip.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(firstTouch(levelCue(0, -0.1, 0), bad, balls, kParams));
}

TEST(CueSweep, TheStrikeAtTheTouchIsTheOneTheCuesLineMakes)
{
  // Random strikes within the limits: the cue that makes each (cueStickFor), stroked through the
  // ball between two samples, touches it, and aimCue at the touch gives the strike back.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  const Ball<double> ball = restingBall(5, 0.3, -0.2);
  for (int i = 0; i < 500; ++i)
  {
    CueStrike<double> strike;
    strike.speed = 0.5 + 5 * unit(rng);
    strike.phi = 2 * M_PI * unit(rng) - M_PI;
    strike.theta = 1.2 * unit(rng);
    const double offset = 0.49 * std::sqrt(unit(rng)), angle = 2 * M_PI * unit(rng);
    strike.a = offset * std::cos(angle);
    strike.b = offset * std::sin(angle);
    CuePose from, to;
    from.cue = cueStickFor(ball, strike, kParams, 0.03);
    to.cue = from.cue;
    to.cue.tip += from.cue.axis * 0.05;
    to.stamp = 0.01;
    const auto touch = firstTouch(from, to, {ball}, kParams);
    ASSERT_TRUE(touch) << "strike " << i;
    EXPECT_NEAR((tipCentre(touch->cue, kParams) - ball.r).norm(), R + r_tip, 1e-12);
    CueAim aim;
    ASSERT_EQ(aimCue({ball}, kParams, backedOff(touch->cue, 1e-9), strike.speed, aim), "") << "strike " << i;
    EXPECT_NEAR(std::remainder(aim.strike.phi - strike.phi, 2 * M_PI), 0, 1e-9);
    EXPECT_NEAR(aim.strike.theta, strike.theta, 1e-9);
    EXPECT_NEAR(aim.strike.a, strike.a, 1e-9);
    EXPECT_NEAR(aim.strike.b, strike.b, 1e-9);
  }
}
