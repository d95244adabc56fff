// The queue of candidate events of Engine::advance (internal to engine_events.cpp): each ball
// keeps the candidates found for it, and a tournament tree over the balls keeps each ball's
// earliest. An event walks a few levels of the tree, each one cache line: their number follows
// the number of balls, not of candidates waiting (5 levels at 1024 balls, where one binary heap of
// all candidates had 11 to 13).
//
// A candidate is filed under a ball it involves. When a ball changes, everything filed under it
// is dropped at once; what is filed under other balls and involves it is stale from then on (each
// entry carries the versions of its balls) and is dropped when it comes up. This is the classic
// arrangement of event-driven molecular dynamics (Marin, Risso and Cordero 1993, "Efficient
// algorithms for many-body hard particle molecular dynamics", J. Comput. Phys. 109, 306).
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace cue_sim
{
namespace physics
{
/// Candidate needs `time`, `ball`, `other` (-1 if none) and a strict order `before`.
template <typename Candidate>
class EventQueue
{
public:
  explicit EventQueue(std::size_t balls) : filed_(balls), version_(balls, 0), waiting_(balls, 0)
  {
    std::size_t leaves = 1;
    while (leaves < balls)
    {
      first_leaf_ += leaves;
      leaves *= 4;
    }
    earliest_slot_.assign(leaves, -1);
    groups_.assign((first_leaf_ + leaves + 2) / 4, Group{});
    for (std::size_t i = 0; i < leaves; ++i)
      node(first_leaf_ + i).ball = static_cast<int>(i);
    for (std::size_t k = first_leaf_; k-- > 0;)
      node(k) = groups_[k].node[0];  // all empty: the first child stands for them
  }

  /// Files a candidate under `ball`, which it must involve (as its ball or its other).
  void file(int ball, const Candidate& candidate)
  {
    filed_.push(ball, {candidate, version_[candidate.ball], candidate.other >= 0 ? version_[candidate.other] : 0u});
    markWaiting(ball);
  }

  /// The ball has changed: every candidate involving it is void.
  void changed(int ball)
  {
    ++version_[ball];
    filed_.clear(ball);
    markWaiting(ball);
  }

  /// The earliest candidate still valid, or null if none is left. Valid until the next call.
  const Candidate* top()
  {
    for (;;)
    {
      settleWaiting();
      const int ball = root_.ball;
      const int slot = earliest_slot_[ball];
      if (slot < 0)
        return nullptr;
      const Entry& entry = filed_.at(ball, slot);
      if (!stale(entry))
        return &entry.candidate;
      markWaiting(ball);  // its earliest is stale: look again among the rest
    }
  }

  /// Removes the candidate top() returned.
  void pop()
  {
    const int ball = root_.ball;
    filed_.erase(ball, earliest_slot_[ball]);
    markWaiting(ball);
  }

private:
  struct Entry
  {
    Candidate candidate;
    unsigned version, other_version;
  };
  /// A match of the tournament: the ball whose earliest candidate is earliest in the subtree,
  /// and that candidate's time (+inf if none).
  struct Node
  {
    double time = std::numeric_limits<double>::infinity();
    int ball = 0;
  };
  /// The four matches under one node, in one cache line.
  struct alignas(64) Group
  {
    Node node[4];
  };

  bool stale(const Entry& e) const
  {
    return e.version != version_[e.candidate.ball] ||
           (e.candidate.other >= 0 && e.other_version != version_[e.candidate.other]);
  }
  void markWaiting(int ball)
  {
    if (!waiting_[ball])
    {
      waiting_[ball] = 1;
      waiting_list_.push_back(ball);
    }
  }
  /// Finds each waiting ball's earliest valid candidate (dropping the stale ones), then replays
  /// their matches up the tree: first all leaves, so that no match compares a candidate that
  /// has moved.
  void settleWaiting()
  {
    for (int ball : waiting_list_)
    {
      waiting_[ball] = 0;
      int slot = -1;
      for (int i = 0; i < filed_.size(ball);)
      {
        if (stale(filed_.at(ball, i)))
        {
          filed_.erase(ball, i);
          continue;
        }
        if (slot < 0 || filed_.at(ball, i).candidate.before(filed_.at(ball, slot).candidate))
          slot = i;
        ++i;
      }
      earliest_slot_[ball] = slot;
      node(first_leaf_ + static_cast<std::size_t>(ball)).time =
          slot < 0 ? std::numeric_limits<double>::infinity()
                   : static_cast<double>(filed_.at(ball, slot).candidate.time);
    }
    for (int ball : waiting_list_)
      replay(ball);
    waiting_list_.clear();
  }
  /// Node k of the tree: 0 is the final, and node k's four matches are group k, nodes 4k+1 to
  /// 4k+4.
  Node& node(std::size_t k) { return k == 0 ? root_ : groups_[(k - 1) / 4].node[(k - 1) % 4]; }
  /// Replays the matches above the ball's leaf, up to the first whose result stands (another
  /// ball's, unchanged: nothing above it can change either).
  void replay(int ball)
  {
    std::size_t k = first_leaf_ + static_cast<std::size_t>(ball);
    while (k > 0)
    {
      k = (k - 1) / 4;
      const Node& won = winner(groups_[k]);
      Node& result = node(k);
      if (won.ball != ball && won.ball == result.ball && won.time == result.time)
        return;
      result = won;
    }
  }
  /// The earliest of four matches: by time without branches, and by the full order only when
  /// two share the earliest time.
  const Node& winner(const Group& g) const
  {
    const Node* c = g.node;
    const int first_pair = c[1].time < c[0].time ? 1 : 0;
    const int second_pair = c[3].time < c[2].time ? 3 : 2;
    const int w = c[second_pair].time < c[first_pair].time ? second_pair : first_pair;
    const double t = c[w].time;
    const int sharing = (c[0].time == t) + (c[1].time == t) + (c[2].time == t) + (c[3].time == t);
    if (sharing == 1 || t == std::numeric_limits<double>::infinity())
      return c[w];
    int best = 0;
    for (int j = 1; j < 4; ++j)
      if (earlier(c[j], c[best]))
        best = j;
    return c[best];
  }
  /// Whether match x's candidate comes before match y's.
  bool earlier(const Node& x, const Node& y) const
  {
    if (x.time != y.time)
      return x.time < y.time;
    const int sx = earliest_slot_[x.ball], sy = earliest_slot_[y.ball];
    if (sx < 0 || sy < 0)
      return sy < 0 && sx >= 0;
    // The same time: the full order decides, as one queue of all candidates would.
    return filed_.at(x.ball, sx).candidate.before(filed_.at(y.ball, sy).candidate);
  }

  /// Each ball's filed candidates, in one array: the same room for every ball, doubled for all
  /// when one needs more (rarely: a ball seldom has more than four).
  class Shelves
  {
  public:
    explicit Shelves(std::size_t balls) : count_(balls, 0), entries_(balls * room_) {}
    int size(int ball) const { return count_[ball]; }
    Entry& at(int ball, int i) { return entries_[static_cast<std::size_t>(ball) * room_ + i]; }
    const Entry& at(int ball, int i) const { return entries_[static_cast<std::size_t>(ball) * room_ + i]; }
    void push(int ball, const Entry& entry)
    {
      if (static_cast<std::size_t>(count_[ball]) == room_)
        grow();
      at(ball, count_[ball]++) = entry;
    }
    /// Removes entry i; the last takes its place.
    void erase(int ball, int i) { at(ball, i) = at(ball, --count_[ball]); }
    void clear(int ball) { count_[ball] = 0; }

  private:
    void grow()
    {
      std::vector<Entry> wider(entries_.size() * 2);
      for (std::size_t ball = 0; ball < count_.size(); ++ball)
        std::copy_n(&entries_[ball * room_], count_[ball], &wider[ball * 2 * room_]);
      entries_.swap(wider);
      room_ *= 2;
    }
    std::size_t room_ = 4;
    std::vector<int> count_;
    std::vector<Entry> entries_;
  };
  Shelves filed_;
  std::vector<int> earliest_slot_;  ///< per leaf: where its ball's earliest filed candidate is, or -1
  std::vector<unsigned> version_;
  /// The tournament: each ball's leaf holds its earliest candidate's time, each node the
  /// earliest of its four matches. A 4-way tree is half as deep as a 2-way one, and each level
  /// of a replay reads one cache line.
  std::size_t first_leaf_ = 0;  ///< node of ball 0's leaf (leaves past the last ball stay empty)
  Node root_;
  std::vector<Group> groups_;
  std::vector<char> waiting_;
  std::vector<int> waiting_list_;  ///< balls whose earliest must be found again
};

}  // namespace physics
}  // namespace cue_sim
