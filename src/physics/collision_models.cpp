#include "cue_sim/physics/collision_models.hpp"

#include <stdexcept>

namespace cue_sim
{
namespace physics
{
template <typename S>
void FrictionlessBallBall<S>::resolve(Ball<S>& a, Ball<S>& b, const PhysicsParams<S>& p) const
{
  Vec3<S> n = b.r - a.r;
  n.z() = S(0);
  n.normalize();
  const S approach = (a.v - b.v).dot(n);  // > 0 while closing
  if (!(approach > S(0)))
    return;
  // Lander 1999, Eq. 5 with m_A = m_B: j = -(1 + e) (v_A - v_B).n / (2/m).
  const S j = -(S(1) + p.e_ball) * approach * p.ball_mass / S(2);
  a.v += (j / p.ball_mass) * n;
  b.v -= (j / p.ball_mass) * n;
}

template <typename S>
void SimpleCushion<S>::resolve(Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p) const
{
  const S v_n = ball.v.dot(normal);
  if (v_n < S(0))
    ball.v -= (S(1) + p.e_cushion) * v_n * normal;
}

std::vector<std::string> ballBallModelNames()
{
  return {"frictionless"};
}

std::vector<std::string> cushionModelNames()
{
  return {"simple"};
}

namespace
{
std::string joined(const std::vector<std::string>& names)
{
  std::string out;
  for (const auto& n : names)
    out += (out.empty() ? "" : ", ") + n;
  return out;
}
}  // namespace

template <typename S>
std::unique_ptr<BallBallModel<S>> makeBallBallModel(const std::string& name)
{
  if (name == "frictionless")
    return std::make_unique<FrictionlessBallBall<S>>();
  throw std::invalid_argument("unknown ball-ball model '" + name + "' (known: " + joined(ballBallModelNames()) + ")");
}

template <typename S>
std::unique_ptr<CushionModel<S>> makeCushionModel(const std::string& name)
{
  if (name == "simple")
    return std::make_unique<SimpleCushion<S>>();
  throw std::invalid_argument("unknown cushion model '" + name + "' (known: " + joined(cushionModelNames()) + ")");
}

template class FrictionlessBallBall<double>;
template class FrictionlessBallBall<long double>;
template class SimpleCushion<double>;
template class SimpleCushion<long double>;
template std::unique_ptr<BallBallModel<double>> makeBallBallModel(const std::string&);
template std::unique_ptr<BallBallModel<long double>> makeBallBallModel(const std::string&);
template std::unique_ptr<CushionModel<double>> makeCushionModel(const std::string&);
template std::unique_ptr<CushionModel<long double>> makeCushionModel(const std::string&);

}  // namespace physics
}  // namespace cue_sim
