#include "cue_sim/evaluation/time_stepping.hpp"

#include <algorithm>
#include <cmath>

#include "cue_sim/physics/motion.hpp"
#include "evaluation/stepper_model.hpp"

namespace cue_sim
{
namespace physics
{
const char* integratorName(Integrator integrator)
{
  switch (integrator)
  {
    case Integrator::SymplecticEuler:
      return "symplectic_euler";
    case Integrator::RungeKutta4:
      return "rk4";
    case Integrator::DormandPrince54:
      return "dopri54";
  }
  return "unknown";
}

struct TimeStepper::Impl
{
  StepperModel model;
  StepperOptions options;
};

TimeStepper::TimeStepper(std::shared_ptr<const TableModel> table, const PhysicsParams<double>& params,
                         const ModelChoice& models, const StepperOptions& options)
{
  auto impl = std::make_shared<Impl>();
  impl->model.table = std::move(table);
  impl->model.p = params;
  impl->model.ball_ball = makeBallBallModel<double>(models.ball_ball);
  impl->model.cushion = makeCushionModel<double>(models.cushion);
  impl->model.ball_table = makeBallTableModel<double>(models.ball_table);
  if (impl->model.ball_ball->needsCloth())  // as the engine does: a pair in the air meets by the default model
    impl->model.ball_ball_in_air = makeBallBallModel<double>(ballBallModelNames().front());
  impl->options = options;
  if (!(options.step > 0))
    throw std::invalid_argument("StepperOptions::step must be > 0");
  impl_ = impl;
}

StepperReport TimeStepper::run(TableState<double> state, const std::vector<double>& sample_times,
                               const SampleCallback& sample) const
{
  if (impl_->options.integrator == Integrator::DormandPrince54)
    return runDormandPrince(impl_->model, impl_->options, std::move(state), sample_times, sample);
  const StepperModel& m = impl_->model;
  const StepperOptions& options = impl_->options;
  StepperReport report;
  std::vector<Ball<double>> balls;
  for (std::size_t i = 0; i < state.balls.size(); ++i)
    balls.push_back(evolve(state.balls[i], state.time, m.p));
  const double h = options.step;
  const double start = state.time;
  std::size_t next_sample = 0;
  const auto sampleUpTo = [&](double t) {
    while (next_sample < sample_times.size() && sample_times[next_sample] <= t + h / 2)
      sample(sample_times[next_sample++], balls);
  };
  sampleUpTo(start);
  std::vector<Ball<double>> before;
  for (long k = 1; k <= options.max_steps; ++k)
  {
    const bool moving = std::any_of(balls.begin(), balls.end(), [](const Ball<double>& b) { return b.moving(); });
    const double t = start + k * h;  // no accumulated rounding in the clock
    if (!moving || t - start > options.max_time + h / 2)
    {
      report.finished = !moving;
      report.end_time = start + (k - 1) * h;
      break;
    }
    before = balls;
    const double energy_before = m.energy(balls);
    m.clampFriction(balls, h, report);
    m.step(balls, h, options.integrator);
    m.switchStates(balls, before, report);
    m.resolveContacts(balls, before, report);
    report.energy_gain = std::max(report.energy_gain, m.energy(balls) - energy_before);
    ++report.steps;
    sampleUpTo(t);
  }
  // Balls at rest stay where they are for the samples after the end.
  while (next_sample < sample_times.size())
    sample(sample_times[next_sample++], balls);
  return report;
}

}  // namespace physics
}  // namespace cue_sim
