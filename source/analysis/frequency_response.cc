#include <cdea/analysis/frequency_response.h>
#include <cdea/analysis/run_setup.h>
#include <cdea/base/run_control.h>
#include <cdea/fe/linear_dynamics.h>
#include <cdea/input/solver_settings.h>
#include <cdea/output/hdf5_writer.h>

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
    /// Real and imaginary parts of @p values times @p factor, row-major.
    void complex_datasets(Hdf5Writer &w, const std::string &path, const Eigen::MatrixXcd &values,
                          const double factor, const std::string &unit,
                          const std::string &description)
    {
      const std::size_t   rows = values.rows(), columns = values.cols();
      std::vector<double> re, im;
      for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t k = 0; k < columns; ++k)
          {
            re.push_back(factor * values(i, k).real());
            im.push_back(factor * values(i, k).imag());
          }
      const std::vector<std::size_t> dims =
        columns == 1 ? std::vector<std::size_t>{rows} : std::vector<std::size_t>{rows, columns};
      w.dataset(path + "_real", dims, re, unit, description + " (real part)");
      w.dataset(path + "_imag", dims, im, unit, description + " (imaginary part)");
    }

    std::vector<double> column_values(const Eigen::MatrixXd &m)
    {
      std::vector<double> v;
      for (Eigen::Index i = 0; i < m.rows(); ++i)
        for (Eigen::Index j = 0; j < m.cols(); ++j)
          v.push_back(m(i, j));
      return v;
    }
  } // namespace

  void write_response_file(const std::string &path, const std::string &parameter_text,
                           const FrequencyResponse &r)
  {
    Hdf5Writer          w(path);
    std::vector<double> bias_kV;
    for (const double v : r.bias)
      bias_kV.push_back(v * 1e-3);
    w.attribute("/", "parameters", parameter_text);
    w.attribute("/", "code_version", std::string(CDEA_VERSION));
    w.attribute("/", "bias_voltage_kV", bias_kV);
    w.attribute("/", "displacement_mm", r.displacement * 1e3);
    w.attribute("/", "volume_mm3", r.volume * 1e9);
    w.attribute("/", "drive_scale_kV", r.drive_scale * 1e-3);
    w.attribute("/", "disk_mass_g", r.disk_mass * 1e3);
    w.attribute("/", "water_column_mass_kg_per_m4", r.water_mass);
    w.attribute("/", "membrane_density_kg_per_m3", r.density);
    w.attribute("/", "seconds", r.seconds);
    const std::size_t n = r.frequency.size();
    w.group("/transfer");
    w.dataset("/transfer/frequency_Hz", {n}, r.frequency, "Hz", "drive frequency");
    // Per kV: m/V * 1e3 mm/m * 1e3 V/kV = 1e6.
    complex_datasets(w, "/transfer/disk_mm_per_kV", r.disk, 1e6, "mm/kV",
                     "displacement amplitude of the disk per kV on each ring (frequencies x rings)");
    complex_datasets(w, "/transfer/volume_mm3_per_kV", r.volume_per_volt, 1e12, "mm^3/kV",
                     "enclosed volume amplitude per kV on each ring (frequencies x rings)");
    complex_datasets(w, "/transfer/drive_disk_mm_per_kV", r.disk_drive, 1e6, "mm/kV",
                     "displacement amplitude of the disk per kV of the drive (every ring in "
                     "proportion to its bias voltage, drive_scale_kV the largest)");
    complex_datasets(w, "/transfer/drive_volume_mm3_per_kV", r.volume_drive, 1e12, "mm^3/kV",
                     "enclosed volume amplitude per kV of the drive");
    std::vector<double> amplitude, phase;
    for (Eigen::Index i = 0; i < r.disk_drive.size(); ++i)
      {
        amplitude.push_back(1e6 * std::abs(r.disk_drive[i]));
        phase.push_back(std::arg(r.disk_drive[i]) * 180. / M_PI);
      }
    w.dataset("/transfer/drive_disk_amplitude_mm_per_kV", {n}, amplitude, "mm/kV",
              "|drive_disk|: the Bode amplitude");
    w.dataset("/transfer/drive_disk_phase_deg", {n}, phase, "deg",
              "arg(drive_disk): the Bode phase (0: in phase with the voltage)");
    w.group("/modes");
    const std::size_t m = r.mode_frequency.size(), s = r.sample_R.size();
    std::vector<double> R_mm;
    for (const double R : r.sample_R)
      R_mm.push_back(R * 1e3);
    w.dataset("/modes/frequency_Hz", {m}, r.mode_frequency, "Hz",
              "natural frequencies (modes of Re K(omega) and M at their own omega)");
    w.dataset("/modes/damping_ratio", {m}, r.mode_damping, "1",
              "modal damping ratio u^T Im K u / (2 u^T Re K u)");
    w.dataset("/modes/R_mm", {s}, R_mm, "mm", "reference radius of the shape samples");
    w.dataset("/modes/shape_r", {m, s}, column_values(r.mode_r), "1",
              "radial displacement of each mode per unit disk displacement (modes x samples)");
    w.dataset("/modes/shape_z", {m, s}, column_values(r.mode_z), "1",
              "vertical displacement of each mode per unit disk displacement (modes x samples)");
    w.commit();
  }
} // namespace cdea
