// The queue of candidate events of the event search (internal to event_search.cpp): each ball
// keeps the candidates found for it, and a tournament tree over the balls keeps each ball's
// earliest. An event walks a few levels of the tree, each one cache line: their number follows
// the number of balls, not of candidates waiting (5 levels at 1024 balls, where one binary heap of
// all candidates had 11 to 13).
//
// A candidate is filed under a ball it involves. When a ball changes, everything filed under it
// is dropped at once; what is filed under other balls and involves it is stale from then on (each
// entry carries the versions of its balls) and is dropped when it comes up. This is the per-
// particle event tree of event-driven molecular dynamics (Marin, Risso and Cordero 1993, "Efficient
// algorithms for many-body hard particle molecular dynamics", J. Comput. Phys. 109, 306), there a
// binary tree.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "physics/search/shelves.hpp"

namespace cue_sim
{
namespace physics
{
/// Candidate needs `time`, `ball`, `other` (-1 if none) and a strict order `before`.
template <typename Candidate>
class EventQueue
{
public:
  explicit EventQueue(std::size_t balls) : balls_(balls) { layTree(1); }
  EventQueue(const EventQueue&) = delete;
  EventQueue& operator=(const EventQueue&) = delete;

  /// Room for balls 0 to balls - 1 (a ball placed on the table); never shrinks, so a ball that
  /// left keeps its place and its versions for the next to take it.
  void reserveBalls(std::size_t balls)
  {
    if (balls > balls_.size())
      balls_.resize(balls);
  }

  /// Files a candidate under `ball`, which it must involve (as its ball or its other).
  void file(int ball, const Candidate& candidate)
  {
    if (balls_[ball].leaf < 0)
      balls_[ball].leaf = filed_.add();  // in the tree from its next settling
    filed_.push(balls_[ball].leaf, {candidate, balls_[candidate.ball].version,
                                    candidate.other >= 0 ? balls_[candidate.other].version : 0u});
    markWaiting(ball);
  }

  /// The ball has changed: every candidate involving it is void.
  void changed(int ball)
  {
    ++balls_[ball].version;
    if (balls_[ball].leaf >= 0)
      filed_.clear(balls_[ball].leaf);
    markWaiting(ball);
  }

  /// The earliest candidate still valid, or null if none is left. Valid until the next call.
  const Candidate* top()
  {
    for (;;)
    {
      settleWaiting();
      if (tree_[0].time == std::numeric_limits<double>::infinity())
        return nullptr;
      const Ball& ball = balls_[tree_[0].ball];
      const Entry& entry = filed_.at(ball.leaf, ball.earliest);
      if (!stale(entry))
        return &entry.candidate;
      markWaiting(tree_[0].ball);  // its earliest is stale: look again among the rest
    }
  }

