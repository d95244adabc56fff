#include "physics/search/airborne_walls.hpp"

#include <algorithm>
#include <cmath>

#include "physics/models/flight.hpp"
#include "physics/search/contact_times.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// A post's rim is searched on this many samples of the time the ball is within its reach, then
/// by bisection to the last bit. A graze between two samples that the samples miss is shallower
/// than (the interval / this)^2 |f''| / 8: under a nanometre for any flight on a table.
constexpr int kRimSamples = 64;

/// The search for one flying ball: each wall is searched up to the earliest event found so far.
template <typename S>
class AirborneWallSearch
{
public:
  AirborneWallSearch(const Trajectory<S>& path, S base, const TableGeometry<S>& geometry, S R, Candidate<S>& first,
                     const std::vector<WallTouch>* touching)
    : p_(path), base_(base), g_(geometry), R_(R), first_(first), touching_(touching)
  {
  }

  void run()
  {
    // A ball in the air beyond the table's edge (placed there) falls to the floor now, where it is.
    if (!touching_ && !((p_.c0.array() >= g_.edge_low.array()).all() && (p_.c0.array() <= g_.edge_high.array()).all()))
    {
      keep(S(0), Candidate<S>::Overboard, 0);
      return;
    }
    // Beyond both cushions' lines at once, clear of the noses and coming down there (placed over
    // a corner's rail, or behind a corner pocket outside its capture circle): no cushion's line
    // runs beside it for a segment to find it over its top, so it comes down now where
    // departureOf says.
    if (!touching_ && aboveTop(S(0)) > S(0) && beyondBothCushionLines() && !inACaptureCircle() &&
        comesDownBeyondTheCushions())
    {
      keep(S(0), Candidate<S>::Overboard, 0);
      return;
    }
    // A flight that stays in the clear box about the cloth's centre meets no wall.
    bool clear = true;
    for (int axis = 0; axis < 2 && clear; ++axis)
    {
      const Poly4<S> x = {p_.c0[axis], p_.c1[axis], p_.c2[axis], S(0), S(0)};
      clear = lowest(x) > g_.clear_low[axis] && highest(x) < g_.clear_high[axis];
    }
    // (A pocket's capture circle may reach into it: pockets are searched whatever the box.)
    if (!clear)
    {
      for (std::size_t k = 0; k < g_.segments.size(); ++k)
        if (!touches(k, false))
          segment(g_.segments[k], k);
      for (std::size_t k = 0; k < g_.circles.size(); ++k)
        if (!touches(k, true))
          post(g_.circles[k], k);
    }
    for (std::size_t k = 0; k < g_.pockets.size(); ++k)
      pocket(g_.pockets[k], k);
  }

private:
  using Segment = typename TableGeometry<S>::Segment;

  bool touches(std::size_t k, bool post) const
  {
    if (!touching_)
      return false;
    return std::any_of(touching_->begin(), touching_->end(), [&](const WallTouch& w) {
      const bool is_post = w.surface == Surface::PostSide || w.surface == Surface::Rim;
      return is_post == post && w.index == static_cast<int>(k);
    });
  }
  using Circle = typename TableGeometry<S>::Circle;

  S limit() const
  {
    const S end = first_.time - base_;
    return std::isfinite(static_cast<double>(end)) ? end : kEndlessHorizon<S>;
  }
  /// The least and the greatest of c0 + c1 tau + c2 tau^2 over [0, limit].
  S lowest(const Poly4<S>& c) const { return extreme(c, false); }
  S highest(const Poly4<S>& c) const { return extreme(c, true); }
  S extreme(const Poly4<S>& c, bool greatest) const
  {
    const S T = limit();
    S best = c[0];
    const auto take = [&](S x) { best = greatest ? std::max(best, x) : std::min(best, x); };
    take(evaluatePoly(c, T));
    if (c[2] != S(0))
    {
      const S vertex = -c[1] / (S(2) * c[2]);
      if (vertex > S(0) && vertex < T)
        take(evaluatePoly(c, vertex));
    }
    return best;
  }

