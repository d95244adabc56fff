// Snooker under the WPBSA Official Rules of the Games of Snooker and English Billiards: Section 1
// (the table's markings, physics/snooker_markings.hpp), Section 2 (definitions: ball on,
// snookered) and Section 3 (the game). Balls: 0 the cue ball, 1-15 the reds, then the colours by
// value: 16 yellow (2 points), 17 green (3), 18 brown (4), 19 blue (5), 20 pink (6), 21 black (7).
//
// Where the rules ask a referee's judgement or leave a choice to a player, the simulator takes one
// and says so in its rulings (doc/games.md, "Snooker"):
// - Nomination: the colour the cue ball meets first is the one nominated, as a referee takes an
//   obvious choice for a nomination; so is a free ball.
// - The miss rule is never applied. A referee calls "foul and a miss" when, in their judgement,
//   the striker has not made the best possible attempt to hit a ball on. A simulated shot is its
//   planner's choice struck through the execution noise: the simulator cannot judge the intent
//   behind it, so it deems every attempt the best possible. The foul stands with its penalty and
//   the incoming player plays from where the balls lie.
// - After a foul the incoming player always plays (the rules also let them ask the offender to
//   play again).
// - Snookered (for a free ball) counts balls not on in the cue ball's straight paths; a cushion
//   or jaw in the way is not counted. Snookering the opponent behind a free ball is not judged.
// - A re-spotted black's first stroke goes to the player who did not play the stroke that tied
//   the frame (the rules draw lots).
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "cue_sim/physics/snooker_markings.hpp"
#include "game/rules/rules_factories.hpp"

