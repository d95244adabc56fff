// The equations of motion and contact handling the time-steppers share (internal).
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "cue_sim/evaluation/time_stepping.hpp"
#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/table_model.hpp"
#include "physics/models/ball_table/slate_landing.hpp"

namespace cue_sim
{
namespace physics
{
struct StepperModel
{
  std::shared_ptr<const TableModel> table;
  PhysicsParams<double> p;
  std::unique_ptr<BallBallModel<double>> ball_ball;
  std::unique_ptr<CushionModel<double>> cushion;
  std::unique_ptr<BallTableModel<double>> ball_table;
  std::unique_ptr<BallBallModel<double>> ball_ball_in_air;  ///< set when ball_ball needs both balls on the cloth

  /// dv/dt and dw/dt of one ball in the given motion state, with the friction direction taken
  /// from this very velocity and spin: the non-smooth force law itself.
  void derivative(Motion motion, const Vec3<double>& v, const Vec3<double>& w, Vec3<double>& dv, Vec3<double>& dw) const
  {
    dv.setZero();
    dw.setZero();
    const double R = p.ball_radius;
    if (motion == Motion::Airborne)
    {
      dv.z() = -p.gravity;  // flight: gravity alone, the spin carried (src/physics/models/flight.hpp)
      return;
    }
    if (motion == Motion::Sliding)
    {
      const Vec3<double> u = slipVelocity(v, w, R);
      const double speed = u.norm();
      if (speed > 0)
      {
        const Vec3<double> u_hat = u / speed;
        dv = -p.slideDecel() * u_hat;
        dw.x() = -u_hat.y() * 2.5 * p.slideDecel() / R;
        dw.y() = u_hat.x() * 2.5 * p.slideDecel() / R;
      }
    }
    else if (motion == Motion::Rolling)
    {
      const double speed = v.norm();
      if (speed > 0)
      {
        dv = -p.rollDecel() * v / speed;
        dw.x() = -dv.y() / R;
        dw.y() = dv.x() / R;
      }
    }
    if (motion != Motion::Stationary && motion != Motion::Pocketed && w.z() != 0)
      dw.z() = -std::copysign(p.spinDecel(), w.z());
  }

  /// The friction clamp of game engines: a slip (or roll) that one step of friction would
  /// remove is ended before the step. Without it RK4 stalls: with the slip inside one step's
  /// change its four stages see the friction alternate (-, +, -, +) and cancel exactly.
  void clampFriction(std::vector<Ball<double>>& balls, double h, StepperReport& report) const
  {
    const double R = p.ball_radius;
    // Whether one step of friction would end the ball's motion state.
    const auto endsWithinStep = [&](const Ball<double>& b) {
      switch (b.motion)
      {
        case Motion::Sliding:
          return slipVelocity(b.v, b.w, R).norm() <= 3.5 * p.slideDecel() * h;
        case Motion::Rolling:
          return b.v.norm() <= p.rollDecel() * h;
        case Motion::Spinning:
          return std::abs(b.w.z()) <= p.spinDecel() * h;
        default:
          return false;
      }
    };
    for (auto& b : balls)
      while (b.moving() && endsWithinStep(b))
      {
        report.slip_reversals += b.motion == Motion::Sliding;
        applyTransition(b, p);  // the engine's own switch: roll on, or stop
      }
  }

  void step(std::vector<Ball<double>>& balls, double h, Integrator integrator) const
  {
    for (auto& b : balls)
    {
      if (!b.moving())
        continue;
      Vec3<double> dv, dw;
      if (integrator == Integrator::SymplecticEuler)
      {
        derivative(b.motion, b.v, b.w, dv, dw);
        b.v += h * dv;
        b.w += h * dw;
        b.r += h * b.v;
      }
      else
      {
        Vec3<double> k_v[4], k_w[4], k_r[4];
        Vec3<double> v = b.v, w = b.w;
        const double weights[4] = {0.0, 0.5, 0.5, 1.0};
        for (int k = 0; k < 4; ++k)
        {
          if (k > 0)
          {
            v = b.v + weights[k] * h * k_v[k - 1];
            w = b.w + weights[k] * h * k_w[k - 1];
          }
          derivative(b.motion, v, w, k_v[k], k_w[k]);
          k_r[k] = v;
        }
        b.r += h / 6 * (k_r[0] + 2 * k_r[1] + 2 * k_r[2] + k_r[3]);
        b.v += h / 6 * (k_v[0] + 2 * k_v[1] + 2 * k_v[2] + k_v[3]);
        b.w += h / 6 * (k_w[0] + 2 * k_w[1] + 2 * k_w[2] + k_w[3]);
      }
      if (!b.airborne())
      {
        b.r.z() = p.ball_radius;
        b.v.z() = 0;
      }
    }
  }

  /// Ends a motion state whose driving quantity reversed within the step (slip, speed, spin).
  void switchStates(std::vector<Ball<double>>& balls, const std::vector<Ball<double>>& before,
                    StepperReport& report) const
  {
    const double R = p.ball_radius;
    for (std::size_t i = 0; i < balls.size(); ++i)
    {
      Ball<double>& b = balls[i];
      const Ball<double>& old = before[i];
      if (b.motion != old.motion || !b.moving())
        continue;
      const bool reversed =
          (b.motion == Motion::Sliding && slipVelocity(b.v, b.w, R).dot(slipVelocity(old.v, old.w, R)) <= 0) ||
          (b.motion == Motion::Rolling && b.v.dot(old.v) <= 0);
      if (reversed)
      {
        report.slip_reversals += b.motion == Motion::Sliding;
        applyTransition(b, p);
      }
      if (b.moving() && b.w.z() * old.w.z() < 0)  // z-spin ran out within the step
      {
        if (b.motion == Motion::Spinning)
          applyTransition(b, p);
        else
          b.w.z() = 0;
      }
    }
  }

