// Three-cushion billiards under the UMB World Rules of Carom Billiard: Art. 13 (spots), 23
// (starting position), 27 (balls in contact), 28 (balls off the table), 41 (fouls) and 83 (three
// cushions). Balls: 0 the white (player 1's cue ball), 1 the yellow (player 2's), 2 the red.
//
// Where the rules leave a choice to a player, the simulator takes one: the breaker's ball goes
// on the starting spot to the left of the bottom spot (Art. 23 lets the breaker choose a side),
// and a cue ball frozen to an object ball is always re-spotted (Art. 27 lets the player play away
// from it instead). A game is a race to the target without an equalizing inning, as UMB's
// knock-out matches have been played since 2020.
#include <cmath>

#include "game/rules/rules_factories.hpp"

namespace cue_sim
{
namespace game
{
namespace
{
constexpr int kWhite = 0, kYellow = 1, kRed = 2;

/// Three-cushion's count (Art. 83): the cue ball meets both object balls and, before the
/// second, at least this many cushion impacts (the same cushion may count more than once).
constexpr int kCushionsForAPoint = 3;

/// [m] Balls closer than this are touching (Art. 27): no referee's eye or light sees a gap of
/// 10 um, and the engine's resting balls that never met are farther apart by orders of magnitude.
constexpr double kFrozenGap = 1e-5;

/// UMB's usual distance for a match (40 points; World Cups play 50).
constexpr int kDefaultTarget = 40;

const char* ballName(int id)
{
  switch (id)
  {
    case kWhite:
      return "the white (0)";
    case kYellow:
      return "the yellow (1)";
    case kRed:
      return "the red (2)";
    default:
      return "an unknown ball";
  }
}

class ThreeCushion : public Rules
{
public:
  std::string rack() const override { return "carom"; }
  bool callsShots() const override { return false; }
  bool threeFoulsLose() const override { return false; }
  int cueBall(int player) const override { return player == 0 ? kWhite : kYellow; }
  bool strikable(int ball) const override { return ball == kWhite || ball == kYellow; }
  bool needsPockets() const override { return false; }
  BallInHand ballInHandOnBreak() const override { return BallInHand::None; }
  int defaultTarget() const override { return kDefaultTarget; }
  bool scoresCaroms() const override { return true; }

  std::vector<int> legalFirst(const GameState& state, const std::vector<int>& on_table) const override
  {
    if (!state.break_shot)
      return on_table;
    // Art. 23: the starting stroke is played directly on the red.
    for (const int id : on_table)
      if (id == kRed)
        return {kRed};
    return on_table;
  }

  Ruling judge(const GameState& state, const std::vector<int>& on_table, const Shot& shot) const override
  {
    const ShotFacts& f = shot.facts;
    const int shooter = state.turn;
    if (f.cue_ball != cueBall(shooter))
      return foul(shooter, "UMB Art. 41",
                  "foul (UMB Art. 41, the wrong ball): the shooter played " + std::string(ballName(f.cue_ball)) +
                      ", not " + ballName(cueBall(shooter)),
                  {});
    std::vector<int> off = f.off_table;
    if (f.cue_ball_off_table)
      off.push_back(f.cue_ball);
    if (!off.empty())
      return foul(shooter, "UMB Art. 28",
                  "foul (UMB Art. 28, a ball off the table): " + ballList(off) + " left the table and " +
                      (off.size() == 1 ? "is" : "are") + " spotted",
                  off);
    const std::vector<int> legal = legalFirst(state, on_table);
    if (state.break_shot && f.first_contact >= 0 &&
        std::find(legal.begin(), legal.end(), f.first_contact) == legal.end())
      return foul(shooter, "UMB Art. 23",
                  "foul (UMB Art. 23, the starting stroke): the cue ball met " +
                      std::string(ballName(f.first_contact)) + " first, not the red",
                  {});
    if (f.first_contact >= 0 && f.second_contact >= 0 && f.cushions_before_second >= kCushionsForAPoint)
      return point(state, f);
    Ruling r;
    r.rule = "UMB Art. 83";
    r.next_player = 1 - shooter;
    r.reason = "no point (UMB Art. 83): " + whyNoPoint(f) + "; the inning ends";
    return r;
  }

  void placeForBreak(const physics::TableModel& /*table*/, double /*ball_radius*/, int breaker,
                     physics::TableState<double>& balls) const override
  {
    // The rack puts the white on the starting spot; the yellow breaks from there instead.
    if (breaker != kYellow)
      return;
    auto& white = balls.balls[static_cast<std::size_t>(balls.indexOf(kWhite))];
    auto& yellow = balls.balls[static_cast<std::size_t>(balls.indexOf(kYellow))];
    std::swap(white.r, yellow.r);
  }

  void respot(const physics::TableModel& table, double ball_radius, const std::vector<int>& ids, const GameState& state,
              physics::TableState<double>& balls) const override
  {
    spotOnCaromSpots(table, ball_radius, ids, state.turn, balls);
  }

