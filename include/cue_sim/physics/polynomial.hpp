// Real roots of polynomials up to degree 4 on an interval, for event detection.
//
// Instead of closed-form Ferrari/Cardano (which lose accuracy near double roots and blow up
// when the leading coefficient is tiny), the roots of p are isolated between the roots of p'
// (found recursively; a quadratic's in closed form) and each bracket is solved by safeguarded
// Newton. On each bracket p is monotonic, so the method cannot miss or duplicate a simple
// root; a tiny leading coefficient only moves roots far outside the interval; a double root
// appears as a critical point where |p| is within its rounding error. The approach is that of
// interval-restricted root isolation (see Strobach 2010; Orellana and De Michele, ACM TOMS
// Algorithm 1010, 2020, for the numerical pitfalls).
#pragma once

#include <array>
#include <cstddef>

namespace cue_sim
{
namespace physics
{
/// p(x) = c[0] + c[1] x + c[2] x^2 + c[3] x^3 + c[4] x^4.
template <typename S>
using Poly4 = std::array<S, 5>;

template <typename S>
S evaluatePoly(const Poly4<S>& c, S x);

/// Up to 4 real roots in [lo, hi], ascending, each multiple root once. Returns their count.
/// An identically zero polynomial has no isolated roots and returns 0.
template <typename S>
int polyRootsIn(const Poly4<S>& c, S lo, S hi, S* roots);

/// The first x in (lo, hi] at which p passes from positive to non-positive, or +inf: the
/// moment a gap function (distance minus contact distance) closes. A touch without a sign
/// change (grazing) is not a crossing. If p(lo) <= 0 the first crossing after p has become
/// positive is returned.
template <typename S>
S firstDownCrossing(const Poly4<S>& c, S lo, S hi);

}  // namespace physics
}  // namespace cue_sim
