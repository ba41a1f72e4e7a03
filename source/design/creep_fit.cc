// The creep fit: the displacements of the quasi-static time run at the
// curve's sample times and their derivatives (creep_with_sensitivities),
// fitted by least squares.

#include <cdea/analysis/creep_sensitivity.h>
#include <cdea/base/format.h>
#include <cdea/base/units.h>
#include <cdea/design/viscous_fit.h>
#include <cdea/input/solver_settings.h>

#include <algorithm>
#include <cmath>

namespace cdea
{
  CreepModel::CreepModel(const Parameters &p_in, const CreepData &data_in,
                         const std::vector<SceneParameter> &free_in)
    : p(p_in)
    , data(data_in)
    , free(free_in)
  {
    const Scene scene = p.scene();
    for (const SceneParameter &f : free)
      law_parameters.push_back(law_parameter_of(scene, f));
  }

  bool CreepModel::evaluate(const std::vector<double> &values, Eigen::VectorXd &d,
                            Eigen::MatrixXd *jacobian, std::string *message)
  {
    Parameters at = p;
    for (std::size_t j = 0; j < free.size(); ++j)
      set_law_parameter(at, law_parameters[j], values[j]);
    CreepSensitivity out;
    std::string      why;
    ++runs_;
    std::vector<LawParameter> wanted = jacobian ? law_parameters : std::vector<LawParameter>{};
    if (!creep_with_sensitivities(at, wanted, data.times, out, why))
      {
        if (message)
          *message = why;
        return false;
      }
    d = Eigen::Map<const Eigen::VectorXd>(out.displacement.data(),
                                          Eigen::Index(out.displacement.size()));
    if (jacobian)
      *jacobian = out.jacobian;
    return true;
  }

  void require_waveform_match(const Parameters &p, const CreepData &data, const std::string &file)
  {
    const Scene    scene    = p.scene();
    const Waveform waveform = time_settings(p, scene).waveform;
    for (std::size_t i = 0; i < data.size(); ++i)
      {
        if (data.times[i] > waveform.end_time() * (1. + 1e-12))
          throw InputError(file + ", row " + std::to_string(i + 1) + ": time " +
                           format_number(data.times[i]) + " s is after the end of the waveform (" +
                           format_number(waveform.end_time()) + " s, subsection Time)");
        const std::vector<double> v = waveform.voltages(data.times[i]);
        for (std::size_t r = 0; r < v.size(); ++r)
          if (std::abs(v[r] - data.voltages[i][r]) > 1e-3)
            throw InputError(file + ", row " + std::to_string(i + 1) + ", column V" +
                             std::to_string(r + 1) + "_kV: " +
                             format_number(units::kV.from_si(data.voltages[i][r])) +
                             " kV, but the waveform of subsection Time drives " +
                             format_number(units::kV.from_si(v[r])) +
                             " kV at " + format_number(data.times[i]) + " s");
      }
  }

  FitResult fit_creep(const Parameters &p, const CreepData &data, const FitSettings &settings,
                      const std::function<void(unsigned int, double, const std::vector<double> &)>
                        &progress)
  {
    // Relaxation times from a hundredth of the shortest sample interval to a
    // hundred times the curve's length.
    double spacing = HUGE_VAL;
    for (std::size_t i = 1; i < data.size(); ++i)
      spacing = std::min(spacing, data.times[i] - data.times[i - 1]);
    const FitSettings bounded =
      relaxation_time_window(p.scene(), settings, 1e-2 * spacing, 1e2 * data.times.back());
    CreepModel      model(p, data, settings.free);
    FitObservations observations{
      Eigen::Map<const Eigen::VectorXd>(data.displacement.data(), Eigen::Index(data.size())),
      Eigen::Map<const Eigen::VectorXd>(data.weight.data(), Eigen::Index(data.size())),
      units::mm.to_si}; // residuals in mm
    return fit_observations(p.scene(), observations, bounded,
                            [&model](const std::vector<double> &v, Eigen::VectorXd &d,
                                     Eigen::MatrixXd *J, std::string *message) {
                              return model.evaluate(v, d, J, message);
                            },
                            progress);
  }
} // namespace cdea