namespace cue_sim
{
namespace game
{
namespace
{
constexpr int kCue = 0, kFirstRed = 1, kLastRed = 15, kYellow = 16, kBlack = 21;

/// A foul costs at least this many points (WPBSA Section 3, Penalties).
constexpr int kMinimumPenalty = 4;

/// [m] How far inside another ball's reach a straight path must pass to count as obstructed: the
/// rounding of positions computed at contact, far below what any eye on the table sees.
constexpr double kObstructionTolerance = 1e-9;

bool isRed(int id)
{
  return id >= kFirstRed && id <= kLastRed;
}
bool isColour(int id)
{
  return id >= kYellow && id <= kBlack;
}
int valueOf(int id)
{
  return isRed(id) ? 1 : isColour(id) ? id - kYellow + 2 : 0;
}
bool contains(const std::vector<int>& ids, int id)
{
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

std::string ballName(int id)
{
  static const char* const colours[] = {"yellow", "green", "brown", "blue", "pink", "black"};
  if (id == kCue)
    return "the cue ball";
  if (isRed(id))
    return "a red (" + std::to_string(id) + ")";
  if (isColour(id))
    return std::string("the ") + colours[id - kYellow] + " (" + std::to_string(id) + ")";
  return "ball " + std::to_string(id);
}

/// The ball or balls on (WPBSA Section 2): the reds while any remain, a colour after a red is
/// potted, then the colours in ascending order.
struct BallsOn
{
  std::vector<int> balls;
  int value = 0;     ///< its value for a penalty; a colour after a red: the nominated one's, below
  std::string text;  ///< "a red", "a colour", "the yellow (16)"
  bool colours_in_order = false;
};

BallsOn ballsOn(const GameState& state, const std::vector<int>& on_table)
{
  BallsOn on;
  std::vector<int> reds, colours;
  for (const int id : on_table)
    (isRed(id) ? reds : colours).push_back(id);
  if (state.colour_next)
  {
    on.balls = colours;
    on.text = "a colour";
  }
  else if (!reds.empty())
  {
    on.balls = reds;
    on.value = 1;
    on.text = "a red";
  }
  else if (!colours.empty())
  {
    on.balls = {colours.front()};
    on.value = valueOf(colours.front());
    on.text = ballName(colours.front());
    on.colours_in_order = true;
  }
  return on;
}

/// Whether the cue ball at c can meet the ball at o on both its extreme edges in straight lines
/// no ball in `obstacles` is in the way of (WPBSA Section 2, Snookered).
bool bothEdgesFree(const Eigen::Vector2d& c, const Eigen::Vector2d& o, const std::vector<Eigen::Vector2d>& obstacles,
                   double R)
{
  const double d = (o - c).norm();
  if (d <= 2 * R)
    return true;  // touching: it is met at once
  const Eigen::Vector2d along = (o - c) / d;
  const double alpha = std::asin(2 * R / d);  // a path grazing one edge passes 2R from o's centre
  for (const double side : {-1.0, 1.0})
  {
    const double a = side * alpha;
    const Eigen::Vector2d u(along.x() * std::cos(a) - along.y() * std::sin(a),
                            along.x() * std::sin(a) + along.y() * std::cos(a));
    const double length = d * std::cos(alpha);  // to where the cue ball grazes o
    for (const Eigen::Vector2d& b : obstacles)
    {
      const double t = std::clamp((b - c).dot(u), 0.0, length);
      if ((c + t * u - b).norm() < 2 * R - kObstructionTolerance)
        return false;
    }
  }
  return true;
}

class Snooker : public Rules
{
public:
  std::string rack() const override { return "snooker"; }
  bool callsShots() const override { return false; }
  bool threeFoulsLose() const override { return false; }
  BallInHand ballInHandOnBreak() const override { return BallInHand::InD; }
  bool keepsScore() const override { return true; }
  bool breaksOpen() const override { return false; }

  std::vector<int> legalFirst(const GameState& state, const std::vector<int>& on_table) const override
  {
    if (state.free_ball)  // any ball may be nominated, and then counts as a ball on
      return on_table;
    return ballsOn(state, on_table).balls;
  }

  Ruling judge(const GameState& state, const std::vector<int>& on_table, const Shot& shot) const override
  {
    const ShotFacts& f = shot.facts;
    const int shooter = state.turn, other = 1 - shooter;
    const BallsOn on = ballsOn(state, on_table);
    // The nominations: the colour met first after a red; the free ball, when it is not a ball on.
    const int nominated = state.colour_next && isColour(f.first_contact) ? f.first_contact : -1;
    const int free_ball =
        state.free_ball && f.first_contact >= 0 && !contains(on.balls, f.first_contact) ? f.first_contact : -1;
    const int on_value = state.colour_next ? valueOf(nominated) : on.value;
    const auto pottable = [&](int id) {
      return id == free_ball || (state.colour_next ? id == nominated : contains(on.balls, id));
    };

    std::vector<std::string> fouls;
    int penalty = std::max(kMinimumPenalty, on_value);
    const auto involving = [&](int id) { penalty = std::max(penalty, valueOf(id)); };
    if (f.first_contact < 0)
      fouls.push_back(
          "the cue ball met no ball (no miss is called: the simulator deems every attempt the best "
          "possible)");
    else if (!contains(on.balls, f.first_contact) && f.first_contact != free_ball)
    {
      fouls.push_back("the cue ball met " + ballName(f.first_contact) + " first, not " + on.text);
      involving(f.first_contact);
    }
    for (const int id : f.pocketed)
      if (!pottable(id))
      {
        fouls.push_back(ballName(id) + " was potted and was not on");
        involving(id);
      }
    if (f.scratch)
      fouls.push_back("the cue ball went in off");
    if (f.cue_ball_off_table)
      fouls.push_back("the cue ball was forced off the table");
    for (const int id : f.off_table)
    {
      fouls.push_back(ballName(id) + " was forced off the table");
      involving(id);
    }
    const bool foul = !fouls.empty();

    Ruling r;
    r.next_player = other;
    r.ball_in_hand = f.scratch || f.cue_ball_off_table ? BallInHand::InD : BallInHand::None;
    r.respot = respotted(state, on, f, foul, free_ball);
    if (foul)
    {
      r.foul = true;
      r.rule = "WPBSA Section 3, Fouls";
      r.penalty = penalty;
      r.reason = "foul (WPBSA Section 3, Fouls and Penalties): " + joined(fouls) + "; " + std::to_string(penalty) +
                 " points to " + state.players[static_cast<std::size_t>(other)];
    }
    else
    {
      r.points = pointsFor(on, f, free_ball);
      r.rule = "WPBSA Section 3, Mode of Play";
      r.continues = r.points > 0;
      r.next_player = r.continues ? shooter : other;
      r.colour_next = r.continues && !state.colour_next && !on.colours_in_order;  // a red, or a free ball as one
      r.reason =
          r.continues
              ? "potted " + potList(f.pocketed, free_ball) + " for " + std::to_string(r.points) +
                    (r.points == 1 ? " point" : " points")
              : "nothing potted" +
                    std::string(f.first_contact >= 0 ? " after the cue ball met " + ballName(f.first_contact) : "");
    }
    if (!endOfFrame(state, on, f, r))
      r.reason += r.continues                         ? "; the shooter plays on"
                  : r.ball_in_hand == BallInHand::InD ? "; the incoming player plays from in hand in the D"
                                                      : "; the incoming player plays from where the balls lie";
    return r;
  }

  void placeForBreak(const physics::TableModel& /*table*/, double /*ball_radius*/, int /*breaker*/,
                     physics::TableState<double>& /*balls*/) const override
  {
    // The rack leaves the cue ball in the D, where the breaker plays from in hand.
  }

  void respot(const physics::TableModel& table, double ball_radius, const std::vector<int>& ids,
              const GameState& /*state*/, physics::TableState<double>& balls) const override
  {
    spotColours(table, ball_radius, ids, balls);
  }

  std::string beforeShot(const physics::TableModel& /*table*/, double ball_radius, GameState& state,
                         physics::TableState<double>& balls) const override
  {
    if (state.over || !state.last_shot_foul || state.ball_in_hand != BallInHand::None)
      return "";
    const BallsOn on = ballsOn(state, objectBallsOnTable(balls, kCue));
    if (on.balls.empty())
      return "";
    const Eigen::Vector2d cue = balls.balls[static_cast<std::size_t>(balls.indexOf(kCue))].r.head<2>();
    std::vector<Eigen::Vector2d> not_on;
    for (const auto& b : balls.balls)
      if (b.id != kCue && b.inPlay() && !contains(on.balls, b.id))
        not_on.push_back(b.r.head<2>());
    for (const int id : on.balls)
      if (bothEdgesFree(cue, balls.balls[static_cast<std::size_t>(balls.indexOf(id))].r.head<2>(), not_on, ball_radius))
        return "";
    state.free_ball = true;
    return "free ball (WPBSA Section 3, Free Ball): after the foul no ball on (" + on.text +
           ") can be met on both its edges in a straight line; any ball may be nominated, the first the cue ball "
           "meets, and counts as " +
           on.text;
  }

private:
  /// The colours that go back on their spots: every colour potted or forced off the table, except
  /// the ball on potted fairly once the colours are taken in order (WPBSA Section 3, Spotting
  /// Colours); a red never. Highest value first, as the rules give the higher its spot first.
  static std::vector<int> respotted(const GameState& state, const BallsOn& on, const ShotFacts& f, bool foul,
                                    int free_ball)
  {
    std::vector<int> ids;
    const auto consider = [&](int id) {
      const bool stays_down =
          !foul && on.colours_in_order && !state.colour_next && id == on.balls.front() && id != free_ball;
      if (isColour(id) && !stays_down && !contains(ids, id))
        ids.push_back(id);
    };
    for (const int id : f.pocketed)
      consider(id);
    for (const int id : f.off_table)
      consider(id);
    std::sort(ids.begin(), ids.end(), [](int a, int b) { return a > b; });
    return ids;
  }

  /// A fair shot's points: each red 1, a colour its value, a free ball the value of the ball on.
  /// With the colours in order, a free ball potted with the ball on scores nothing besides it.
  static int pointsFor(const BallsOn& on, const ShotFacts& f, int free_ball)
  {
    int points = 0;
    const bool ball_on_potted = std::any_of(f.pocketed.begin(), f.pocketed.end(),
                                            [&](int id) { return id != free_ball && contains(on.balls, id); });
    for (const int id : f.pocketed)
      if (id != free_ball)
        points += valueOf(id);
      else if (!(on.colours_in_order && ball_on_potted))
        points += on.value;
    return points;
  }

  /// The frame ends when the black, the last ball, is potted or a foul is made on it (WPBSA
  /// Section 3, End of Frame); the higher score wins. Scores level then: the black is re-spotted
  /// and played from in hand in the D.
  /// Whether it did: the ruling's text then says all.
  static bool endOfFrame(const GameState& state, const BallsOn& on, const ShotFacts& f, Ruling& r)
  {
    if (!on.colours_in_order || on.balls.front() != kBlack)
      return false;
    const bool black_down = contains(f.pocketed, kBlack) || contains(f.off_table, kBlack);
    if (!r.foul && !black_down)
      return false;
    const int shooter = state.turn;
    std::array<int, 2> score = state.score;
    score[static_cast<std::size_t>(shooter)] += r.points;
    score[static_cast<std::size_t>(1 - shooter)] += r.penalty;
    const std::string scores = std::to_string(score[0]) + " to " + std::to_string(score[1]);
    if (score[0] == score[1])
    {
      r.respot = {kBlack};
      r.continues = false;
      r.next_player = 1 - shooter;
      r.ball_in_hand = BallInHand::InD;
      r.reason += "; the scores are level at " + scores +
                  ": the black is re-spotted (WPBSA Section 3, End of Frame), and " +
                  state.players[static_cast<std::size_t>(1 - shooter)] +
                  " plays from in hand in the D (the rules draw lots; the simulator gives the stroke to the player "
                  "who did not tie the frame)";
      return true;
    }
    r.respot.clear();
    r.game_over = true;
    r.continues = false;
    r.winner = score[0] > score[1] ? 0 : 1;
    r.reason += "; the frame ends on the black, " + scores + ": " + state.players[static_cast<std::size_t>(r.winner)] +
                " wins (WPBSA Section 3, End of Frame)";
    return true;
  }

  /// WPBSA Section 3, Spotting Colours: on its own spot; if that is taken, on the highest-value
  /// spot available; if none is, as near its own spot as it stands, towards the top cushion on
  /// the line through the spot along the table, or else towards the bottom cushion. A spot is
  /// taken when a ball there would touch another.
  static void spotColours(const physics::TableModel& table, double R, const std::vector<int>& ids,
                          physics::TableState<double>& balls)
  {
    const physics::SnookerMarkings m = physics::snookerMarkings(table);
    for (const int id : ids)  // lifted first: a ball to spot does not take a spot with where it lay
      balls.balls[static_cast<std::size_t>(balls.indexOf(id))].motion = physics::Motion::OffTable;
    for (const int id : ids)
    {
      const Eigen::Vector2d own = m.spots[static_cast<std::size_t>(id - kYellow)];
      Eigen::Vector2d place = own;
      bool placed = standsFree(table, R, balls, place);
      for (int spot = 5; !placed && spot >= 0; --spot)
        placed = standsFree(table, R, balls, place = m.spots[static_cast<std::size_t>(spot)]);
      for (const double direction : {1.0, -1.0})
        for (double step = 0; !placed && std::abs(step) < table.clothLength(); step += direction * R / 64)
          placed = standsFree(table, R, balls, place = own + Eigen::Vector2d(step, 0));
      if (!placed)
        throw std::runtime_error("no room on the table to spot " + ballName(id));
      spotAt(balls, id, place, R);
    }
  }

  /// Whether a ball may stand at p touching no ball in play.
  static bool standsFree(const physics::TableModel& table, double R, const physics::TableState<double>& balls,
                         const Eigen::Vector2d& p)
  {
    if (!table.whyNotPlaceable(p, R).empty())
      return false;
    for (const auto& b : balls.balls)
      if (b.inPlay() && (b.r.head<2>() - p).norm() <= 2 * R)
        return false;
    return true;
  }

  static std::string joined(const std::vector<std::string>& parts)
  {
    std::string text;
    for (std::size_t k = 0; k < parts.size(); ++k)
      text += (k == 0 ? "" : k + 1 == parts.size() ? " and " : ", ") + parts[k];
    return text;
  }

  static std::string potList(const std::vector<int>& ids, int free_ball)
  {
    std::vector<std::string> names;
    for (const int id : ids)
      names.push_back(ballName(id) + (id == free_ball ? " as a free ball" : ""));
    return joined(names);
  }
};
}  // namespace

std::unique_ptr<Rules> make_rules_snooker()
{
  return std::make_unique<Snooker>();
}

}  // namespace game
}  // namespace cue_sim
