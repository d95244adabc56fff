#include "cue_sim/physics/polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cue_sim/physics/types.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
S evaluatePoly(const Poly4<S>& c, S x)
{
  return (((c[4] * x + c[3]) * x + c[2]) * x + c[1]) * x + c[0];
}

namespace
{
template <typename S>
int degreeOf(const Poly4<S>& c)
{
  for (int d = 4; d >= 0; --d)
    if (c[d] != S(0))
      return d;
  return -1;
}

template <typename S>
Poly4<S> derivativeOf(const Poly4<S>& c)
{
  return {c[1], S(2) * c[2], S(3) * c[3], S(4) * c[4], S(0)};
}

/// Bound on the rounding error of Horner's rule at x (Higham, "Accuracy and Stability of
/// Numerical Algorithms", 5.1): within it, the computed sign of p(x) means nothing.
template <typename S>
S roundingBound(const Poly4<S>& c, S x)
{
  const S ax = std::abs(x);
  S sum = S(0);
  for (int i = 4; i >= 0; --i)
    sum = sum * ax + std::abs(c[i]);
  return S(10) * std::numeric_limits<S>::epsilon() * sum;
}

/// The root of p in (lo, hi), where p(lo) and p(hi) have opposite non-zero signs and p is
/// monotonic: Newton steps, falling back to bisection whenever Newton leaves the bracket or
/// does not halve the step (as in Numerical Recipes' rtsafe).
template <typename S>
S solveBracket(const Poly4<S>& c, const Poly4<S>& dc, S lo, S hi, S p_lo)
{
  const bool rising = p_lo < S(0);
  S x = S(0.5) * (lo + hi);
  S step_before_last = hi - lo;
  S last_step = step_before_last;
  for (int iteration = 0; iteration < 200; ++iteration)
  {
    const S px = evaluatePoly(c, x);
    if (px == S(0))
      return x;
    if ((px < S(0)) == rising)
      lo = x;
    else
      hi = x;
    const S slope = evaluatePoly(dc, x);
    S next = x - px / slope;
    const bool newton_ok = next > lo && next < hi && std::abs(S(2) * px) < std::abs(step_before_last * slope);
    if (!newton_ok)
      next = S(0.5) * (lo + hi);
    step_before_last = last_step;
    last_step = next - x;
    const S tolerance = S(2) * std::numeric_limits<S>::epsilon() * std::max(std::abs(next), std::abs(x)) +
                        std::numeric_limits<S>::denorm_min();
    if (std::abs(next - x) <= tolerance || next == lo || next == hi)
      return next;
    x = next;
  }
  return x;
}

template <typename S>
void addRoot(S x, S lo, S hi, S* roots, int& count)
{
  if (!(x >= lo && x <= hi))
    return;
  for (int i = 0; i < count; ++i)
    if (roots[i] == x)
      return;
  roots[count++] = x;
}

/// Degree <= 2 in closed form; a negative discriminant within rounding of zero is a double
/// root at the vertex, so grazing is decided the same way as for higher degrees.
template <typename S>
int lowDegreeRoots(const Poly4<S>& c, int degree, S lo, S hi, S* roots)
{
  int count = 0;
  if (degree == 1)
  {
    addRoot(-c[0] / c[1], lo, hi, roots, count);
    return count;
  }
  const S a = c[2], b = c[1], k = c[0];
  const S discriminant = b * b - S(4) * a * k;
  const S vertex = -b / (S(2) * a);
  if (discriminant < S(0))
  {
    if (std::abs(evaluatePoly(c, vertex)) <= roundingBound(c, vertex))
      addRoot(vertex, lo, hi, roots, count);
    return count;
  }
  // The stable pair of formulas: no cancellation between b and the square root.
  const S q = S(-0.5) * (b + std::copysign(std::sqrt(discriminant), b));
  S x1 = q / a;
  S x2 = q != S(0) ? k / q : x1;
  if (x2 < x1)
    std::swap(x1, x2);
  addRoot(x1, lo, hi, roots, count);
  addRoot(x2, lo, hi, roots, count);
  return count;
}

/// lo, the critical points of p inside (lo, hi), and hi: p is monotonic between neighbours.
template <typename S>
int monotonicBreakpoints(const Poly4<S>& c, S lo, S hi, S* points)
{
  S critical[4];
  const int n_critical = polyRootsIn(derivativeOf(c), lo, hi, critical);
  int n = 0;
  points[n++] = lo;
  for (int i = 0; i < n_critical; ++i)
    if (critical[i] > lo && critical[i] < hi)
      points[n++] = critical[i];
  points[n++] = hi;
  return n;
}

}  // namespace

template <typename S>
int polyRootsIn(const Poly4<S>& c, S lo, S hi, S* roots)
{
  const int degree = degreeOf(c);
  if (degree <= 0 || !(lo <= hi))
    return 0;
  if (degree <= 2)
    return lowDegreeRoots(c, degree, lo, hi, roots);

  S points[6];
  const int n_points = monotonicBreakpoints(c, lo, hi, points);
  const Poly4<S> dc = derivativeOf(c);
  int count = 0;
  S previous_value = evaluatePoly(c, points[0]);
  if (previous_value == S(0))
    addRoot(points[0], lo, hi, roots, count);
  for (int i = 1; i < n_points; ++i)
  {
    const S x = points[i];
    S value = evaluatePoly(c, x);
    const bool interior_critical = i + 1 < n_points;
    // A critical point where p is within rounding of zero is a multiple root.
    if (interior_critical && std::abs(value) <= roundingBound(c, x))
      value = S(0);
    if (previous_value != S(0) && value != S(0) && (previous_value < S(0)) != (value < S(0)))
      addRoot(solveBracket(c, dc, points[i - 1], x, previous_value), lo, hi, roots, count);
    if (value == S(0))
      addRoot(x, lo, hi, roots, count);
    previous_value = value;
  }
  std::sort(roots, roots + count);
  return count;
}

template <typename S>
S firstDownCrossing(const Poly4<S>& c, S lo, S hi)
{
  const int degree = degreeOf(c);
  if (degree <= 0 || !(lo < hi))
    return infinity<S>();
  S points[6];
  int n_points = 2;
  points[0] = lo;
  points[1] = hi;
  if (degree >= 2)
    n_points = monotonicBreakpoints(c, lo, hi, points);
  const Poly4<S> dc = derivativeOf(c);
  S previous_value = evaluatePoly(c, points[0]);
  for (int i = 1; i < n_points; ++i)
  {
    S value = evaluatePoly(c, points[i]);
    // A minimum within rounding of zero is a graze, not a crossing: p touches zero and rises.
    if (i + 1 < n_points && previous_value > S(0) && std::abs(value) <= roundingBound(c, points[i]))
      continue;
    if (previous_value > S(0) && value <= S(0))
      return value == S(0) ? points[i] : solveBracket(c, dc, points[i - 1], points[i], previous_value);
    previous_value = value;
  }
  return infinity<S>();
}

template double evaluatePoly(const Poly4<double>&, double);
template long double evaluatePoly(const Poly4<long double>&, long double);
template int polyRootsIn(const Poly4<double>&, double, double, double*);
template int polyRootsIn(const Poly4<long double>&, long double, long double, long double*);
template double firstDownCrossing(const Poly4<double>&, double, double);
template long double firstDownCrossing(const Poly4<long double>&, long double, long double);

}  // namespace physics
}  // namespace cue_sim
