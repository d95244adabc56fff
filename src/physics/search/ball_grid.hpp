// A uniform grid over the table in which each ball is listed in every cell its path box covers
// (internal to event_search.cpp): balls whose boxes share no cell cannot meet, so an event
// looks only at the few balls near the ones it changed, however many are on the table.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>
#ifdef __SSE__
#include <xmmintrin.h>
#endif

#include "cue_sim/physics/types.hpp"
#include "physics/search/shelves.hpp"

namespace cue_sim
{
namespace physics
{
/// Below this many balls every ball is looked at directly: cheaper than keeping a grid.
constexpr std::size_t kGridFrom = 32;

template <typename S>
class BallGrid
{
public:
  /// Cells of about two balls each, never smaller than four ball radii.
  BallGrid(const Vec2<S>& low, const Vec2<S>& high, std::size_t balls, S radius)
    : origin_(low), listed_(balls, Rect{0, -1, 0, -1})
  {
    const Vec2<S> size = high - low;
    const S target = std::max<S>(S(1), S(balls) / S(2));
    cell_ = std::max(std::sqrt(size.x() * size.y() / target), S(4) * radius);
    // Listings keep their first cell in 16 bits.
    cell_ = std::max({cell_, size.x() / S(kMaxCells), size.y() / S(kMaxCells)});
    nx_ = std::max(1, static_cast<int>(std::ceil(size.x() / cell_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(size.y() / cell_)));
    cells_ = Shelves<Listing>(16, static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_));
  }

  S cell() const { return cell_; }

  /// Room for balls 0 to balls - 1 (a ball placed on the table).
  void reserveBalls(std::size_t balls)
  {
    if (balls > listed_.size())
      listed_.resize(balls, Rect{0, -1, 0, -1});
  }

  void place(int ball, const Vec2<S>& low, const Vec2<S>& high)
  {
    remove(ball);
    Rect& r = listed_[ball];
    r = rectOf(low, high);
    const Listing listing = listingOf(ball, low, high, r);
    for (int y = r.y0; y <= r.y1; ++y)
      for (int x = r.x0; x <= r.x1; ++x)
        cells_.push(index(x, y), listing);
  }

  void remove(int ball)
  {
    const Rect& r = listed_[ball];
    for (int y = r.y0; y <= r.y1; ++y)
      for (int x = r.x0; x <= r.x1; ++x)
      {
        const int c = index(x, y);
        std::size_t i = 0;
        while (cells_.at(c, i).ball != ball)
          ++i;
        cells_.erase(c, i);
      }
    listed_[ball] = Rect{0, -1, 0, -1};
  }

