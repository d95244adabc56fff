#include "cue_sim/game/self_play.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cue_sim
{
namespace game
{
namespace
{
/// A candidate's worth from its ruling and the table it leaves: a won game, then a legal pot,
/// then no foul; a pot that leaves the shooter open shots is worth more (position), a miss that
/// leaves the opponent none is worth more (safety); the slower of equals (more control).
double score(const Ruling& r, int shooter, double speed, int open_after)
{
  const double position = PottingPlanner::kPositionWeight * std::min(open_after, PottingPlanner::kOpenShotsCounted);
  double s = -0.01 * speed;
  if (r.game_over)
    s += r.winner == shooter ? 1000 : -1000;
  else if (r.foul)
    s -= 100;
  else if (r.continues)
    s += 100 + position;
  else
    s -= position;
  return s;
}

/// Whether a ball of radius R travelling from a to b would touch a ball in play other than
/// those in `ignore` (the straight path's corridor of width 4R).
bool blocked(const physics::TableState<double>& table, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double R,
             std::initializer_list<int> ignore)
{
  const Eigen::Vector2d d = b - a;
  const double length = d.norm();
  if (!(length > 0))
    return false;
  for (const auto& ball : table.balls)
  {
    if (!ball.inPlay() || std::find(ignore.begin(), ignore.end(), ball.id) != ignore.end())
      continue;
    const Eigen::Vector2d p = ball.r.head<2>() - a;
    const double along = std::clamp(p.dot(d) / length, 0.0, length);
    if ((p - along * d / length).norm() < 2 * R)
      return true;
  }
  return false;
}

physics::CueStrike<double> aimedAt(const Eigen::Vector2d& from, const Eigen::Vector2d& at, double speed)
{
  physics::CueStrike<double> strike;
  strike.speed = speed;
  strike.phi = std::atan2(at.y() - from.y(), at.x() - from.x());
  return strike;
}

Eigen::Vector2d positionOf(const GamePlay& game, int id)
{
  return game.table().balls[static_cast<std::size_t>(game.table().indexOf(id))].r.head<2>();
}

}  // namespace

int openShots(const GamePlay& game)
{
  if (game.state().over)
    return 0;
  const auto& table = game.engine().table();
  const double R = game.engine().params().ball_radius;
  const bool in_hand = game.state().ball_in_hand != BallInHand::None;
  const Eigen::Vector2d cue = game.table().balls[static_cast<std::size_t>(game.table().indexOf(0))].r.head<2>();
  int open = 0;
  for (const int ball : game.legalFirst())
  {
    const Eigen::Vector2d object = game.table().balls[static_cast<std::size_t>(game.table().indexOf(ball))].r.head<2>();
    for (const auto& pocket : table.pockets())
    {
      const Eigen::Vector2d to_pocket = (pocket.centre - object).normalized();
      const Eigen::Vector2d ghost = object - 2 * R * to_pocket;
      if (blocked(game.table(), object, pocket.centre, R, {0, ball}))
        continue;
      if (!in_hand &&
          ((ghost - cue).norm() < 1e-9 ||
           std::acos(std::clamp((ghost - cue).normalized().dot(to_pocket), -1.0, 1.0)) > PottingPlanner::kMaxCut ||
           blocked(game.table(), cue, ghost, R, {0, ball})))
        continue;
      ++open;
    }
  }
  return open;
}

namespace
{
Choice breakChoice(const GamePlay& game)
{
  Choice c;
  const auto& table = game.engine().table();
  if (game.state().ball_in_hand != BallInHand::None)
  {
    c.place_cue_ball = true;
    c.cue_ball = breakSpot(table, game.engine().params().ball_radius);
  }
  const Eigen::Vector2d from = c.place_cue_ball ? c.cue_ball : positionOf(game, 0);
  c.strike = aimedAt(from, table.footSpot(), PottingPlanner::kBreakSpeed);
  return c;
}

/// Plays `candidate` on a copy of `trial` (the cue ball placed and the call made) and keeps it in
/// `best` if it scores above `best_score`.
void keepIfBetter(const GamePlay& trial, const Choice& candidate, int shooter, Choice& best, double& best_score)
{
  GamePlay play = trial;
  const Turn t = play.shoot(candidate.strike);
  const double s = score(t.ruling, shooter, candidate.strike.speed, openShots(play));
  if (s > best_score)
  {
    best_score = s;
    best = candidate;
  }
}

/// Where the cue ball in hand may go besides behind a pot's ghost: a grid of kInHandGrid x
/// kInHandGrid points over the region the rules allow (the D, behind the head string, the cloth).
std::vector<Eigen::Vector2d> inHandPlaces(const GamePlay& game)
{
  std::vector<Eigen::Vector2d> places;
  Eigen::Vector2d low, high;
  if (!inHandRegion(game.engine().table(), game.engine().params().ball_radius, game.state().ball_in_hand, low, high))
    return places;
  for (int i = 0; i < PottingPlanner::kInHandGrid; ++i)
    for (int j = 0; j < PottingPlanner::kInHandGrid; ++j)
      places.push_back(low + Eigen::Vector2d((i + 0.5) / PottingPlanner::kInHandGrid * (high.x() - low.x()),
                                             (j + 0.5) / PottingPlanner::kInHandGrid * (high.y() - low.y())));
  return places;
}

}  // namespace

Choice PottingPlanner::choose(const GamePlay& game) const
{
  if (game.state().break_shot && game.rules().breaksOpen())
    return breakChoice(game);
  const auto& table = game.engine().table();
  const double R = game.engine().params().ball_radius;
  const bool in_hand = game.state().ball_in_hand != BallInHand::None;
  const bool calls = game.rules().callsShots();
  const int shooter = game.state().turn;
  Choice best;  // none yet while best_score is -inf
  double best_score = -std::numeric_limits<double>::infinity();
  const std::vector<int> legal = game.legalFirst();
  for (const int ball : legal)
    for (int pocket = 0; pocket < static_cast<int>(table.pockets().size()); ++pocket)
    {
      const Eigen::Vector2d object = positionOf(game, ball);
      const Eigen::Vector2d to_pocket =
          (table.pockets()[static_cast<std::size_t>(pocket)].centre - object).normalized();
      const Eigen::Vector2d ghost = object - 2 * R * to_pocket;
      // In hand: behind the ghost on the line of the pot, else anywhere the rules allow.
      std::vector<Eigen::Vector2d> places{ghost - 0.3 * to_pocket, ghost - 0.15 * to_pocket};
      if (in_hand)
        for (const Eigen::Vector2d& p : inHandPlaces(game))
          places.push_back(p);
      int tried = 0;
      for (const Eigen::Vector2d& place : places)
      {
        if (tried == (in_hand ? kInHandTrials : 1))
          break;
        Choice c;
        if (calls)
        {
          c.ball = ball;
          c.pocket = pocket;
        }
        GamePlay trial = game;
        if (in_hand)
        {
          c.place_cue_ball = true;
          c.cue_ball = place;
          if (!trial.placeCueBall(c.cue_ball).empty())
            continue;
        }
        const Eigen::Vector2d cue = positionOf(trial, 0);
        if ((ghost - cue).norm() < 1e-6 ||
            std::acos(std::clamp((ghost - cue).normalized().dot(to_pocket), -1.0, 1.0)) > kMaxCut)
          continue;
        if (calls && !trial.call(c.ball, c.pocket).empty())
          continue;
        ++tried;
        for (const double speed : {1.5, 3.0})
        {
          c.strike = aimedAt(cue, ghost, speed);
          keepIfBetter(trial, c, shooter, best, best_score);
        }
      }
    }
  // Safeties: each ball that may be met first, full and half-ball either side, softly and firmly,
  // from where the cue ball lies (or the first place in hand it may go): kept when no pot beats a
  // shot without a foul that leaves the opponent fewer open shots.
  if (!(best_score > 0) && !legal.empty())
  {
    GamePlay trial = game;
    Choice c;
    if (in_hand)
      for (const Eigen::Vector2d& p : inHandPlaces(game))
        if (trial.placeCueBall(p).empty())
        {
          c.place_cue_ball = true;
          c.cue_ball = p;
          break;
        }
    const Eigen::Vector2d cue = positionOf(trial, 0);
    for (const int ball : legal)
    {
      const Eigen::Vector2d object = positionOf(trial, ball);
      const Eigen::Vector2d across = Eigen::Vector2d(cue.y() - object.y(), object.x() - cue.x()).normalized();
      for (const double offset : {0.0, -R, R})
        for (const double speed : {1.0, 2.5})
        {
          c.strike = aimedAt(cue, object + offset * across, speed);
          if (calls && !trial.call(ball, -1).empty())
            continue;
          c.ball = calls ? ball : -1;
          c.pocket = -1;
          keepIfBetter(trial, c, shooter, best, best_score);
        }
    }
  }
  if (best_score > -std::numeric_limits<double>::infinity())
    return best;
  Choice fallback;
  if (!legal.empty())
    fallback.strike = aimedAt(positionOf(game, 0), positionOf(game, legal.front()), 2.0);
  else
    fallback.strike = aimedAt(positionOf(game, 0), table.clothCentre(), 2.0);
  return fallback;
}

std::unique_ptr<Planner> plannerFor(const Rules& rules)
{
  if (rules.scoresCaroms())
    return std::make_unique<CaromPlanner>();
  return std::make_unique<PottingPlanner>();
}

namespace
{
/// One candidate of the CaromPlanner: its strike and what it did on a copy of the game.
struct CaromTrial
{
  physics::CueStrike<double> strike;
  bool won = false, point = false, foul = false, met_a_ball = false;
};

/// How many of the `reach` headings either side of trial k (same speed and spin) also score.
int scoringNeighbours(const std::vector<CaromTrial>& trials, std::size_t k, int directions, int reach)
{
  const int block = static_cast<int>(k) / directions * directions, d = static_cast<int>(k) % directions;
  int n = 0;
  for (int step = -reach; step <= reach; ++step)
    if (step != 0 && trials[static_cast<std::size_t>(block + (d + step + directions) % directions)].point)
      ++n;
  return n;
}
}  // namespace

Choice CaromPlanner::choose(const GamePlay& game) const
{
  const int shooter = game.state().turn;
  std::vector<CaromTrial> trials;
  trials.reserve(kSpeeds.size() * kSide.size() * kDirections);
  for (const double speed : kSpeeds)
    for (const double side : kSide)
      for (int d = 0; d < kDirections; ++d)
      {
        CaromTrial t;
        t.strike.speed = speed;
        t.strike.a = side;
        t.strike.phi = 2 * M_PI * d / kDirections;
        GamePlay play = game;
        const Turn turn = play.shoot(t.strike);
        t.won = turn.ruling.game_over && turn.ruling.winner == shooter;
        t.point = turn.ruling.points > 0;
        t.foul = turn.ruling.foul;
        t.met_a_ball = turn.facts.first_contact >= 0;
        trials.push_back(t);
      }
  double best_score = -std::numeric_limits<double>::infinity();
  Choice best;
  for (std::size_t k = 0; k < trials.size(); ++k)
  {
    const CaromTrial& t = trials[k];
    double s = -0.01 * t.strike.speed;
    if (t.won || t.point)
      s += (t.won ? 1000 : 100) + 10 * scoringNeighbours(trials, k, kDirections, 2);
    else if (t.foul)
      s -= 100;
    else if (!t.met_a_ball)
      s -= 10;
    if (s > best_score)
    {
      best_score = s;
      best.strike = t.strike;
    }
  }
  return best;
}

SelfPlaySummary selfPlay(const physics::Engine<double>& engine, const SelfPlayOptions& options,
                         const std::function<void(const GameRecord&)>& progress)
{
  SelfPlaySummary summary;
  physics::NoisyCue cue(options.noise, options.seed);
  const std::unique_ptr<Planner> planner = plannerFor(*makeRules(options.rules));
  for (int g = 0; g < options.games; ++g)
  {
    // Each game racks with seeds of its own, and the break alternates.
    GameRecord record;
    record.rules = options.rules;
    record.index = g;
    record.players = {"planner A", "planner B"};
    record.rack_seed = static_cast<unsigned>(options.seed * 1000 + static_cast<std::uint64_t>(g) * 10);
    record.first_player = g % 2;
    GamePlay game(engine, options.rules, record.players, gameRack(record.rack_seed), record.first_player);
    game.setShotCap(options.max_shots);
    if (options.target > 0)
      if (const std::string why = game.setTarget(options.target); !why.empty())
        throw std::invalid_argument(why);
    int visit = 0;  // the points of the shooter's visit so far: their break
    while (!game.state().over)
    {
      Choice choice = planner->choose(game);
      if (choice.place_cue_ball && !game.placeCueBall(choice.cue_ball).empty())
        choice.place_cue_ball = false;
      game.call(choice.ball, choice.pocket);
      record.before.push_back(game.table());
      record.state_before.push_back(game.state());
      const physics::CueStrike<double> executed = cue.execute(choice.strike, engine.params().ball_radius);
      const Turn turn = game.shoot(executed);
      summary.shots += 1;
      summary.fouls += turn.ruling.foul;
      summary.penalty_points += turn.ruling.penalty;
      visit += turn.ruling.points;
      summary.highest_break = std::max(summary.highest_break, visit);
      if (!turn.ruling.continues)
        visit = 0;
      record.turns.push_back(turn);
    }
    record.end = game.state();
    summary.games += 1;
    summary.points += record.end.score[0] + record.end.score[1];
    summary.innings += record.end.innings[0] + record.end.innings[1];
    if (record.end.winner >= 0)
    {
      summary.finished += 1;
      summary.wins[static_cast<std::size_t>(record.end.winner)] += 1;
    }
    else
      summary.capped += 1;
    if (progress)
      progress(record);
    summary.records.push_back(std::move(record));
  }
  return summary;
}

}  // namespace game
}  // namespace cue_sim
