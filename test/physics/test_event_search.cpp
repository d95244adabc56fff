// The engine's event search structures on their own, against plain references: the queue of
// candidate events (event_queue.hpp) against a list scanned in full, the ball grid
// (ball_grid.hpp) against box tests in double precision, the bound that defers a pair's solving
// (contact_times.hpp) against the solved contact, and the search with its grid against the same
// search looking at every pair.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "physics/search/ball_grid.hpp"
#include "physics/search/contact_times.hpp"
#include "physics/search/event_queue.hpp"
#include "physics/search/event_search.hpp"
#include "scattered_scene.hpp"

namespace
{
using cue_sim::physics::BallGrid;
using cue_sim::physics::EventQueue;
using cue_sim::physics::Poly4;
using cue_sim::physics::Vec2;

/// What the queue needs of a candidate; `tag` tells candidates of the same time and balls apart.
struct TestCandidate
{
  double time = 0;
  int ball = -1, other = -1, tag = 0;
  bool before(const TestCandidate& c) const
  {
    return std::tie(time, ball, other, tag) < std::tie(c.time, c.ball, c.other, c.tag);
  }
  bool operator==(const TestCandidate& c) const
  {
    return std::tie(time, ball, other, tag) == std::tie(c.time, c.ball, c.other, c.tag);
  }
};

/// Every candidate ever filed, with the versions of its balls: the earliest valid one is the
/// answer the queue must give.
struct ReferenceQueue
{
  struct Filed
  {
    TestCandidate candidate;
    unsigned version, other_version;
    bool removed = false;
  };
  std::vector<unsigned> version;
  std::vector<Filed> filed;
  explicit ReferenceQueue(int balls) : version(balls, 0) {}
  void file(const TestCandidate& c) { filed.push_back({c, version[c.ball], c.other >= 0 ? version[c.other] : 0u}); }
  bool valid(const Filed& f) const
  {
    return !f.removed && f.version == version[f.candidate.ball] &&
           (f.candidate.other < 0 || f.other_version == version[f.candidate.other]);
  }
  Filed* top()
  {
    Filed* best = nullptr;
    for (auto& f : filed)
      if (valid(f) && (!best || f.candidate.before(best->candidate)))
        best = &f;
    return best;
  }
};

/// Random filing, changing and popping, with many equal times so that ties are decided by the
/// full order; for ball counts that fill the 4-way tree exactly, leave it ragged, or make it a
/// single leaf.
TEST(EventQueue, GivesTheEarliestValidCandidateAsAFullScanWould)
{
  for (int balls : {1, 2, 3, 4, 5, 16, 17, 63, 200})
  {
    std::mt19937 random(static_cast<unsigned>(balls));
    EventQueue<TestCandidate> queue(static_cast<std::size_t>(balls));
    ReferenceQueue reference(balls);
    int tag = 0;
    const auto randomBall = [&] { return static_cast<int>(random() % static_cast<unsigned>(balls)); };
    for (int step = 0; step < 4000; ++step)
    {
      const unsigned action = random() % 10;
      if (action < 6)
      {
        TestCandidate c;
        c.time = static_cast<double>(random() % 50);  // few distinct times: many ties
        c.ball = randomBall();
        c.other = balls > 1 && random() % 2 ? randomBall() : -1;
        if (c.other == c.ball)
          c.other = -1;
        c.tag = ++tag;
        // Filed under either ball it involves, as the engine files a pair under its finder.
        const int under = c.other >= 0 && random() % 2 ? c.other : c.ball;
        queue.file(under, c);
        reference.file(c);
      }
      else if (action < 8)
      {
        const int ball = randomBall();
        queue.changed(ball);
        ++reference.version[ball];
      }
      else
      {
        const TestCandidate* got = queue.top();
        ReferenceQueue::Filed* expected = reference.top();
        ASSERT_EQ(got == nullptr, expected == nullptr) << balls << " balls, step " << step;
        if (got)
        {
          ASSERT_TRUE(*got == expected->candidate)
              << balls << " balls, step " << step << ": got t=" << got->time << " tag " << got->tag
              << ", expected t=" << expected->candidate.time << " tag " << expected->candidate.tag;
          queue.pop();
          expected->removed = true;
        }
      }
    }
    // Drained to the end, in order.
    for (;;)
    {
      const TestCandidate* got = queue.top();
      ReferenceQueue::Filed* expected = reference.top();
      ASSERT_EQ(got == nullptr, expected == nullptr) << balls << " balls, draining";
      if (!got)
        break;
      ASSERT_TRUE(*got == expected->candidate) << balls << " balls, draining";
      queue.pop();
      expected->removed = true;
    }
  }
}

TEST(EventQueue, KeepsEveryCandidateOfABallWithManyFiled)
{
  // More than the room first given to each ball: its shelf grows, and nothing is lost.
  EventQueue<TestCandidate> queue(5);
  for (int k = 0; k < 40; ++k)
    queue.file(3, TestCandidate{static_cast<double>(40 - k), 3, k % 5 == 3 ? -1 : k % 5, k});
  queue.file(1, TestCandidate{20.5, 1, -1, 100});
  std::vector<double> times;
  while (const TestCandidate* c = queue.top())
  {
    times.push_back(c->time);
    queue.pop();
  }
  ASSERT_EQ(times.size(), 41u);
  EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
}

TEST(EventQueue, DropsWhatAChangedBallWasPartOf)
{
  EventQueue<TestCandidate> queue(4);
  queue.file(0, TestCandidate{1.0, 0, 2, 1});  // filed under ball 0, involves ball 2
  queue.file(1, TestCandidate{2.0, 1, -1, 2});
  queue.changed(2);
  ASSERT_NE(queue.top(), nullptr);
  EXPECT_EQ(queue.top()->tag, 2);
  queue.pop();
  EXPECT_EQ(queue.top(), nullptr);
}

/// The grid may give a ball whose box misses the query by a float's rounding, never miss one
/// whose box meets it, and gives each once.
TEST(BallGrid, FindsEveryBallWhoseBoxMeetsAndEachOnce)
{
  std::mt19937 random(11);
  const auto unit = [&] { return static_cast<double>(random()) / 4294967296.0; };
  const Vec2<double> low(-4.0, -2.0), high(4.0, 2.0);
  const int balls = 300;
  BallGrid<double> grid(low, high, balls, 0.028575);
  std::vector<Vec2<double>> box_low(balls), box_high(balls);
  std::vector<bool> listed(balls, true);
  const auto randomBox = [&](Vec2<double>& l, Vec2<double>& h) {
    const Vec2<double> centre(-4.5 + 9.0 * unit(), -2.5 + 5.0 * unit());  // some beyond the cloth
    const Vec2<double> half(0.03 + 0.6 * unit() * unit(), 0.03 + 0.6 * unit() * unit());
    l = centre - half;
    h = centre + half;
  };
  for (int b = 0; b < balls; ++b)
  {
    randomBox(box_low[b], box_high[b]);
    grid.place(b, box_low[b], box_high[b]);
  }
  const auto meets = [](const Vec2<double>& l0, const Vec2<double>& h0, const Vec2<double>& l1,
                        const Vec2<double>& h1) {
    return !(l0.x() > h1.x() || l1.x() > h0.x() || l0.y() > h1.y() || l1.y() > h0.y());
  };
  std::vector<int> found;
  long exact = 0, extra = 0;
  for (int round = 0; round < 2000; ++round)
  {
    // Move a ball, then ask around another, or around a free box.
    const int moved = static_cast<int>(random() % balls);
    randomBox(box_low[moved], box_high[moved]);
    listed[moved] = round % 7 != 0;
    if (listed[moved])
      grid.place(moved, box_low[moved], box_high[moved]);
    else
      grid.remove(moved);
    const bool free_box = round % 2 == 0;
    const int asking = static_cast<int>(random() % balls);
    Vec2<double> ql, qh;
    if (free_box)
    {
      randomBox(ql, qh);
      const auto in_box = grid.inBox(ql, qh);
      found.assign(in_box.begin(), in_box.end());
    }
    else
    {
      if (!listed[asking])
        continue;
      ql = box_low[asking];
      qh = box_high[asking];
      const auto near = grid.near(asking, ql, qh);
      found.assign(near.begin(), near.end());
    }
    std::set<int> unique(found.begin(), found.end());
    ASSERT_EQ(unique.size(), found.size()) << "round " << round << ": a ball given twice";
    for (int b = 0; b < balls; ++b)
    {
      const bool wanted = listed[b] && (free_box || b != asking) && meets(ql, qh, box_low[b], box_high[b]);
      if (wanted)
      {
        ++exact;
        ASSERT_TRUE(unique.count(b)) << "round " << round << ": ball " << b << " missed";
      }
      else if (unique.count(b))
      {
        ASSERT_TRUE(listed[b] && (free_box || b != asking)) << "round " << round << ": ball " << b;
        // Only a rounding away: widened by ten micrometres, the boxes meet.
        const Vec2<double> slack = Vec2<double>::Constant(1e-5);
        ASSERT_TRUE(meets(ql - slack, qh + slack, box_low[b], box_high[b])) << "round " << round << ": ball " << b;
        ++extra;
      }
    }
  }
  EXPECT_GT(exact, 1000);  // the test did look at balls that meet
  EXPECT_LE(extra, exact / 100);
}

/// A cluster far denser than the grid was sized for (a rack on a large table): the cells' room
/// grows, and no listing made before is lost or given twice.
TEST(BallGrid, KeepsEveryListingWhenCellsOverflow)
{
  const Vec2<double> low(-4.0, -2.0), high(4.0, 2.0);
  const int balls = 200, cluster = 150;
  BallGrid<double> grid(low, high, balls, 0.028575);
  std::vector<Vec2<double>> box_low(balls), box_high(balls);
  std::mt19937 random(5);
  const auto unit = [&] { return static_cast<double>(random()) / 4294967296.0; };
  for (int b = 0; b < balls; ++b)
  {
    // The cluster within a millimetre of (1, 0.5); the rest anywhere, some boxes long.
    const Vec2<double> centre = b < cluster ? Vec2<double>(1.0 + 1e-3 * unit(), 0.5 + 1e-3 * unit())
                                            : Vec2<double>(-4.0 + 8.0 * unit(), -2.0 + 4.0 * unit());
    const Vec2<double> half = b < cluster ? Vec2<double>::Constant(0.03) : Vec2<double>(1.5 * unit(), 0.03);
    box_low[b] = centre - half;
    box_high[b] = centre + half;
    grid.place(b, box_low[b], box_high[b]);
  }
  std::vector<bool> listed(balls, true);
  const auto check = [&](int asking) {
    const auto near = grid.near(asking, box_low[asking], box_high[asking]);
    const std::vector<int> found(near.begin(), near.end());
    const std::set<int> unique(found.begin(), found.end());
    ASSERT_EQ(unique.size(), found.size()) << "a ball given twice";
    for (int b = 0; b < balls; ++b)
    {
      const bool meets = listed[b] && b != asking &&
                         !(box_low[asking].x() > box_high[b].x() || box_low[b].x() > box_high[asking].x() ||
                           box_low[asking].y() > box_high[b].y() || box_low[b].y() > box_high[asking].y());
      EXPECT_EQ(unique.count(b) == 1, meets) << "asking " << asking << ", ball " << b;
    }
  };
  check(0);
  check(cluster);
  // Half the cluster leaves, and its place is taken again.
  for (int b = 0; b < cluster; b += 2)
  {
    grid.remove(b);
    listed[b] = false;
  }
  check(1);
  for (int b = 0; b < cluster; b += 4)
  {
    grid.place(b, box_low[b], box_high[b]);
    listed[b] = true;
  }
  check(0);
  check(cluster + 1);
}

/// A pair is solved only when its bound comes up, so the bound must never be later than the
/// contact the engine solves for, whatever the scale: balls touching, a hair apart, grazing,
/// head-on, and far apart on a large table with slow, long paths where the gap quartic's
/// coefficients are largest.
TEST(PairBound, IsNeverLaterThanTheSolvedContact)
{
  using namespace cue_sim::physics;
  const double R = 0.028575, reach = 2 * R;
  std::mt19937 random(11);
  const auto unit = [&] { return static_cast<double>(random()) / 4294967296.0; };
  const auto direction = [&] {
    const double angle = 2 * M_PI * unit();
    return Vec2<double>(std::cos(angle), std::sin(angle));
  };
  int solved = 0, tight = 0;
  for (int k = 0; k < 200000; ++k)
  {
    // The distance between centres: touching to 1e-12 m, a rack's gaps, the table, a large one.
    const int scale = k % 4;
    const double apart = scale == 0   ? 1e-12 * unit()
                         : scale == 1 ? 1e-3 * unit()
                         : scale == 2 ? 3.0 * unit()
                                      : 25.0 * unit();
    const Vec2<double> c0 = (reach + apart) * direction();
    // Aimed at the other ball within an offset of up to 1.2 reach (grazing near 1), or anywhere.
    const Vec2<double> towards = -c0.normalized();
    const Vec2<double> across(-towards.y(), towards.x());
    const double speed = std::pow(10.0, -4.0 + 5.0 * unit());
    const Vec2<double> c1 =
        k % 3 == 0 ? speed * direction()
                   : speed * (towards * (reach + apart) + across * (1.2 * reach * (2 * unit() - 1))).normalized();
    const Vec2<double> c2 = 2.5 * unit() * direction();
    const double limit = k % 5 == 0 ? kEndlessHorizon<double> : 40.0 * unit();
    const double tau =
        contactTime(distanceGap<double>(c0, c1, c2, reach), limit, -2 * reach * cue_sim::physics::zeroSpeed<double>(),
                    touchTolerance(reach * reach), true);
    if (!(tau <= limit))
      continue;
    ++solved;
    const double bound = earliestMeeting<double>(c0, c1, c2, reach);
    ASSERT_LE(bound, tau) << "case " << k << ": c0 " << c0.transpose() << ", c1 " << c1.transpose() << ", c2 "
                          << c2.transpose();
    if (bound > 0.5 * tau)
      ++tight;
  }
  // Enough contacts were solved, and the bound is no mere zero: most head-on ones it holds off
  // until past half their time.
  EXPECT_GT(solved, 40000);
  EXPECT_GT(tight, solved / 4);
}
}  // namespace

