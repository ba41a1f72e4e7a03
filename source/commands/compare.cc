// `cdea compare FILE.prm`: the FE and the shooting model along the same load
// stages (by load stepping, nothing written), and the differences of their
// last converged states. SIGINT, SIGTERM, SIGHUP end it with exit 2 and no
// table.

#include <cdea/analysis/run_input.h>
#include <cdea/analysis/run_setup.h>
#include <cdea/base/format.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>
#include <cdea/input/solver_settings.h>
#include <cdea/shooting/shooting_model.h>
#include <cdea/solver/load_stepper.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace cdea
{
  namespace
  {
    /// A run of a model without output: its last step and result.
    struct QuietRun
    {
      RunResult   result;
      StepSummary last;
      double      seconds = 0.;
    };

    QuietRun quiet_run(EquilibriumModel &model, const RunInput &in)
    {
      QuietRun    run;
      LoadStepper stepper(in.scene, model, stepping_settings(in.parameters));
      stepper.on_step  = [&](const StepSummary &s) {
        run.last = s;
        if (const int signal = StopOnSignals::requested())
          throw RunInterrupted(signal); // SIGINT, SIGTERM, SIGHUP: no comparison
      };
      const auto start = std::chrono::steady_clock::now();
      run.result       = stepper.run();
      run.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return run;
    }

    /// One line of the table: FE, shooting, difference and relative difference.
    void row(const std::string &what, const double x, const double y, const std::string &unit)
    {
      std::cout << std::left << std::setw(34) << what << std::right << std::setw(16)
                << std::setprecision(10) << x << std::setw(16) << y << std::setw(13)
                << std::setprecision(3) << std::scientific << x - y << std::setw(11)
                << std::abs(x - y) / std::max(std::abs(y), 1e-300) << std::defaultfloat << "  "
                << unit << '\n';
    }

    class Compare final : public CommandJob
    {
    public:
      void check(Invocation &invocation) override
      {
        input = run_input(invocation.parameters, invocation.parameter_text, RunMethod::shooting,
                          "compare", &note);
      }

      int run(Invocation &) override
      {
        if (!note.empty())
          std::cout << note << '\n';
        const Parameters       &p      = input.parameters;
        const auto              fe_ptr = make_fe_model(p, input.scene);
        MembraneModel          &fe     = *fe_ptr;
        shooting::ShootingModel sh(input.scene, shooting_options(p));
        QuietRun                a, b;
        try
          {
            a = quiet_run(fe, input);
            b = quiet_run(sh, input);
          }
        catch (const RunInterrupted &e)
          {
            std::cerr << "cdea: " << e.what() << " before both runs had ended: no comparison\n";
            return exit_not_complete;
          }
        print_header(fe, a, b);
        print_states(fe, sh, a, b);
        print_profiles(fe, sh);
        print_onsets(a, b);
        std::cout << "\nwall time: FE " << std::setprecision(3) << a.seconds * 1e3
                  << " ms, shooting " << b.seconds * 1e3 << " ms\n";
        return a.result.completed && b.result.completed ? exit_success : exit_not_complete;
      }

    private:
      RunInput    input;
      std::string note; ///< the path followed by load stepping, if that changed it

      void print_header(const MembraneModel &fe, const QuietRun &a, const QuietRun &b) const
      {
        const Parameters &p = input.parameters;
        std::cout << "cdea compare: FE (" << fe.n_elements() << " elements, p = "
                  << p.discretization.polynomial_degree << ", " << fe.n_dofs()
                  << " unknowns) vs shooting (tolerance " << p.shooting.tolerance << ")\n";
        for (const auto *r : {&a, &b})
          if (!r->result.completed)
            std::cout << (r == &a ? "FE" : "shooting") << " run stopped early: "
                      << r->result.message << '\n';
        std::cout << "state compared: the last converged step of each run, voltages FE "
                  << format_kV(a.last.voltages) << ", shooting " << format_kV(b.last.voltages)
                  << "\n\n";
        std::cout << std::left << std::setw(34) << "quantity" << std::right << std::setw(16)
                  << "FE" << std::setw(16) << "shooting" << std::setw(13) << "FE - sh."
                  << std::setw(11) << "relative" << '\n';
      }

      void print_states(MembraneModel &fe, shooting::ShootingModel &sh, const QuietRun &a,
                        const QuietRun &b) const
      {
        const double mu = input.scene.material.shear_modulus;
        row("displacement", a.last.displacement * 1e3, b.last.displacement * 1e3, "mm");
        row("stroke", a.last.stroke * 1e3, b.last.stroke * 1e3, "mm");
        row("enclosed volume", fe.enclosed_volume() * 1e9, sh.enclosed_volume() * 1e9, "mm^3");
        for (unsigned int k = 0; k < input.scene.n_rings(); ++k)
          row("s2/mu, inner edge of ring " + std::to_string(k + 1),
              a.last.s2_ring_inner[k] / mu, b.last.s2_ring_inner[k] / mu, "-");
      }

      /// The FE solution at the shooting solver's sample radii.
      void print_profiles(MembraneModel &fe, shooting::ShootingModel &sh) const
      {
        const double        a   = input.scene.disk_radius;
        const StepFields    ref = sh.fields();
        std::vector<double> r, z;
        fe.profile_at(ref.R, r, z);
        double dr = 0., dz = 0.;
        for (std::size_t i = 0; i < ref.R.size(); ++i)
          {
            dr = std::max(dr, std::abs(r[i] - ref.r[i]));
            dz = std::max(dz, std::abs(z[i] - ref.z[i]));
          }
        std::cout << std::left << std::setw(34) << "max |r_FE - r_sh| over the meridian"
                  << std::right << std::setw(16) << std::setprecision(3) << std::scientific
                  << dr * 1e3 << " mm (" << dr / a << " a)\n"
                  << std::left << std::setw(34) << "max |z_FE - z_sh| over the meridian"
                  << std::right << std::setw(16) << dz * 1e3 << " mm (" << dz / a << " a)\n"
                  << std::defaultfloat;
      }

      void print_onsets(const QuietRun &a, const QuietRun &b) const
      {
        if (a.result.onset.found && b.result.onset.found)
          {
            for (unsigned int k = 0; k < input.scene.n_rings(); ++k)
              row("onset voltage, ring " + std::to_string(k + 1) + " (kV)",
                  a.result.onset.voltages[k] * 1e-3, b.result.onset.voltages[k] * 1e-3, "kV");
            row("onset radius r", a.result.onset.radius * 1e3, b.result.onset.radius * 1e3,
                "mm");
          }
        else
          std::cout << "onset: FE " << (a.result.onset.found ? "found" : "none")
                    << ", shooting " << (b.result.onset.found ? "found" : "none") << '\n';
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> compare_job()
  {
    return std::make_unique<Compare>();
  }
} // namespace cdea
