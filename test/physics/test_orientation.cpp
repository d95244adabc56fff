// A ball's orientation along its closed-form motion: a rolling ball turns by distance / R about
// the horizontal axis across its path; a spinning ball about z by the integral of its spin; and a
// sliding ball whose spin axis swings (side spin and follow) as an independent fine integration
// of dq/dt = w/2 q says.
#include <gtest/gtest.h>

#include <cmath>

#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/orientation.hpp"

using namespace cue_sim::physics;

namespace
{
const PhysicsParams<double> p;

Ball<double> ballWith(const Eigen::Vector3d& v, const Eigen::Vector3d& w)
{
  Ball<double> b;
  b.time = 0.25;  // a ball's own clock need not start at zero
  b.r = Eigen::Vector3d(0.1, -0.2, p.ball_radius);
  b.v = v;
  b.w = w;
  settleMotion(b, p.ball_radius);
  return b;
}

/// The angle between two rotations [rad].
double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
  return Eigen::AngleAxisd(a.inverse() * b).angle();
}

/// dq/dt = (0, w) q / 2 by classical Runge-Kutta at a fixed small step: the reference.
Eigen::Quaterniond integrateFinely(const Ball<double>& ball, double t, int steps)
{
  const auto rate = [&](double s, const Eigen::Quaterniond& q) {
    const Eigen::Vector3d w = evolve(ball, s, p).w;
    Eigen::Quaterniond d = Eigen::Quaterniond(0, w.x(), w.y(), w.z()) * q;
    d.coeffs() *= 0.5;
    return d;
  };
  const auto plus = [](const Eigen::Quaterniond& q, const Eigen::Quaterniond& d, double h) {
    Eigen::Quaterniond out;
    out.coeffs() = q.coeffs() + h * d.coeffs();
    return out;
  };
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  const double h = (t - ball.time) / steps;
  for (int k = 0; k < steps; ++k)
  {
    const double s = ball.time + k * h;
    const Eigen::Quaterniond k1 = rate(s, q), k2 = rate(s + h / 2, plus(q, k1, h / 2)),
                             k3 = rate(s + h / 2, plus(q, k2, h / 2)), k4 = rate(s + h, plus(q, k3, h));
    q.coeffs() += h / 6 * (k1.coeffs() + 2 * k2.coeffs() + 2 * k3.coeffs() + k4.coeffs());
    q.normalize();
  }
  return q;
}
}  // namespace

TEST(Orientation, ARollingBallTurnsByDistanceOverRAcrossItsPath)
{
  const Eigen::Vector3d v(1.2, 0.7, 0);
  const Ball<double> b = ballWith(v, Eigen::Vector3d::UnitZ().cross(v) / p.ball_radius);
  ASSERT_EQ(b.motion, Motion::Rolling);
  const double end = b.time + timeToTransition(b, p);
  for (const double t : {b.time + 0.01, b.time + 0.4, end})
  {
    const double distance = (evolve(b, t, p).r - b.r).norm();
    const Eigen::AngleAxisd turned(rotationAlong(b, t, p));
    const Eigen::Vector3d across = Eigen::Vector3d::UnitZ().cross(v.normalized());
    EXPECT_NEAR(std::abs(turned.axis().dot(across)), 1.0, 1e-12) << "about the horizontal axis across the path";
    // A rotation knows its angle up to whole turns.
    const double signed_angle = turned.angle() * turned.axis().dot(across);
    EXPECT_NEAR(std::remainder(signed_angle - distance / p.ball_radius, 2 * M_PI), 0.0,
                1e-12 * (1 + distance / p.ball_radius))
        << t;
  }
}

TEST(Orientation, ASpinningBallTurnsAboutZByItsSpinsIntegral)
{
  const double w0 = 30.0;
  const Ball<double> b = ballWith(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, w0));
  ASSERT_EQ(b.motion, Motion::Spinning);
  const double stop = timeToTransition(b, p), decel = w0 / stop;  // the spin falls linearly to zero
  for (const double dt : {0.05, 0.3, stop})
  {
    const Eigen::AngleAxisd turned(rotationAlong(b, b.time + dt, p));
    const double expected = w0 * dt - 0.5 * decel * dt * dt;
    EXPECT_NEAR(std::fmod(turned.angle() * turned.axis().z() + 4 * M_PI, 2 * M_PI),
                std::fmod(expected + 4 * M_PI, 2 * M_PI), 1e-11)
        << dt;
  }
}

TEST(Orientation, ASlidingBallWithSideSpinAndFollowMatchesAFineIntegration)
{
  // Struck at 3 m/s with follow and right English: w swings as friction turns w_xy.
  const Eigen::Vector3d v(3.0, 0.5, 0);
  const Ball<double> b = ballWith(v, Eigen::Vector3d(-40.0, 95.0, 60.0));
  ASSERT_EQ(b.motion, Motion::Sliding);
  const double end = b.time + timeToTransition(b, p);
  const Eigen::Quaterniond reference = integrateFinely(b, end, 200000);
  const Eigen::Quaterniond mine = rotationAlong(b, end, p);
  const double error = angleBetween(mine, reference);
  EXPECT_LT(error, 1e-9) << "Magnus against RK4 at 200000 steps";
  // The axis swings: turning about the integral of w (as if the axis stood still) is far off.
  Eigen::Vector3d integral = Eigen::Vector3d::Zero();
  const int steps = 100000;
  for (int k = 0; k < steps; ++k)
    integral += evolve(b, b.time + (k + 0.5) * (end - b.time) / steps, p).w * (end - b.time) / steps;
  const Eigen::Quaterniond about_the_mean(Eigen::AngleAxisd(integral.norm(), integral.normalized()));
  EXPECT_GT(angleBetween(about_the_mean, reference), 1e-3);
}

TEST(Orientation, TurningInPiecesIsTurningAtOnce)
{
  const Ball<double> b = ballWith(Eigen::Vector3d(2.0, -1.0, 0), Eigen::Vector3d(10.0, 30.0, -25.0));
  const double end = b.time + timeToTransition(b, p), middle = b.time + 0.37 * (end - b.time);
  const Eigen::Quaterniond whole = rotationAlong(b, end, p);
  const Eigen::Quaterniond pieces = rotationAlong(evolve(b, middle, p), end, p) * rotationAlong(b, middle, p);
  EXPECT_LT(angleBetween(whole, pieces), 1e-10);
}

TEST(Orientation, ABallAtRestOrAskedForNoTimeDoesNotTurnAndHugeSpinsCostABoundedAmount)
{
  const Ball<double> still = ballWith(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  EXPECT_EQ(angleBetween(rotationAlong(still, 10.0, p), Eigen::Quaterniond::Identity()), 0.0);
  const Ball<double> moving = ballWith(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d::Zero());
  EXPECT_EQ(angleBetween(rotationAlong(moving, moving.time, p), Eigen::Quaterniond::Identity()), 0.0);
  const Ball<double> wild = ballWith(Eigen::Vector3d(50, 0, 0), Eigen::Vector3d(0, 0, BallLimits::max_spin));
  const Eigen::Quaterniond q = rotationAlong(wild, wild.time + timeToTransition(wild, p), p);
  EXPECT_NEAR(q.norm(), 1.0, 1e-12);
}
