// The bundled tables (urdf/) as the engine sees them: balls that meet a jaw or a cushion's end and
// then the cushion behind it never enter it, and placement follows the closed boundary of
// cushions, jaws and pockets (issue 15).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "cue_sim/game/self_play.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"

using namespace cue_sim;
using namespace cue_sim::physics;

namespace
{
std::shared_ptr<const TableModel> bundled(const std::string& name)
{
  return std::make_shared<const TableModel>(tableFromUrdfFile(tableUrdfPath(name)));
}

/// The deepest a ball in play is inside a cushion or jaw at the state's time [m].
double deepestIntoACushion(const Engine<double>& engine, const TableState<double>& s)
{
  const double R = engine.params().ball_radius;
  double deepest = 0;
  for (std::size_t i = 0; i < s.balls.size(); ++i)
  {
    if (!s.balls[i].inPlay())
      continue;
    const Eigen::Vector2d c = engine.ballAt(s, i, s.time).r.head<2>();
    for (const auto& seg : engine.table().segments())
    {
      const double along = std::clamp((c - seg.start).dot(seg.direction), 0.0, seg.length);
      deepest = std::max(deepest, R - (seg.start + along * seg.direction - c).norm());
    }
    for (const auto& circle : engine.table().circles())
      deepest = std::max(deepest, R + circle.radius - (c - circle.centre).norm());
  }
  return deepest;
}

/// A shot that starts at the end of a straight cushion `s`, headed back along it: either in the
/// pocket's mouth beyond the end, its centre less than R from the cushion's line but clear of
/// the jaw, headed past the jaw (spin then curves many back onto the cushion a few millimetres
/// on); or touching the jaw (or end cap) there, up to 40 degrees round it into the mouth, and
/// slightly into it. Where the next cushion continues `s` (a carom table's corner), the ball
/// touches `s` a little before the corner and heads into it.
struct EndShot
{
  Ball<double> ball;
  int segment;
};

EndShot atACushionEnd(const TableModel& table, double R, std::mt19937& random)
{
  const auto unit = [&] { return static_cast<double>(random()) / 4294967296.0; };
  const int index = static_cast<int>(random() % table.segments().size());
  const auto& s = table.segments()[index];
  const bool at_start = unit() < 0.5;
  const Eigen::Vector2d end = at_start ? s.start : s.end;
  const Eigen::Vector2d beyond = at_start ? Eigen::Vector2d(-s.direction) : s.direction;  // past the end
  const Eigen::Vector2d& n = s.normal;
  const double degree = M_PI / 180;
  const CircularCushion* cap = nullptr;
  for (const auto& c : table.circles())
    if ((c.centre - end).norm() <= c.radius + 1e-9)
      cap = &c;
  Eigen::Vector2d centre, heading;
  const double angle = 15 * degree * unit();
  if (!cap)
  {
    centre = end - 2 * R * unit() * beyond + R * n;
    heading = std::cos(angle) * beyond - std::sin(angle) * n;
  }
  else if (unit() < 0.5)
  {
    // In the mouth: the centre `g` from the line (less than R), just clear of the jaw.
    const double g = R * (0.7 + 0.3 * unit()), r = cap->radius;
    const Eigen::Vector2d jaw = cap->centre;
    // Along the line from the jaw's centre's foot, far enough that the jaw is not touched.
    const double depth = (end - jaw).dot(n);  // how far behind the line the jaw's centre lies
    const double along = std::sqrt(std::max(0.0, (R + r) * (R + r) - (g + depth) * (g + depth))) + 0.2 * R * unit();
    centre = jaw + depth * n + along * beyond + g * n;
    heading = -std::cos(angle) * beyond + std::sin(angle) * n;
  }
  else
  {
    const double round = (-10 + 50 * unit()) * degree;
    centre = cap->centre + (R + cap->radius) * (std::cos(round) * n + std::sin(round) * beyond);
    heading = -std::cos(angle) * beyond - std::sin(angle) * n;
  }
  EndShot shot;
  shot.segment = index;
  shot.ball.id = 0;
  shot.ball.r = Eigen::Vector3d(centre.x(), centre.y(), R);
  const double speed = 0.2 + 3 * unit();
  shot.ball.v = Eigen::Vector3d(speed * heading.x(), speed * heading.y(), 0);
  shot.ball.w = Eigen::Vector3d(200 * (unit() - 0.5), 200 * (unit() - 0.5), 100 * (unit() - 0.5));
  settleMotion(shot.ball, R);
  return shot;
}
}  // namespace

