// The root finder against roots known in advance.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cue_sim/physics/polynomial.hpp"

using cue_sim::physics::firstDownCrossing;
using cue_sim::physics::Poly4;
using cue_sim::physics::polyRootsIn;

namespace
{
/// Coefficients (ascending) of lead * prod (x - r_i).
Poly4<double> fromRoots(const std::vector<double>& roots, double lead = 1.0)
{
  std::vector<double> c = {lead};
  for (double r : roots)
  {
    std::vector<double> next(c.size() + 1, 0.0);
    for (std::size_t i = 0; i < c.size(); ++i)
    {
      next[i + 1] += c[i];
      next[i] -= r * c[i];
    }
    c = next;
  }
  Poly4<double> out{};
  for (std::size_t i = 0; i < c.size(); ++i)
    out[i] = c[i];
  return out;
}

std::vector<double> roots(const Poly4<double>& c, double lo, double hi)
{
  double r[4];
  const int n = polyRootsIn(c, lo, hi, r);
  return std::vector<double>(r, r + n);
}

void expectRoots(const std::vector<double>& got, const std::vector<double>& want, double tolerance)
{
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i)
    EXPECT_NEAR(got[i], want[i], tolerance) << "root " << i;
}
}  // namespace

TEST(Polynomial, FourSimpleRoots)
{
  expectRoots(roots(fromRoots({1, 2, 3, 4}), -10, 10), {1, 2, 3, 4}, 1e-14);
  expectRoots(roots(fromRoots({-3.5, 0.25, 1e-3, 7}, -2.0), -10, 10), {-3.5, 1e-3, 0.25, 7}, 1e-13);
}

TEST(Polynomial, OnlyRootsInsideTheInterval)
{
  expectRoots(roots(fromRoots({1, 2, 3, 4}), 1.5, 3.5), {2, 3}, 1e-14);
  expectRoots(roots(fromRoots({1, 2, 3, 4}), 4.5, 9), {}, 0);
}

TEST(Polynomial, DoubleRootsAreFoundOnce)
{
  expectRoots(roots(fromRoots({1, 1, 3, -2}), -10, 10), {-2, 1, 3}, 1e-12);
  expectRoots(roots(fromRoots({0.5, 0.5, 0.5, 0.5}), -10, 10), {0.5}, 1e-3);
  expectRoots(roots(fromRoots({2, 2}), -10, 10), {2}, 1e-14);
  // x^2 + 1: no real root at all.
  expectRoots(roots({1, 0, 1, 0, 0}, -10, 10), {}, 0);
}

TEST(Polynomial, ZeroLeadingCoefficientsReduceTheDegree)
{
  expectRoots(roots(fromRoots({-1, 2, 5}), -10, 10), {-1, 2, 5}, 1e-13);  // cubic
  expectRoots(roots(fromRoots({0.3, 4}), -10, 10), {0.3, 4}, 1e-14);      // quadratic
  expectRoots(roots({-3, 2, 0, 0, 0}, -10, 10), {1.5}, 0);                // linear
  expectRoots(roots({5, 0, 0, 0, 0}, -10, 10), {}, 0);                    // constant
  expectRoots(roots({0, 0, 0, 0, 0}, -10, 10), {}, 0);                    // zero
}

TEST(Polynomial, TinyLeadingCoefficientOnlyAddsFarRoots)
{
  // 1e-20 x^4 + (x - 1)(x - 2): its other two roots are near +-1e10, outside the interval.
  Poly4<double> c = fromRoots({1, 2});
  c[4] = 1e-20;
  expectRoots(roots(c, 0, 100), {1, 2}, 1e-12);
}

TEST(Polynomial, FirstDownCrossing)
{
  // (x - 1)(x - 2): positive before 1, negative between.
  EXPECT_NEAR(firstDownCrossing(fromRoots({1, 2}), 0.0, 10.0), 1.0, 1e-15);
  // Negative at the start: the first crossing after it has become positive again.
  EXPECT_NEAR(firstDownCrossing(fromRoots({1, 2, 3, 4}), 1.5, 10.0), 3.0, 1e-14);
  // Grazing (x - 1)^2 never goes negative: no crossing.
  EXPECT_TRUE(std::isinf(firstDownCrossing(fromRoots({1, 1}), 0.0, 10.0)));
  // Just below a graze: (x - 1)^2 - 1e-12 crosses at 1 - 1e-6. The root is ill-conditioned:
  // storing 1 - 1e-12 rounds it by up to 1.1e-16, which moves the root by 1.1e-16 / p'(root)
  // = 1.1e-16 / 2e-6 = 5.5e-11, so that is all the accuracy there is to ask for.
  Poly4<double> near_graze = fromRoots({1, 1});
  near_graze[0] -= 1e-12;
  EXPECT_NEAR(firstDownCrossing(near_graze, 0.0, 10.0), 1.0 - 1e-6, 6e-11);
  // The same in long double, whose rounding is 2048 times finer.
  const Poly4<long double> near_graze_exact = {1.0L - 1e-12L, -2.0L, 1.0L, 0.0L, 0.0L};
  EXPECT_NEAR(static_cast<double>(firstDownCrossing(near_graze_exact, 0.0L, 10.0L)), 1.0 - 1e-6, 1e-13);
  // Beyond the interval: none.
  EXPECT_TRUE(std::isinf(firstDownCrossing(fromRoots({1, 2}), 0.0, 0.5)));
}

TEST(Polynomial, LongDoubleAgrees)
{
  long double r[4];
  const Poly4<long double> c = {24.0L, -50.0L, 35.0L, -10.0L, 1.0L};
  ASSERT_EQ(polyRootsIn(c, -10.0L, 10.0L, r), 4);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(static_cast<double>(r[i]), i + 1.0, 1e-17);
}
