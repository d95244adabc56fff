// Mathavan, Jackson and Parkin 2010, "A theoretical analysis of billiard ball dynamics under
// cushion impacts", Proc. IMechE Part C 224(9), 1863-1873.
//
// The cushion is rigid and its nose touches the ball at I, alpha = asin(h/R - 1) above the
// equator; the cloth touches it at C, straight below. The impact is followed in the normal
// impulse P at I, which grows through compression (the ball closing on I) and restitution until
// the normal force has given back e^2 of the work it took (the paper's work-done restitution,
// Stronge's energetic coefficient). Along the way Coulomb friction mu_cushion acts against the
// slip at I, the cloth pushes up with whatever keeps the ball on it (the paper's P_C), and
// friction mu_slide acts against the slip at C. Written here with vectors, which gives the
// paper's component equations (its Eq. 13-17) in its cushion frame.
#include "physics/models/cushion/cushion_impact.hpp"
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
class MathavanCushion : public CushionModel<S>
{
public:
  S sustainedFriction(const PhysicsParams<S>& p) const override { return p.mu_cushion; }
  void resolve(Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p) const override
  {
    CushionImpact<S> impact(cushionImpact(ball, normal, p, p.mu_cushion, p.mu_slide));
    impact.integrate(p.e_cushion_work, p.cushion_impact_tolerance);
    ball.v = impact.velocities();
    ball.w = impact.spins();
  }
};
}  // namespace

CUE_SIM_MODEL_FACTORY(cushion, mathavan2010, MathavanCushion)

}  // namespace physics
}  // namespace cue_sim
