// The learning environments: every point of the action box is a strike the engine takes, bad
// actions are refused and change nothing, a seed fixes an episode, the vector environment is N
// single environments bit for bit, and the rewards say what the shots did.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include "cue_sim/game/referee.hpp"
#include "cue_sim/learning/environment.hpp"
#include "cue_sim/learning/vector_environment.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"
#include "learning/actions.hpp"
#include "learning/pixel_renderer.hpp"
#include "learning/state_observation.hpp"

namespace cue_sim
{
namespace learning
{
namespace
{
std::shared_ptr<const physics::Engine<double>> engineOf(const std::string& table)
{
  const auto model = std::make_shared<const physics::TableModel>(tableFromUrdfFile(tableUrdfPath(table)));
  return std::make_shared<const physics::Engine<double>>(model, physics::tableDefaults(*model));
}

std::vector<float> stateOf(const Environment& env)
{
  return std::vector<float>(env.spaces().state.size());
}

/// A point of the action box: each component at its low bound, its high bound or between.
std::vector<double> actionAt(const BoxSpec& box, Random& random)
{
  std::vector<double> a(box.size());
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    const double u = random.unit();
    a[i] = u < 0.2 ? box.low[i] : u < 0.4 ? box.high[i] : random.uniform(box.low[i], box.high[i]);
  }
  return a;
}

TEST(LearningActions, EveryPointOfTheBoxIsAStrikeTheEngineTakes)
{
  const auto engine = engineOf("7ft");
  for (const char* kind : {"absolute", "relative"})
  {
    EnvOptions o;
    o.action = kind;
    o.spin = true;
    o.balls = 4;
    Environment env(engine, o);
    ActionLayout layout(o);
    std::vector<float> state = stateOf(env);
    Random random(3);
    for (int k = 0; k < 2000; ++k)
    {
      env.reset(k, {state.data(), nullptr});
      const std::vector<double> a = actionAt(layout.box(), random);
      ASSERT_TRUE(layout.whyInvalid(a.data(), a.size()).empty());
      AimContext aim{&env.table(), &engine->table(), engine->params().ball_radius,
                     game::objectBallsOnTable(env.table())};
      const physics::CueStrike<double> s = layout.plan(a.data(), aim).strike;
      ASSERT_TRUE(physics::validateStrike(s).empty()) << physics::validateStrike(s);
      ASSERT_TRUE(engine->whyNotStrikable(env.table(), 0, s).empty()) << engine->whyNotStrikable(env.table(), 0, s);
    }
  }
}

TEST(LearningActions, TipOffsetsFillTheDiscOfTheLargestOffset)
{
  const double r = physics::CueLimits::max_offset;
  double a, b;
  squareToTipOffset(0, 0, a, b);
  EXPECT_EQ(a, 0);
  EXPECT_EQ(b, 0);
  // The square's edges reach the rim; its axes stay axes.
  for (double t = -1; t <= 1; t += 0.125)
    for (const auto& [u, v] : {std::pair{1.0, t}, std::pair{-1.0, t}, std::pair{t, 1.0}, std::pair{t, -1.0}})
    {
      squareToTipOffset(u, v, a, b);
      EXPECT_NEAR(std::hypot(a, b), r, 1e-12) << u << " " << v;
    }
  squareToTipOffset(0, 0.5, a, b);
  EXPECT_EQ(a, 0);
  EXPECT_DOUBLE_EQ(b, 0.5 * r);
}

TEST(LearningActions, BadActionsAreRefusedNamingTheComponentAndChangeNothing)
{
  EnvOptions o;
  o.balls = 3;
  Environment env(engineOf("7ft"), o);
  std::vector<float> before = stateOf(env), after = stateOf(env);
  env.reset(7, {before.data(), nullptr});
  const auto table = env.table();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::pair<std::vector<double>, std::string>> bad = {
      {{nan, 2.0}, "phi"},           {{0.1, nan}, "speed"},
      {{0.1, 0.0}, "speed"},         {{0.1, 12.5}, "speed"},
      {{4.0, 2.0}, "phi"},           {{0.1}, "2 values"},
      {{0.1, 2.0, 0.0}, "2 values"}, {{0.1, -std::numeric_limits<double>::infinity()}, "speed"}};
  for (const auto& [action, field] : bad)
  {
    try
    {
      env.step(action.data(), action.size(), {after.data(), nullptr});
      ADD_FAILURE() << "accepted an action for " << field;
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
    EXPECT_FALSE(env.done());
    ASSERT_EQ(env.table().balls.size(), table.balls.size());
    for (std::size_t i = 0; i < table.balls.size(); ++i)
      EXPECT_EQ(env.table().balls[i].r, table.balls[i].r);
  }
  const std::vector<double> good = {0.1, 2.0};
  env.step(good.data(), good.size(), {after.data(), nullptr});
  EXPECT_TRUE(env.done());
  EXPECT_THROW(env.step(good.data(), good.size(), {after.data(), nullptr}), std::logic_error);
}

TEST(LearningOptions, WrongOptionsNameTheField)
{
  const auto engine = engineOf("7ft");
  const auto refused = [&](EnvOptions o, const std::string& field) {
    try
    {
      Environment env(engine, o);
      ADD_FAILURE() << "accepted " << field;
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind(field, 0), 0u) << e.what();
    }
  };
  EnvOptions o;
  o.task = "bagatelle";
  refused(o, "task");
  o = {};
  o.balls = 16;
  refused(o, "balls");
  o = {};
  o.observation = "rgb";
  refused(o, "observation");
  o = {};
  o.observation = "pixels";
  o.pixel_width = 4;
  refused(o, "pixel_width");
  o = {};
  o.noise_model.speed = -1;
  refused(o, "noise_model");
  EXPECT_THROW(Environment(engineOf("carom"), EnvOptions()), std::invalid_argument);  // no pockets to pot into
}

/// Plays `steps` shots of seeded random actions, resetting when an episode ends; every
/// observation and reward in order.
std::vector<double> playthrough(Environment& env, std::uint64_t seed, int steps)
{
  std::vector<double> trace;
  std::vector<float> state = stateOf(env);
  Random actions(seed + 1000);
  env.reset(seed, {state.data(), nullptr});
  for (int k = 0; k < steps; ++k)
  {
    const std::vector<double> a = actionAt(env.spaces().action, actions);
    const StepResult r = env.step(a.data(), a.size(), {state.data(), nullptr});
    trace.insert(trace.end(), state.begin(), state.end());
    trace.push_back(r.reward);
    if (r.terminated || r.truncated)
      env.reset(std::nullopt, {state.data(), nullptr});
  }
  return trace;
}

TEST(LearningEnvironment, ASeedFixesTheEpisodesAndACopyPlaysOnAlike)
{
  EnvOptions o;
  o.balls = 5;
  o.max_shots = 4;
  const auto engine = engineOf("7ft");
  Environment a(engine, o), b(engine, o);
  EXPECT_EQ(playthrough(a, 11, 60), playthrough(b, 11, 60));
  Environment c(engine, o);
  EXPECT_NE(playthrough(a, 11, 60), playthrough(c, 12, 60));
  Environment copy = a;
  EXPECT_EQ(playthrough(copy, 5, 30), playthrough(a, 5, 30));
  // A copy carries the random streams along: the same strike from the same point, noise and all,
  // without a seed of its own.
  std::vector<float> state = stateOf(a);
  a.reset(std::nullopt, {state.data(), nullptr});
  Environment twin = a;
  const std::vector<double> action = {0.25, 3.0};
  a.step(action.data(), action.size(), {state.data(), nullptr});
  twin.step(action.data(), action.size(), {state.data(), nullptr});
  EXPECT_EQ(a.lastStrike().phi, twin.lastStrike().phi);
  EXPECT_EQ(a.lastStrike().speed, twin.lastStrike().speed);
  EXPECT_NE(a.lastStrike().phi, 0.25) << "the noise is on";
  EXPECT_NE(a.lastStrike().speed, 3.0) << "the noise is on";
  // A fresh environment's copy, never seeded, strikes with the noise too.
  Environment fresh(engine, o);
  Environment fresh_copy = fresh;
  fresh_copy.reset(std::nullopt, {state.data(), nullptr});
  fresh_copy.step(action.data(), action.size(), {state.data(), nullptr});
  EXPECT_NE(fresh_copy.lastStrike().phi, 0.25);
}

TEST(LearningVectorEnvironment, IsNSingleEnvironmentsBitForBit)
{
  for (const char* task : {"pot", "break", "nine_ball", "eight_ball"})
  {
    EnvOptions o;
    o.task = task;
    o.opponent = std::string(task) == "nine_ball" ? "self" : "planner";
    o.balls = 4;
    o.max_shots = 3;
    const auto engine = engineOf("7ft");
    const int n = 7;
    VectorEnvironment vector(engine, o, n, 2);
    std::vector<Environment> singles(n, Environment(engine, o));
    const std::size_t d = vector.spaces().state.size(), m = vector.spaces().action.size();
    std::vector<float> vs(n * d), ss(d);
    vector.reset(100, {vs.data()});
    for (int i = 0; i < n; ++i)
    {
      singles[i].reset(100 + i, {ss.data(), nullptr});
      ASSERT_TRUE(std::equal(ss.begin(), ss.end(), vs.begin() + i * d));
    }
    Random random(9);
    std::vector<double> rewards(n);
    std::vector<std::uint8_t> terminated(n), truncated(n), autoreset(n);
    std::vector<std::uint8_t> ended(n, 0);
    int resets = 0;
    for (int step = 0; step < 25; ++step)
    {
      std::vector<double> actions;
      for (int i = 0; i < n; ++i)
      {
        const std::vector<double> a = actionAt(vector.spaces().action, random);
        actions.insert(actions.end(), a.begin(), a.end());
      }
      vector.step(actions.data(), n, m,
                  {vs.data(), nullptr, rewards.data(), terminated.data(), truncated.data(), autoreset.data(), nullptr});
      for (int i = 0; i < n; ++i)
      {
        double reward = 0;
        bool term = false, trunc = false;
        if (ended[i])
        {
          singles[i].reset(std::nullopt, {ss.data(), nullptr});
          ++resets;
        }
        else
        {
          const StepResult r = singles[i].step(actions.data() + i * m, m, {ss.data(), nullptr});
          reward = r.reward;
          term = r.terminated;
          trunc = r.truncated;
        }
        ASSERT_EQ(autoreset[i], ended[i]) << task << " step " << step << " table " << i;
        ASSERT_EQ(rewards[i], reward);
        ASSERT_EQ(terminated[i], term);
        ASSERT_EQ(truncated[i], trunc);
        ASSERT_TRUE(std::equal(ss.begin(), ss.end(), vs.begin() + i * d)) << task << " step " << step << " table " << i;
        ended[i] = term || trunc;
      }
    }
    if (!isGameTask(task))
    {
      EXPECT_GT(resets, 5) << "the episodes must end and restart for the test to see autoreset";
    }
    // A bad row is refused before any table moves.
    std::vector<double> actions(n * m, 1.0);
    actions[3 * m + 1] = std::numeric_limits<double>::quiet_NaN();
    const std::vector<float> held = vs;
    try
    {
      vector.step(actions.data(), n, m, {vs.data()});
      ADD_FAILURE() << "a NaN was accepted";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind("row 3: action: speed", 0), 0u) << e.what();
    }
    EXPECT_EQ(vs, held);
  }
}

TEST(LearningPot, RewardsSayWhatTheShotDid)
{
  EnvOptions o;
  o.balls = 3;
  o.noise = false;
  const auto engine = engineOf("7ft");
  Environment env(engine, o);
  std::vector<float> state = stateOf(env);
  Random random(4);
  int pots = 0, scratches = 0;
  for (int k = 0; k < 3000; ++k)
  {
    env.reset(k, {state.data(), nullptr});
    const int before = static_cast<int>(game::objectBallsOnTable(env.table()).size());
    const std::vector<double> a = actionAt(env.spaces().action, random);
    const StepResult r = env.step(a.data(), a.size(), {state.data(), nullptr});
    const int after = static_cast<int>(game::objectBallsOnTable(env.table()).size());
    const bool cue_gone = env.table().indexOf(0) < 0 || !env.table().balls[env.table().indexOf(0)].inPlay();
    ASSERT_EQ(r.info.pocketed, before - after);
    ASSERT_EQ(r.info.scratch, cue_gone);
    ASSERT_EQ(r.reward, cue_gone ? -1.0 : static_cast<double>(before - after));
    ASSERT_TRUE(r.terminated);  // one shot an episode by default
    // The observation is the table: each ball's slot set exactly when it is on the table.
    for (int id = 0; id < kBallSlots; ++id)
    {
      const int index = env.table().indexOf(id);
      const bool on = index >= 0 && env.table().balls[index].inPlay();
      ASSERT_EQ(state[3 * id + 2], on ? 1.0f : 0.0f);
    }
    pots += r.reward > 0;
    scratches += r.info.scratch;
  }
  EXPECT_GT(pots, 30);
  EXPECT_GT(scratches, 30);
}

TEST(LearningPot, NormalisedPositionsStayWithinTheirBound)
{
  // Balls at rest in a pocket's mouth are the farthest out; the bound must hold without the clamp.
  for (const char* table : {"7ft", "9ft"})
  {
    EnvOptions o;
    o.balls = 15;
    const auto engine = engineOf(table);
    Environment env(engine, o);
    std::vector<float> state = stateOf(env);
    Random random(8);
    double largest = 0;
    const Eigen::Vector2d half(engine->table().clothLength() / 2, engine->table().clothWidth() / 2);
    for (int k = 0; k < 400; ++k)
    {
      env.reset(k, {state.data(), nullptr});
      const std::vector<double> a = actionAt(env.spaces().action, random);
      env.step(a.data(), a.size(), {state.data(), nullptr});
      for (const auto& b : env.table().balls)
        if (b.inPlay())
          largest = std::max(largest,
                             (b.r.head<2>() - engine->table().clothCentre()).cwiseQuotient(half).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(largest, kPositionBound) << table;
    EXPECT_GT(largest, 0.9) << table;  // balls do reach the cushions
  }
}

TEST(LearningPot, TheRelativeActionAimsAtTheBallAndPocketItNames)
{
  // A ghost-ball aim at the pocket the object ball is most nearly in line with pots far more often
  // than a random heading: the action means the shot it names.
  EnvOptions o;
  o.balls = 1;
  o.action = "relative";
  o.noise = false;
  const auto engine = engineOf("7ft");
  Environment env(engine, o);
  std::vector<float> state = stateOf(env);
  const double R = engine->params().ball_radius;
  int pots = 0, tries = 0, turned_pots = 0;
  for (int k = 0; k < 600; ++k)
  {
    env.reset(k, {state.data(), nullptr});
    const Eigen::Vector2d cue = env.table().balls[env.table().indexOf(0)].r.head<2>();
    const Eigen::Vector2d object = env.table().balls[env.table().indexOf(1)].r.head<2>();
    const auto& pockets = engine->table().pockets();
    int best = -1;
    double best_cut = M_PI;
    for (std::size_t p = 0; p < pockets.size(); ++p)
    {
      const Eigen::Vector2d to_pocket = (pockets[p].centre - object).normalized();
      const Eigen::Vector2d to_ghost = object - 2 * R * to_pocket - cue;
      const double cut = std::acos(std::clamp(to_ghost.normalized().dot(to_pocket), -1.0, 1.0));
      if (cut < best_cut)
      {
        best_cut = cut;
        best = static_cast<int>(p);
      }
    }
    if (best_cut > 0.5)  // under about 30 degrees of cut, where throw stays small
      continue;
    // The same shot turned by the largest offset the action allows, on a copy.
    Environment turned = env;
    const std::vector<double> a = {0.0, (best + 0.5) / pockets.size(), 0.0, 2.5};
    const std::vector<double> off = {0.0, (best + 0.5) / pockets.size(), kMaxCutOffset, 2.5};
    const StepResult r = env.step(a.data(), a.size(), {state.data(), nullptr});
    const StepResult t = turned.step(off.data(), off.size(), {state.data(), nullptr});
    ++tries;
    pots += r.info.pocketed == 1;
    turned_pots += t.info.pocketed == 1;
  }
  ASSERT_GT(tries, 100);
  std::cout << "aimed: " << pots << " of " << tries << ", turned: " << turned_pots << "\n";
  EXPECT_GT(static_cast<double>(pots) / tries, 0.8) << pots << " of " << tries;
  EXPECT_LT(static_cast<double>(turned_pots) / tries, 0.1) << turned_pots << " of " << tries;
}

TEST(LearningBreak, TheRewardIsTheRulingsAndTheRackIsJittered)
{
  for (const char* rack : {"eight", "nine"})
  {
    EnvOptions o;
    o.task = "break";
    o.rack = rack;
    o.noise = false;
    const auto engine = engineOf("7ft");
    Environment env(engine, o), other(engine, o);
    std::vector<float> state = stateOf(env), other_state = stateOf(other);
    int legal = 0;
    for (int k = 0; k < 40; ++k)
    {
      env.reset(k, {state.data(), nullptr});
      other.reset(k + 1000, {other_state.data(), nullptr});
      EXPECT_NE(state, other_state) << "racks of different seeds are jittered differently";
      // Full at the apex ball, hard.
      const Eigen::Vector2d cue = env.table().balls[env.table().indexOf(0)].r.head<2>();
      const Eigen::Vector2d apex = env.table().balls[env.table().indexOf(1)].r.head<2>();
      const std::vector<double> a = {std::atan2(apex.y() - cue.y(), apex.x() - cue.x()), 9.0};
      const StepResult r = env.step(a.data(), a.size(), {state.data(), nullptr});
      EXPECT_TRUE(r.terminated);
      EXPECT_FALSE(r.info.reason.empty());
      EXPECT_NE(r.info.reason.find("WPA"), std::string::npos) << r.info.reason;
      if (r.info.foul)
        EXPECT_EQ(r.reward, -1);
      else
      {
        EXPECT_EQ(r.reward, r.info.pocketed);
        ++legal;
      }
    }
    EXPECT_GE(legal, 30) << rack << ": a hard full break into a jittered rack is legal most times";
  }
}

TEST(LearningPixels, TheCameraShowsTheBallsWhereTheStateHasThem)
{
  EnvOptions o;
  o.balls = 4;
  o.observation = "both";
  o.pixel_width = 160;
  o.pixel_height = 80;
  const auto engine = engineOf("7ft");
  Environment env(engine, o);
  ASSERT_EQ(env.spaces().pixelBytes(), 160u * 80 * 3);
  std::vector<float> state = stateOf(env);
  std::vector<std::uint8_t> pixels(env.spaces().pixelBytes());
  // The picture spans the cloth and the frame's margin, the cloth's centre at the image's centre,
  // the table's length across it and +y up. A ball's centre is as deep below the lens as the
  // framing assumes, so the scale at it is the framing's [px/m].
  const double length = engine->table().clothLength(), width = engine->table().clothWidth();
  const double scale = std::min(160 / (length + 2 * kPixelFrameMargin), 80 / (width + 2 * kPixelFrameMargin));
  const double radius = engine->params().ball_radius * scale;
  const auto cloth = [&](int x, int y) {
    const std::uint8_t* p = &pixels[(y * 160 + x) * 3];
    return p[1] > p[0] + 30 && p[1] > p[2] + 30;  // green
  };
  for (int k = 0; k < 20; ++k)
  {
    env.reset(k, {state.data(), pixels.data()});
    std::vector<Eigen::Vector2d> expected;
    for (int id = 0; id < kBallSlots; ++id)
      if (state[3 * id + 2] > 0)
        expected.emplace_back(79.5 + state[3 * id] * length / 2 * scale, 39.5 - state[3 * id + 1] * width / 2 * scale);
    // Each ball covers the pixel at its centre...
    for (const Eigen::Vector2d& c : expected)
      EXPECT_FALSE(cloth(static_cast<int>(std::lround(c.x())), static_cast<int>(std::lround(c.y()))))
          << "seed " << k << ": no ball at " << c.transpose();
    // ...and whatever is not cloth, inside the cushions, is a ball where the state has one.
    for (int y = 0; y < 80; ++y)
      for (int x = 0; x < 160; ++x)
      {
        const Eigen::Vector2d on_table((x - 79.5) / scale, (39.5 - y) / scale);
        if (std::abs(on_table.x()) > length / 2 - 0.06 || std::abs(on_table.y()) > width / 2 - 0.06 || cloth(x, y))
          continue;
        double nearest = 1e9;
        for (const Eigen::Vector2d& c : expected)
          nearest = std::min(nearest, (c - Eigen::Vector2d(x, y)).norm());
        EXPECT_LT(nearest, radius + 1.5) << "seed " << k << ": pixel " << x << ", " << y
                                         << " is neither cloth nor ball";
      }
  }
}

TEST(LearningPosition, APotScoresOneAndLeavingShotsUpToOneMore)
{
  EnvOptions o;
  o.task = "position";
  o.balls = 4;
  o.action = "relative";
  o.noise = false;
  const auto engine = engineOf("7ft");
  Environment env(engine, o);
  std::vector<float> state = stateOf(env);
  Random random(6);
  int pots = 0, full = 0, none = 0, partial = 0;
  for (int k = 0; k < 1500; ++k)
  {
    env.reset(k, {state.data(), nullptr});
    const int lowest = game::objectBallsOnTable(env.table()).front();
    EXPECT_GE(game::objectBallsOnTable(env.table()).size(), 2u);
    EXPECT_EQ(state[3 * kBallSlots + lowest - 1], 1.0f);  // the target's flag
    const std::vector<double> a = {0.0, random.unit(), random.uniform(-0.02, 0.02), random.uniform(1.0, 4.0)};
    const StepResult r = env.step(a.data(), a.size(), {state.data(), nullptr});
    const auto left = game::objectBallsOnTable(env.table());
    const bool potted = std::find(left.begin(), left.end(), lowest) == left.end();
    if (r.reward >= 1)
    {
      ASSERT_TRUE(potted);
      ASSERT_EQ(r.info.first_contact, lowest);
      ASSERT_FALSE(r.info.scratch);
      const double bonus = left.empty() ? 1.0 : std::min(r.info.open_shots, 3) / 3.0;
      ASSERT_EQ(r.reward, 1 + bonus) << r.info.reason;
      ++pots;
      full += r.reward == 2;
      none += r.reward == 1;
      partial += r.reward > 1 && r.reward < 2;
    }
    else
      ASSERT_EQ(r.info.open_shots, -1);
  }
  // Both outcomes are met: the bonus is earned, not given.
  EXPECT_GT(pots, 150);
  EXPECT_GT(full, 5);
  EXPECT_GT(none, 10);
  EXPECT_GT(partial, 50);
}

/// Where the feature of that name is in the state observation.
std::size_t featureIndex(const Environment& env, const std::string& name)
{
  const auto& names = env.spaces().state.names;
  const auto at = std::find(names.begin(), names.end(), name);
  EXPECT_NE(at, names.end()) << name;
  return static_cast<std::size_t>(at - names.begin());
}

/// A game's episode to its end with random actions: the rewards, rulings and features agree
/// with the game's own state at every step.
void checkGame(const std::string& rules, const std::string& opponent, std::uint64_t seed)
{
  EnvOptions o;
  o.task = rules;
  o.opponent = opponent;
  o.action = "relative";
  const auto engine = engineOf("7ft");
  Environment env(engine, o);
  std::vector<float> state = stateOf(env);
  Random random(seed);
  env.reset(seed, {state.data(), nullptr});
  const std::size_t features = featureIndex(env, "group_open"), in_hand = featureIndex(env, "in_hand_none");
  const std::size_t legal = featureIndex(env, "legal_first1");
  for (int step = 0; step < 400 && !env.done(); ++step)
  {
    for (std::size_t i = 0; i < state.size(); ++i)
      ASSERT_TRUE(state[i] >= env.spaces().state.low[i] && state[i] <= env.spaces().state.high[i]) << i;
    // Exactly one group and one ball-in-hand flag; the legal balls are on the table.
    EXPECT_EQ(state[features] + state[features + 1] + state[features + 2], 1.0f);
    EXPECT_EQ(state[in_hand] + state[in_hand + 1] + state[in_hand + 2] + state[in_hand + 3], 1.0f);
    for (int id = 1; id < 16; ++id)
      if (state[legal - 1 + id] > 0)
      {
        EXPECT_EQ(state[3 * id + 2], 1.0f) << "ball " << id << " is legal but not on the table";
      }
    const std::vector<double> a = actionAt(env.spaces().action, random);
    const StepResult r = env.step(a.data(), a.size(), {state.data(), nullptr});
    EXPECT_FALSE(r.info.reason.empty());
    if (opponent == "planner")
    {
      EXPECT_EQ(r.info.player, 0);
    }
    if (r.terminated)
    {
      ASSERT_GE(r.info.winner, 0);
      // The shooter's reward carries the game's end: +1 won, -1 lost, and at most the shaping.
      const double end = r.info.winner == (opponent == "planner" ? 0 : r.info.player) ? 1.0 : -1.0;
      EXPECT_NEAR(r.reward, end, 0.1 * 16 + 1e-12) << r.info.reason;
      EXPECT_GT(r.reward * end, 0) << r.info.reason;
    }
    else
      EXPECT_LE(std::abs(r.reward), 0.1 * 16 + 1e-12);
  }
  EXPECT_TRUE(env.done()) << rules << " did not end in 400 shots";
}

TEST(LearningGames, RewardsRulingsAndFeaturesAgreeWithTheGame)
{
  for (std::uint64_t seed = 0; seed < 6; ++seed)
    for (const char* rules : {"eight_ball", "nine_ball"})
      for (const char* opponent : {"planner", "self"})
        checkGame(rules, opponent, seed);
}

TEST(LearningGames, TheCueBallInHandGoesWhereTheActionPlacesIt)
{
  EnvOptions o;
  o.task = "nine_ball";
  o.opponent = "self";
  o.action = "relative";
  o.noise = false;
  const auto engine = engineOf("7ft");
  const double R = engine->params().ball_radius;
  Environment env(engine, o);
  std::vector<float> state = stateOf(env);
  int checked = 0;
  std::vector<double> creeps;
  Random random(2);
  for (std::uint64_t seed = 0; seed < 30; ++seed)
  {
    env.reset(seed, {state.data(), nullptr});
    // The break, placed: behind the head string.
    for (int shot = 0; shot < 6 && !env.done(); ++shot)
    {
      Eigen::Vector2d low, high;
      const bool in_hand = state[3 * kBallSlots + 3] == 0;
      const game::BallInHand place = state[3 * kBallSlots + 4] > 0   ? game::BallInHand::Anywhere
                                     : state[3 * kBallSlots + 5] > 0 ? game::BallInHand::BehindHeadString
                                                                     : game::BallInHand::None;
      const double u = random.unit(), v = random.unit();
      // Relative: aim at the legal ball, through the table's first pocket; a creep, so that the cue
      // ball stays within a few millimetres of where it was placed unless it touches a ball.
      std::vector<double> a(env.spaces().action.size(), 0.0);
      a[3] = 0.05;
      a[a.size() - 3] = u;
      a[a.size() - 2] = v;
      physics::TableState<double> before = env.table();
      const StepResult r = env.step(a.data(), a.size(), {state.data(), nullptr});
      if (!in_hand || r.info.first_contact >= 0 || r.info.scratch)
      {
        // A creep that touches no ball fouls, and the next player has the ball in hand: go on.
        if (!in_hand && !env.done())
        {
          a[1] = random.unit();
          a[3] = 6.0;
          env.step(a.data(), a.size(), {state.data(), nullptr});
        }
        continue;
      }
      ASSERT_TRUE(game::inHandRegion(engine->table(), R, place, low, high));
      const Eigen::Vector2d wanted = low + Eigen::Vector2d(u, v).cwiseProduct(high - low);
      const auto& cue = env.table().balls[static_cast<std::size_t>(env.table().indexOf(0))];
      before.balls.erase(before.balls.begin() + before.indexOf(0));
      if (game::whyNotInHand(engine->table(), R, before, wanted, place).empty())
      {
        // The creep rolls the cue ball the same short way from wherever it is placed (about
        // 1.6 cm at 0.05 m/s with the default cloth, no noise): each placement was exact.
        creeps.push_back((cue.r.head<2>() - wanted).norm());
        EXPECT_LT(creeps.back(), 0.025) << "placed at " << wanted.transpose();
        ++checked;
      }
      else
        EXPECT_TRUE((cue.r.head<2>().array() >= low.array() - 0.01).all() &&
                    (cue.r.head<2>().array() <= high.array() + 0.01).all());
    }
  }
  EXPECT_GT(checked, 20);
  EXPECT_LT(*std::max_element(creeps.begin(), creeps.end()) - *std::min_element(creeps.begin(), creeps.end()), 1e-9);
}

TEST(LearningGames, ThreeCushionSeesItsOwnCueBallAndScoreAndEndsOnTheRace)
{
  // Self-play with random strikes: before each step the features say which cue ball the shooter
  // strikes and both scores (as shares of the race), as the points each step reports add up;
  // the episode ends when a player reaches the race, which is that player's +1.
  for (std::uint64_t seed = 0; seed < 3; ++seed)
  {
    EnvOptions o;
    o.task = "three_cushion";
    o.opponent = "self";
    o.race = 2;
    o.max_shots = 1000;
    Environment env(engineOf("carom"), o);
    std::vector<float> state = stateOf(env);
    Random random(seed);
    env.reset(seed, {state.data(), nullptr});
    std::array<int, 2> score{0, 0};
    int steps = 0, points = 0;
    while (!env.done() && steps < 1000)
    {
      const float yellow = state[featureIndex(env, "cue_ball_1")], own = state[featureIndex(env, "own_score")],
                  other = state[featureIndex(env, "opponent_score")];
      const std::vector<double> a = actionAt(env.spaces().action, random);
      const StepResult r = env.step(a.data(), a.size(), {state.data(), nullptr});
      ++steps;
      const std::size_t me = static_cast<std::size_t>(r.info.player);
      EXPECT_EQ(yellow, r.info.player == 1 ? 1.0f : 0.0f) << "player " << r.info.player << " strikes its own ball";
      EXPECT_EQ(own, score[me] / 2.0f);
      EXPECT_EQ(other, score[1 - me] / 2.0f);
      ASSERT_TRUE(r.info.points == 0 || r.info.points == 1);
      score[me] += r.info.points;
      points += r.info.points;
      EXPECT_EQ(r.info.points == 1, r.info.reason.rfind("a point (UMB Art. 83)", 0) == 0) << r.info.reason;
      if (r.terminated)
      {
        EXPECT_EQ(score[static_cast<std::size_t>(r.info.winner)], 2);
        EXPECT_EQ(r.info.winner, r.info.player);
        EXPECT_NEAR(r.reward, 1.0 + 0.1, 1e-12);  // the won game and the point that won it
      }
    }
    EXPECT_TRUE(env.done()) << "seed " << seed << ": no race won in " << steps << " random shots";
    EXPECT_GE(points, 2);
  }
  // The carom table takes only carom games, and aiming at pockets needs pockets.
  EnvOptions o;
  o.task = "three_cushion";
  EXPECT_THROW(Environment(engineOf("7ft"), o), std::invalid_argument);
  o.action = "relative";
  EXPECT_THROW(Environment(engineOf("carom"), o), std::invalid_argument);
  o = {};
  o.task = "eight_ball";
  EXPECT_THROW(Environment(engineOf("carom"), o), std::invalid_argument);
  o.race = 3;
  EXPECT_THROW(Environment(engineOf("7ft"), o), std::invalid_argument);  // 8-ball keeps no score
}

TEST(LearningGames, ThreeCushionAgainstThePlannerIsARaceTheCaromPlannerPlays)
{
  // The opponent is the carom planner: its turns score (it finds a point nearly every time
  // without noise), and within the agent's steps the game reaches its end.
  EnvOptions o;
  o.task = "three_cushion";
  o.race = 3;
  o.opponent_noise = false;
  Environment env(engineOf("carom"), o);
  std::vector<float> state = stateOf(env);
  Random random(5);
  env.reset(5, {state.data(), nullptr});
  int steps = 0, opponent_shots = 0;
  StepResult last;
  while (!env.done() && steps < 100)
  {
    const std::vector<double> a = actionAt(env.spaces().action, random);
    last = env.step(a.data(), a.size(), {state.data(), nullptr});
    EXPECT_EQ(last.info.player, 0);
    opponent_shots += last.info.opponent_shots;
    ++steps;
  }
  ASSERT_TRUE(last.terminated);
  EXPECT_EQ(last.info.winner, 1) << "random strikes against a planner that finds its points: " << last.info.reason;
  EXPECT_GE(opponent_shots, 3);
  EXPECT_NE(last.info.opponent_reason.find("wins"), std::string::npos) << last.info.opponent_reason;
}

}  // namespace

TEST(LearningGames, SnookerSeesEachOfItsBallsTheDAndBothScores)
{
  // A frame in self-play with random strikes on the snooker table: a slot for each of the 22
  // balls, the cue ball in hand in the D at the break, the balls that may be met first on the
  // table, a colour on after a red, and both scores as shares of 147 as the points and penalties
  // each step reports add up.
  EnvOptions o;
  o.task = "snooker";
  o.opponent = "self";
  o.max_shots = 300;
  Environment env(engineOf("snooker"), o);
  const auto& names = env.spaces().state.names;
  ASSERT_NE(std::find(names.begin(), names.end(), "ball21_on_table"), names.end());
  ASSERT_NE(std::find(names.begin(), names.end(), "legal_first21"), names.end());
  std::vector<float> state = stateOf(env);
  Random random(7);
  env.reset(7, {state.data(), nullptr});
  EXPECT_EQ(state[featureIndex(env, "in_hand_d")], 1.0f);
  EXPECT_EQ(state[featureIndex(env, "ball21_on_table")], 1.0f) << "the black on its spot";
  const std::size_t legal = featureIndex(env, "legal_first1");
  std::array<int, 2> score{0, 0};
  int colours_on = 0;
  while (!env.done())
  {
    for (int id = 1; id <= 21; ++id)
      if (state[legal - 1 + static_cast<std::size_t>(id)] > 0)
      {
        EXPECT_EQ(state[3 * static_cast<std::size_t>(id) + 2], 1.0f) << "ball " << id;
      }
    colours_on += state[featureIndex(env, "colour_next")] > 0;
    const float own = state[featureIndex(env, "own_score")], other = state[featureIndex(env, "opponent_score")];
    const std::vector<double> a = actionAt(env.spaces().action, random);
    const StepResult r = env.step(a.data(), a.size(), {state.data(), nullptr});
    const std::size_t me = static_cast<std::size_t>(r.info.player);
    EXPECT_FLOAT_EQ(own, std::min(1.0f, score[me] / 147.0f));
    EXPECT_FLOAT_EQ(other, std::min(1.0f, score[1 - me] / 147.0f));
    score[me] += r.info.points;
    score[1 - me] += r.info.penalty;
    EXPECT_EQ(r.info.foul, r.info.penalty >= 4) << r.info.reason;
  }
  EXPECT_GT(score[0] + score[1], 0);
  EXPECT_GT(colours_on, 0) << "a red went down and a colour was on";
}

}  // namespace learning
}  // namespace cue_sim