  /// Whether the centre is beyond the cushions' lines on both axes now (a corner).
  bool beyondBothCushionLines() const
  {
    const auto beyond = [&](int axis) { return p_.c0[axis] < g_.cloth_low[axis] || p_.c0[axis] > g_.cloth_high[axis]; };
    return beyond(0) && beyond(1);
  }
  bool inACaptureCircle() const
  {
    for (const Circle& pocket : g_.pockets)
      if ((p_.c0 - pocket.centre).squaredNorm() < pocket.radius * pocket.radius)
        return true;
    return false;
  }
  /// Whether the flight comes down to the rails' top (where departureOf lands it) beyond the
  /// cushions' lines, rather than back over the cloth: a ball placed over a rail and thrown
  /// towards the table flies over the nose and lands on the cloth.
  bool comesDownBeyondTheCushions() const
  {
    S tau = timeToHeight(R_ + p_.h0, p_.h1, R_ + g_.rail_height, S(-2) * p_.h2);
    if (!std::isfinite(static_cast<double>(tau)))
      tau = S(0);  // below the rails' top already: it comes down where it is
    const Vec2<S> spot = p_.at(tau);
    return !((spot.array() >= g_.cloth_low.array()).all() && (spot.array() <= g_.cloth_high.array()).all());
  }
  /// The centre's height above the walls' top at tau (the path's height is the ball's lowest
  /// point's, R below the centre).
  S aboveTop(S tau) const { return p_.heightAt(tau) + R_ - g_.nose_height; }

  void segment(const Segment& seg, std::size_t k)
  {
    const Vec2<S> rel = p_.c0 - seg.start;
    const Poly4<S> across = {seg.normal.dot(rel), seg.normal.dot(p_.c1), seg.normal.dot(p_.c2), S(0), S(0)};
    const Poly4<S> along = {seg.direction.dot(rel), seg.direction.dot(p_.c1), seg.direction.dot(p_.c2), S(0), S(0)};
    // Every meeting (face, edge, over) needs the centre within R in front of the line and beside
    // it, or, for a flight over the line, beside it or its jaws.
    const S ends = R_ + g_.widest_post;
    if (lowest(across) > R_ + S(kBoxMargin) || lowest(along) > seg.length + ends || highest(along) < -ends)
      return;
    const auto beside = [&](S tau) {
      const S along = seg.direction.dot(p_.at(tau) - seg.start);
      return along >= S(0) && along <= seg.length;
    };
    // The face: the centre R in front of the cushion's line, at or below its top.
    const Poly4<S> face = {across[0] - R_, across[1], across[2], S(0), S(0)};
    const S tau_face = contactTime(face, limit(), -zeroSpeed<S>(), touchTolerance(R_), true);
    if (tau_face <= limit() && beside(tau_face) && aboveTop(tau_face) <= S(0))
      keep(tau_face, Candidate<S>::Segment, k);
    // The nose's edge: the centre R from the line along the top of the face, in front of the
    // face and above its top: across^2 + above^2 - R^2, a quartic.
    const Poly4<S> edge = distanceGap<S>(Vec2<S>(across[0], S(0)), Vec2<S>(across[1], S(0)), Vec2<S>(across[2], S(0)),
                                         p_.h0 + R_ - g_.nose_height, p_.h1, p_.h2, R_);
    const S edge_touch = touchTolerance(R_ * R_);
    // Within the edge's reach at the start, beyond the cushion's end (over its jaw, which meets it
    // there): the edge is met where the gap next comes down through zero beside the cushion. The
    // gap's return to its start, which contactTime takes for a touching ball, is later, and the
    // ball 0.3 mm into the nose's edge by then (a ball off a jaw onto the next cushion's edge).
    const bool within_reach = edge[0] < -edge_touch && !beside(S(0));
    S from = S(0);
    for (int root = 0; root < 4; ++root)
    {
      // Touching and pressed on by gravity, it is met now (as a ball pressed on a cushion is).
      const S tau = root == 0 && !within_reach
                        ? contactTime(edge, limit(), -S(2) * R_ * zeroSpeed<S>(), edge_touch, true)
                        : firstDownCrossing(edge, from, limit());
      if (!(tau <= limit()))
        break;
      if (evaluatePoly(across, tau) >= S(0) && aboveTop(tau) > S(0) && beside(tau))
      {
        keep(tau, Candidate<S>::Segment, k);
        break;
      }
      // Touching the edge's reach at the start and not met there (low beside a pocket's mouth,
      // where the jaw is met instead): the first root found may be the gap's return to its start,
      // not its crossing. The search starts again from the start for the ball coming down onto
      // the edge once beside the cushion.
      if (root == 0 && !within_reach && edge[0] <= edge_touch)
        continue;
      if (!(tau > from))
        break;
      from = tau;
    }
    // Over the top: the centre crosses the nose's line above it, beside the cushion or over the
    // jaws and posts at its ends (where a flight over them would otherwise come down behind the
    // cushion's line; where the ball lands, a pocket included, departureOf decides).
    if (across[0] <= S(0) && aboveTop(S(0)) > S(0) && along[0] >= -ends && along[0] <= seg.length + ends &&
        comesDownBeyondTheCushions())
      keep(S(0), Candidate<S>::Overboard, k);  // over the cushion's top already (placed there)
    else if (across[0] > S(0))
    {
      const S tau = firstDownCrossing(across, S(0), limit());
      const S at = evaluatePoly(along, tau);
      if (tau <= limit() && at >= -ends && at <= seg.length + ends && aboveTop(tau) > S(0))
        keep(tau, Candidate<S>::Overboard, k);
    }
  }