  std::string beforeShot(const physics::TableModel& table, double ball_radius, GameState& state,
                         physics::TableState<double>& balls) const override
  {
    if (state.over)
      return "";
    const int own = cueBall(state.turn);
    const Eigen::Vector2d at = balls.balls[static_cast<std::size_t>(balls.indexOf(own))].r.head<2>();
    std::vector<int> frozen;
    for (const auto& b : balls.balls)
      if (b.id != own && b.inPlay() && (b.r.head<2>() - at).norm() < 2 * ball_radius + kFrozenGap)
        frozen.push_back(b.id);
    if (frozen.empty())
      return "";
    std::vector<int> concerned = frozen;
    concerned.insert(concerned.begin(), own);
    spotOnCaromSpots(table, ball_radius, concerned, state.turn, balls);
    return ballList(concerned) +
           " were touching: re-spotted on their spots (UMB Art. 27; the rules also let the "
           "player play away from the ball, which the simulator does not)";
  }

private:
  Ruling foul(int shooter, const std::string& rule, const std::string& reason, const std::vector<int>& respot) const
  {
    Ruling r;
    r.foul = true;
    r.rule = rule;
    r.reason = reason + "; the inning ends without a point (UMB Art. 41)";
    r.next_player = 1 - shooter;
    r.respot = respot;
    return r;
  }

  Ruling point(const GameState& state, const ShotFacts& f) const
  {
    const int shooter = state.turn;
    Ruling r;
    r.rule = "UMB Art. 83";
    r.points = 1;
    const int score = state.score[static_cast<std::size_t>(shooter)] + 1;
    r.reason = "a point (UMB Art. 83): the cue ball met " + std::string(ballName(f.first_contact)) + ", then " +
               ballName(f.second_contact) + " after " + std::to_string(f.cushions_before_second) + " cushions; " +
               std::to_string(score) + " to " + std::to_string(state.score[static_cast<std::size_t>(1 - shooter)]);
    if (state.target > 0 && score >= state.target)
    {
      r.game_over = true;
      r.winner = shooter;
      r.next_player = 1 - shooter;
      r.reason += ": the shooter reaches " + std::to_string(state.target) + " and wins";
      return r;
    }
    r.continues = true;
    r.next_player = shooter;
    r.reason += ": the shooter continues";
    return r;
  }

  static std::string whyNoPoint(const ShotFacts& f)
  {
    if (f.first_contact < 0)
      return "the cue ball met no ball (" + std::to_string(f.cushions_before_second) + " cushions)";
    if (f.second_contact < 0)
      return "the cue ball met " + std::string(ballName(f.first_contact)) + " but not the other object ball";
    return "the cue ball met " + std::string(ballName(f.second_contact)) + " second after only " +
           std::to_string(f.cushions_before_second) + " cushions, fewer than " + std::to_string(kCushionsForAPoint);
  }

  /// Art. 27, 28: the red on the top spot (the foot spot), the incoming shooter's ball on the
  /// bottom spot (the head spot), the other cue ball on the centre spot. A ball whose spot is
  /// taken goes on the spot of the ball that takes it, or else on the spot left free.
  void spotOnCaromSpots(const physics::TableModel& table, double ball_radius, const std::vector<int>& ids, int shooter,
                        physics::TableState<double>& balls) const
  {
    const int own = cueBall(shooter), other = cueBall(1 - shooter);
    const auto spotOf = [&](int id) {
      return id == kRed ? table.footSpot() : id == own ? table.headSpot() : table.clothCentre();
    };
    // The balls to spot are lifted first, so that none blocks a spot with where it lay.
    for (const int id : ids)
      balls.balls[static_cast<std::size_t>(balls.indexOf(id))].motion = physics::Motion::OffTable;
    for (const int id : {kRed, own, other})
    {
      if (std::find(ids.begin(), ids.end(), id) == ids.end())
        continue;
      Eigen::Vector2d place = spotOf(id);
      if (const int taker = occupant(balls, place, ball_radius); taker >= 0)
      {
        place = spotOf(taker);
        if (occupant(balls, place, ball_radius) >= 0)
          for (const int any : {kRed, own, other})
            if (occupant(balls, spotOf(any), ball_radius) < 0)
            {
              place = spotOf(any);
              break;
            }
      }
      spotAt(balls, id, place, ball_radius);
    }
  }

  /// A ball in play overlapping a ball placed at p, or -1.
  static int occupant(const physics::TableState<double>& balls, const Eigen::Vector2d& p, double ball_radius)
  {
    for (const auto& b : balls.balls)
      if (b.inPlay() && (b.r.head<2>() - p).norm() < 2 * ball_radius)
        return b.id;
    return -1;
  }
};
}  // namespace

std::unique_ptr<Rules> make_rules_three_cushion()
{
  return std::make_unique<ThreeCushion>();
}

}  // namespace game
}  // namespace cue_sim
