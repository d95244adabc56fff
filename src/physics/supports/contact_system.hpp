// The equations of motion of balls in sustained contact (internal to the physics core): a group of
// balls, each touching others, the slate, a cushion's face or nose, a post's side or rim, moves
// under gravity and the contact forces that keep the touching surfaces from passing into each other
// (Baraff, "Fast contact force computation for nonpenetrating rigid bodies", SIGGRAPH 1994). At
// each contact a normal force lambda >= 0 acts only while the surfaces press (complementarity);
// Coulomb friction mu lambda opposes the slip or, while it sticks, takes whatever keeps it stuck
// within that bound; a rolling-resistance couple and a drilling couple do the same for the turning
// of one surface on the other, with the cloth's own coefficients, so that a ball on the slate under
// its weight alone moves exactly as the closed-form motion says (doc/physics.md, "Resting
// contact"). With each contact's modes fixed, the forces are one linear system; the modes are
// chosen by pivoting until every force and every free acceleration is consistent.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "cue_sim/physics/physics_params.hpp"
#include "physics/supports/contact_geometry.hpp"

namespace cue_sim
{
namespace physics
{
/// One ball of a group: its state, and whether the contact equations move it (dynamic) or it
/// follows its own closed-form path (a ball touching the group that nothing presses on).
template <typename S>
struct ContactBody
{
  Vec3<S> r, v, w;
  bool dynamic = true;
  /// A kinematic body's acceleration: what its own closed-form path gives it (a ball on the cloth that
  /// nothing presses on, rolling or sliding as the cloth alone decides).
  Vec3<S> a_free = Vec3<S>::Zero();
  /// Whether it may follow its own path while nothing presses on it (a ball on the cloth outside the
  /// group): the mode decision then takes it as kinematic unless a contact presses on it.
  bool free_on_cloth = false;
};

/// A contact the group's equations keep track of.
template <typename S>
struct ContactLink
{
  int body = -1;                     ///< the ball (index into the group's bodies)
  int other = -1;                    ///< the other ball (Surface::Ball), else -1
  int obstacle = -1;                 ///< the cushion's segment or the post's circle, else -1
  Surface surface = Surface::Slate;  ///< as met at the start of the step
  S mu = S(0);                       ///< Coulomb friction of a sliding slip
  S rolling = S(0);                  ///< rolling resistance: a couple of at most rolling * lambda [m]
  S drilling = S(0);                 ///< drilling resistance: a couple of at most drilling * lambda [m]
  S grip = S(0);                     ///< the most a stuck slip holds, over lambda (static friction, >= mu)
};

/// How a resistance at a contact acts (the friction against the slip, the couples against the
/// turning about the tangent and about the normal): stuck, it holds its motion at zero, taking what
/// that needs within its bound; sliding, it opposes the motion with its bound, scaled down in
/// proportion below ContactSystem::slideSpeed (Coulomb's law regularized there: the stick-slip
/// transition of coupled contacts has otherwise no consistent modes, Painleve's paradox, and chatters).
enum class Resist : std::uint8_t
{
  Stuck,
  Sliding,
};

/// How each contact acts, and what it took: the modes of a linear complementarity problem and its
/// solution.
template <typename S>
struct LinkMode
{
  bool pressed = false;            ///< a normal force acts (else the surfaces are free to part)
  bool bilateral = false;          ///< held both ways, frictionless, where no modes were consistent (holdTogether)
  Resist slip = Resist::Sliding;   ///< Coulomb friction against the slip
  Resist roll = Resist::Sliding;   ///< rolling resistance (while the slip sticks)
  Resist drill = Resist::Sliding;  ///< drilling resistance
  // What the contact takes (on `body`; the other takes the opposite).
  S lambda = S(0);                     ///< [N]
  Vec3<S> friction = Vec3<S>::Zero();  ///< [N]
  Vec3<S> couple = Vec3<S>::Zero();    ///< rolling and drilling couples [N m]
};

/// What a margin (ContactSystem::margins) watches: the mode that stops holding when it turns negative.
enum class MarginKind : std::uint8_t
{
  Surface,  ///< the contact is still on the surface it met (no mode of its own: the step just ends)
  Gap,      ///< a free contact stays open
  Press,    ///< a pressed contact's force stays positive
  Slip,     ///< a stuck slip's friction stays within its bound
  Roll,     ///< a stuck rolling couple stays within its bound
  Drill,    ///< a stuck drilling couple stays within its bound
  Height,   ///< a ball in the air stays above the slate (added by the stepper)
};

struct MarginTag
{
  int link = -1;
  MarginKind kind = MarginKind::Surface;
};

/// Turns the mode a crossed margin watched to the mode that holds beyond it (a free contact pressed, a
/// pressed one let go, a stuck resistance sliding); false where the margin has no such mode, or where
/// a pressed contact still presses harder than `graze_force` [N] (it is let go at the step's end, where
/// its force reaches zero: let go before it, its bodies' own paths would still press it, and the
/// event search find it again at once).
template <typename S>
bool flipMode(const MarginTag& tag, std::vector<LinkMode<S>>& modes, S graze_force);

template <typename S>
struct BodyRates
{
  Vec3<S> a, alpha;
};

/// The equations of one group's contacts on one table.
template <typename S>
class ContactSystem
{
public:
  ContactSystem(const TableGeometry<S>& geometry, const PhysicsParams<S>& params);

