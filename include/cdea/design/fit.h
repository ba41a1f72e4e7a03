#pragma once
// `cdea fit FILE.prm DATA.csv`: least-squares calibration of material and
// load parameters (subsection Calibration: any of shear modulus, Jlim,
// permittivity, mass, pre-stretch, and the own constants of the law of
// Material/Model by their entries, Jlim only under a law that has it) to
// measured disk displacements at given ring voltages (doc/optimization.md,
// "Calibration").
//
// Every data point is the state reached by ramping its ring voltages
// proportionally from zero (the branch continued from zero voltage), as
// `cdea run` with that point as the only waypoint. When the parameters
// change, each point continues from its own last state with the tangent
// predictor x + dx/dp dp (a ramp again if that fails). The Jacobian is exact
// (fe/sensitivities.h); Ceres' Levenberg-Marquardt minimises
// sum w_i (d_model,i - d_measured,i)^2. Standard errors and correlations
// come from the Jacobian at the optimum, s^2 (J^T W J)^-1 with s^2 the
// weighted residual variance, and a nearly singular J^T W J is reported as
// parameters the data do not determine.

#include <cdea/input/parameter_input.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/fe/sensitivities.h>
#include <cdea/model/product.h>
#include <cdea/solver/load_stepper.h>

#include <cmath>
#include <functional>
#include <istream>
#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  struct Parameters;

  /// Measured points: ring voltages (V), displacement (m), weight.
  struct CalibrationData
  {
    std::vector<std::vector<double>> voltages;
    std::vector<double>              displacement;
    std::vector<double>              weight;
    std::size_t                      size() const { return displacement.size(); }
  };

  /// Reads the CSV file (a regular file of at most 64 MB): a header line
  /// naming the columns V1_kV .. VN_kV (one per ring), displacement_mm and
  /// optionally weight, in any order; then one line per point, at most 10000.
  /// '#' starts a comment; a UTF-8 byte order mark is skipped. Voltages from
  /// 0 to @p voltage_ceiling (V; voltage_ceiling() of the scene, input/validation.h),
  /// displacements |z(A) - z(B)| from 0, weights above 0. Throws InputError
  /// naming the file, line and column.
  CalibrationData read_calibration_data(const std::string &file, unsigned int n_rings,
                                        double voltage_ceiling = HUGE_VAL);
  /// The same from @p in (CSV text), named @p name in the messages.
  CalibrationData read_calibration_data(std::istream &in, const std::string &name,
                                        unsigned int n_rings, double voltage_ceiling = HUGE_VAL);

  struct FitSettings
  {
    std::vector<SceneParameter> free;
    unsigned int                max_iterations = 100;
    double                      tolerance      = 1e-10;
    /// Per free parameter (empty: none), an interval (SI) narrower than the
    /// law's own bounds that the fit keeps it in: the relaxation times the
    /// data can see (viscous_fit.h, relaxation_time_window()).
    std::vector<std::pair<double, double>> window;
  };

  /// Subsection Calibration's free parameters (names as fit_settings()
  /// accepts them, checked against the law of Material/Model), iterations and
  /// tolerance; nothing about the kind of data.
  FitSettings free_parameter_settings(const Parameters &p);

  /// Subsection Calibration checked; throws InputError naming the parameter
  /// and, for a name the law of Material/Model does not have (or Jlim under
  /// a law without the Gent limit), the names this law allows.
  FitSettings fit_settings(const Parameters &p);

  /// Throws InputError (naming the data @p name) if @p data has fewer points
  /// than @p settings has free parameters.
  void require_enough_points(const CalibrationData &data, const FitSettings &settings,
                             const std::string &name);

  /// The name of @p p in the fit's messages and tables ("shear modulus",
  /// "pre-stretch").
  std::string label(const SceneParameter &p);

  /// @p value (SI) of @p p in the unit of its prm entry: "20 kPa", "280 g", "150".
  std::string value_text(const SceneParameter &p, double value);

  /// @p base with the free parameters set to @p values.
  Scene scene_with(const Scene &base, const std::vector<SceneParameter> &free,
                   const std::vector<double> &values);

  /// The displacement of every data point and its Jacobian with respect to
  /// the free parameters, for given parameter values.
  class DisplacementModel
  {
  public:
    DisplacementModel(const Scene &base, const CalibrationData &data,
                      const std::vector<SceneParameter> &free, const FeDiscretization &disc,
                      const NewtonSettings &newton, const SteppingSettings &stepping);
    ~DisplacementModel();

    /// false (with @p message) if some point cannot be reached. The first
    /// evaluation (the start) ramps every point from zero voltage and
    /// continues one the ramp misses from the nearest point reached; the
    /// message names the point, the values and why.
    bool evaluate(const std::vector<double> &values, Eigen::VectorXd &displacement,
                  Eigen::MatrixXd *jacobian, std::string *message = nullptr);

    /// The model along the data in file order (for plots): @p steps states
    /// between neighbouring points, by continuation from the first point.
    void curve(const std::vector<double> &values, unsigned int steps,
               std::vector<std::vector<double>> &voltages, std::vector<double> &displacement);

    unsigned int solves() const { return solves_; }
    unsigned int ramps() const { return ramps_; }

  private:
    const Scene                       base;
    const CalibrationData             data;
    const std::vector<SceneParameter> free;
    const FeDiscretization            discretization;
    const NewtonSettings              newton;
    const SteppingSettings            stepping;
    Scene                             scene;
    std::unique_ptr<MembraneModel>    model;
    std::vector<double>               model_values;
    /// Per point: its last state and dx/dp there, and the values they belong to.
    std::vector<ModelState>      states;
    std::vector<Eigen::MatrixXd> state_derivatives;
    std::vector<double>          state_values;
    unsigned int                 solves_ = 0, ramps_ = 0;

    MembraneModel &model_for(const std::vector<double> &values);
    LoadState      load_of(unsigned int point) const;
    /// The point reached by load stepping from zero voltage, proportionally
    /// to its voltages, or (@p via >= 0) through data point @p via first;
    /// false with why in @p message.
    bool        ramp(unsigned int point, std::string *message, int via = -1);
    std::string point_text(unsigned int point) const;
    std::string values_text(const std::vector<double> &values) const;
    /// The point's displacement, Jacobian row, state and dx/dp kept.
    void keep(unsigned int point, const StateSensitivity &at, Eigen::VectorXd &d,
              Eigen::MatrixXd *jacobian);
    /// At the start: the points the ramp from zero missed (with why),
    /// continued from the nearest point reached; false with the message.
    bool reach_along_the_data(const std::vector<std::pair<unsigned int, std::string>> &missed,
                              const std::vector<double> &values, Eigen::VectorXd &d,
                              Eigen::MatrixXd *jacobian, std::string *message);
  };

  struct FitResult
  {
    std::vector<double> initial, values, standard_errors; ///< SI units
    Eigen::MatrixXd     correlation;
    /// s^2 (J^T W J)^-1 (SI units; NaN where there are no standard errors).
    Eigen::MatrixXd     covariance;
    Eigen::VectorXd     fitted, residuals; ///< m, per point (model - measured)
    double              rms = 0.;          ///< sqrt(sum w r^2 / sum w), m
    double              condition = 0.;    ///< of the column-scaled Jacobian
    bool                converged = false;
    /// false: the start values reach not every data point (status says
    /// which and why); values are the start values, nothing else is set.
    bool                started = true;
    std::string         status;
    std::vector<std::string> warnings; ///< parameters the data do not determine
    unsigned int        iterations = 0, evaluations = 0;
  };

  /// Observations of any kind (displacements, moduli) in SI units, their
  /// weights, and the unit residuals and costs are measured in (1e-3: mm).
  struct FitObservations
  {
    Eigen::VectorXd measured, weight;
    double          unit = 1.;
  };

  /// The model of the observations at given parameter values (SI) and its
  /// Jacobian (if asked); false with why in the message.
  using FitFunction = std::function<bool(const std::vector<double> &, Eigen::VectorXd &,
                                         Eigen::MatrixXd *, std::string *)>;

  /// The least-squares fit itself (Ceres, bounds, standard errors and
  /// correlations, as fit() describes) of @p model to @p data.
  FitResult fit_observations(
    const Scene &base, const FitObservations &data, const FitSettings &settings,
    const FitFunction                                                            &model,
    const std::function<void(unsigned int, double, const std::vector<double> &)> &progress = {});

  /// Fit the free parameters of @p settings, starting from their values in
  /// @p base. @p progress (if set) is told about every iteration.
  FitResult fit(const Scene &base, const CalibrationData &data, const FitSettings &settings,
                DisplacementModel &model,
                const std::function<void(unsigned int, double, const std::vector<double> &)>
                  &progress = {});

  /// The parameter file entry that holds @p value of @p parameter.
  ParameterChange fitted_entry(const SceneParameter &parameter, double value);

  /// The entries of the parameter file that hold @p values of @p free
  /// (fitted_entry(), and for a branch's modulus or relaxation time the
  /// lists Material/Branch shear moduli (kPa) and Branch relaxation times
  /// (s) of every branch).
  std::vector<ParameterChange> fitted_entries(const Scene &base,
                                              const std::vector<SceneParameter> &free,
                                              const std::vector<double>         &values);

  /// The entries of subsection Uncertainty that hold the covariance of @p r
  /// (Mode = none; Standard deviations of the identified constants in their
  /// entries' units, Correlations of every pair), so that the fitted
  /// parameter file carries its uncertainty into a run (doc/uncertainty.md).
  std::vector<ParameterChange> uncertainty_entries(const std::vector<SceneParameter> &free,
                                                   const FitResult                   &r);

  /// A whole calibration as `cdea fit` and cdea.fit() run it: the fit, and
  /// the model along the data at the fitted values (if it got there).
  struct Calibrated
  {
    FitResult                        result;
    std::vector<std::vector<double>> curve_voltages;     ///< ring voltages along the data (V)
    std::vector<double>              curve_displacement; ///< the model's displacement there (m)
    unsigned int                     solves = 0, ramps = 0;
  };

  /// Fits @p settings to @p data with the model of @p p (@p base its
  /// scene), as fit() does, then traces the model along the data with 8
  /// steps between points.
  Calibrated calibrate(const Parameters &p, const Scene &base, const CalibrationData &data,
                       const FitSettings &settings,
                       const std::function<void(unsigned int, double, const std::vector<double> &)>
                         &progress = {});

  /// The product of a calibration (model/quantities_fit.h): the root
  /// attributes, /correlation, /data and /curve of doc/optimization.md, in
  /// SI; written to <Base name>_fit.h5 and returned by cdea.fit().
  Product fit_product(const std::string &parameter_text, const CalibrationData &data,
                      const FitSettings &settings, const Calibrated &calibrated);
} // namespace cdea