TEST(BundledTables, ABallMeetingAJawOrACushionsEndAndThenTheCushionNeverEntersIt)
{
  for (const std::string& name : tableNames())
  {
    const auto table = bundled(name);
    const Engine<double> engine(table, tableDefaults(*table));
    const double R = engine.params().ball_radius;
    std::mt19937 random(15);
    int shots = 0, onto_the_cushion = 0;
    for (int k = 0; shots < 3000; ++k)
    {
      const EndShot shot = atACushionEnd(engine.table(), R, random);
      TableState<double> start;
      start.balls.push_back(shot.ball);
      if (!engine.whyInvalid(start).empty())
        continue;
      ++shots;
      Simulation<double> simulation(engine, start);
      int collisions = 0;
      bool jaw_first = false;
      for (Event<double> e = simulation.step(); e.valid(); e = simulation.step())
      {
        const double inside = deepestIntoACushion(engine, simulation.state());
        ASSERT_LT(inside, 1e-9) << name << ", shot " << k << ": " << inside << " m inside a cushion after "
                                << eventKindName(e.kind) << " at " << e.time << " s";
        if (!e.isCollision())
          continue;
        ++collisions;
        const double travel = (simulation.state().balls[0].r - shot.ball.r).norm();
        // Onto the cushion from its end within three radii: straight from the mouth, or after
        // the jaw or the next cushion.
        if (e.kind == EventKind::BallCushion && e.obstacle == shot.segment && travel < 3 * R &&
            (collisions == 1 || (collisions == 2 && jaw_first)))
          ++onto_the_cushion;
        jaw_first = collisions == 1 && e.kind != EventKind::BallCushion;
        jaw_first = jaw_first || (collisions == 1 && e.obstacle != shot.segment);
      }
      const Ball<double>& end = simulation.state().balls[0];
      ASSERT_EQ(end.inPlay() ? engine.table().whyNotPlaceable(end.r.head<2>(), R) : "", "")
          << name << ", shot " << k << " ends off the cloth";
    }
    EXPECT_GT(onto_the_cushion, 50) << name << ": too few shots went from a cushion's end onto the cushion";
  }
}

TEST(BundledTables, BehindAPocketsMouthIsOffTheCloth)
{
  for (const std::string& name : tableNames())
  {
    const auto table = bundled(name);
    const double R = tableDefaults(*table).ball_radius;
    for (const auto& pocket : table->pockets())
    {
      // The pocket's axis: from the nearest point of the cloth's rectangle out to its centre.
      const Eigen::Vector2d half(table->clothLength() / 2, table->clothWidth() / 2);
      const Eigen::Vector2d nearest =
          table->clothCentre() + (pocket.centre - table->clothCentre()).cwiseMax(-half).cwiseMin(half);
      const Eigen::Vector2d outwards = (pocket.centre - nearest).normalized();
      const Eigen::Vector2d beside(-outwards.y(), outwards.x());
      // Beyond the capture circle, and beside it on either hand: behind the mouth.
      for (const Eigen::Vector2d& p :
           {Eigen::Vector2d(pocket.centre + (pocket.radius + 0.02) * outwards),
            Eigen::Vector2d(pocket.centre + (pocket.radius + R) * beside),
            Eigen::Vector2d(pocket.centre - (pocket.radius + R) * beside),
            Eigen::Vector2d(pocket.centre + (pocket.radius + 0.01) * (beside + outwards).normalized()),
            Eigen::Vector2d(pocket.centre + (pocket.radius + 0.01) * (outwards - beside).normalized())})
      {
        const std::string why = table->whyNotPlaceable(p, R);
        EXPECT_NE(why.find("off the cloth"), std::string::npos)
            << name << ", " << pocket.name << ": (" << p.x() << ", " << p.y() << ") " << why;
      }
      // Hanging in the mouth, just outside the capture circle on the cloth's side: on the table.
      const Eigen::Vector2d hanging = pocket.centre - (pocket.radius + 1e-3) * outwards;
      EXPECT_EQ(table->whyNotPlaceable(hanging, R), "") << name << ", " << pocket.name;
    }
  }
  // The issue's own case: past the cushion line, beside the side pocket's capture circle.
  const double R = PhysicsParams<double>().ball_radius;
  const auto seven = bundled("7ft");
  EXPECT_NE(seven->whyNotPlaceable(Eigen::Vector2d(0.12, 0.51), R).find("behind cushion_ypos_foot"), std::string::npos);
  const Engine<double> engine(seven, PhysicsParams<double>());
  TableState<double> s;
  Ball<double> b;
  b.r = Eigen::Vector3d(0.12, 0.51, R);
  s.balls.push_back(b);
  EXPECT_NE(engine.whyInvalid(s).find("off the cloth"), std::string::npos);
}

