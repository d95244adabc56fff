#include "cue_sim/physics/simulation.hpp"

#include <algorithm>
#include <cmath>

#include "cue_sim/physics/motion.hpp"
#include "physics/search/contact_times.hpp"
#include "physics/search/event_search.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// A pointer to an engine the caller keeps alive: shares no ownership.
template <typename S>
std::shared_ptr<const Engine<S>> borrowed(const Engine<S>& engine)
{
  return std::shared_ptr<const Engine<S>>(std::shared_ptr<const Engine<S>>(), &engine);
}
}  // namespace

template <typename S>
Simulation<S>::Simulation(const Engine<S>& engine, TableState<S> state) : Simulation(borrowed(engine), std::move(state))
{
}

template <typename S>
Simulation<S>::Simulation(std::shared_ptr<const Engine<S>> engine, TableState<S> state)
  : engine_(std::move(engine)), state_(std::move(state)), search_(std::make_unique<EventSearch<S>>(*engine_, state_))
{
  refresh();
}

template <typename S>
Simulation<S>::Simulation(const Simulation& other)
  : engine_(other.engine_),
    state_(other.state_),
    search_(std::make_unique<EventSearch<S>>(*engine_, state_)),
    events_in_shot_(other.events_in_shot_)
{
  refresh();
}

template <typename S>
Simulation<S>& Simulation<S>::operator=(const Simulation& other)
{
  if (this != &other)
  {
    engine_ = other.engine_;
    state_ = other.state_;
    search_ = std::make_unique<EventSearch<S>>(*engine_, state_);
    events_in_shot_ = other.events_in_shot_;
    refresh();
  }
  return *this;
}

template <typename S>
Simulation<S>::Simulation(Simulation&& other) noexcept = default;
template <typename S>
Simulation<S>& Simulation<S>::operator=(Simulation&& other) noexcept = default;
template <typename S>
Simulation<S>::~Simulation() = default;

template <typename S>
void Simulation<S>::advanceThrough(S t_end, std::vector<Event<S>>* events)
{
  if (std::isnan(static_cast<double>(t_end)))
    throw std::invalid_argument("advance: the time to advance to is NaN");
  try
  {
    search_->processThrough(state_, t_end, events, events_in_shot_);
  }
  catch (const EventLimitError&)
  {
    refresh();
    throw;
  }
  state_.time = std::max(state_.time, t_end);
  refresh();
}

template <typename S>
ShotResult<S> Simulation<S>::runToRest()
{
  const S start = state_.time;
  ShotResult<S> result;
  advance(start + S(engine_->limits().max_shot_time), &result.events);
  result.at_rest = atRest();
  if (result.at_rest)
    state_.time = std::max(start, state_.event_time);
  result.duration = state_.time - start;
  return result;
}

template <typename S>
Event<S> Simulation<S>::step(S t_end)
{
  Event<S> event;
  try
  {
    // What does not happen within the search's horizon for endless motion never happens.
    event = search_->processNext(state_, std::min(t_end, state_.time + kEndlessHorizon<S>), events_in_shot_);
  }
  catch (const EventLimitError&)
  {
    refresh();
    throw;
  }
  if (event.valid())
    state_.time = std::max(state_.time, event.time);
  refresh();
  return event;
}

template <typename S>
std::string Simulation<S>::whyNotStrikable(int ball_id, const CueStrike<S>& strike) const
{
  return engine_->whyNotStrikable(state_, ball_id, strike);
}

template <typename S>
void Simulation<S>::strike(int ball_id, const CueStrike<S>& strike)
{
  const std::vector<Ball<S>> before = state_.balls;
  engine_->strike(state_, ball_id, strike);  // throws, changing nothing, if it may not
  const int struck = state_.indexOf(ball_id);
  search_->ballChanged(state_, struck);
  for (std::size_t j = 0; j < before.size(); ++j)
    if (static_cast<int>(j) != struck &&
        (before[j].motion != state_.balls[j].motion || before[j].time != state_.balls[j].time))
      search_->ballChanged(state_, static_cast<int>(j));  // it fell off the struck ball, or left its group
  edited();
}

