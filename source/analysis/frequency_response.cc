#include <cdea/analysis/frequency_response.h>
#include <cdea/analysis/run_setup.h>
#include <cdea/base/run_control.h>
#include <cdea/fe/linear_dynamics.h>
#include <cdea/input/solver_settings.h>
#include <cdea/model/quantities_common.h>
#include <cdea/model/quantities_response.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#ifndef CDEA_VERSION
#  define CDEA_VERSION "unknown"
#endif

namespace cdea
{
  namespace
  {
    /// The equilibrium at the end of the voltage path, reached
    /// quasi-statically with the material relaxed (network B carries
    /// nothing: a viscoelastic film after a long hold).
    std::unique_ptr<MembraneModel> relaxed_equilibrium(const Parameters &p, const Scene &scene)
    {
      auto       model   = make_fe_model(p, scene);
      const bool viscous = scene.law()->n_internal_variables() > 0;
      if (viscous)
        model->set_time_step(std::numeric_limits<double>::infinity(), TimeScheme::backward_euler);
      LoadStepper stepper(scene, *model, study_stepping_settings(p));
      // `cdea response` under SIGINT, SIGTERM, SIGHUP: stop at the next step.
      stepper.on_step = [](const StepSummary &) {
        if (const int signal = StopOnSignals::requested())
          throw RunInterrupted(signal);
      };
      const RunResult run = stepper.run();
      if (!run.completed)
        throw std::runtime_error("no equilibrium at the end of the voltage path: " + run.message);
      if (viscous)
        {
          model->relax_internal_variables();
          model->set_time_step(0., TimeScheme::backward_euler);
        }
      return model;
    }

    /// The mode shapes' r and z at @p R (disk's z(A) = 1).
    void mode_shapes(MembraneModel &model, const std::vector<LinearizedDynamics::Mode> &modes,
                     FrequencyResponse &r)
    {
      const std::vector<double> state = model.solution();
      r.mode_r.resize(modes.size(), r.sample_R.size());
      r.mode_z.resize(modes.size(), r.sample_R.size());
      std::vector<double> rr, zz;
      for (std::size_t k = 0; k < modes.size(); ++k)
        {
          const Eigen::VectorXd &u = modes[k].shape;
          model.set_solution(std::vector<double>(u.data(), u.data() + u.size()));
          model.profile_at(r.sample_R, rr, zz);
          for (std::size_t j = 0; j < rr.size(); ++j)
            {
              r.mode_r(k, j) = rr[j];
              r.mode_z(k, j) = zz[j];
            }
          r.mode_frequency.push_back(modes[k].frequency);
          r.mode_damping.push_back(modes[k].damping_ratio);
        }
      model.set_solution(state);
    }

    /// Transfer functions at every frequency (the timed part).
    void transfer_functions(const LinearizedDynamics &dynamics, FrequencyResponse &r)
    {
      const std::size_t n_f = r.frequency.size(), n_r = r.bias.size();
      r.disk.resize(n_f, n_r);
      r.volume_per_volt.resize(n_f, n_r);
      r.disk_drive.resize(n_f);
      r.volume_drive.resize(n_f);
      const auto start = std::chrono::steady_clock::now();
      for (std::size_t i = 0; i < n_f; ++i)
        {
          const Eigen::MatrixXcd u = dynamics.response(2. * M_PI * r.frequency[i]);
          r.disk.row(i)            = u.row(dynamics.disk_dof());
          r.volume_per_volt.row(i) =
            dynamics.volume_gradient().cast<std::complex<double>>().transpose() * u;
          r.disk_drive[i] = r.volume_drive[i] = 0.;
          for (std::size_t k = 0; k < n_r; ++k)
            {
              const double share = r.drive_scale > 0. ? r.bias[k] / r.drive_scale : 0.;
              r.disk_drive[i] += share * r.disk(i, k);
              r.volume_drive[i] += share * r.volume_per_volt(i, k);
            }
        }
      r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  } // namespace

