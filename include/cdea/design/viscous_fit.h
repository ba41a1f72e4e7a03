#pragma once
// Fits of the viscoelastic film (doc/materials.md, "Fits"): the relaxation
// spectrum's branch moduli and relaxation times and network A's constants
// fitted to a DMA table (the small-strain Prony moduli, closed form) or to a
// creep curve (the quasi-static time run of the parameter file,
// analysis/creep_sensitivity.h), by the least squares of design/fit.h.

#include <cdea/design/fit.h>
#include <cdea/design/fit_data.h>
#include <cdea/input/parameters.h>

namespace cdea
{
  /// Subsection Calibration for data of @p kind (dma or creep): the free
  /// parameters this kind depends on (DMA: shear modulus and the branches'
  /// constants; creep: also Jlim and permittivity), checked; InputError
  /// naming a parameter the data do not depend on and what they allow, or
  /// the film (Material/Model = viscoelastic for DMA; Time/Enabled = true
  /// and Time/Inertia = false for creep).
  FitSettings viscous_fit_settings(const Parameters &p, FitDataKind kind);

  /// The law parameter (law input, SI) a free parameter of a creep fit is.
  LawParameter law_parameter_of(const Scene &scene, const SceneParameter &p);

  /// @p settings with every free relaxation time of the viscoelastic law
  /// (own_constant(2(k-1)+1)) kept in [@p shortest, @p longest] (s): times
  /// the data cannot see (a branch relaxed within a sample interval, or
  /// never relaxed over the whole curve) are left out, where a fit would
  /// otherwise wander to the law's bounds (1e-12 s: a time run of tiny steps).
  FitSettings relaxation_time_window(const Scene &scene, FitSettings settings, double shortest,
                                     double longest);
  /// The value (SI) of law parameter @p q in @p p, and @p p with it set.
  double law_parameter_value(const Parameters &p, LawParameter q);
  void   set_law_parameter(Parameters &p, LawParameter q, double value);

  /// The small-strain uniaxial moduli of the viscoelastic law of a scene
  /// (the Prony series of material_chart.h, with E_A = 3 mu_A, E_k = 3 mu_k):
  ///   E'(f)  = E_A + sum_k E_k x_k^2 / (1 + x_k^2),
  ///   E''(f) = sum_k E_k x_k / (1 + x_k^2),   x_k = 2 pi f tau_k,
  /// and their exact derivatives with respect to the free parameters:
  ///   dE'/dmu_A = 3, dE'/dmu_k = 3 x^2 / (1 + x^2), dE''/dmu_k = 3 x / (1 + x^2),
  ///   dE'/dtau_k = E_k 2 x / (1 + x^2)^2 2 pi f,
  ///   dE''/dtau_k = E_k (1 - x^2) / (1 + x^2)^2 2 pi f.
  /// Rows 2i and 2i + 1: storage and loss at frequency i.
  class DmaModel
  {
  public:
    /// InputError if the law's small-strain response is not this Prony
    /// series (a branch law whose small-strain modulus is not 3 mu_k).
    DmaModel(const Scene &base, const std::vector<double> &frequency,
             const std::vector<SceneParameter> &free);
    bool evaluate(const std::vector<double> &values, Eigen::VectorXd &moduli,
                  Eigen::MatrixXd *jacobian, std::string *message = nullptr) const;

  private:
    const Scene                       base;
    const std::vector<double>         frequency;
    const std::vector<SceneParameter> free;
  };

  /// The creep curve's displacements at its sample times (creep_with_sensitivities).
  class CreepModel
  {
  public:
    CreepModel(const Parameters &p, const CreepData &data, const std::vector<SceneParameter> &free);
    bool evaluate(const std::vector<double> &values, Eigen::VectorXd &displacement,
                  Eigen::MatrixXd *jacobian, std::string *message = nullptr);
    unsigned int runs() const { return runs_; }

  private:
    const Parameters                  p;
    const CreepData                   data;
    const std::vector<SceneParameter> free;
    std::vector<LawParameter>         law_parameters;
    unsigned int                      runs_ = 0;
  };

  /// InputError naming @p file if a row's voltages differ from the waveform
  /// of the Time subsection of @p p at its time by more than 1e-6 kV: the
  /// waveform drives the model, the columns say what the data saw.
  void require_waveform_match(const Parameters &p, const CreepData &data, const std::string &file);

  /// The fits: observations (DMA: storage and loss per row, in kPa;
  /// creep: displacements in mm) and their least squares (fit_observations).
  FitResult fit_dma(const Scene &base, const DmaData &data, const FitSettings &settings,
                    const std::function<void(unsigned int, double, const std::vector<double> &)>
                      &progress = {});
  FitResult fit_creep(const Parameters &p, const CreepData &data, const FitSettings &settings,
                      const std::function<void(unsigned int, double, const std::vector<double> &)>
                        &progress = {});

  /// The product of a DMA or creep fit (model/quantities_fit.h): the root
  /// attributes of fit_product() and /data with the table's columns
  /// (frequency_Hz and storage_kPa, loss_kPa, fitted and residual ones; or
  /// time_s, voltage_kV, displacement_mm, fitted_mm, residual_mm) and weight.
  Product dma_fit_product(const std::string &parameter_text, const DmaData &data,
                          const FitSettings &settings, const FitResult &r);
  Product creep_fit_product(const std::string &parameter_text, const CreepData &data,
                            const FitSettings &settings, const FitResult &r);
} // namespace cdea