template <typename S>
std::string Simulation<S>::whyNotPlaceable(const Ball<S>& ball) const
{
  Ball<S> now = ball;
  now.time = state_.time;
  return engine_->whyNotPlaceable(state_, now);
}

template <typename S>
void Simulation<S>::place(Ball<S> ball)
{
  ball.time = state_.time;
  settleMotion(ball, engine_->params().ball_radius);
  const std::string why = engine_->whyNotPlaceable(state_, ball);
  if (!why.empty())
    throw std::invalid_argument(why);
  const int index = state_.indexOf(ball.id);
  if (index >= 0)
  {
    state_.balls[index] = ball;
    search_->ballChanged(state_, index);
  }
  else
  {
    state_.balls.push_back(ball);
    search_->ballAdded(state_);
  }
  letHeldBallsFall();
  state_.event_time = state_.time;
  state_.events_this_instant = 0;
  edited();
}

template <typename S>
void Simulation<S>::remove(int ball_id)
{
  const int index = state_.indexOf(ball_id);
  if (index < 0)
    throw std::invalid_argument("ball_id " + std::to_string(ball_id) + " is not on the table");
  const int last = static_cast<int>(state_.balls.size()) - 1;
  state_.balls[index] = state_.balls[last];
  state_.balls.pop_back();
  search_->ballRemoved(state_, index, last);
  letHeldBallsFall();
  state_.event_time = state_.time;
  state_.events_this_instant = 0;
  edited();
}

template <typename S>
void Simulation<S>::letHeldBallsFall()
{
  for (int j : engine_->letAllHeldBallsFall(state_))
    search_->ballChanged(state_, j);
}

template <typename S>
void Simulation<S>::setEngine(std::shared_ptr<const Engine<S>> engine)
{
  engine->letAllHeldBallsFall(state_);  // what holds a ball may not hold it under new parameters
  search_ = std::make_unique<EventSearch<S>>(*engine, state_);
  engine_ = std::move(engine);
  edited();
}

template <typename S>
void Simulation<S>::reset(TableState<S> state)
{
  state_ = std::move(state);
  search_ = std::make_unique<EventSearch<S>>(*engine_, state_);
  edited();
}

template <typename S>
TableState<S> Simulation<S>::release() &&
{
  search_.reset();
  return std::move(state_);
}

template <typename S>
void Simulation<S>::edited()
{
  events_in_shot_ = 0;
  refresh();
}

template <typename S>
void Simulation<S>::refresh()
{
  next_ = search_->nextTime();
  moving_ = state_.anyMoving();
}

template <typename S>
void advance(const Engine<S>& engine, TableState<S>& state, S t_end, std::vector<Event<S>>* events)
{
  Simulation<S> simulation(engine, std::move(state));
  try
  {
    simulation.advance(t_end, events);
  }
  catch (...)
  {
    state = std::move(simulation).release();
    throw;
  }
  state = std::move(simulation).release();
}

template <typename S>
ShotResult<S> simulateToRest(const Engine<S>& engine, TableState<S>& state)
{
  Simulation<S> simulation(engine, std::move(state));
  ShotResult<S> result;
  try
  {
    result = simulation.runToRest();
  }
  catch (...)
  {
    state = std::move(simulation).release();
    throw;
  }
  state = std::move(simulation).release();
  return result;
}

template class Simulation<double>;
template class Simulation<long double>;
template void advance(const Engine<double>&, TableState<double>&, double, std::vector<Event<double>>*);
template void advance(const Engine<long double>&, TableState<long double>&, long double,
                      std::vector<Event<long double>>*);
template ShotResult<double> simulateToRest(const Engine<double>&, TableState<double>&);
template ShotResult<long double> simulateToRest(const Engine<long double>&, TableState<long double>&);

}  // namespace physics
}  // namespace cue_sim