  /// The squared distance from the centre to a post of radius rho at `centre` (its side, its rim
  /// or its top, whichever is nearest), less R^2.
  S postGap(const Circle& post, S tau) const
  {
    const S side = std::max((p_.at(tau) - post.centre).norm() - post.radius, S(0));
    const S above = std::max(aboveTop(tau), S(0));
    return side * side + above * above - R_ * R_;
  }

  void post(const Circle& post, std::size_t k)
  {
    const S reach = R_ + post.radius;
    const Vec2<S> rel = p_.c0 - post.centre;
    if (cannotMeet<S>(rel, p_.c1, p_.c2, reach, limit()))
      return;
    const Poly4<S> within = distanceGap<S>(rel, p_.c1, p_.c2, reach);
    const S touch = touchTolerance(reach * reach);
    // The times the centre is within reach of the post's axis: from `enter` to the next root.
    S enter = S(0);
    if (within[0] > touch)
      enter = firstDownCrossing(within, S(0), limit());
    else if (aboveTop(S(0)) <= S(0))
    {
      // Touching its side now, at or below its top: pressed or closing, met now, as on the cloth.
      const S now = contactTime(within, limit(), -S(2) * reach * zeroSpeed<S>(), touch, true);
      if (now == S(0))
      {
        keep(now, Candidate<S>::Circle, k);
        return;
      }
      // Moving off its side: met again only once back within reach.
      if (within[1] > S(0))
        enter = firstDownCrossing(within, S(0), limit());
    }
    for (int pass = 0; pass < 3 && enter <= limit(); ++pass)
    {
      if (enter > S(0) && aboveTop(enter) <= S(0))
      {
        keep(enter, Candidate<S>::Circle, k);  // its side, found on the gap quartic
        return;
      }
      // Within reach: the side (coming down beside it), the rim or the top.
      // Out of reach again where the gap rises through zero (a root at `enter` itself, where it
      // touches, is not that).
      const Poly4<S> outside = {-within[0], -within[1], -within[2], -within[3], -within[4]};
      const S leave = std::min(firstDownCrossing(outside, enter, limit()), limit());
      S tau;
      if (rimContact(post, enter, leave, tau))
      {
        keep(tau, Candidate<S>::Circle, k);
        return;
      }
      enter = firstDownCrossing(within, leave, limit());
    }
  }

