// Han 2005, "Dynamics in carom and three cushion billiards", J. Mech. Sci. Technol. 19(4): one
// impulse where the cushion's nose, cushion_height above the cloth, touches the ball. Normal
// impulse from e_cushion along the contact normal; friction f_cushion times it against the
// contact point's slip, capped by the no-slip impulse. Spin changes the rebound.
#include "physics/models/cushion/nose_contact.hpp"
#include "physics/models/friction_impulse.hpp"
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
class HanCushion : public CushionModel<S>
{
public:
  void resolve(Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p) const override
  {
    const S m = p.ball_mass, R = p.ball_radius, inertia = S(0.4) * m * R * R;
    const NoseContact<S> nose(normal, p);
    const Vec3<S>&contact = nose.offset, &contact_normal = nose.normal;
    const S approach = -ball.v.dot(contact_normal);  // a sphere's spin adds nothing along it
    if (!(approach > S(0)))
      return;
    const S normal_impulse = (S(1) + p.e_cushion) * m * approach;
    Vec3<S> impulse = normal_impulse * contact_normal;
    Vec3<S> slip = ball.v + ball.w.cross(contact);
    slip -= slip.dot(contact_normal) * contact_normal;
    // Tangential inverse mass at the contact: 1/m + R^2/I = 7/(2m).
    impulse += frictionImpulse(slip, p.f_cushion * normal_impulse, S(3.5) / m);
    ball.v += impulse / m;
    ball.v.z() = S(0);  // the part pressing the ball into the cloth is taken by the cloth
    ball.w += contact.cross(impulse) / inertia;
  }
};
}  // namespace

CUE_SIM_MODEL_FACTORY(cushion, han2005, HanCushion)

}  // namespace physics
}  // namespace cue_sim