TEST(BundledTables, EveryTableWithPocketsHostsAGame)
{
  // The head string, foot spot and rack come from the table: on each bundled table with pockets
  // both rulesets rack, break legally and play to the end; a table without pockets is refused.
  for (const std::string& name : tableNames())
  {
    const auto table = bundled(name);
    const Engine<double> engine(table, tableDefaults(*table));
    if (engine.table().pockets().empty())
    {
      EXPECT_THROW(game::GamePlay(engine, "eight_ball"), std::invalid_argument) << name;
      continue;
    }
    for (const std::string rules : {"eight_ball", "nine_ball"})
    {
      game::SelfPlayOptions options;
      options.rules = rules;
      options.games = 2;
      options.seed = 11;
      const game::SelfPlaySummary s = game::selfPlay(engine, options);
      EXPECT_EQ(s.finished, 2) << name << " " << rules;
      for (const auto& record : s.records)
      {
        ASSERT_FALSE(record.turns.empty());
        EXPECT_FALSE(record.turns.front().ruling.rerack)
            << name << " " << rules << ": " << record.turns.front().ruling.reason;
      }
    }
  }
}

// The snooker table (issue 34): its mouths are those make_table_urdf.py names (89 mm at the
// corners, 83 mm in the middle, between the cushions' ends), its knuckles leave a 52.5 mm ball a
// way through, and a ball sent straight at each pocket, slow or fast, drops into it.
TEST(BundledTables, TheSnookerTablesPocketsTakeABallSentStraightIn)
{
  const auto table = bundled("snooker");
  const PhysicsParams<double> p = tableDefaults(*table);
  ASSERT_NEAR(p.ball_radius, 0.02625, 1e-12);
  EXPECT_NEAR(table->clothLength(), 3.569, 1e-9);
  EXPECT_NEAR(table->clothWidth(), 1.778, 1e-9);
  ASSERT_EQ(table->pockets().size(), 6u);
  const auto segment = [&](const std::string& name) {
    for (const auto& s : table->segments())
      if (s.name == name)
        return s;
    ADD_FAILURE() << "no " << name;
    return table->segments().front();
  };
  EXPECT_NEAR((segment("cushion_yneg_head").start - segment("cushion_head").end).norm(), 0.089, 1e-9);
  EXPECT_NEAR((segment("cushion_yneg_foot").end - segment("cushion_foot").start).norm(), 0.089, 1e-9);
  EXPECT_NEAR((segment("cushion_yneg_head").end - segment("cushion_yneg_foot").start).norm(), 0.083, 1e-9);
  EXPECT_NEAR((segment("cushion_ypos_foot").end - segment("cushion_ypos_head").start).norm(), 0.083, 1e-9);
  const Engine<double> engine(table, p);
  for (std::size_t k = 0; k < table->pockets().size(); ++k)
  {
    const Pocket& pocket = table->pockets()[k];
    // The two knuckles nearest the pocket leave more than a ball's width between them.
    std::vector<const CircularCushion*> jaws;
    for (const auto& c : table->circles())
      if ((c.centre - pocket.centre).norm() < pocket.radius + 1e-9 && c.radius > 0)
        jaws.push_back(&c);
    ASSERT_EQ(jaws.size(), 2u) << pocket.name;
    const double gap = (jaws[0]->centre - jaws[1]->centre).norm() - jaws[0]->radius - jaws[1]->radius;
    EXPECT_GT(gap, 2 * p.ball_radius + 0.01) << pocket.name;
    EXPECT_LT(gap, 2 * p.ball_radius + 0.03) << pocket.name << ": a snooker pocket is tight";
    // From 40 cm out along the pocket's axis, rolling, at a crawl and hard.
    const Eigen::Vector2d mouth = (jaws[0]->centre + jaws[1]->centre) / 2;
    const Eigen::Vector2d inwards = (mouth - pocket.centre).normalized();
    for (const double speed : {0.4, 1.5, 5.0})
    {
      TableState<double> s;
      Ball<double> b;
      b.id = 1;
      b.r = Eigen::Vector3d(mouth.x() + 0.4 * inwards.x(), mouth.y() + 0.4 * inwards.y(), p.ball_radius);
      b.v = Eigen::Vector3d(-speed * inwards.x(), -speed * inwards.y(), 0);
      b.w = Eigen::Vector3d::UnitZ().cross(b.v) / p.ball_radius;
      b.motion = Motion::Rolling;
      s.balls.push_back(b);
      ASSERT_EQ(engine.whyInvalid(s), "") << pocket.name;
      const ShotResult<double> result = simulateToRest(engine, s);
      ASSERT_FALSE(result.events.empty()) << pocket.name << " at " << speed << " m/s";
      EXPECT_EQ(result.events.back().kind, EventKind::Pocketed) << pocket.name << " at " << speed << " m/s";
      EXPECT_EQ(result.events.back().obstacle, static_cast<int>(k)) << pocket.name << " at " << speed << " m/s";
      EXPECT_FALSE(s.balls[0].inPlay());
    }
  }
}
