// Stronge's compliant frictional impact along one tangent (stronge2018's core): the limits the
// book gives in closed form, and an independent integration of the two springs in time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "physics/models/cushion/tangential_compliance.hpp"

using cue_sim::physics::slipAfterCompliantImpact;

namespace
{
const double kBall = 3.5;  // tangential inverse mass of a ball at its surface, in units of 1/m

/// The same impact integrated in time with small steps, from its equations alone: the normal
/// force m v sin(psi) (psi = tau in compression, then pi/2 + (tau - pi/2)/e), the slip s falling
/// at eta^2 x, and the tangential spring's stretch x (times omega_n) following the slip while it
/// is within mu beta v sin(psi) / eta^2 and held at that limit otherwise (the far end sliding).
/// Semi-implicit Euler: first order in the step.
double integrated(double slip, double approach, double mu, double e, double eta, double step)
{
  const double limit = mu * kBall * approach / (eta * eta);
  const double end = M_PI / 2 * (1 + e);
  double s = slip, x = 0;
  for (double tau = 0; tau < end;)
  {
    const double h = std::min(step, end - tau);
    tau += h;
    s -= eta * eta * x * h;
    const double psi = tau <= M_PI / 2 ? tau : M_PI / 2 + (tau - M_PI / 2) / e;
    const double bound = limit * std::sin(std::min(psi, M_PI));
    x = std::clamp(x + s * h, -bound, bound);
  }
  return s;
}
}  // namespace

TEST(TangentialCompliance, WithoutFrictionTheSlipIsKept)
{
  for (const double eta : {0.5, 1.7, 20.0})
    EXPECT_EQ(slipAfterCompliantImpact(0.8, 1.0, 0.0, kBall, 0.9, eta), 0.8) << eta;
}

TEST(TangentialCompliance, SlidingThroughoutTheSlipFallsByMuBetaTimesTheImpulse)
{
  // A slip too fast to stop, and faster than a soft spring can follow at the start (mu beta_t
  // v_n / eta^2, here 10 m/s at eta = 0.3): the far end slides all through the impact and the
  // slip falls by mu beta_t (1 + e) v_n, as with rigid Coulomb friction.
  for (const double eta : {0.3, 1.7, 50.0})
    for (const double e : {0.0, 0.5, 1.0})
    {
      const double mu = 0.2, v = 1.3, slip = 40.0;
      EXPECT_NEAR(slipAfterCompliantImpact(slip, v, mu, kBall, e, eta), slip - mu * kBall * (1 + e) * v, 1e-14)
          << eta << " " << e;
    }
}

TEST(TangentialCompliance, StuckThroughoutTheSpringVibratesFreely)
{
  // Friction that always holds (the book's sticking limit): the tangential spring is a free
  // oscillator at eta for the impact's duration pi (1 + e) / 2 in tau, so the slip leaves at
  // s cos(eta pi (1 + e) / 2). It can come back reversed: the tangential restitution is an
  // outcome, -1 for eta = 1 and e = 1, and +0.22 for a ball on rubber (1.7, 0.85). The far end
  // still slides as the normal force vanishes, by a slip of order mu (s / limit)^2: nothing at
  // mu = 1e14.
  for (const double eta : {0.6, 1.0, 1.7, 2.5, 4.1})
    for (const double e : {0.3, 0.85, 1.0})
    {
      const double slip = 0.7, expected = slip * std::cos(eta * M_PI * (1 + e) / 2);
      EXPECT_NEAR(slipAfterCompliantImpact(slip, 1.0, 1e14, kBall, e, eta), expected, 1e-12) << eta << " " << e;
    }
  EXPECT_NEAR(slipAfterCompliantImpact(0.7, 1.0, 1e14, kBall, 1.0, 1.0), -0.7, 1e-12);  // reversed
}

