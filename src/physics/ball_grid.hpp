// A uniform grid over the table in which each ball is listed in every cell its path box covers
// (internal to engine_events.cpp): balls whose boxes share no cell cannot meet, so an event
// looks only at the few balls near the ones it changed, however many are on the table.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "cue_sim/physics/types.hpp"

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
    : origin_(low), first_entry_(balls, -1), listed_(balls, Rect{0, -1, 0, -1}), seen_(balls, 0)
  {
    const Vec2<S> size = high - low;
    const S target = std::max<S>(S(1), S(balls) / S(2));
    cell_ = std::max(std::sqrt(size.x() * size.y() / target), S(4) * radius);
    nx_ = std::max(1, static_cast<int>(std::ceil(size.x() / cell_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(size.y() / cell_)));
    head_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), -1);
    entries_.reserve(4 * balls);
  }

  S cell() const { return cell_; }

  void place(int ball, const Vec2<S>& low, const Vec2<S>& high)
  {
    remove(ball);
    Rect& r = listed_[ball];
    r = rectOf(low, high);
    for (int y = r.y0; y <= r.y1; ++y)
      for (int x = r.x0; x <= r.x1; ++x)
      {
        int entry;
        if (free_ >= 0)
        {
          entry = free_;
          free_ = entries_[entry].next;
        }
        else
        {
          entry = static_cast<int>(entries_.size());
          entries_.push_back({});
        }
        const std::size_t cell = index(x, y);
        const int next = head_[cell];
        entries_[entry] = {ball, -1, next, first_entry_[ball], static_cast<int>(cell)};
        if (next >= 0)
          entries_[next].prev = entry;
        head_[cell] = entry;
        first_entry_[ball] = entry;
      }
  }

  void remove(int ball)
  {
    // Each of the ball's entries is unlinked from its cell's list where it stands: no search.
    Rect& r = listed_[ball];
    for (int entry = first_entry_[ball]; entry >= 0;)
    {
      Entry& e = entries_[entry];
      const int following = e.same_ball;
      if (e.prev >= 0)
        entries_[e.prev].next = e.next;
      else
        head_[e.cell] = e.next;
      if (e.next >= 0)
        entries_[e.next].prev = e.prev;
      e.next = free_;
      free_ = entry;
      entry = following;
    }
    first_entry_[ball] = -1;
    r = Rect{0, -1, 0, -1};
  }

  /// Calls visit(o) once for every ball listed in a cell the box covers.
  template <typename Visit>
  void visitBox(const Vec2<S>& low, const Vec2<S>& high, Visit&& visit)
  {
    visitRect(rectOf(low, high), visit);
  }
  /// Calls visit(o) once for every other ball listed in a cell of this ball's box.
  template <typename Visit>
  void visitNear(int ball, Visit&& visit)
  {
    seen_[ball] = stamp_ + 1;
    visitRect(listed_[ball], visit);
  }

private:
  struct Rect
  {
    int x0, x1, y0, y1;
  };
  /// One listing of a ball in a cell: the cells' lists are linked through one pool, so placing
  /// and moving balls does not allocate.
  struct Entry
  {
    int ball = -1;
    int prev = -1, next = -1;  ///< in the cell's list
    int same_ball = -1;        ///< the ball's next entry
    int cell = -1;
  };
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * nx_ + static_cast<std::size_t>(x); }
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
  template <typename Visit>
  void visitRect(const Rect& r, Visit& visit)
  {
    ++stamp_;
    for (int y = r.y0; y <= r.y1; ++y)
      for (int x = r.x0; x <= r.x1; ++x)
        for (int entry = head_[index(x, y)]; entry >= 0; entry = entries_[entry].next)
        {
          const int o = entries_[entry].ball;
          if (seen_[o] != stamp_)
          {
            seen_[o] = stamp_;
            visit(o);
          }
        }
  }

  Vec2<S> origin_;
  S cell_ = S(1);
  int nx_ = 1, ny_ = 1;
  std::vector<int> head_;  ///< first entry of each cell's list, or -1
  std::vector<Entry> entries_;
  int free_ = -1;                 ///< first unused entry
  std::vector<int> first_entry_;  ///< each ball's first entry, or -1
  std::vector<Rect> listed_;
  std::vector<unsigned> seen_;
  unsigned stamp_ = 0;
};

}  // namespace physics
}  // namespace cue_sim
