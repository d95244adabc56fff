// Frictional inelastic impacts of equal spheres (Alciatore, TP ): the normal
// impulse as in the frictionless model; at the contact point the surfaces slide past each other
// and a friction impulse mu_b(v) times the normal impulse opposes that slip, capped by the
// impulse that stops it. It changes both balls' velocities and spins: cut- and spin-induced
// throw and spin transfer.
#include <cmath>

#include "physics/models/friction_impulse.hpp"
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
class FrictionalBallBall : public BallBallModel<S>
{
public:
  S sustainedFriction(const PhysicsParams<S>& p) const override { return p.mu_ball_a + p.mu_ball_b; }
  void resolve(Ball<S>& a, Ball<S>& b, const PhysicsParams<S>& p) const override
  {
    // Horizontal for balls on the cloth (both centres at z = R), tilted when one is in the air.
    const Vec3<S> n = (b.r - a.r).normalized();
    const S approach = (a.v - b.v).dot(n);
    if (!(approach > S(0)))
      return;
    const S m = p.ball_mass, R = p.ball_radius, inertia = S(0.4) * m * R * R;
    // The impulse J acts on a at its contact point R n, and -J on b at -R n.
    const S normal_impulse = (S(1) + p.e_ball) * m / S(2) * approach;
    Vec3<S> impulse = -normal_impulse * n;
    // Slip of a's surface past b's at the contact: (v_a + w_a x R n) - (v_b + w_b x (-R n)).
    Vec3<S> slip = a.v - b.v + R * (a.w + b.w).cross(n);
    slip -= slip.dot(n) * n;
    // A tangential impulse J_t on each ball changes the slip by -7 J_t / m in all (1/m for the
    // centre and R^2/I = 5/(2m) for the spin, per ball), so J_t = m |slip| / 7 stops it.
    const S mu = p.mu_ball_a + p.mu_ball_b * std::exp(-p.mu_ball_c * slip.norm());
    impulse += frictionImpulse(slip, mu * normal_impulse, S(7) / m);
    a.v += impulse / m;
    b.v -= impulse / m;
    // (R n) x J for a and (-R n) x (-J) for b: both spins change alike.
    const Vec3<S> spin_change = (R * n).cross(impulse) / inertia;
    a.w += spin_change;
    b.w += spin_change;
    // Vertical friction on balls on the cloth goes into it: they stay on it. (With a ball in the
    // air, the engine lands any ball driven into the slate, and one driven up leaves the cloth.)
    if (!a.airborne() && !b.airborne())
    {
      a.v.z() = S(0);
      b.v.z() = S(0);
    }
  }
};
}  // namespace

CUE_SIM_MODEL_FACTORY(ball_ball, frictional, FrictionalBallBall)

}  // namespace physics
}  // namespace cue_sim
