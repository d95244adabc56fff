// Execution noise: reproducible from a seed, Gaussian with the stated deviations, and never
// turning a valid plan into an invalid strike.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cue_sim/physics/execution_noise.hpp"

using namespace cue_sim::physics;

namespace
{
const double kRadius = 0.028575;

CueStrike<double> plan(double speed, double phi, double theta, double a, double b)
{
  CueStrike<double> s;
  s.speed = speed;
  s.phi = phi;
  s.theta = theta;
  s.a = a;
  s.b = b;
  return s;
}

bool same(const CueStrike<double>& x, const CueStrike<double>& y)
{
  return x.speed == y.speed && x.phi == y.phi && x.theta == y.theta && x.a == y.a && x.b == y.b;
}
}  // namespace

TEST(ExecutionNoise, NoneLeavesThePlanExactly)
{
  NoisyCue cue(ExecutionNoise::none(), 7);
  const CueStrike<double> planned = plan(3.1, 0.7, 0.2, 0.1, -0.3);
  EXPECT_TRUE(same(cue.execute(planned, kRadius), planned));
}

TEST(ExecutionNoise, TheSameSeedGivesTheSameStrikesAndAnotherSeedOthers)
{
  const CueStrike<double> planned = plan(3, 0.5, 0.1, 0, 0);
  NoisyCue first(ExecutionNoise(), 42), second(ExecutionNoise(), 42), other(ExecutionNoise(), 43);
  for (int i = 0; i < 100; ++i)
  {
    const CueStrike<double> x = first.execute(planned, kRadius);
    EXPECT_TRUE(same(x, second.execute(planned, kRadius))) << "strike " << i;
    EXPECT_FALSE(same(x, other.execute(planned, kRadius))) << "strike " << i;
    EXPECT_FALSE(same(x, planned));
  }
}

TEST(ExecutionNoise, EachParameterIsGaussianWithItsDeviation)
{
  const ExecutionNoise noise;  // the tournament deviations
  NoisyCue cue(noise, 2026);
  const CueStrike<double> planned = plan(4, 1.0, 0.3, 0.1, -0.1);  // far from every limit
  const int n = 40000;
  struct Stat
  {
    double sum = 0, sum2 = 0;
    int within_one_sd = 0;
  };
  Stat stats[5];
  const double sd[5] = {noise.speed, noise.phi, noise.theta, noise.a / kRadius, noise.b / kRadius};
  for (int i = 0; i < n; ++i)
  {
    const CueStrike<double> s = cue.execute(planned, kRadius);
    const double d[5] = {s.speed - planned.speed, s.phi - planned.phi, s.theta - planned.theta, s.a - planned.a,
                         s.b - planned.b};
    for (int k = 0; k < 5; ++k)
    {
      stats[k].sum += d[k];
      stats[k].sum2 += d[k] * d[k];
      stats[k].within_one_sd += std::abs(d[k]) <= sd[k];
    }
  }
  for (int k = 0; k < 5; ++k)
  {
    const double mean = stats[k].sum / n, measured_sd = std::sqrt(stats[k].sum2 / n - mean * mean);
    EXPECT_LT(std::abs(mean), 5 * sd[k] / std::sqrt(n)) << "parameter " << k;
    EXPECT_NEAR(measured_sd / sd[k], 1.0, 0.02) << "parameter " << k;
    // A normal distribution has 68.27 % within one deviation (binomial sd 0.23 % here).
    EXPECT_NEAR(stats[k].within_one_sd / double(n), 0.6827, 0.01) << "parameter " << k;
  }
}

TEST(ExecutionNoise, APlanAtTheLimitsAlwaysGivesAValidStrike)
{
  ExecutionNoise loud;
  loud.speed = 2;
  loud.theta = 0.5;
  loud.a = loud.b = 5e-3;
  NoisyCue cue(loud, 3);
  for (const CueStrike<double>& planned :
       {plan(CueLimits::max_speed, 0, 0, 0.5, 0), plan(0.01, 0, CueLimits::max_elevation, 0, -0.5),
        plan(5, 0, 0, 0.3535533905932738, 0.3535533905932738)})
    for (int i = 0; i < 2000; ++i)
    {
      const CueStrike<double> s = cue.execute(planned, kRadius);
      ASSERT_EQ(validateStrike(s), "") << "strike " << i;
    }
}

TEST(ExecutionNoise, NegativeOrNonFiniteDeviationsAreRefusedByName)
{
  ExecutionNoise noise;
  EXPECT_EQ(noise.validate(), "");
  noise.theta = -1;
  EXPECT_NE(noise.validate().find("theta"), std::string::npos);
  noise = ExecutionNoise();
  noise.b = std::nan("");
  EXPECT_NE(noise.validate().find("noise b"), std::string::npos);
}
