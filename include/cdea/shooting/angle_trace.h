#pragma once
// The shooting model traced by its angle: with the meridian angle at the disk
// edge theta0 prescribed, the unknown is the voltage-path parameter t (the
// dead load and pre-stretch are those of the voltage stage). Along theta0 the
// voltage-displacement curve has no turning points in t, so a fold of the
// curve in voltage is simply a maximum of t(theta0). This is the independent
// check of the limit points that arc-length continuation finds in the FE model.

#include <cdea/model/scene.h>
#include <cdea/shooting/meridian.h>
#include <cdea/shooting/options.h>

#include <optional>
#include <string>

namespace cdea::shooting
{
  struct AnglePoint
  {
    bool        ok            = false;
    double      theta0        = 0.; ///< rad
    double      t             = 0.; ///< voltage-path parameter
    double      lambda1_start = 0.;
    double      displacement  = 0.; ///< m
    std::string message;            ///< why it failed (empty if ok)
  };

  class AngleTrace
  {
  public:
    AngleTrace(const Scene &scene, const ShootingOptions &options);

    /// Equilibrium with angle @p theta0: root in t of r(B) = b, searched near
    /// @p t_guess (continuation, no global scan).
    AnglePoint solve(double theta0, double t_guess, double lambda1_guess) const;

    /// From the equilibrium @p start, step theta0 by |@p dtheta| in the
    /// direction in which t increases until t decreases again, then maximise t(theta0) by golden-section search to
    /// @p tolerance in theta0. Returns the fold, or nothing (with @p why) if t
    /// never turns within the path or the integration fails.
    std::optional<AnglePoint> limit_point(const AnglePoint &start, double dtheta,
                                          double tolerance = 1e-10,
                                          std::string *why = nullptr) const;

  private:
    Scene              scene;
    MeridianIntegrator integrator;

    MeridianLoad load(double t) const;
  };
} // namespace cdea::shooting
