#pragma once
// One shooting integration of the axisymmetric membrane (Guo et al. 2025,
// eqs. 1-15, with the denominator of eq. 8 corrected to R ds1/dl1).
//
// Reference radius R runs from the disk edge A to the frame B; the state is
// y = (r, z, theta, l1) and l2 = r/R. With C = F / (2 pi H), eqs. (4) and (6)
// give the first integral R s1 sin(theta) = C, and eqs. (4)-(5) give
//   dr/dR = l1 cos(theta),  dz/dR = -l1 sin(theta),
//   dtheta/dR = -s2 sin(theta) / (s1 R),
//   dl1/dR = (s2 cos(theta) - s1 - R s12 dl2/dR) / (R s11),
//   dl2/dR = (l1 cos(theta) - l2) / R.
// The integration starts at R = A with r = lam A (lam: the current
// equi-biaxial pre-stretch, lam A = a once pre-stretched), z = 0 and the
// shooting angle theta0; l1(A) follows from 2 pi A H s1 sin(theta0) = F. At an
// interior ring edge r, z, theta and s1 are continuous (eq. 14) and l1 jumps
// to the value that gives the same s1 under the next ring's voltage.
//
// Without a dead load (F = 0) the film stays flat: theta = 0, z = 0, and the
// unknown at R = A is l1 itself (in-plane problem). Internally the radii are
// scaled by A, so the error control sees numbers of order one.
//
// The law is the scene's (any elastic MembraneLaw that serves every model,
// Scene::law()); the integration asks it for the stresses and the tangent at
// once, refuses states outside its range (MembraneLaw::range_margin, named by
// its limit()) and where ds1/dl1 <= 0 (loss of ellipticity of the membrane
// in the meridian direction, pull-in), and solves for l1 inside the range of
// l1 that the law states at the hoop stretch (meridian_stretch_range()).

