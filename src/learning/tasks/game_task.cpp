// A game, one task per ruleset (game::rulesNames()): whole games under the referee, a shot a step.
// Against the built-in opponent (the core's planner for the game, game::plannerFor: pots in pool,
// caroms in three-cushion; with execution noise and a skill), whose turns are played within the
// agent's step; or in self-play, where every step is the shot of whoever is to play and everything
// is seen from the shooter's side (its own cue ball, its own score).
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/game/self_play.hpp"
#include "cue_sim/physics/rack.hpp"
#include "learning/tasks/task.hpp"

namespace cue_sim
{
namespace learning
{
namespace
{
/// A whole game's shot cap when max_shots leaves it to the task: self-play's for pool; in a race
/// (three-cushion) this many shots per point of the target, where the planner takes about 5.5.
constexpr int kGameShotCap = 150;
constexpr int kRaceShotsPerPoint = 10;

class GameTask : public Task
{
public:
  GameTask(const physics::Engine<double>& engine, const EnvOptions& options)
    : engine_(engine),
      rules_(options.task),
      self_play_(options.opponent == "self"),
      skill_(options.opponent_skill),
      opponent_noise_(options.opponent_noise ? physics::ExecutionNoise() : physics::ExecutionNoise::none()),
      shaping_(options.shaping),
      race_(options.race),
      cap_(options.max_shots > 0 ? options.max_shots : kGameShotCap),
      planner_(game::plannerFor(*game::makeRules(rules_)))
  {
    const auto rules = game::makeRules(rules_);
    const int target = rules->defaultTarget();
    if (options.race > 0 && target == 0)
      throw std::invalid_argument("race: " + rules_ + " keeps no score; race must be 0");
    if (options.max_shots == 0 && target > 0)
      cap_ = kRaceShotsPerPoint * (race_ > 0 ? race_ : target);
    if (const std::string why = game::whyNotPlayableOn(*rules, rules_, engine.table()); !why.empty())
      throw std::invalid_argument("task: " + why);
    for (const auto& b : physics::rackLayout<double>(rules->rack(), engine.table(), engine.params().ball_radius).balls)
      slots_ = std::max(slots_, b.id + 1);
  }
  GameTask(const GameTask& other)
    : Task(other),
      engine_(other.engine_),
      rules_(other.rules_),
      self_play_(other.self_play_),
      skill_(other.skill_),
      opponent_noise_(other.opponent_noise_),
      shaping_(other.shaping_),
      race_(other.race_),
      cap_(other.cap_),
      slots_(other.slots_),
      planner_(other.planner_),
      game_(other.game_ ? std::make_unique<game::GamePlay>(*other.game_) : nullptr),
      start_(other.start_),
      turns_(other.turns_),
      placement_(other.placement_)
  {
  }
  std::unique_ptr<Task> clone() const override { return std::make_unique<GameTask>(*this); }

  void reset(Random& random) override
  {
    // Who breaks is drawn; against the opponent, its turns up to the agent's are played now (a
    // game it wins before the agent's first shot is drawn again).
    do
    {
      start_.rules = rules_;
      start_.breaker = random.integer(0, 1);
      start_.rack_seed = static_cast<unsigned>(random.bits());
      start_.target = race_;
      game_ = std::make_unique<game::GamePlay>(engine_, rules_, players(), game::gameRack(start_.rack_seed),
                                               start_.breaker);
      game_->setShotCap(cap_);
      if (race_ > 0)
        game_->setTarget(race_);
      turns_.clear();
      placement_.reset();
      if (!self_play_)
      {
        StepResult ignored;
        playOpponent(random, ignored);
      }
    } while (game_->state().over);
  }
  const physics::TableState<double>& table() const override { return game_->table(); }
  std::vector<int> aimChoices() const override { return game_->legalFirst(); }

  void placeCueBall(double u, double v) override
  {
    Eigen::Vector2d low, high;
    if (!game::inHandRegion(engine_.table(), engine_.params().ball_radius, game_->state().ball_in_hand, low, high))
      return;
    const Eigen::Vector2d wanted = low + Eigen::Vector2d(u, v).cwiseProduct(high - low);
    placeNearest(wanted, low, high);
    placement_ = cueBall();
  }