  const PhysicsParams<S>& params() const { return params_; }
  /// Slips slower than this [m/s], and turnings slower than this over R [rad/s], may stick: a sliding
  /// resistance below it is scaled down in proportion (Resist).
  S slideSpeed() const { return slide_speed_; }
  /// The force [N] below which a free contact is not pressed (kGrazeForce of the weight).
  S grazeForce() const;
  /// The band [m/s] below which a sliding resistance of the link, of coefficient mu (a couple's over
  /// R), is scaled down in proportion: the slide speed, or wider for a large mu (kBandPerMu) except on
  /// the slate, whose resistances are the closed forms'.
  S bandFor(const ContactLink<S>& link, S mu) const;

  /// The contact's geometry at the bodies' positions.
  ContactGeometry<S> geometryOf(const ContactLink<S>& link, const std::vector<ContactBody<S>>& bodies) const;

  /// Accelerations of every body under its contacts in the modes given (kept as they are: the forces
  /// found are written into `modes`). A kinematic body's are its own: not computed, left as given.
  void accelerations(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                     std::vector<LinkMode<S>>& modes, std::vector<BodyRates<S>>& rates) const;

  /// Chooses every contact's modes at this state (the complementarity problem), and the
  /// accelerations they give. Contacts separating faster than `parting` [m/s] are not pressed.
  /// Returns false if the pivoting did not settle (the last modes are kept), or settled on forces only
  /// an impulse would give (nearPainleve).
  bool decideModes(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                   std::vector<LinkMode<S>>& modes, std::vector<BodyRates<S>>& rates) const;

  /// How far each mode is from becoming wrong, scaled so that 1 is large: a negative value means
  /// the frozen modes no longer hold (a force turned negative, a stuck resistance beyond its bound, a
  /// free contact closing, a surface left for another).
  /// Written after `accelerations` at the same state and modes.
  void margins(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
               const std::vector<LinkMode<S>>& modes, const std::vector<BodyRates<S>>& rates,
               const std::vector<S>& start_gaps, std::vector<S>& out, std::vector<MarginTag>* tags = nullptr) const;

