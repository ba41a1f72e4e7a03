#pragma once
// The uncertain constants of a scene (subsection Uncertainty,
// doc/uncertainty.md) and the two ways their uncertainty reaches an answer J:
//
//   linear:       sigma_J^2 = g^T C g, g = dJ/dp the exact gradient
//                 (fe/sensitivities.h), C the constants' covariance;
//   Monte-Carlo:  p_i = p_0 + L z_i, L L^T = C, z_i standard normal (seeded),
//                 J evaluated at each p_i; mean, standard deviation and
//                 percentiles of the samples.
//
// The constants are scene parameters (SceneParameter) in the units the
// sensitivities use: Pa, F/m, kg, a law constant in its entry's unit.

#include <cdea/fe/sensitivities.h>
#include <cdea/input/parameters.h>
#include <cdea/input/parameters_uncertainty.h>
#include <cdea/model/scene.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace cdea
{
  /// The uncertain constants of a scene with their covariance.
  struct UncertainConstants
  {
    UncertaintyMode             mode = UncertaintyMode::none;
    std::vector<SceneParameter> parameters;
    std::vector<std::string>    names;      ///< as the user or the fit file named them
    Eigen::MatrixXd             covariance; ///< the parameters' units squared
    unsigned int                samples = 0, seed = 0;

    bool active() const { return mode != UncertaintyMode::none; }
    /// One standard deviation of an answer with gradient @p g (by the
    /// parameters): sqrt(g^T C g).
    double linear_sd(const Eigen::VectorXd &g) const;
  };

  /// The constants of subsection Uncertainty for @p scene (nothing but the
  /// mode when Mode = none). Throws InputError naming the entry: an unknown
  /// constant (with the names allowed), a negative standard deviation, a
  /// correlation outside [-1, 1] or of a constant without a standard
  /// deviation, a matrix that is not positive semidefinite, both or neither
  /// of Covariance file and Standard deviations, a file that cannot be read
  /// or has no covariance.
  UncertainConstants uncertain_constants(const Parameters &p, const Scene &scene);

  /// InputError unless Uncertainty/Mode = none or @p command carries it
  /// (`cdea run` of the quasi-static FE model): the commands that do not yet.
  void require_uncertainty_support(const Parameters &p, const std::string &command);

  /// @p n samples of the constants' values (n x parameters) around their
  /// values in @p scene, drawn with @p seed: the same seed, the same samples.
  Eigen::MatrixXd sample_constants(const UncertainConstants &c, const Scene &scene,
                                   unsigned int n, unsigned int seed);

  /// @p scene with the constants set to @p values (one row of sample_constants()).
  Scene with_constants(const Scene &scene, const UncertainConstants &c,
                       const Eigen::VectorXd &values);

  /// Mean, standard deviation (n - 1) and the 5, 50, 95 % percentiles
  /// (linear between order statistics) of @p values; NaN if there are none.
  struct SampleStatistics
  {
    double              mean = 0., sd = 0.;
    std::vector<double> percentiles;
    std::size_t         n = 0;
  };
  SampleStatistics sample_statistics(std::vector<double> values);
} // namespace cdea