  StepResult shoot(const ShotPlan& plan, Random& random) override
  {
    StepResult result;
    const int shooter = game_->state().turn;
    PlayedTurn played;
    played.player = shooter;
    played.ball = game_->cueBall();
    if (placement_)
    {
      played.placed = true;
      played.x = placement_->x();
      played.y = placement_->y();
      placement_.reset();
    }
    // A player calls the shot it aims.
    if (plan.aimed_ball >= 0 && game_->call(plan.aimed_ball, plan.aimed_pocket).empty())
    {
      played.called_ball = plan.aimed_ball;
      played.called_pocket = plan.aimed_pocket;
    }
    played.push_out = plan.push_out && game_->state().push_out_allowed;
    played.strike = plan.strike;
    turns_.assign(1, played);
    const game::Turn turn = game_->shoot(plan.strike, played.push_out);
    describeTurn(turn, result.info);
    result.info.player = shooter;
    result.reward = shapedReward(turn, shooter);
    if (!self_play_)
      playOpponent(random, result);
    const game::GameState& after = game_->state();
    result.info.next_player = after.turn;
    result.info.winner = after.winner;
    result.terminated = after.over && after.winner >= 0;
    result.truncated = after.over && after.winner < 0;  // the shot cap
    return result;
  }

  std::optional<GameStart> gameStart() const override { return start_; }
  std::vector<PlayedTurn> lastTurns() const override { return turns_; }

  int ballSlots() const override { return slots_; }

  // The features: the shooter's group (3), ball in hand (4: none, anywhere, behind the head
  // string, in the D), break shot, push-out allowed, fouls in a row (2), which balls may be met
  // first (one per object ball slot), the share of the shot cap used, snooker's colour on and
  // free ball, whether the shooter strikes ball 1, and both scores.
  static constexpr int kLegalFirst = 11;  ///< where the legal-first block starts
  int afterLegal() const { return kLegalFirst + slots_ - 1; }
  int featureCount() const { return afterLegal() + 6; }

  void addFeatures(BoxSpec& box) const override
  {
    const auto add = [&box](const std::string& name) {
      box.names.push_back(name);
      box.low.push_back(0);
      box.high.push_back(1);
    };
    for (const char* group : {"group_open", "group_solids", "group_stripes"})
      add(group);
    for (const char* place : {"in_hand_none", "in_hand_anywhere", "in_hand_behind_head_string", "in_hand_d"})
      add(place);
    add("break_shot");
    add("push_out_allowed");
    add("own_fouls");
    add("opponent_fouls");
    for (int id = 1; id < slots_; ++id)
      add("legal_first" + std::to_string(id));
    add("shots_used");
    add("colour_next");     // snooker: a colour is on (a red was just potted)
    add("free_ball");       // snooker: any ball may be met first
    add("cue_ball_1");      // the shooter strikes ball 1 (three-cushion's yellow), not ball 0
    add("own_score");       // where the game keeps a score: the shooter's, as a share of the target
    add("opponent_score");  // and the other player's
  }
  void writeFeatures(float* out) const override
  {
    const game::GameState& s = game_->state();
    const int me = s.turn, other = 1 - s.turn;
    std::fill(out, out + featureCount(), 0.0f);
    out[static_cast<int>(s.groups[static_cast<std::size_t>(me)])] = 1;
    out[3 + static_cast<int>(s.ball_in_hand)] = 1;
    out[7] = s.break_shot;
    out[8] = s.push_out_allowed;
    out[9] = static_cast<float>(std::min(2, s.consecutive_fouls[static_cast<std::size_t>(me)])) / 2;
    out[10] = static_cast<float>(std::min(2, s.consecutive_fouls[static_cast<std::size_t>(other)])) / 2;
    for (const int id : game_->legalFirst())
      if (id >= 1 && id < slots_)
        out[kLegalFirst - 1 + id] = 1;
    float* rest = out + afterLegal();
    rest[0] = static_cast<float>(std::min(1.0, static_cast<double>(s.shots) / cap_));
    rest[1] = s.colour_next;
    rest[2] = s.free_ball;
    rest[3] = game_->cueBall() == 1;
    // A race's scores as shares of its target; a frame's (snooker) of the highest break.
    const double scale = s.target > 0 ? s.target : game_->rules().keepsScore() ? kFrameScoreScale : 0;
    if (scale > 0)
    {
      rest[4] = static_cast<float>(std::min(1.0, s.score[static_cast<std::size_t>(me)] / scale));
      rest[5] = static_cast<float>(std::min(1.0, s.score[static_cast<std::size_t>(other)] / scale));
    }
  }

private:
  Eigen::Vector2d cueBall() const
  {
    return game_->table().balls[static_cast<std::size_t>(game_->table().indexOf(game_->cueBall()))].r.head<2>();
  }

  std::array<std::string, 2> players() const
  {
    return self_play_ ? std::array<std::string, 2>{"player 1", "player 2"}
                      : std::array<std::string, 2>{"agent", "opponent"};
  }

