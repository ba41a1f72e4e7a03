#pragma once
// The fit of a film's constants to material tests (doc/materials.md, "The
// material-test model"): the material point of the scene's law
// (material/material_point.h) along every test's history, its exact
// Jacobian, and the least squares of design/fit.h (its free-parameter names,
// scaling, bounds, covariance and warnings), from a data-driven start and
// several others; per file the rms residual, absolute and relative to the
// file's largest stress.

#include <cdea/design/fit.h>
#include <cdea/design/material_test_data.h>

#include <functional>
#include <string>
#include <vector>

namespace cdea
{
  /// The nominal stresses of every sample of several tests (file after
  /// file) and their derivatives with respect to free parameters of the
  /// scene's law (the film's shear modulus and Jlim, the law's own constants:
  /// branch moduli and relaxation times, shear-thinning constants, ...).
  class MaterialTestModel
  {
  public:
    /// InputError if a free parameter is no constant of the law.
    MaterialTestModel(const Scene &base, const std::vector<MaterialTestData> &tests,
                      const std::vector<SceneParameter> &free,
                      const MaterialPointSettings       &settings = {});

    /// Stresses (Pa) and, if asked, the Jacobian (Pa per SI unit of each
    /// parameter) at @p values; false with a message naming the test's file,
    /// line, time and stretch where the law cannot follow the history.
    bool evaluate(const std::vector<double> &values, Eigen::VectorXd &stress,
                  Eigen::MatrixXd *jacobian, std::string *message = nullptr) const;

    std::size_t size() const { return offsets.back(); } ///< samples of all tests
    /// The first row of test @p k in evaluate()'s vectors.
    std::size_t offset(std::size_t k) const { return offsets[k]; }
    const std::vector<MaterialTestData> &tests() const { return data; }

  private:
    const Scene                       base;
    const std::vector<MaterialTestData> data;
    const std::vector<SceneParameter> free;
    const MaterialPointSettings       settings;
    std::vector<LawParameter>         law_parameters;
    std::vector<std::size_t>          offsets;
  };

  /// How well one test is met: sqrt(sum w r^2 / sum w) over its samples
  /// (w its rows' weights, r model - measured) and that over the largest
  /// |measured stress| of the file.
  struct TestMeasures
  {
    std::string name;
    std::size_t samples = 0;
    double      rms     = 0.; ///< Pa
    double      largest = 0.; ///< Pa
    double      relative = 0.;
  };

  /// The measures of every test of @p model for the model stresses @p stress.
  std::vector<TestMeasures> test_measures(const MaterialTestModel &model,
                                          const Eigen::VectorXd   &stress);

  struct MaterialFitSettings
  {
    FitSettings           fit;   ///< free parameters, iterations, tolerance
    MaterialPointSettings point; ///< the time steps of every history
    /// One weight per test (empty: 1 each), times its rows' weights.
    std::vector<double> test_weights;
    /// Starts: the data-driven one and starts - 1 variations of it
    /// (material_test_starts()); 0: the scene's own values only.
    unsigned int starts = 3;
    /// With several starts, each is first fitted for at most this many
    /// iterations, and only the one with the lowest cost goes on to
    /// convergence.
    unsigned int screening_iterations = 10;
  };

  struct MaterialFitResult
  {
    FitResult                 fit; ///< of the best start (fitted, residuals in Pa)
    std::vector<TestMeasures> tests;
    /// Every start's values and the weighted cost sum w r^2 (kPa^2) its
    /// screening ended at (NaN: it could not start); the best one's index.
    std::vector<std::vector<double>> starts;
    std::vector<double>              costs;
    std::size_t                      best = 0;
    unsigned int                     evaluations = 0; ///< over all starts
  };

  /// Starts for the free parameters from the data (doc/materials.md): the
  /// relaxation times spread log-evenly from three sample intervals to a third
  /// of the longest test; network A's modulus (an elastic law's shear
  /// modulus) scaled so that the law's relaxed stress meets the data's
  /// long-time plateau (the ends of holds, or the slowest loading); the
  /// branches' moduli sharing the data's initial stiffness above that plateau;
  /// Jlim kept at least twice the largest I1 - 3 of the data; other constants
  /// the scene's. Start 0 is that guess; start s > 0 shifts every relaxation
  /// time by a fraction of the spacing and leans the moduli towards the short
  /// or the long times. Values in SI units, one vector per start.
  std::vector<std::vector<double>> material_test_starts(const Scene &base,
                                                        const std::vector<MaterialTestData> &tests,
                                                        const std::vector<SceneParameter>   &free,
                                                        unsigned int                         starts);

  /// Fits the free parameters of @p settings to @p tests jointly (residuals
  /// in kPa, weight = test weight times row weight), from each start
  /// (screened, MaterialFitSettings), and keeps the fit with the lowest
  /// cost; relaxation times kept between a
  /// hundredth of the shortest sample interval and a hundred times the
  /// longest test (relaxation_time_window()). The result's measures are
  /// those of that fit. @p progress as fit_observations().
  MaterialFitResult fit_material_tests(
    const Scene &base, const std::vector<MaterialTestData> &tests,
    const MaterialFitSettings                                                    &settings,
    const std::function<void(unsigned int, double, const std::vector<double> &)> &progress = {});

  /// One file of a material-test fit as it is reported: the data, its
  /// weight, whether it was fitted or only predicted (--predict), the
  /// model's stresses at the fitted values and its measures.
  struct MaterialTestOutcome
  {
    const MaterialTestData *data   = nullptr;
    double                  weight = 1.;
    bool                    fitted = true;
    std::vector<double>     model; ///< Pa at every sample (NaN: the model failed)
    TestMeasures            measures;
  };

  /// The outcome of every file: @p fitted (with @p weights, empty: 1 each)
  /// from the fit's stresses, then @p predicted evaluated at the fitted
  /// values. A predicted file the model cannot follow gets NaN stresses and
  /// measures, and the reason in @p warnings.
  std::vector<MaterialTestOutcome> material_test_outcomes(
    const Scene &base, const std::vector<SceneParameter> &free, const MaterialFitResult &r,
    const std::vector<MaterialTestData> &fitted, const std::vector<double> &weights,
    const std::vector<MaterialTestData> &predicted, std::vector<std::string> &warnings);

  /// The product of a material-test fit (model/quantities_material_fit.h
  /// besides the root attributes and /correlation of every fit), in SI;
  /// written to <Base name>_fit.h5.
  Product material_fit_product(const std::string &parameter_text, const FitSettings &settings,
                               const MaterialFitResult                &r,
                               const std::vector<MaterialTestOutcome> &outcomes);
} // namespace cdea