  /// Takes out, by the impulses of the contacts, every relative velocity the modes say is zero: the
  /// normal velocity of a pressed contact, and (unless `normals_only`) the slip of a sticking one and
  /// the turning of a stuck one. The projection is the nearest state in the kinetic-energy metric, so
  /// it takes energy out and never adds it.
  void projectVelocities(std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                         const std::vector<LinkMode<S>>& modes, bool normals_only = false) const;
  /// Where the modes have no consistent choice (Painleve's paradox: friction at one contact lifting the
  /// body off another, or sliding that cannot stop and cannot go on), the contacts jam: an impulse
  /// takes out the normal closing, the slip and the turning of every touching contact with friction
  /// and resistances, as a tangential impact would with friction enough (Stewart, SIAM Review 42(1),
  /// 2000; Genot and Brogliato, Eur. J. Mech. A 18, 1999). It only takes energy out.
  void jam(std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links) const;
  /// Where even jammed the modes are not consistent (a contact that pulls when pressed and is pressed
  /// into when free: friction or a rolling couple that grows with the normal force faster than the
  /// normal force parts the bodies, as a rolling resistance above the cloth's friction does), that
  /// contact holds both ways for the next step, without friction: a workless constraint, so no energy
  /// is made, and the bodies move on together until their motion lets the modes settle. The
  /// accelerations are written again.
  void holdTogether(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                    std::vector<LinkMode<S>>& modes, std::vector<BodyRates<S>>& rates) const;
  /// Moves the dynamic bodies (each the same share of a gap, walls not at all) until every pressed
  /// contact's gap is zero: the integration's drift off its contacts, a few ulps a step.
  void projectPositions(std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                        const std::vector<LinkMode<S>>& modes) const;

  /// The slip velocity at the contact (body against other), its turning (angular velocity of the
  /// body relative to the other).
  Vec3<S> slip(const ContactLink<S>& link, const ContactGeometry<S>& c,
               const std::vector<ContactBody<S>>& bodies) const;
  Vec3<S> turning(const ContactLink<S>& link, const std::vector<ContactBody<S>>& bodies) const;
  /// The relative velocity of the centres (body minus other).
  Vec3<S> relativeVelocity(const ContactLink<S>& link, const std::vector<ContactBody<S>>& bodies) const;

private:
  using Matrix = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<S, Eigen::Dynamic, 1>;
  struct Assembly;
  /// The equations in the given modes: the pressed contacts' normal forces (or every contact's) and
  /// the stuck resistances.
  void assemble(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                const std::vector<LinkMode<S>>& modes, bool every_normal, Assembly& out) const;
  /// The bodies' accelerations and each contact's forces for the unknowns x.
  void applyForces(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                   const Assembly& assembly, const Vector& x, std::vector<LinkMode<S>>& modes,
                   std::vector<BodyRates<S>>& rates) const;
  /// The bodies as the mode decision moves them: a ball on the cloth that no contact but the slate
  /// presses follows its own closed-form path (kinematic, its acceleration a_free).
  std::vector<ContactBody<S>> followed(const std::vector<ContactBody<S>>& bodies,
                                       const std::vector<ContactLink<S>>& links,
                                       const std::vector<LinkMode<S>>& modes) const;
  /// How hard the bodies press into a free contact, as a force [N] beyond a graze's (positive: it
  /// must be pressed).
  S pressingInto(const ContactLink<S>& link, const std::vector<ContactBody<S>>& used,
                 const std::vector<BodyRates<S>>& rates) const;
  /// True if a contact of either body of `pressed` has a resistance too stiff to integrate sliding
  /// (kStiffShare).
  bool stiffAbout(const std::vector<ContactLink<S>>& links, const ContactLink<S>& pressed) const;
  /// True if a pressed contact's force is beyond what any sustained contact carries (kJamLoad): the
  /// modes are next to Painleve's paradox, and the contacts jam.
  bool nearPainleve(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                    const std::vector<LinkMode<S>>& modes) const;
  /// The normal forces of the complementarity problem, with the stuck resistances held; false if it
  /// could not be solved.
  bool pressNormals(const Assembly& assembly, Vector& x) const;

  const TableGeometry<S>& geometry_;
  PhysicsParams<S> params_;
  S inertia_;      ///< 2/5 m R^2
  S slide_speed_;  ///< [m/s]
};

/// The kinetic energy of the bodies and their height's potential above the cloth [J].
template <typename S>
S groupEnergy(const std::vector<ContactBody<S>>& bodies, const PhysicsParams<S>& p);

}  // namespace physics
}  // namespace cue_sim
