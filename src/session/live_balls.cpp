#include "cue_sim/session/live_balls.hpp"

namespace cue_sim
{
namespace session
{
physics::TableState<double> onCloth(physics::TableState<double> state, double R)
{
  for (auto& b : state.balls)
    if (b.inPlay())
      b.r.z() = R;
  return state;
}

LiveBalls::LiveBalls(std::shared_ptr<const physics::Engine<double>> engine, bool orientations)
  : engine_(std::move(engine)), simulation_(engine_, physics::TableState<double>()), turning_(orientations)
{
}

void LiveBalls::advance(double time, std::vector<physics::Event<double>>* happened)
{
  if (simulation_.atRest())
  {
    simulation_.advance(time);  // nothing moves: no physics to do
    return;
  }
  try
  {
    if (turning_)
      advanceTurning(time, happened);
    else
      simulation_.advance(time, happened);
  }
  catch (const physics::EventLimitError&)
  {
    // Not reachable for strikes (they run to rest first) nor for placements at rest; kept so
    // that the table goes on from its last event with a new allowance of events.
    simulation_.reset(simulation_.state());
  }
}

void LiveBalls::advanceTurning(double time, std::vector<physics::Event<double>>* happened)
{
  for (;;)
  {
    const double next = simulation_.nextCheck();
    if (!(next <= time))
      break;
    simulation_.advance(next, happened);
    orientations_.sync(simulation_.state().balls, engine_->params());
  }
  simulation_.advance(time, happened);
}

void LiveBalls::look()
{
  if (simulation_.atRest() && looked_at_rest_)
    return;  // nothing moved since the last look
  balls_ = simulation_.snapshot();
  if (turning_)
  {
    orientations_.sync(simulation_.state().balls, engine_->params());  // after changes too
    orientations_now_ = orientations_.advance(simulation_.state().balls, simulation_.time(), engine_->params());
  }
  else
    orientations_now_.assign(balls_.size(), Eigen::Quaterniond::Identity());
  looked_at_rest_ = simulation_.atRest();
}

void LiveBalls::startFrom(physics::TableState<double> state)
{
  simulation_.reset(std::move(state));
  looked_at_rest_ = false;
  ++layout_version_;
}

void LiveBalls::restartAtRest()
{
  simulation_.reset(physics::atTimeZero(simulation_.state()));
}

void LiveBalls::strike(int ball_id, const physics::CueStrike<double>& strike)
{
  orientations_.sync(simulation_.state().balls, engine_->params());  // before the struck ball's state changes
  simulation_.strike(ball_id, strike);
  ++strike_count_;
  looked_at_rest_ = false;
}

void LiveBalls::place(const physics::Ball<double>& ball)
{
  simulation_.place(ball);
  looked_at_rest_ = false;
  ++layout_version_;
}

void LiveBalls::remove(int ball_id)
{
  simulation_.remove(ball_id);
  looked_at_rest_ = false;
  ++layout_version_;
}

std::string LiveBalls::whyNotFit(const physics::Engine<double>& engine) const
{
  return engine.whyInvalid(onCloth(simulation_.state(), engine.params().ball_radius));
}

bool LiveBalls::applyPendingPhysics()
{
  if (!pending_engine_ || !simulation_.atRest())
    return false;
  std::shared_ptr<const physics::Engine<double>> engine = std::move(pending_engine_);
  pending_engine_.reset();
  if (!whyNotFit(*engine).empty())
    return false;  // the balls changed since and would not fit: setPhysics checks again
  const physics::TableState<double> resting = onCloth(simulation_.state(), engine->params().ball_radius);
  engine_ = std::move(engine);
  simulation_ = physics::Simulation<double>(engine_, resting);
  looked_at_rest_ = false;  // the ball radius may have changed where the balls sit
  ++layout_version_;        // and what is drawn of the table (the cushion height)
  return true;
}

}  // namespace session
}  // namespace cue_sim
