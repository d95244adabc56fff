// Lander 1999, "Physics on the Back of a Cocktail Napkin", Eq. 1-5: an impulse along the line of
// centres with restitution e_ball; tangential velocities and spins are unchanged.
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
class FrictionlessBallBall : public BallBallModel<S>
{
public:
  S sustainedFriction(const PhysicsParams<S>&) const override { return S(0); }
  void resolve(Ball<S>& a, Ball<S>& b, const PhysicsParams<S>& p) const override
  {
    // Horizontal for balls on the cloth (both centres at z = R), tilted when one is in the air.
    const Vec3<S> n = (b.r - a.r).normalized();
    const S approach = (a.v - b.v).dot(n);  // > 0 while closing
    if (!(approach > S(0)))
      return;
    // Lander 1999, Eq. 5 with m_A = m_B: j = -(1 + e) (v_A - v_B).n / (2/m).
    const S j = -(S(1) + p.e_ball) * approach * p.ball_mass / S(2);
    a.v += (j / p.ball_mass) * n;
    b.v -= (j / p.ball_mass) * n;
  }
};
}  // namespace

CUE_SIM_MODEL_FACTORY(ball_ball, frictionless, FrictionlessBallBall)

}  // namespace physics
}  // namespace cue_sim