  /// Contacts found by overlap at the end of the step, resolved there with the engine's models.
  /// A ball in the air meets the slate and other balls (in three dimensions); it meets cushions,
  /// jaws and pockets as a ball on the cloth does, so a scene with flight keeps its flights over
  /// open cloth.
  void resolveContacts(std::vector<Ball<double>>& balls, const std::vector<Ball<double>>& before,
                       StepperReport& report) const
  {
    const double R = p.ball_radius;
    for (std::size_t i = 0; i < balls.size(); ++i)
    {
      Ball<double>& b = balls[i];
      if (!b.inPlay())
        continue;
      if (b.airborne() && b.r.z() <= R && b.v.z() < 0)
      {
        report.max_overlap = std::max(report.max_overlap, R - b.r.z());
        landOnSlate(b, *ball_table, p);  // the engine's impact and its rule that ends the bounces
        ++report.collisions;
      }
      const Vec2<double> c = b.r.head<2>();
      for (std::size_t k = 0; k < table->pockets().size(); ++k)
        if ((c - table->pockets()[k].centre).norm() < table->pockets()[k].radius)
        {
          b.motion = Motion::Pocketed;
          b.pocket = static_cast<int>(k);
          b.v.setZero();
          b.w.setZero();
        }
      if (!b.inPlay())
        continue;
      for (const auto& s : table->segments())
      {
        const double along = (c - s.start).dot(s.direction);
        if (along < 0 || along > s.length)
          continue;
        const double gap = (c - s.start).dot(s.normal) - R;
        const double gap_before = (before[i].r.head<2>() - s.start).dot(s.normal) - R;
        if (gap < -R && gap_before > -R)
          report.tunnelled = true;  // the centre went behind the nose line
        if (gap < 0 && gap > -R && b.v.head<2>().dot(s.normal) < 0)
        {
          report.max_overlap = std::max(report.max_overlap, -gap);
          cushion->resolve(b, Vec3<double>(s.normal.x(), s.normal.y(), 0), p);
          settleMotion(b, R);
          ++report.collisions;
        }
      }
      for (const auto& circle : table->circles())
      {
        const Vec2<double> d = c - circle.centre;
        const double gap = d.norm() - R - circle.radius;
        if (gap < 0 && b.v.head<2>().dot(d) < 0)
        {
          report.max_overlap = std::max(report.max_overlap, -gap);
          const Vec2<double> n = d.normalized();
          cushion->resolve(b, Vec3<double>(n.x(), n.y(), 0), p);
          settleMotion(b, R);
          ++report.collisions;
        }
      }
    }
    for (std::size_t i = 0; i < balls.size(); ++i)
      for (std::size_t j = i + 1; j < balls.size(); ++j)
      {
        Ball<double>& a = balls[i];
        Ball<double>& b = balls[j];
        if (!a.inPlay() || !b.inPlay() || (!a.moving() && !b.moving()))
          continue;
        const Vec3<double> d = b.r - a.r;
        const double distance = d.norm();
        if (distance < 2 * R && (a.v - b.v).dot(d) > 0)
        {
          report.max_overlap = std::max(report.max_overlap, 2 * R - distance);
          const bool a_on_cloth = !a.airborne(), b_on_cloth = !b.airborne();
          (ball_ball_in_air && !(a_on_cloth && b_on_cloth) ? *ball_ball_in_air : *ball_ball).resolve(a, b, p);
          // The cloth takes the vertical part of the impulse on a ball that is on it, as in the
          // engine (whose further impulses of a tilted meeting these steppers leave out).
          if (a_on_cloth)
            a.v.z() = 0;
          if (b_on_cloth)
            b.v.z() = 0;
          settleMotion(a, R);
          settleMotion(b, R);
          ++report.collisions;
        }
        else if (distance >= 2 * R)
        {
          // Passed through each other within the step: closest approach of the straight
          // chord between the two step ends.
          const Vec3<double> d0 = before[j].r - before[i].r;
          const Vec3<double> e = d - d0;
          const double s = e.squaredNorm() > 0 ? std::clamp(-d0.dot(e) / e.squaredNorm(), 0.0, 1.0) : 0.0;
          if ((d0 + s * e).norm() < 2 * R && d0.norm() >= 2 * R)
            report.tunnelled = true;
        }
      }
  }

  double energy(const std::vector<Ball<double>>& balls) const
  {
    double e = 0;
    for (const auto& b : balls)
      e += mechanicalEnergy(b, p);  // a falling ball gains speed, not energy
    return e;
  }
};

/// Adaptive Dormand-Prince 5(4) with events located on the step's dense output.
StepperReport runDormandPrince(const StepperModel& model, const StepperOptions& options, TableState<double> state,
                               const std::vector<double>& sample_times, const SampleCallback& sample);

}  // namespace physics
}  // namespace cue_sim