  /// Removes the candidate top() returned.
  void pop()
  {
    Ball& ball = balls_[tree_[0].ball];
    filed_.erase(ball.leaf, ball.earliest);
    markWaiting(tree_[0].ball);
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
  bool stale(const Entry& e) const
  {
    return e.version != balls_[e.candidate.ball].version ||
           (e.candidate.other >= 0 && e.other_version != balls_[e.candidate.other].version);
  }
  void markWaiting(int ball)
  {
    if (!balls_[ball].waiting)
    {
      balls_[ball].waiting = true;
      waiting_list_.push_back(ball);
    }
  }
  /// Finds each waiting ball's earliest valid candidate (dropping the stale ones), then replays
  /// their matches up the tree: first all leaves, so that no match compares a candidate that
  /// has moved.
  void settleWaiting()
  {
    for (int index : waiting_list_)
    {
      Ball& ball = balls_[index];
      ball.waiting = false;
      int slot = -1;
      if (ball.leaf >= 0)
        for (std::size_t i = 0; i < filed_.size(ball.leaf);)
        {
          if (stale(filed_.at(ball.leaf, i)))
          {
            filed_.erase(ball.leaf, i);
            continue;
          }
          if (slot < 0 || filed_.at(ball.leaf, i).candidate.before(filed_.at(ball.leaf, slot).candidate))
            slot = static_cast<int>(i);
          ++i;
        }
      ball.earliest = slot;
    }
    if (filed_.count() > leaves_)
    {
      // More balls have filed than the tree has leaves: a wider tree, every match played afresh.
      std::vector<Node> old_leaves(tree_ + first_leaf_, tree_ + first_leaf_ + leaves_);
      layTree(filed_.count());
      std::copy(old_leaves.begin(), old_leaves.end(), tree_ + first_leaf_);
      for (int index : waiting_list_)
        setLeaf(index);
      for (std::size_t k = first_leaf_; k-- > 0;)
        tree_[k] = winner(&tree_[4 * k + 1]);
    }
    else
    {
      for (int index : waiting_list_)
        setLeaf(index);
      for (int index : waiting_list_)
        if (balls_[index].leaf >= 0)
          replay(balls_[index].leaf);
    }
    waiting_list_.clear();
  }
  /// Puts the ball's earliest time on its leaf, if it has one.
  void setLeaf(int index)
  {
    const Ball& ball = balls_[index];
    if (ball.leaf < 0)
      return;
    Node& leaf = tree_[first_leaf_ + static_cast<std::size_t>(ball.leaf)];
    leaf.ball = index;
    leaf.time = ball.earliest < 0 ? std::numeric_limits<double>::infinity()
                                  : static_cast<double>(filed_.at(ball.leaf, ball.earliest).candidate.time);
  }
  /// An empty tree of at least `leaves` leaves (a power of four).
  void layTree(std::size_t leaves)
  {
    first_leaf_ = 0;
    leaves_ = 1;
    while (leaves_ < leaves)
    {
      first_leaf_ += leaves_;
      leaves_ *= 4;
    }
    // Matches are 16 bytes: with node 1 on a 64-byte boundary, every four that share a node
    // (4k+1 to 4k+4) share a cache line.
    nodes_.assign(first_leaf_ + leaves_ + 3, Node{});
    const std::size_t past = (reinterpret_cast<std::uintptr_t>(&nodes_[1]) / sizeof(Node)) % 4;
    tree_ = nodes_.data() + (4 - past) % 4;
  }
  /// Replays the matches above the ball's leaf, up to the first whose result stands (another
  /// ball's, unchanged: nothing above it can change either).
  void replay(int leaf)
  {
    std::size_t k = first_leaf_ + static_cast<std::size_t>(leaf);
    const int ball = tree_[k].ball;
    while (k > 0)
    {
      k = (k - 1) / 4;
      const Node& won = winner(&tree_[4 * k + 1]);
      Node& result = tree_[k];
      if (won.ball != ball && won.ball == result.ball && won.time == result.time)
        return;
      result = won;
    }
  }
  /// The earliest of four matches: by time without branches, and by the full order only when
  /// two share the earliest time.
  const Node& winner(const Node* c) const
  {
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
    if (x.time != y.time || x.time == std::numeric_limits<double>::infinity())
      return x.time < y.time;
    // The same time: the full order decides, as one queue of all candidates would.
    const Ball& a = balls_[x.ball];
    const Ball& b = balls_[y.ball];
    return filed_.at(a.leaf, a.earliest).candidate.before(filed_.at(b.leaf, b.earliest).candidate);
  }

  /// What the queue keeps of each ball.
  struct Ball
  {
    unsigned version = 0;  ///< how many times the ball has changed
    /// Its leaf in the tree and its shelf of filed candidates: -1 until it files a candidate,
    /// so that balls that never move cost the tree nothing (and a lone ball among resting ones
    /// walks no tree at all).
    int leaf = -1;
    int earliest = -1;     ///< which of its candidates is earliest (-1 if none)
    bool waiting = false;  ///< its earliest must be found again
  };
  std::vector<Ball> balls_;
  /// The balls' filed candidates, a shelf for each ball that has filed one (a ball seldom has
  /// more than four).
  Shelves<Entry> filed_{4};
  /// The tournament: tree_[0] is the final, node k's four matches are nodes 4k+1 to 4k+4, each
  /// ball's leaf holds its earliest candidate's time, and each node the earliest of its four
  /// matches. A 4-way tree is half as deep as a 2-way one, and each level of a replay reads one
  /// cache line.
  std::size_t first_leaf_ = 0;  ///< node of the first leaf
  std::size_t leaves_ = 1;      ///< a power of four
  std::vector<Node> nodes_;
  Node* tree_ = nullptr;           ///< node 0, placed in nodes_ so that node 1 starts a cache line
  std::vector<int> waiting_list_;  ///< balls whose earliest must be found again
};

}  // namespace physics
}  // namespace cue_sim