namespace
{
using cue_sim::physics::BroadPhase;
using cue_sim::physics::Engine;
using cue_sim::physics::Event;
using cue_sim::physics::EventSearch;
using cue_sim::physics::PhysicsParams;
using cue_sim::physics::TableState;
}  // namespace

/// The grid may only save work: on large scenes at low and high gravity and friction, a search
/// with the grid and one that looks at every pair must process the same events, bit for bit.
TEST(BroadPhase, TheGridAndAllPairsFindTheSameEvents)
{
  struct Physics
  {
    double gravity, mu_slide, mu_roll;
  };
  long events = 0;
  for (const int count : {40, 120, 200})
    for (const Physics physics :
         {Physics{0.1, 0.05, 0.002}, Physics{0.1, 1.0, 0.1}, Physics{30.0, 0.05, 0.002}, Physics{30.0, 1.0, 0.1}})
    {
      PhysicsParams<double> p;
      p.gravity = physics.gravity;
      p.mu_slide = physics.mu_slide;
      p.mu_roll = physics.mu_roll;
      cue_sim::physics::EngineLimits limits;
      limits.max_events = 10'000'000;
      const Engine<double> engine(cue_sim::physics::scaledTable(count), p, {}, limits);
      const TableState<double> start =
          cue_sim::physics::scatteredScene(engine, count, static_cast<unsigned>(count + 1000 * physics.gravity));
      TableState<double> with_grid = start, all_pairs = start;
      EventSearch<double> grid(engine, with_grid, BroadPhase::Grid), every(engine, all_pairs, BroadPhase::AllPairs);
      long processed_grid = 0, processed_all = 0;
      const std::string name = std::to_string(count) + " balls, g " + std::to_string(physics.gravity) + ", mu_slide " +
                               std::to_string(physics.mu_slide);
      // A minute of the shot: at a tenth of a metre per second squared the balls roll for an hour.
      for (long k = 0;; ++k)
      {
        const Event<double> a = grid.processNext(with_grid, 60.0, processed_grid);
        const Event<double> b = every.processNext(all_pairs, 60.0, processed_all);
        ASSERT_TRUE(cue_sim::physics::sameEvent(a, b))
            << name << ", event " << k << ": the grid gives " << a.ball << "/" << a.other << " at " << a.time
            << ", all pairs " << b.ball << "/" << b.other << " at " << b.time;
        if (!a.valid())
          break;
        ++events;
      }
      for (std::size_t i = 0; i < start.balls.size(); ++i)
        ASSERT_TRUE(cue_sim::physics::sameBall(with_grid.balls[i], all_pairs.balls[i])) << name << ", ball " << i;
    }
  EXPECT_GT(events, 10000);  // the scenes do collide
}
