// What every ruleset shares. What a simulator cannot judge it does not call: intent (a deliberate
// foul, unsportsmanlike conduct) is not judged, so every foul found is a standard foul; fouls a
// simulated player cannot commit (a double hit or push shot, touching a ball, a jump shot that
// scoops the cue ball under it with the cue) never happen; a cue ball placed where the rules forbid is refused, not
// fouled.
#include "cue_sim/game/referee.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/physics/snooker_markings.hpp"
#include "game/rules/rules_factories.hpp"

namespace cue_sim
{
namespace game
{
const char* groupName(Group group)
{
  switch (group)
  {
    case Group::Solids:
      return "solids";
    case Group::Stripes:
      return "stripes";
    default:
      return "open";
  }
}

const char* ballInHandName(BallInHand place)
{
  switch (place)
  {
    case BallInHand::Anywhere:
      return "anywhere";
    case BallInHand::BehindHeadString:
      return "behind_head_string";
    case BallInHand::InD:
      return "in_d";
    default:
      return "";
  }
}

std::vector<std::string> rulesNames()
{
  return {
#define CUE_SIM_RULES(name, ...) #name,
#include "cue_sim/game/rulesets.def"
#undef CUE_SIM_RULES
  };
}

std::string rulesTitle(const std::string& name)
{
#define CUE_SIM_RULES(rules_name, title, ...)                                                                          \
  if (name == #rules_name)                                                                                             \
    return title;
#include "cue_sim/game/rulesets.def"
#undef CUE_SIM_RULES
  return name;
}

std::string rulesTable(const std::string& name)
{
#define CUE_SIM_RULES(rules_name, title, table, ...)                                                                   \
  if (name == #rules_name)                                                                                             \
    return table;
#include "cue_sim/game/rulesets.def"
#undef CUE_SIM_RULES
  return "";
}

std::unique_ptr<Rules> makeRules(const std::string& name)
{
#define CUE_SIM_RULES(rules_name, ...)                                                                                 \
  if (name == #rules_name)                                                                                             \
    return make_rules_##rules_name();
#include "cue_sim/game/rulesets.def"
#undef CUE_SIM_RULES
  std::string known;
  for (const std::string& n : rulesNames())
    known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown rules '" + name + "' (known: " + known + ")");
}

void Rules::placeForBreak(const physics::TableModel& table, double ball_radius, int /*breaker*/,
                          physics::TableState<double>& balls) const
{
  auto& cue = balls.balls[static_cast<std::size_t>(balls.indexOf(0))];
  cue.r.head<2>() = breakSpot(table, ball_radius);  // the rack's head spot is on the string, not behind it
}

void Rules::respot(const physics::TableModel& table, double ball_radius, const std::vector<int>& ids,
                   const GameState& /*state*/, physics::TableState<double>& balls) const
{
  spotBalls(table, ball_radius, ids, balls);
}

std::string whyNotPlayableOn(const Rules& rules, const std::string& name, const physics::TableModel& table)
{
  const bool pockets = !table.pockets().empty();
  if (pockets == rules.needsPockets())
    return "";
  return name + " is played on a table " + (rules.needsPockets() ? "with" : "without") + " pockets; '" + table.name() +
         "' has " + (pockets ? "some" : "none");
}

std::string ballList(const std::vector<int>& ids)
{
  std::ostringstream out;
  out << (ids.size() == 1 ? "ball " : "balls ");
  for (std::size_t k = 0; k < ids.size(); ++k)
    out << (k == 0 ? "" : k + 1 == ids.size() ? " and " : ", ") << ids[k];
  return out.str();
}

Ruling standardFoul(int shooter, const std::string& rule, const std::string& reason)
{
  Ruling r;
  r.foul = true;
  r.rule = rule;
  r.reason = reason + "; the incoming player has the cue ball in hand anywhere (WPA 1.5)";
  r.next_player = 1 - shooter;
  r.ball_in_hand = BallInHand::Anywhere;
  return r;
}

Ruling generalFoul(int shooter, const ShotFacts& facts, const std::vector<int>& legal_first, bool check_first_and_rail)
{
  if (facts.scratch)
    return standardFoul(shooter, "WPA 6.1", "foul (WPA 6.1, cue ball scratch): the cue ball was pocketed");
  if (facts.cue_ball_off_table)
    return standardFoul(shooter, "WPA 6.1",
                        "foul (WPA 6.1, cue ball off the table): the cue ball was driven off the table");
  if (!facts.off_table.empty())
    return standardFoul(shooter, "WPA 6.5",
                        "foul (WPA 6.5, ball driven off the table): " + ballList(facts.off_table) + " left the table");
  if (!check_first_and_rail)
    return {};
  if (facts.first_contact < 0)
    return standardFoul(shooter, "WPA 6.3",
                        "foul (WPA 6.3, no rail after contact): the cue ball touched no object ball");
  if (std::find(legal_first.begin(), legal_first.end(), facts.first_contact) == legal_first.end())
    return standardFoul(shooter, "WPA 6.2",
                        "foul (WPA 6.2, wrong ball first): the cue ball first touched ball " +
                            std::to_string(facts.first_contact) + ", not " + ballList(legal_first));
  if (facts.pocketed.empty() && !facts.rail_after_contact)
    return standardFoul(shooter, "WPA 6.3",
                        "foul (WPA 6.3, no rail after contact): nothing was pocketed and no ball reached a "
                        "cushion after the cue ball touched ball " +
                            std::to_string(facts.first_contact));
  return {};
}

Ruling judgeShot(const Rules& rules, const GameState& state, const std::vector<int>& on_table, const Shot& shot)
{
  if (state.over)
    throw std::invalid_argument("the game is over: no more shots");
  Ruling r = rules.judge(state, on_table, shot);
  const int shooter = state.turn;
  if (r.foul && !r.game_over && rules.threeFoulsLose() && state.consecutive_fouls[shooter] >= 2)
  {
    r.rule = "WPA 6.14";
    r.reason += "; it is the shooter's third foul in a row, which loses the rack (WPA 6.14)";
    r.game_over = true;
    r.winner = 1 - shooter;
  }
  return r;
}

GameState afterRuling(GameState state, const Ruling& ruling)
{
  const int shooter = state.turn;
  ++state.shots;
  state.consecutive_fouls[shooter] = ruling.foul ? state.consecutive_fouls[shooter] + 1 : 0;
  state.groups = ruling.groups;
  state.push_out_allowed = ruling.push_out_next;
  state.score[shooter] += ruling.points;
  state.score[1 - shooter] += ruling.penalty;
  state.colour_next = ruling.colour_next;
  state.free_ball = false;  // the rules' beforeShot() says whether the next shot has one
  state.last_shot_foul = ruling.foul;
  if (ruling.next_player != shooter && !ruling.game_over)  // the table passes: the other's inning begins
    ++state.innings[ruling.next_player];
  state.turn = ruling.next_player;
  state.ball_in_hand = ruling.ball_in_hand;
  state.break_shot = ruling.rerack;
  if (ruling.rerack)
  {
    state.groups = {Group::Open, Group::Open};
    state.ball_in_hand = BallInHand::BehindHeadString;
  }
  state.called_ball = state.called_pocket = -1;
  state.before_shot.clear();
  if (ruling.game_over)
  {
    state.over = true;
    state.winner = ruling.winner;
  }
  return state;
}

std::vector<int> objectBallsOnTable(const physics::TableState<double>& state, int cue_ball)
{
  std::vector<int> ids;
  for (const auto& b : state.balls)
    if (b.id != cue_ball && b.inPlay())
      ids.push_back(b.id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

namespace
{
/// Whether a ball of radius R centred at p overlaps any in-play ball but `except`.
bool clearOfBalls(const physics::TableState<double>& state, const Eigen::Vector2d& p, double R, int except)
{
  // Touching is allowed: a spotted ball is frozen to the one in its way.
  const double tolerance = 1e-12;
  for (const auto& b : state.balls)
    if (b.id != except && b.inPlay() && (b.r.head<2>() - p).norm() < 2 * R - tolerance)
      return false;
  return true;
}

/// Where along the long string (x) the ball could stand: the spot itself, and each place frozen
/// to a ball that straddles the string, in front of it and behind it.
std::vector<double> spottingCandidates(const physics::TableState<double>& state, const Eigen::Vector2d& spot, double R,
                                       int id)
{
  std::vector<double> xs{spot.x()};
  for (const auto& b : state.balls)
  {
    const double dy = std::abs(b.r.y() - spot.y());
    if (b.id == id || !b.inPlay() || dy >= 2 * R)
      continue;
    const double along = std::sqrt(4 * R * R - dy * dy) * (1 + 1e-12);
    xs.push_back(b.r.x() + along);
    xs.push_back(b.r.x() - along);
  }
  return xs;
}
}  // namespace

void spotBalls(const physics::TableModel& table, double ball_radius, const std::vector<int>& ids,
               physics::TableState<double>& state)
{
  const Eigen::Vector2d spot = table.footSpot();
  for (const int id : ids)
  {
    const int index = state.indexOf(id);
    if (index < 0)
      throw std::invalid_argument("cannot spot ball " + std::to_string(id) + ": it is not in the state");
    std::vector<double> xs = spottingCandidates(state, spot, ball_radius, id);
    const auto stands = [&](double x) {
      const Eigen::Vector2d p(x, spot.y());
      return clearOfBalls(state, p, ball_radius, id) && table.whyNotPlaceable(p, ball_radius).empty();
    };
    // Behind the spot first, nearest first; then in front of it, nearest first.
    std::vector<double> behind, in_front;
    for (const double x : xs)
      (x >= spot.x() ? behind : in_front).push_back(x);
    std::sort(behind.begin(), behind.end());
    std::sort(in_front.begin(), in_front.end(), std::greater<double>());
    double chosen = NAN;
    for (const auto* side : {&behind, &in_front})
      for (const double x : *side)
        if (std::isnan(chosen) && stands(x))
          chosen = x;
    if (std::isnan(chosen))
      throw std::runtime_error("nowhere on the long string to spot ball " + std::to_string(id));
    spotAt(state, id, Eigen::Vector2d(chosen, spot.y()), ball_radius);
  }
}

void spotAt(physics::TableState<double>& balls, int id, const Eigen::Vector2d& p, double ball_radius)
{
  auto& ball = balls.balls[static_cast<std::size_t>(balls.indexOf(id))];
  ball.r = physics::Vec3<double>(p.x(), p.y(), ball_radius);
  ball.v.setZero();
  ball.w.setZero();
  ball.motion = physics::Motion::Stationary;
  ball.pocket = -1;
  ball.time = balls.time;
}

bool inHandRegion(const physics::TableModel& table, double ball_radius, BallInHand place, Eigen::Vector2d& low,
                  Eigen::Vector2d& high)
{
  if (place == BallInHand::None)
    return false;
  const Eigen::Vector2d half(table.clothLength() / 2 - ball_radius, table.clothWidth() / 2 - ball_radius);
  low = table.clothCentre() - half;
  high = table.clothCentre() + half;
  if (place == BallInHand::BehindHeadString)
    high.x() = table.headStringX();
  if (place == BallInHand::InD)
  {
    const physics::SnookerMarkings m = physics::snookerMarkings(table);
    low = low.cwiseMax(m.d_centre - Eigen::Vector2d(m.d_radius, m.d_radius));
    high = high.cwiseMin(Eigen::Vector2d(m.baulk_line_x, m.d_centre.y() + m.d_radius));
  }
  return true;
}

std::string whyNotInHand(const physics::TableModel& table, double ball_radius, const physics::TableState<double>& state,
                         const Eigen::Vector2d& p, BallInHand place)
{
  const bool finite = std::isfinite(p.x()) && std::isfinite(p.y());
  // A place that is free, the common case, is answered without a stream made for it.
  if (finite && place == BallInHand::Anywhere && table.whyNotPlaceable(p, ball_radius).empty() &&
      clearOfBalls(state, p, ball_radius, 0))
    return {};
  std::ostringstream why;
  if (!finite)
    why << "the cue ball's position must be finite, got (" << p.x() << ", " << p.y() << ")";
  else if (place == BallInHand::None)
    why << "the cue ball is not in hand: it is played where it lies";
  else if (place == BallInHand::BehindHeadString && !(p.x() < table.headStringX()))
    why << "the cue ball must be placed behind the head string, not on it (WPA 8.1: x < " << table.headStringX()
        << " m), got x = " << p.x() << " m";
  else if (place == BallInHand::InD && !physics::snookerMarkings(table).inD(p))
  {
    const physics::SnookerMarkings m = physics::snookerMarkings(table);
    why << "the cue ball must be placed in the D (WPBSA Section 3: its centre at most " << m.d_radius
        << " m from the middle of the baulk line, (" << m.d_centre.x() << ", " << m.d_centre.y()
        << "), and not beyond the line, x <= " << m.baulk_line_x << " m), got (" << p.x() << ", " << p.y() << ")";
  }
  else if (const std::string where = table.whyNotPlaceable(p, ball_radius); !where.empty())
    why << where;
  else if (!clearOfBalls(state, p, ball_radius, 0))
    why << "the cue ball at (" << p.x() << ", " << p.y() << ") would overlap another ball";
  return why.str();
}

}  // namespace game
}  // namespace cue_sim
