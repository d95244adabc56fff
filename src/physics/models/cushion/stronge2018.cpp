// Stronge's compliant frictional impact (W. J. Stronge, Impact Mechanics, 2nd ed., Cambridge
// 2018: tangential compliance) at the cushion's nose, cushion_height above the cloth, where the
// other cushion models touch the ball too. The normal velocity there comes back times e_cushion;
// the slip along the nose's tangent plane follows from a tangential spring vibrating at
// cushion_frequency_ratio times the normal one, whose far end sticks or slides with friction
// f_cushion. It can stop, reverse, or keep the slip: the tangential restitution is an outcome.
// For a ball the inverse masses at any point of its surface are 1/m along the normal and 7/(2m)
// in every tangent, with no coupling, so the slip keeps its direction. The cloth takes the
// vertical part of the impulse, as in han2005, which is this model's limit of a rigid tangent
// (cushion_frequency_ratio -> infinity).
#include "physics/models/cushion/nose_contact.hpp"
#include "physics/models/cushion/tangential_compliance.hpp"
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
class StrongeCushion : public CushionModel<S>
{
public:
  S sustainedFriction(const PhysicsParams<S>& p) const override { return p.f_cushion; }
  void resolve(Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p) const override
  {
    const S m = p.ball_mass, tangential_inverse_mass = S(3.5);  // 1 + m R^2 / I, in units of 1/m
    const NoseContact<S> nose(normal, p);
    const S approach = nose.approach(ball);
    if (!(approach > S(0)))
      return;
    Vec3<S> impulse = (S(1) + p.e_cushion) * m * approach * nose.normal;
    const Vec3<S> slip = nose.slip(ball);
    const S speed = slip.norm();
    if (speed > zeroSpeed<S>())
    {
      const S after = slipAfterCompliantImpact(speed, approach, p.f_cushion, tangential_inverse_mass, p.e_cushion,
                                               p.cushion_frequency_ratio);
      impulse += (m / tangential_inverse_mass) * (after - speed) / speed * slip;
    }
    nose.push(ball, impulse, p);
  }
};
}  // namespace

CUE_SIM_MODEL_FACTORY(cushion, stronge2018, StrongeCushion)

}  // namespace physics
}  // namespace cue_sim