  /// The first contact with the post's rim or top in [lo, hi]. At lo the ball may be touching it
  /// (just off it): that is a contact only if it moves into the post.
  bool rimContact(const Circle& post, S lo, S hi, S& tau) const
  {
    const S touch = touchTolerance(R_ * R_);
    if (postGap(post, lo) <= touch && closingOnPost(post, lo))
    {
      tau = lo;
      return true;
    }
    S apart = postGap(post, lo) > touch ? lo : -S(1);
    for (int i = 1; i <= kRimSamples; ++i)
    {
      const S t = lo + (hi - lo) * S(i) / S(kRimSamples);
      const S gap = postGap(post, t);
      if (gap > touch)
        apart = t;
      else if (apart >= S(0) && gap <= S(0))
      {
        tau = bisect(post, apart, t);
        return true;
      }
      else if (apart < S(0) && gap < -touch)
      {
        tau = backOnPost(post, lo, t, touch);
        return true;
      }
    }
    return false;
  }

  /// Touching the post at lo, moving off it (not closing), and inside it at `inside`: gravity
  /// brings it back within the first sample. The moment it is back, found by halving towards lo
  /// until it is seen apart; lo if it never is (pressed into it, met now).
  S backOnPost(const Circle& post, S lo, S inside, S touch) const
  {
    for (;;)
    {
      const S mid = lo + (inside - lo) / S(2);
      if (!(mid > lo && mid < inside))
        return lo;
      if (postGap(post, mid) > touch)
        return bisect(post, mid, inside);
      inside = mid;
    }
  }

  /// Whether the ball moves into the post's rim or top at tau.
  bool closingOnPost(const Circle& post, S tau) const
  {
    const Vec2<S> out = p_.at(tau) - post.centre;
    const S side = std::max(out.norm() - post.radius, S(0));
    const Vec2<S> v = p_.velocityAt(tau);
    const S radial = side > S(0) ? v.dot(out.normalized()) : S(0);
    const S vertical = p_.h1 + S(2) * tau * p_.h2;
    return side * radial + std::max(aboveTop(tau), S(0)) * vertical < -R_ * zeroSpeed<S>();
  }

  /// The first moment in (lo, hi] at which postGap reaches zero, given it is positive at lo and not at hi.
  S bisect(const Circle& post, S lo, S hi) const
  {
    for (;;)
    {
      const S mid = lo + (hi - lo) / S(2);
      if (!(mid > lo && mid < hi))
        return hi;
      (postGap(post, mid) > S(0) ? lo : hi) = mid;
    }
  }

  void pocket(const Circle& pocket, std::size_t k)
  {
    const Vec2<S> rel = p_.c0 - pocket.centre;
    // In the capture circle already (placed there, over the pocket): it drops in, or, above the
    // noses, wherever departureOf says it comes down.
    if (!touching_ && rel.squaredNorm() < pocket.radius * pocket.radius)
    {
      keep(S(0), Candidate<S>::Pocket, k);
      return;
    }
    if (cannotMeet<S>(rel, p_.c1, p_.c2, pocket.radius, limit()))
      return;
    const S tau = contactTime(distanceGap<S>(rel, p_.c1, p_.c2, pocket.radius), limit(), S(0),
                              touchTolerance(pocket.radius * pocket.radius));
    if (tau <= limit())
      keep(tau, Candidate<S>::Pocket, k);
  }

  void keep(S tau, typename Candidate<S>::Rank rank, std::size_t k)
  {
    Candidate<S> c;
    c.time = base_ + tau;
    c.rank = rank;
    c.ball = first_.ball;
    c.obstacle = static_cast<int>(k);
    if (c.before(first_))
      first_ = c;
  }

  const Trajectory<S>& p_;
  const S base_;
  const TableGeometry<S>& g_;
  const S R_;
  Candidate<S>& first_;
  const std::vector<WallTouch>* touching_;
};
}  // namespace

template <typename S>
void findAirborneWallEvents(const Trajectory<S>& path, S base, const TableGeometry<S>& geometry, S ball_radius,
                            Candidate<S>& first, const std::vector<WallTouch>* touching)
{
  AirborneWallSearch<S>(path, base, geometry, ball_radius, first, touching).run();
}

template void findAirborneWallEvents(const Trajectory<double>&, double, const TableGeometry<double>&, double,
                                     Candidate<double>&, const std::vector<WallTouch>*);
template void findAirborneWallEvents(const Trajectory<long double>&, long double, const TableGeometry<long double>&,
                                     long double, Candidate<long double>&, const std::vector<WallTouch>*);

}  // namespace physics
}  // namespace cue_sim