  /// The shooter's reward for a turn: the game's end (1 won, -1 lost), and `shaping_` for each
  /// ball pocketed on a shot that keeps the table and each point scored (three-cushion), less
  /// `shaping_` for a foul.
  double shapedReward(const game::Turn& turn, int shooter) const
  {
    double reward = shaping_ * turn.ruling.points;
    if (turn.ruling.continues)
      reward += shaping_ * static_cast<double>(turn.facts.pocketed.size());
    if (turn.ruling.foul)
      reward -= shaping_;
    if (turn.ruling.game_over && turn.ruling.winner >= 0)
      reward += turn.ruling.winner == shooter ? 1.0 : -1.0;
    return reward;
  }

  /// The opponent's turns until the agent is to play or the game is over; a game it ends counts
  /// for the agent (player 0) in `result`.
  void playOpponent(Random& random, StepResult& result)
  {
    while (!game_->state().over && game_->state().turn != kAgent)
    {
      game::Choice c;
      if (random.unit() < skill_)
        c = planner_->choose(*game_);
      else
        c = wildChoice(random);
      PlayedTurn played;
      played.player = game_->state().turn;
      played.ball = game_->cueBall();
      if (c.place_cue_ball && game_->placeCueBall(c.cue_ball).empty())
      {
        played.placed = true;
        played.x = cueBall().x();
        played.y = cueBall().y();
      }
      if ((c.ball >= 0 || c.pocket >= 0) && game_->call(c.ball, c.pocket).empty())
      {
        played.called_ball = c.ball;
        played.called_pocket = c.pocket;
      }
      const physics::CueStrike<double> strike =
          opponent_noise_.isNone()
              ? c.strike
              : physics::NoisyCue(opponent_noise_, random.bits()).execute(c.strike, engine_.params().ball_radius);
      played.strike = strike;
      turns_.push_back(played);
      const game::Turn turn = game_->shoot(strike);
      result.info.opponent_shots += 1;
      result.info.opponent_reason = turn.ruling.reason;
      if (turn.ruling.game_over && turn.ruling.winner >= 0)
        result.reward += turn.ruling.winner == kAgent ? 1.0 : -1.0;
    }
  }

  /// An unskilled turn: any heading, a moderate speed, the cue ball where it lies.
  static game::Choice wildChoice(Random& random)
  {
    game::Choice c;
    c.strike.phi = random.uniform(-M_PI, M_PI);
    c.strike.speed = random.uniform(0.5, 4.0);
    return c;
  }

  /// The cue ball at `wanted`, or at the nearest free place of the region around it: rings of
  /// half a ball radius, each searched in a fixed order.
  void placeNearest(const Eigen::Vector2d& wanted, const Eigen::Vector2d& low, const Eigen::Vector2d& high)
  {
    if (game_->placeCueBall(wanted).empty())
      return;
    const double step = engine_.params().ball_radius / 2;
    const int rings = static_cast<int>(std::ceil((high - low).norm() / step));
    for (int ring = 1; ring <= rings; ++ring)
    {
      const int points = 8 * ring;
      for (int k = 0; k < points; ++k)
      {
        const double angle = 2 * M_PI * k / points;
        const Eigen::Vector2d p = wanted + ring * step * Eigen::Vector2d(std::cos(angle), std::sin(angle));
        if ((p.array() >= low.array()).all() && (p.array() <= high.array()).all() && game_->placeCueBall(p).empty())
          return;
      }
    }
    // No free place at all: the cue ball stays where it is (where the game put it), which is free.
  }

  static constexpr int kAgent = 0;  ///< against the opponent, the agent is player 0
  /// Snooker's scores are given as shares of the highest break, 147: a frame without fouls
  /// scores at most that for the winner.
  static constexpr double kFrameScoreScale = 147;

  const physics::Engine<double>& engine_;
  std::string rules_;
  bool self_play_;
  double skill_;
  physics::ExecutionNoise opponent_noise_;
  double shaping_;
  int race_;
  int cap_;
  int slots_ = kBallSlots;  ///< the ball block's slots: the rack's highest id + 1, at least kBallSlots
  std::shared_ptr<const game::Planner> planner_;  ///< the opponent's (game::plannerFor)
  std::unique_ptr<game::GamePlay> game_;
  GameStart start_;
  std::vector<PlayedTurn> turns_;             ///< played by the last reset or step
  std::optional<Eigen::Vector2d> placement_;  ///< where the coming shot's cue ball was placed in hand
};
}  // namespace

std::unique_ptr<Task> makeGameTask(const physics::Engine<double>& engine, const EnvOptions& options)
{
  return std::make_unique<GameTask>(engine, options);
}

}  // namespace learning
}  // namespace cue_sim