TEST(TangentialCompliance, ARigidTangentStopsTheSlipLikeCoulombWithStick)
{
  // A tangential spring far stiffer than the normal one (eta -> infinity, the book's rigid
  // limit): the slip falls by mu beta_t times the impulse until it stops, then stays stopped, as
  // in the rigid-body models (han2005). The vibration left when it stops is of order
  // mu beta_t v / eta, so the difference shrinks as 1/eta.
  const double mu = 0.2, v = 1.0, e = 0.85;
  for (const double slip : {0.05, 0.3, 0.6, 1.0})
  {
    const double rigid = std::max(0.0, slip - mu * kBall * (1 + e) * v);
    double previous = 1;
    for (const double eta : {10.0, 100.0, 1000.0})
    {
      const double gap = std::abs(slipAfterCompliantImpact(slip, v, mu, kBall, e, eta) - rigid);
      EXPECT_LT(gap, 2 * mu * kBall * v / eta) << slip << " " << eta;
      EXPECT_LT(gap, previous) << slip << " " << eta;
      previous = gap;
    }
  }
}

TEST(TangentialCompliance, AgreesWithTheSpringsIntegratedInTime)
{
  // Random impacts against the time-stepped springs: halving the step halves the difference,
  // and at 2e-6 of the normal period's quarter it is within 2e-5 of the impact's speed scale.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 24; ++i)
  {
    const double slip = 2 * unit(rng), mu = 0.5 * unit(rng), e = 0.2 + 0.8 * unit(rng), eta = 0.5 + 4 * unit(rng);
    const double exact = slipAfterCompliantImpact(slip, 1.0, mu, kBall, e, eta);
    const double coarse = std::abs(integrated(slip, 1.0, mu, e, eta, 4e-6) - exact);
    const double fine = std::abs(integrated(slip, 1.0, mu, e, eta, 2e-6) - exact);
    const double scale = slip + mu * kBall;
    SCOPED_TRACE("slip " + std::to_string(slip) + " mu " + std::to_string(mu) + " e " + std::to_string(e) + " eta " +
                 std::to_string(eta));
    EXPECT_LT(fine, 2e-5 * scale);
    EXPECT_LT(fine, 0.75 * coarse + 1e-9 * scale);
  }
}

TEST(TangentialCompliance, AgreesWithTheSpringsIntegratedInTimeAtTheRegistrysStiffEnd)
{
  // The same at the registry's stiff end: tangential springs 20 to 100 times the normal one's
  // frequency (a stick and a slip every vibration, each stick's end found by Newton's steps),
  // friction from 0.1 to 10, restitution down to 0.01, slips from 0.1 to 10 times the closing
  // speed. The springs stepped at 2e-7 agree with it to 1e-9 of the impact's speed scale (their
  // rounding, 3e6 steps); a stick's end found wrong would be off by far more.
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 8; ++i)
  {
    const double slip = std::pow(10.0, -1 + 2 * unit(rng)), mu = std::pow(10.0, -1 + 2 * unit(rng)),
                 e = std::pow(10.0, -2 + 2 * unit(rng)), eta = 20 + 80 * unit(rng);
    const double exact = slipAfterCompliantImpact(slip, 1.0, mu, kBall, e, eta);
    const double stepped = integrated(slip, 1.0, mu, e, eta, 2e-7);
    SCOPED_TRACE("slip " + std::to_string(slip) + " mu " + std::to_string(mu) + " e " + std::to_string(e) + " eta " +
                 std::to_string(eta));
    EXPECT_LT(std::abs(stepped - exact), 1e-8 * (slip + mu * kBall));
  }
}

TEST(TangentialCompliance, NeverLeavesFasterThanItCame)
{
  // The springs store what they take and give it back; only the far end's sliding and the
  // normal restitution dissipate. The slip's magnitude never grows, at any coefficients.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 20000; ++i)
  {
    const double slip = std::pow(10.0, -3 + 4 * unit(rng)), approach = std::pow(10.0, -3 + 4 * unit(rng));
    const double mu = 3 * unit(rng) * unit(rng), e = unit(rng), eta = 0.1 * std::pow(1000.0, unit(rng));
    const double after = slipAfterCompliantImpact(slip, approach, mu, kBall, e, eta);
    ASSERT_TRUE(std::isfinite(after));
    ASSERT_LE(std::abs(after), slip * (1 + 1e-13)) << slip << " " << approach << " " << mu << " " << e << " " << eta;
  }
}
