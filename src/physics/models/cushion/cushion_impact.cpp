#include "physics/models/cushion/cushion_impact.hpp"

#include "physics/models/cushion/nose_contact.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
typename CushionImpact<S>::Setup cushionImpact(const Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p,
                                               S mu_nose, S mu_cloth)
{
  const S m = p.ball_mass, R = p.ball_radius, inertia = S(0.4) * m * R * R;
  const NoseContact<S> nose(normal, p);
  const Vec3<S> along = normal.cross(Vec3<S>::UnitZ());  // along the cushion
  const Vec3<S> cloth = -R * Vec3<S>::UnitZ();
  Eigen::Matrix<S, 3, 2> nose_plane, cloth_plane;  // orthonormal tangent bases
  nose_plane << along, nose.normal.cross(along);
  cloth_plane << along, normal;

  typename CushionImpact<S>::Setup setup;
  setup.velocity0 = ball.v;
  setup.velocity0.z() = S(0);
  setup.spin0 = ball.w;
  setup.radius = R;
  setup.mu = {mu_nose, mu_cloth};
  // What each unit impulse does to the centre's velocity (its vertical part taken by the cloth)
  // and to the spin (the normal impulse at the nose points at the centre: no torque).
  for (int k = 0; k < CushionImpact<S>::kImpulses; ++k)
  {
    Vec3<S> at_nose = Vec3<S>::Zero(), at_cloth = Vec3<S>::Zero();
    if (k == 0)
      at_nose = nose.normal;
    else if (k < 3)
      at_nose = nose_plane.col(k - 1);
    else
      at_cloth = cloth_plane.col(k - 3);
    Vec3<S> dv = (at_nose + at_cloth) / m;
    dv.z() = S(0);
    const Vec3<S> dw = (nose.offset.cross(at_nose) + cloth.cross(at_cloth)) / inertia;
    setup.velocity_per_impulse.col(k) = dv;
    setup.spin_per_impulse.col(k) = dw;
    setup.slip_per_impulse.col(k) << nose_plane.transpose() * (dv + dw.cross(nose.offset)),
        cloth_plane.transpose() * (dv + dw.cross(cloth));
    setup.approach_per_impulse(k) = -dv.dot(nose.normal);
    // The cloth pushes up with what the nose pushes down, its friction's part included.
    setup.load(0, k) = k == 0 ? S(1) : S(0);
    setup.load(1, k) = -at_nose.z();
  }
  const Vec3<S>& v0 = setup.velocity0;
  setup.slip0 << nose_plane.transpose() * (v0 + ball.w.cross(nose.offset)),
      cloth_plane.transpose() * (v0 + ball.w.cross(cloth));
  setup.approach0 = -v0.dot(nose.normal);
  return setup;
}

template CushionImpact<double>::Setup cushionImpact(const Ball<double>&, const Vec3<double>&,
                                                    const PhysicsParams<double>&, double, double);
template CushionImpact<long double>::Setup cushionImpact(const Ball<long double>&, const Vec3<long double>&,
                                                         const PhysicsParams<long double>&, long double, long double);

}  // namespace physics
}  // namespace cue_sim