  /// Balls found by a look in the grid, in the grid's own scratch: valid until its next look.
  struct Found
  {
    const int *first, *last;
    const int* begin() const { return first; }
    const int* end() const { return last; }
  };
  /// The balls listed in a cell the box covers whose listed boxes may meet it (compared in
  /// floats rounded outwards: every ball whose box meets it, and rarely one whose box only comes
  /// within a float's rounding of it), each once, in no particular order.
  Found inBox(const Vec2<S>& low, const Vec2<S>& high) const { return collect(rectOf(low, high), low, high, -1); }
  /// The same for the other balls whose boxes may meet this ball's.
  Found near(int ball, const Vec2<S>& low, const Vec2<S>& high) const
  {
    return collect(listed_[ball], low, high, ball);
  }

private:
  static constexpr int kMaxCells = 32000;  ///< per axis
  struct Rect
  {
    int x0, x1, y0, y1;
  };
  /// One listing of a ball in a cell, with its box in floats rounded outwards (24 bytes: a
  /// walk through a cell reads one short array and nothing else). The box is stored as
  /// (low x, low y, -high x, -high y), so that one comparison of four lanes finds whether two
  /// boxes are apart. Rounded outwards, it can only keep a ball the exact test then drops.
  struct Listing
  {
    float bounds[4];
    int ball;
    std::int16_t x0, y0;  ///< the first cell of the ball's listing
  };
  /// A box as compared with listings: (high x, high y, -low x, -low y), rounded outwards.
  struct Query
  {
    float bounds[4];
  };
  /// A float at or below v, and one at or above it: v is moved out by 2^-22 of itself (four
  /// float roundings) and 1e-30, then rounded to the nearest float (no libm call, no branch).
  /// NaN stays NaN, which never culls.
  static float floatBelow(S v) { return static_cast<float>(v - std::abs(v) * S(0x1p-22) - S(1e-30)); }
  static float floatAbove(S v) { return -floatBelow(-v); }
  static Listing listingOf(int ball, const Vec2<S>& low, const Vec2<S>& high, const Rect& r)
  {
    return {{floatBelow(low.x()), floatBelow(low.y()), -floatAbove(high.x()), -floatAbove(high.y())},
            ball,
            static_cast<std::int16_t>(r.x0),
            static_cast<std::int16_t>(r.y0)};
  }
  static Query queryOf(const Vec2<S>& low, const Vec2<S>& high)
  {
    return {{floatAbove(high.x()), floatAbove(high.y()), -floatBelow(low.x()), -floatBelow(low.y())}};
  }
  /// True if the listed box and the queried one are apart on either axis: one comparison of
  /// four lanes where SSE is there.
  static bool apart(const Listing& l, const Query& q)
  {
#ifdef __SSE__
    return _mm_movemask_ps(_mm_cmpgt_ps(_mm_loadu_ps(l.bounds), _mm_loadu_ps(q.bounds))) != 0;
#else
    return (l.bounds[0] > q.bounds[0]) | (l.bounds[1] > q.bounds[1]) | (l.bounds[2] > q.bounds[2]) |
           (l.bounds[3] > q.bounds[3]);
#endif
  }
  int index(int x, int y) const
  {
    return y * nx_ + x;
  }
  /// The cell a coordinate falls in, clamped to the grid (infinite and NaN bounds included).
  static int clampCell(S q, int count, bool upper)
  {
    if (!(q == q))
      return upper ? count - 1 : 0;
    if (q <= S(0))
      return 0;
    if (q >= S(count - 1))
      return count - 1;
    return static_cast<int>(q);
  }
  Rect rectOf(const Vec2<S>& low, const Vec2<S>& high) const
  {
    return Rect{
        clampCell((low.x() - origin_.x()) / cell_, nx_, false), clampCell((high.x() - origin_.x()) / cell_, nx_, true),
        clampCell((low.y() - origin_.y()) / cell_, ny_, false), clampCell((high.y() - origin_.y()) / cell_, ny_, true)};
  }
  Found collect(const Rect& r, const Vec2<S>& low, const Vec2<S>& high, int skip) const
  {
    // Every listing in the cells may be taken: room for all of them, without initialising it.
    std::size_t room = 0;
    for (int y = r.y0; y <= r.y1; ++y)
      for (int x = r.x0; x <= r.x1; ++x)
        room += cells_.size(index(x, y));
    if (taken_.size() < room)
      taken_.resize(2 * room);
    int* const taken = taken_.data();
    std::size_t count = 0;
    const Query query = queryOf(low, high);
    for (int y = r.y0; y <= r.y1; ++y)
    {
      // A ball listed in several of these cells is taken in the first cell the two listings
      // share, and only there: no record of who was seen is needed. A listing in cell (x, y)
      // starts at or before it, so that cell is its first shared one when the listing starts
      // in it, or the walk does.
      const int y_from = y == r.y0 ? std::numeric_limits<int>::min() : y;
      for (int x = r.x0; x <= r.x1; ++x)
      {
        const int x_from = x == r.x0 ? std::numeric_limits<int>::min() : x;
        // Written without branches: whether a listing is taken is as good as random, and a
        // mispredicted branch per listing would cost more than the test.
        const int c = index(x, y);
        for (const Listing *l_it = cells_.begin(c), *l_end = cells_.end(c); l_it != l_end; ++l_it)
        {
          const Listing& l = *l_it;
          taken[count] = l.ball;
          count += static_cast<std::size_t>((l.x0 >= x_from) & (l.y0 >= y_from) & !apart(l, query) & (l.ball != skip));
        }
      }
    }
    return {taken, taken + count};
  }

  Vec2<S> origin_;
  S cell_ = S(1);
  int nx_ = 1, ny_ = 1;
  /// Each cell's listings, 16 to a cell at first (a cell holds about seven).
  Shelves<Listing> cells_{16};
  std::vector<Rect> listed_;        ///< the cells each ball is listed in (none: x1 < x0)
  mutable std::vector<int> taken_;  ///< scratch for collect()
};

}  // namespace physics
}  // namespace cue_sim
