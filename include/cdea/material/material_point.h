#pragma once
// A material point of the film driven through a homogeneous test history, as
// a materials lab runs it (doc/materials.md, "The material-test model"):
//
//   uniaxial tension     l1 = L(t) given, l2 from s2 = 0 (l3 = 1 / (l1 l2));
//   equibiaxial tension  l1 = l2 = L(t);
//   pure shear           l1 = L(t), l2 = 1 (planar tension of a wide strip),
//
// the thickness direction free by incompressibility, at zero voltage. The
// answer is the nominal stress of the loaded direction, s1 = dW/dl1 of the
// law (MembraneLaw's NominalStress): W is per reference volume, so s1 is
// the force over the undeformed cross-section (F = s1 W0 H0 for a strip of
// undeformed width W0 and thickness H0: F d(L0 l1) = W0 H0 L0 s1 dl1).
//
// The law is the FE model's law object and its internal variables follow
// the law's own update (MembraneLaw::evaluate with an InternalStep), in the
// time schemes of the FE time run (numerics/esdirk.h, TimeMethod): backward
// Euler and the trapezoidal rule through the law's update of that scheme,
// and every implicit stage of an ESDIRK step as the law's backward Euler step
// of gamma h from the shifted start Yhat_i = y_n + h sum_{j<i} a_ij K_j (as
// MembraneModel::set_internal_start). The history starts at rest: the
// internal variables relaxed at the first sample's stretch (normally 1);
// between samples the stretch is linear in time; every sample ends a step,
// and sample intervals are cut into steps as MaterialPointSettings says. The
// steps depend on the samples only, never on the constants, so a fit sees a
// smooth model.
//
// With law parameters given, the derivatives of s1 at every sample are
// exact for the discrete scheme (forward sensitivities, as
// fe/time_sensitivity.h): at stage i, with the law's linearization
// (MembraneLaw::linearize: S_l, S_y, f_y, f_l) and its parameter derivatives
// (evolving_parameter_derivative: S_p, f_p),
//
//   (I - gamma h f_y) dY - gamma h f_l dl = dYhat + gamma h f_p,
//   dYhat = dy_n + h sum_{j<i} a_ij dK_j,
//   ds = S_l dl + S_y dY + S_p,   dK = f_y dY + f_l dl + f_p,
//
// where dl = (0, dl2) and, in uniaxial tension, dl2 closes ds2 = 0 (in the
// other tests dl = 0). Solved with the law's exact linearization, not its
// condensed tangent, so the derivatives stay exact where that tangent is
// not (the shear-thinning viscosity). The relaxed start is differentiated
// as TimeSensitivity::start_relaxed does.

#include <cdea/material/membrane_law.h>
#include <cdea/numerics/esdirk.h>

#include <Eigen/Core>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  /// The homogeneous tests.
  enum class TestKind
  {
    uniaxial,
    equibiaxial,
    pure_shear
  };

  /// "uniaxial", "equibiaxial", "pure shear".
  std::string test_kind_name(TestKind kind);

  /// A test's stretch history: the stretch of the loaded direction from the
  /// unstressed state at every sample time.
  struct StretchHistory
  {
    TestKind            kind = TestKind::uniaxial;
    std::vector<double> time;    ///< s, increasing strictly
    std::vector<double> stretch; ///< l1 (-), above 0
  };

  /// How a history becomes time steps (doc/materials.md, "The material-test
  /// model"). A sample interval is cut into at least the larger of
  /// ceil(interval / max_step) and ceil(|change of l1| / max_stretch_step)
  /// equal steps; after every change of the stretch rate (by more than a
  /// tenth of the history's largest rate: the start of a hold, an unloading)
  /// the steps grow geometrically: a step is at most step_growth times the
  /// time since that change, and at least 1 / substeps_after_change of its
  /// interval, so that relaxation at every time scale longer than that is
  /// followed whatever the constants are.
  struct MaterialPointSettings
  {
    /// The scheme of the internal variables; an ESDIRK method takes fixed steps.
    TimeMethod   method           = TimeMethod::trapezoidal;
    double       max_step         = std::numeric_limits<double>::infinity(); ///< s
    double       max_stretch_step = 0.01;
    double       step_growth      = 0.25; ///< 0: no grading
    unsigned int substeps_after_change = 8;
    /// Keep the internal variables at every sample (MaterialPointResult::internal).
    bool record_internal = false;
  };

  /// The model's answer along a history.
  struct MaterialPointResult
  {
    std::vector<double> stress;     ///< s1 (Pa) at every sample
    std::vector<double> transverse; ///< l2 at every sample
    /// n_internal_variables() numbers per sample (if recorded), in the law's order.
    std::vector<double> internal;
    /// d s1 / d parameter at every sample (a row per sample, a column per
    /// parameter, per unit of the parameter: LawParameter's units).
    Eigen::MatrixXd jacobian;
    unsigned int    steps = 0, evaluations = 0; ///< time steps, law evaluations
    /// The sample (from 0) where a failed run stopped (the size of the
    /// history if it did not fail).
    std::size_t failed_sample = 0;
  };

  /// The material point of one law. Not thread-safe (work storage); one
  /// object per thread.
  class MaterialPoint
  {
  public:
    explicit MaterialPoint(const MembraneLaw &law, const MaterialPointSettings &settings = {});
    ~MaterialPoint();
    MaterialPoint(const MaterialPoint &)            = delete;
    MaterialPoint &operator=(const MaterialPoint &) = delete;

    /// s1 along @p history and, for @p parameters, its exact derivatives.
    /// False with @p message (naming the sample, its time and stretch) if the
    /// law cannot follow the history: a stretch outside its range, a local
    /// update or the transverse balance that does not converge, a parameter
    /// the law cannot differentiate.
    bool run(const StretchHistory &history, const std::vector<LawParameter> &parameters,
             MaterialPointResult &result, std::string &message);

  private:
    class Impl;
    std::unique_ptr<Impl> impl;
  };
} // namespace cdea
