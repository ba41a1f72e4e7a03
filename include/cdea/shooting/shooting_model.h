#pragma once
// The shooting model of the actuator behind the common EquilibriumModel
// interface (no finite elements): an independent check of the FE model and a
// fast solver for parameter sweeps.
//
// States:
//  - flat and homogeneous (no dead load, equal ring voltages): closed form
//    r = stretch R, s1 = s2 = equi-biaxial nominal stress;
//  - flat, non-uniform voltages (no dead load): in-plane shooting on l1(A);
//  - cone (dead load F > 0): shooting on the meridian angle theta0 at the disk
//    edge, continued from the current state's theta0 (or, from a flat state,
//    from the small-deflection estimate theta0 ~ F / (2 pi H A s0)).
// The disk and frame radii follow the load's stretch: r(A) = stretch A and
// r(B) = stretch B, i.e. a and b once the pre-stretch is applied.

#include <cdea/model/scene.h>
#include <cdea/shooting/meridian.h>
#include <cdea/shooting/options.h>
#include <cdea/model/equilibrium_model.h>

#include <vector>

namespace cdea::shooting
{
  /// Cost of the last call to ShootingModel::solve().
  struct ShootingStatistics
  {
    unsigned int  root_iterations = 0; ///< shooting integrations of the root solve
    unsigned long rhs_evaluations = 0; ///< all right-hand sides of the solve
    /// Right-hand sides and accepted steps of one integration at the solution.
    unsigned long rhs_evaluations_per_integration = 0;
    unsigned long accepted_steps                  = 0;
    double        wall_seconds                    = 0.;
  };

  class ShootingModel : public EquilibriumModel
  {
  public:
    explicit ShootingModel(const Scene &scene, const ShootingOptions &options = {});

    void         set_reference_state() override;
    SolveReport  solve(const LoadState &load) override;
    double       displacement() const override;
    HoopStresses hoop_stresses() const override;
    StepFields   fields() const override;
    /// pi int r^2 (-z') dR over the profile's samples: cubic Hermite
    /// interpolation of r and z (slopes l1 cos(theta), -l1 sin(theta)) between
    /// neighbouring samples, integrated exactly; error O(h^4) in the sample spacing.
    double      enclosed_volume() const override;

    /// Unknowns: the shooting angle theta0 and the disk-edge stretch l1(A);
    /// the kind of state (homogeneous, flat, cone) follows from the load.
    ModelState state() const override;
    void       set_state(const ModelState &state) override;
    /// Extrapolates the shooting angle and the disk-edge stretch (cone states only).
    void predict(const ModelState &older, double factor) override;

    void                   set_options(const ShootingOptions &options);
    const ShootingOptions &options() const { return integrator.options(); }

    const ShootingStatistics &statistics() const { return stats; }
    /// The current equilibrium: profile (with samples), shooting angle, load.
    const Profile   &profile() const { return current.profile; }
    double           shooting_angle() const { return current.profile.theta0; }
    const LoadState &load() const override { return current.load; }

  private:
    enum class Kind : int
    {
      homogeneous = 0,
      flat        = 1,
      cone        = 2
    };

    struct Current
    {
      Kind         kind = Kind::homogeneous;
      LoadState    load;
      unsigned int iterations = 0;
      Profile      profile;
    };

    Scene              sc;
    MeridianIntegrator integrator;
    Current            current;
    ShootingStatistics stats;

    /// Integrate once from stored start values (exactly reproducible).
    Profile rebuild(Kind kind, const LoadState &load, double theta0,
                    double lambda1_start) const;
    /// The kind of state solve() reaches for @p load.
    static Kind kind_of(const LoadState &load);
  };
} // namespace cdea::shooting
