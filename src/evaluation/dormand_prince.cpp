// Adaptive Dormand-Prince 5(4) (Dormand and Prince 1980; Hairer, Norsett and Wanner, "Solving
// Ordinary Differential Equations I", II.5) for the balls' equations of motion. Contacts and
// motion-state switches are located on each accepted step's dense output (cubic Hermite in
// position and in velocity), the step is then redone exactly to the event, and the event is
// resolved with the engine's own models.
#include "physics/numerics/dormand_prince.hpp"

#include <array>
#include <limits>

#include "evaluation/stepper_model.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// One ball's state for the integrator: r, v, w. A ball on the cloth keeps z = R and v_z = 0, and
/// those two do not count in its error (a ball in the air's do).
using BallVector = Eigen::Matrix<double, 9, 1>;
constexpr int kHeight = 2, kVerticalSpeed = 5;

BallVector pack(const Ball<double>& b)
{
  BallVector y;
  y << b.r, b.v, b.w;
  return y;
}

void unpack(const BallVector& y, Ball<double>& b)
{
  b.r = y.segment<3>(0);
  b.v = y.segment<3>(3);
  b.w = y.segment<3>(6);
}

BallVector rate(const StepperModel& m, Motion motion, const BallVector& y)
{
  Vec3<double> dv, dw;
  m.derivative(motion, y.segment<3>(3), y.segment<3>(6), dv, dw);
  BallVector f;
  f << y.segment<3>(3), dv, dw;
  return f;
}

using dormand_prince::kA;
using dormand_prince::kE;

struct Step
{
  std::vector<BallVector> y1, f0, f1;
  double error = 0;  ///< scaled error norm; <= 1 accepts
};

Step takeStep(const StepperModel& m, const std::vector<Ball<double>>& balls, double h, double tolerance)
{
  Step out;
  double sum = 0;
  int count = 0;
  for (const auto& b : balls)
  {
    const BallVector y0 = pack(b);
    std::array<BallVector, 7> k;
    k[0] = rate(m, b.motion, y0);
    for (int s = 1; s < 7; ++s)
    {
      BallVector y = y0;
      for (int j = 0; j < s; ++j)
        y += h * kA[s][j] * k[j];
      k[s] = rate(m, b.motion, y);
    }
    BallVector y1 = y0, error = BallVector::Zero();
    for (int s = 0; s < 7; ++s)
    {
      y1 += h * kA[6][s < 6 ? s : 0] * (s < 6 ? k[s] : BallVector::Zero());
      error += h * kE[s] * k[s];
    }
    if (b.moving())
      for (int i = 0; i < 9; ++i)
      {
        if (!b.airborne() && (i == kHeight || i == kVerticalSpeed))
          continue;
        const double scale = tolerance * (1 + std::max(std::abs(y0[i]), std::abs(y1[i])));
        sum += (error[i] / scale) * (error[i] / scale);
        ++count;
      }
    out.y1.push_back(y1);
    out.f0.push_back(k[0]);
    out.f1.push_back(k[6]);
  }
  out.error = count ? std::sqrt(sum / count) : 0.0;
  return out;
}

/// The dense output: the ball at fraction s of the step, cubic Hermite in each component from
/// the values and rates at both ends.
BallVector denseOutput(const BallVector& y0, const BallVector& y1, const BallVector& f0, const BallVector& f1, double h,
                       double s)
{
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s), h01 = s * s * (3 - 2 * s),
               h11 = s * s * (s - 1);
  return h00 * y0 + h10 * h * f0 + h01 * y1 + h11 * h * f1;
}

/// The landing's event function: the centre's height above R, a ball at R and rising counting as
/// just above it. A hop that begins at a step's start and ends within its first probe is then
/// bracketed from the start, and found.
double heightAboveSlate(const BallVector& y, double R)
{
  const double above = y[kHeight] - R;
  return above == 0 && y[kVerticalSpeed] > 0 ? std::numeric_limits<double>::denorm_min() : above;
}

/// Event functions at one instant, each positive until its event happens: slip, roll and spin
/// reversals, a landing on the slate, and every gap to a cushion, jaw, pocket or ball (in three
/// dimensions). Each is watched on its own: one
/// just resolved (a gap a rounding below zero) must not hide another.
std::vector<double> eventFunctions(const StepperModel& m, const std::vector<Ball<double>>& start,
                                   const std::vector<BallVector>& y)
{
  const double R = m.p.ball_radius;
  std::vector<double> g;
  for (std::size_t i = 0; i < start.size(); ++i)
  {
    const Ball<double>& b0 = start[i];
    if (!b0.inPlay())
      continue;
    const Vec2<double> r(y[i][0], y[i][1]);
    const Vec3<double> v = y[i].segment<3>(3), w = y[i].segment<3>(6);
    g.push_back(b0.motion == Motion::Sliding ? slipVelocity(v, w, R).dot(slipVelocity(b0.v, b0.w, R)) : 1.0);
    g.push_back(b0.motion == Motion::Rolling ? v.dot(b0.v) : 1.0);
    g.push_back(b0.moving() && b0.w.z() != 0 ? w.z() * b0.w.z() : 1.0);
    g.push_back(b0.airborne() ? heightAboveSlate(y[i], R) : 1.0);
    if (!b0.translating())
      continue;
    for (const auto& seg : m.table->segments())
    {
      const double along = (r - seg.start).dot(seg.direction);
      g.push_back(along >= 0 && along <= seg.length ? (r - seg.start).dot(seg.normal) - R : 1.0);
    }
    for (const auto& circle : m.table->circles())
      g.push_back((r - circle.centre).norm() - R - circle.radius);
    for (const auto& pocket : m.table->pockets())
      g.push_back((r - pocket.centre).norm() - pocket.radius);
    for (std::size_t j = 0; j < start.size(); ++j)
      if (j != i && start[j].inPlay())
        g.push_back((y[i].segment<3>(0) - y[j].segment<3>(0)).norm() - 2 * R);
  }
  return g;
}
}  // namespace

