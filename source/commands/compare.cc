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
#include <cdea/model/product.h>
#include <cdea/model/quantities_compare.h>
#include <cdea/shooting/shooting_model.h>
#include <cdea/solver/load_stepper.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <tuple>

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
        const Product product = compare_product(fe, sh, a, b);
        print_header(fe, a, b);
        print_states(product);
        print_profiles(product);
        print_onsets(product);
        std::cout << "\nwall time: FE " << std::setprecision(3) << units::ms.from_si(a.seconds)
                  << " ms, shooting " << units::ms.from_si(b.seconds) << " ms\n";
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

      /// The product of the comparison: each model's last state and the
      /// distance of their meridians (the FE solution at the shooting
      /// solver's sample radii).
      Product compare_product(MembraneModel &fe, shooting::ShootingModel &sh, const QuietRun &a,
                              const QuietRun &b) const
      {
        using namespace compare_quantity;
        const double mu = input.scene.material.shear_modulus;
        Product      product;
        const std::tuple<const char *, const QuietRun *, double> models[] = {
          {"/finite_elements", &a, fe.enclosed_volume()}, {"/shooting", &b, sh.enclosed_volume()}};
        for (const auto &[name, run, enclosed] : models)
          {
            std::vector<double> s2;
            for (const double x : run->last.s2_ring_inner)
              s2.push_back(x / mu);
            ProductGroup &g = product.group(name);
            g.set(displacement, run->last.displacement)
              .set(stroke, run->last.stroke)
              .set(volume, enclosed)
              .set(s2_over_mu, s2);
            if (run->result.onset.found)
              g.set(onset_voltage, run->result.onset.voltages)
                .set(onset_radius, run->result.onset.radius);
          }
        const StepFields    ref = sh.fields();
        std::vector<double> r, z;
        fe.profile_at(ref.R, r, z);
        double dr = 0., dz = 0.;
        for (std::size_t i = 0; i < ref.R.size(); ++i)
          {
            dr = std::max(dr, std::abs(r[i] - ref.r[i]));
            dz = std::max(dz, std::abs(z[i] - ref.z[i]));
          }
        const double disk = input.scene.disk_radius;
        product.root()
          .set(r_difference, dr)
          .set(z_difference, dz)
          .set(r_difference_over_a, dr / disk)
          .set(z_difference_over_a, dz / disk);
        return product;
      }

      /// A line of the table: @p row of both models (the @p k'th value).
      static void row(const Product &product, const std::string &what, const Quantity &q,
                      const std::size_t k = 0)
      {
        const ProductGroup &fe = product.at("/finite_elements"), &sh = product.at("/shooting");
        cdea::row(what, fe.at(q).value(k), sh.at(q).value(k),
                  q.unit.name == std::string("1") ? "-" : q.unit.name);
      }

      void print_states(const Product &product) const
      {
        using namespace compare_quantity;
        row(product, "displacement", displacement);
        row(product, "stroke", stroke);
        row(product, "enclosed volume", volume);
        for (unsigned int k = 0; k < input.scene.n_rings(); ++k)
          row(product, "s2/mu, inner edge of ring " + std::to_string(k + 1), s2_over_mu, k);
      }

      static void print_profiles(const Product &product)
      {
        using namespace compare_quantity;
        const ProductGroup &root  = product.root();
        const auto          value = [&](const Quantity &q) { return root.at(q).value(0); };
        std::cout << std::left << std::setw(34) << "max |r_FE - r_sh| over the meridian"
                  << std::right << std::setw(16) << std::setprecision(3) << std::scientific
                  << value(r_difference) << " mm (" << value(r_difference_over_a) << " a)\n"
                  << std::left << std::setw(34) << "max |z_FE - z_sh| over the meridian"
                  << std::right << std::setw(16) << value(z_difference) << " mm ("
                  << value(z_difference_over_a) << " a)\n"
                  << std::defaultfloat;
      }

      void print_onsets(const Product &product) const
      {
        using namespace compare_quantity;
        const bool fe = product.at("/finite_elements").find(onset_radius) != nullptr;
        const bool sh = product.at("/shooting").find(onset_radius) != nullptr;
        if (fe && sh)
          {
            for (unsigned int k = 0; k < input.scene.n_rings(); ++k)
              row(product, "onset voltage, ring " + std::to_string(k + 1) + " (kV)",
                  onset_voltage, k);
            row(product, "onset radius r", onset_radius);
          }
        else
          std::cout << "onset: FE " << (fe ? "found" : "none") << ", shooting "
                    << (sh ? "found" : "none") << '\n';
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> compare_job()
  {
    return std::make_unique<Compare>();
  }
} // namespace cdea