  FrequencyResponse frequency_response(const RunInput &input)
  {
    const Parameters &p     = input.parameters;
    const Scene      &scene = input.scene;
    auto              model = relaxed_equilibrium(p, scene);
    FrequencyResponse r;
    r.bias         = model->load().voltages;
    r.displacement = model->displacement();
    r.volume       = model->enclosed_volume();
    for (const double v : r.bias)
      r.drive_scale = std::max(r.drive_scale, std::abs(v));
    r.disk_mass  = p.time.inertia ? scene.mass : 0.;
    // The liquid column's rho_w h / S at the state, if the time runs move it.
    const LiquidColumn column = liquid_column(p);
    r.water_mass = column.present() ? column.mass(model->enclosed_volume()) : 0.;
    r.density    = p.response.membrane_density;
    const unsigned int n = p.response.frequencies;
    const double       lo = p.response.lowest_frequency_Hz, hi = p.response.highest_frequency_Hz;
    for (unsigned int i = 0; i < n; ++i)
      r.frequency.push_back(lo * std::pow(hi / lo, double(i) / (n - 1)));
    const double A = scene.inner_reference_radius(), B = scene.outer_reference_radius();
    for (unsigned int j = 0; j <= 100; ++j)
      r.sample_R.push_back(A + (B - A) * j / 100.);

    const LinearizedDynamics dynamics(*model, r.disk_mass, r.density, r.water_mass);
    transfer_functions(dynamics, r);
    mode_shapes(*model, dynamics.modes(p.response.modes), r);
    return r;
  }
} // namespace cdea

namespace cdea
{
  namespace
  {
    /// The values of @p m row by row, and the dimensions of a dataset of
    /// them (one dimension if @p m has one column).
    template <typename Matrix>
    auto row_major(const Matrix &m, std::vector<std::size_t> &dims)
    {
      std::vector<typename Matrix::Scalar> v;
      for (Eigen::Index i = 0; i < m.rows(); ++i)
        for (Eigen::Index j = 0; j < m.cols(); ++j)
          v.push_back(m(i, j));
      dims = m.cols() == 1 ? std::vector<std::size_t>{std::size_t(m.rows())} :
                             std::vector<std::size_t>{std::size_t(m.rows()), std::size_t(m.cols())};
      return v;
    }

    /// |z| of each of @p values.
    std::vector<double> magnitudes(const Eigen::VectorXcd &values)
    {
      std::vector<double> v;
      for (Eigen::Index i = 0; i < values.size(); ++i)
        v.push_back(std::abs(values[i]));
      return v;
    }
  } // namespace

  Product response_product(const std::string &parameter_text, const FrequencyResponse &r)
  {
    using namespace response_quantity;
    Product product;
    product.root()
      .set(common_quantity::parameters, parameter_text)
      .set(common_quantity::code_version, CDEA_VERSION)
      .set(bias_voltage, r.bias)
      .set(displacement, r.displacement)
      .set(volume, r.volume)
      .set(drive_scale, r.drive_scale)
      .set(disk_mass, r.disk_mass)
      .set(water_mass, r.water_mass)
      .set(density, r.density)
      .set(seconds, r.seconds);
    std::vector<double> phase_values;
    for (Eigen::Index i = 0; i < r.disk_drive.size(); ++i)
      phase_values.push_back(std::arg(r.disk_drive[i]));
    ProductGroup &transfer = product.group("/transfer");
    transfer.set(frequency, r.frequency);
    const std::pair<const Quantity *, Eigen::MatrixXcd> complex_values[] = {
      {&disk, r.disk},
      {&volume_per_volt, r.volume_per_volt},
      {&drive_disk, r.disk_drive},
      {&drive_volume, r.volume_drive}};
    for (const auto &[row, values] : complex_values)
      {
        std::vector<std::size_t> dims;
        const auto               v = row_major(values, dims);
        transfer.set(*row, v, dims);
      }
    transfer.set(amplitude, magnitudes(r.disk_drive)).set(phase, phase_values);
    const std::size_t        m = r.mode_frequency.size(), s = r.sample_R.size();
    std::vector<std::size_t> dims;
    const auto               shapes_r = row_major(r.mode_r, dims);
    const auto               shapes_z = row_major(r.mode_z, dims);
    product.group("/modes")
      .set(mode_frequency, r.mode_frequency)
      .set(mode_damping, r.mode_damping)
      .set(sample_R, r.sample_R)
      .set(shape_r, shapes_r, {m, s})
      .set(shape_z, shapes_z, {m, s});
    return product;
  }
} // namespace cdea
