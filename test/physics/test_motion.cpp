// Closed-form motion against the textbook results (PHYSICS.md; Lander 1999).
#include <gtest/gtest.h>

#include <cmath>

#include "cue_sim/physics/motion.hpp"

using namespace cue_sim::physics;

namespace
{
const PhysicsParams<double> p;

Ball<double> slidingBall(double speed, double heading)
{
  Ball<double> b;
  b.r = Vec3<double>(0.1, -0.2, p.ball_radius);
  b.v = speed * Vec3<double>(std::cos(heading), std::sin(heading), 0);
  settleMotion(b, p.ball_radius);
  return b;
}
}  // namespace

TEST(Motion, StunBallSlidesThenRollsAtFiveSevenths)
{
  const double v0 = 3.0;
  Ball<double> b = slidingBall(v0, 0.7);
  ASSERT_EQ(b.motion, Motion::Sliding);
  const double expected = 2 * v0 / (7 * p.mu_slide * p.gravity);
  EXPECT_NEAR(timeToTransition(b, p), expected, 1e-15);
  b = evolve(b, expected, p);
  EXPECT_EQ(applyTransition(b, p), EventKind::SlideToRoll);
  EXPECT_EQ(b.motion, Motion::Rolling);
  EXPECT_NEAR(b.v.norm(), 5.0 / 7.0 * v0, 1e-14);
  EXPECT_NEAR(slipVelocity(b.v, b.w, p.ball_radius).norm(), 0.0, 1e-14);
}

TEST(Motion, RollingStopsAfterVSquaredOverTwoMuG)
{
  const double v0 = 1.2;
  Ball<double> b = slidingBall(v0, -2.0);
  b.w = Vec3<double>(-b.v.y(), b.v.x(), 0) / p.ball_radius;
  settleMotion(b, p.ball_radius);
  ASSERT_EQ(b.motion, Motion::Rolling);
  const Vec3<double> start = b.r;
  const double t_stop = timeToTransition(b, p);
  EXPECT_NEAR(t_stop, v0 / (p.mu_roll * p.gravity), 1e-12);
  b = evolve(b, t_stop, p);
  EXPECT_NEAR((b.r - start).norm(), v0 * v0 / (2 * p.mu_roll * p.gravity), 1e-12);
  EXPECT_EQ(applyTransition(b, p), EventKind::RollToStop);
  EXPECT_EQ(b.motion, Motion::Stationary);
}

TEST(Motion, StateAtAnyTimeMatchesTheClosedForms)
{
  // Sliding with sidespin and backspin; formulas written out here, independently.
  Ball<double> b;
  b.r = Vec3<double>(0.3, 0.1, p.ball_radius);
  b.v = Vec3<double>(2.0, -1.0, 0);
  b.w = Vec3<double>(15.0, 40.0, 25.0);
  settleMotion(b, p.ball_radius);
  ASSERT_EQ(b.motion, Motion::Sliding);
  const double R = p.ball_radius, g = p.gravity;
  const Vec3<double> u0(b.v.x() - R * b.w.y(), b.v.y() + R * b.w.x(), 0);
  const Vec3<double> u_hat = u0.normalized();
  const double tau = 2 * u0.norm() / (7 * p.mu_slide * g);
  for (double t : {0.0, 1e-9, 0.013, 0.5 * tau, 0.99 * tau, tau})
  {
    const Ball<double> e = evolve(b, t, p);
    const Vec3<double> r = b.r + b.v * t - 0.5 * p.mu_slide * g * t * t * u_hat;
    const Vec3<double> v = b.v - p.mu_slide * g * t * u_hat;
    const Vec3<double> spin_axis(-u_hat.y(), u_hat.x(), 0);  // z x u_hat
    const Vec3<double> w_xy = Vec3<double>(b.w.x(), b.w.y(), 0) + 5 * p.mu_slide * g / (2 * R) * t * spin_axis;
    const double w_z = std::max(b.w.z() - 5 * p.mu_spin * g / (2 * R) * t, 0.0);
    EXPECT_NEAR((e.r - r).norm(), 0, 1e-15) << "t = " << t;
    EXPECT_NEAR((e.v - v).norm(), 0, 1e-15) << "t = " << t;
    EXPECT_NEAR(e.w.x(), w_xy.x(), 1e-12) << "t = " << t;
    EXPECT_NEAR(e.w.y(), w_xy.y(), 1e-12) << "t = " << t;
    EXPECT_NEAR(e.w.z(), w_z, 1e-12) << "t = " << t;
    // The slip keeps its direction and shrinks at 7/2 mu_s g.
    const Vec3<double> u = slipVelocity(e.v, e.w, R);
    EXPECT_NEAR(u.norm(), u0.norm() - 3.5 * p.mu_slide * g * t, 1e-12);
  }
}

TEST(Motion, ZSpinDecaysToASpinningStop)
{
  Ball<double> b;
  b.r = Vec3<double>(0, 0, p.ball_radius);
  b.w = Vec3<double>(0, 0, -20.0);
  settleMotion(b, p.ball_radius);
  ASSERT_EQ(b.motion, Motion::Spinning);
  const double expected = 20.0 * 2 * p.ball_radius / (5 * p.mu_spin * p.gravity);
  EXPECT_NEAR(timeToTransition(b, p), expected, 1e-12);
  EXPECT_NEAR(evolve(b, expected / 2, p).w.z(), -10.0, 1e-12);
  EXPECT_NEAR(p.spinDecel(), 10.9, 0.05);  // PHYSICS.md: 10.9 rad/s^2
}

TEST(Motion, TrajectoryCoefficientsReproduceTheState)
{
  const Ball<double> b = slidingBall(2.5, 1.1);
  const Trajectory<double> traj = trajectoryFrom(b, 0.05, p);
  for (double tau : {0.0, 0.01, 0.1})
    EXPECT_NEAR((traj.at(tau) - evolve(b, 0.05 + tau, p).r.head<2>()).norm(), 0, 1e-15);
}

TEST(Motion, FrictionlessClothNeverEnds)
{
  PhysicsParams<double> q;
  q.mu_slide = q.mu_roll = 0;
  Ball<double> b = slidingBall(1.0, 0);
  EXPECT_TRUE(std::isinf(timeToTransition(b, q)));
  EXPECT_NEAR(evolve(b, 2.0, q).r.x(), b.r.x() + 2.0, 1e-15);
}