#include <cdea/material/gent_law.h>
#include <cdea/material/gent_dielectric.h>
#include <cdea/material/tension_field.h>
#include <cdea/model/records.h>
#include <cdea/model/scene.h>
#include <cdea/shooting/options.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cdea::shooting
{
  /// The load a meridian is integrated for.
  struct MeridianLoad
  {
    double              stretch = 1.; ///< equi-biaxial pre-stretch: r(A) = stretch A, target r(B) = stretch B
    double              force   = 0.; ///< dead load F >= 0 on the disk (N)
    std::vector<double> voltages;     ///< V, one per ring
  };

  /// Result of one integration from A to B.
  struct Profile
  {
    bool        ok = false;
    std::string message; ///< why the integration failed (empty if ok)

    double theta0         = 0.; ///< meridian angle at R = A (rad)
    double lambda1_start  = 0.; ///< l1 at R = A on the inner ring's side
    double r_end          = 0.; ///< r(B) (m)
    double z_disk         = 0.; ///< z(A) with z(B) = 0 (m)
    double displacement   = 0.; ///< |z(A) - z(B)| (m)
    double s2_min         = 0.; ///< smallest s2 at accepted points, ring edges and samples (Pa)
    double s2_min_radius  = 0.; ///< reference radius R of s2_min (m)
    std::vector<double> s2_ring_inner; ///< s2 at each ring's inner edge, ring side (Pa)

    unsigned long rhs_evaluations = 0;
    unsigned long accepted_steps  = 0;
    unsigned long rejected_steps  = 0;

    /// Samples along R (SI), filled only on request; both sides of each
    /// interior ring edge appear (two samples at the same R).
    StepFields samples;
  };

  /// The law the integrator uses at a point of a ring: the scene's elastic
  /// law at the ring's voltage, plain or relaxed (its tension field). The
  /// plain hoop stress stays available: it defines the loss of tension in
  /// both cases.
  class ShootingLaw
  {
  public:
    /// @p plain elastic; @p film: the film's thickness (the field) and
    /// shear modulus (the scale of the stresses).
    ShootingLaw(std::shared_ptr<const MembraneLaw> plain, const MaterialConstants &film,
                double voltage, bool relaxed);

    /// Stresses and tangent of the law (relaxed if asked) at once; false
    /// outside its range.
    bool respond(double l1, double l2, NominalStress &s, StressTangent &t) const;
    /// The stresses (NaN outside the range).
    NominalStress stress(double l1, double l2) const;
    /// ds1/dl1 (NaN outside the range).
    double        s11(double l1, double l2) const;
    NominalStress plain_stress(double l1, double l2) const;
    double        range_margin(double l1, double l2) const
    {
      return plain->range_margin(l1, l2);
    }
    /// The open interval of l1 inside the law's range at hoop stretch l2.
    std::pair<double, double> meridian_stretch_range(double l2) const
    {
      return plain->meridian_stretch_range(l2);
    }
    LawLimit limit() const { return plain->limit(); }
    /// "the Gent limit was reached (g <= 0)", or the like for the law.
    std::string limit_reached() const;
    /// What the diagnostics print of the margin: ", g = 0.93" (empty without a limit).
    std::string margin_text(double l1, double l2) const;
    double      electric_field(double l1, double l2) const { return phi * l1 * l2 / H; }
    double      voltage() const { return phi; }
    double      shear_modulus() const { return mu; }

  private:
    std::shared_ptr<const MembraneLaw>  plain;
    std::shared_ptr<const TensionField> relaxation; ///< null: plain
    double                              H, mu, phi;
  };

  /// Solve s1(l1, l2) = target for l1 under @p law, starting from @p guess:
  /// a bracket is grown around the guess inside the law's range of l1 (where
  /// s1 runs from -inf to +inf for the Gent law), then safeguarded Newton.
  /// The root must have ds1/dl1 > 0 on the way from the guess; otherwise,
  /// or without a bracket, nullopt and @p why is set.
  std::optional<double> solve_lambda1(const ShootingLaw &law, double lambda2, double target,
                                      double guess, std::string *why = nullptr);

  std::optional<double> solve_lambda1(const GentDielectric &law, double lambda2,
                                      double target, double guess,
                                      std::string *why = nullptr);

  /// Open interval of l1 where the Gent margin is positive at fixed l2
  /// (first <= 0 if there is none).
  std::pair<double, double> gent_lambda1_range(double jlim, double lambda2);

  class MeridianIntegrator
  {
  public:
    MeridianIntegrator(const Scene &scene, const ShootingOptions &options);

    /// l1 at the disk edge from 2 pi A H s1(l1, stretch) sin(theta0) = F.
    std::optional<double> disk_edge_lambda1(const MeridianLoad &load, double theta0,
                                            double guess,
                                            std::string *why = nullptr) const;

    /// Integrate from A to B starting with (theta0, lambda1_start). For F > 0,
    /// theta0 must lie in (0, pi); for F = 0 it must be 0 (flat, in-plane).
    Profile integrate(const MeridianLoad &load, double theta0,
                      double lambda1_start, bool with_samples) const;

    /// disk_edge_lambda1 followed by integrate (F > 0).
    Profile shoot(const MeridianLoad &load, double theta0, double lambda1_guess,
                  bool with_samples) const;

    /// Closed-form homogeneous flat state r = stretch R (F = 0, all ring
    /// voltages equal): s1 = s2 = nominal equi-biaxial stress everywhere.
    Profile homogeneous(const MeridianLoad &load, bool with_samples) const;

    /// Equi-biaxial nominal stress s1 = s2 at @p stretch and @p voltage (Pa).
    double equibiaxial_stress(double stretch, double voltage) const;

    const Scene           &scene() const { return sc; }
    const ShootingOptions &options() const { return opts; }
    /// The scene's law (plain).
    const MembraneLaw &law() const { return *plain_law; }

  private:
    Scene                              sc;
    ShootingOptions                    opts;
    std::shared_ptr<const MembraneLaw> plain_law;
    double              A;     ///< inner reference radius (m): the length unit
    std::vector<double> edges; ///< ring edges R_v / A, n+1 values from 1 to B/A

    std::vector<ShootingLaw> laws(const MeridianLoad &load) const;
    std::string check_load(const MeridianLoad &load) const;
  };
} // namespace cdea::shooting