StepperReport runDormandPrince(const StepperModel& m, const StepperOptions& options, TableState<double> state,
                               const std::vector<double>& sample_times, const SampleCallback& sample)
{
  StepperReport report;
  std::vector<Ball<double>> balls;
  for (const auto& b : state.balls)
    balls.push_back(evolve(b, state.time, m.p));
  double t = state.time, h = options.step;
  const double end = state.time + options.max_time;
  std::size_t next_sample = 0;
  while (next_sample < sample_times.size() && sample_times[next_sample] <= t)
    sample(sample_times[next_sample++], balls);
  const auto anyMoving = [&] {
    return std::any_of(balls.begin(), balls.end(), [](const Ball<double>& b) { return b.moving(); });
  };
  while (anyMoving() && t < end && report.steps < options.max_steps)
  {
    // Land on sample times, so that samples are states, not interpolations.
    const double until_sample = next_sample < sample_times.size() ? sample_times[next_sample] - t : INFINITY;
    h = std::min({h, until_sample, end - t});
    if (h < 1e-13 && until_sample > 1e-13 && end - t > 1e-13)
    {
      report.stalled = true;  // the step collapsed: a stiff or non-smooth point it cannot pass
      break;
    }
    const Step step = takeStep(m, balls, h, options.tolerance);
    if (step.error > 1)
    {
      ++report.rejected_steps;
      h *= std::max(0.2, 0.9 * std::pow(step.error, -0.2));
      continue;
    }
    // Bracket the earliest event on the dense output, then bisect it.
    const std::vector<Ball<double>> before = balls;
    std::vector<BallVector> y0;
    for (const auto& b : balls)
      y0.push_back(pack(b));
    const auto at = [&](double s) {
      std::vector<BallVector> y;
      for (std::size_t i = 0; i < balls.size(); ++i)
        y.push_back(balls[i].moving() ? denseOutput(y0[i], step.y1[i], step.f0[i], step.f1[i], h, s) : y0[i]);
      return eventFunctions(m, before, y);
    };
    double event_fraction = -1;
    const int probes = 8;
    std::vector<double> previous = at(0);
    for (int k = 1; k <= probes && event_fraction < 0; ++k)
    {
      const double s = static_cast<double>(k) / probes;
      const std::vector<double> value = at(s);
      for (std::size_t f = 0; f < value.size(); ++f)
        if (previous[f] > 0 && value[f] <= 0)
        {
          double lo = s - 1.0 / probes, hi = s;
          for (int i = 0; i < 60 && hi - lo > 1e-15; ++i)
            (at(0.5 * (lo + hi))[f] > 0 ? lo : hi) = 0.5 * (lo + hi);
          if (event_fraction < 0 || hi < event_fraction)
            event_fraction = hi;  // just past it: the contact has begun
        }
      previous = value;
    }
    // At an event the balls take the dense output just past it, where the event function has
    // turned non-positive: re-integrating to that time could land a rounding short of it.
    const double taken = event_fraction > 0 ? event_fraction * h : h;
    const double energy_before = m.energy(balls);
    for (std::size_t i = 0; i < balls.size(); ++i)
      if (balls[i].moving())
      {
        unpack(
            event_fraction > 0 ? denseOutput(y0[i], step.y1[i], step.f0[i], step.f1[i], h, event_fraction) : step.y1[i],
            balls[i]);
        if (!balls[i].airborne())
        {
          balls[i].r.z() = m.p.ball_radius;
          balls[i].v.z() = 0;
        }
      }
    t += taken;
    m.switchStates(balls, before, report);
    m.resolveContacts(balls, before, report);
    report.energy_gain = std::max(report.energy_gain, m.energy(balls) - energy_before);
    ++report.steps;
    while (next_sample < sample_times.size() && sample_times[next_sample] <= t + 1e-12)
      sample(sample_times[next_sample++], balls);
    if (event_fraction < 0)
      h *= std::min(5.0, 0.9 * std::pow(std::max(step.error, 1e-10), -0.2));
  }
  report.finished = !anyMoving();
  report.hit_step_limit = !report.finished && !report.stalled && report.steps >= options.max_steps;
  report.end_time = t;
  while (next_sample < sample_times.size())
    sample(sample_times[next_sample++], balls);
  return report;
}

}  // namespace physics
}  // namespace cue_sim
