// `cdea frequency-sweep FILE.prm`: the periodic steady state of the prm's
// waveform at each frequency of subsection Frequency sweep
// (analysis/frequency_sweep.h), a line per frequency as it is done (with the
// time left, base/progress.h), the usable band, and
// <Base name>_frequency_sweep.h5. Under mpirun the frequencies are dealt
// round-robin to the ranks; rank 0 reports the progress, then prints the
// table and writes the file. 0 written, 1 bad input, 2 a frequency
// without a steady state (the file is written with it flagged) or not written.

#include <cdea/analysis/frequency_sweep.h>
#include <cdea/base/format.h>
#include <cdea/base/mpi_session.h>
#include <cdea/base/progress.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>
#include <cdea/model/quantities_frequency_sweep.h>
#include <cdea/output/product_file.h>
#include <cdea/output/product_table.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace cdea
{
  namespace
  {
    class FrequencySweepJob final : public CommandJob
    {
    public:
      void check(Invocation &invocation) override
      {
        input    = run_input(invocation.parameters, invocation.parameter_text,
                             RunMethod::finite_elements, "frequency-sweep");
        settings = frequency_sweep_settings(invocation.parameters);
      }

      std::string output_path(const Invocation &invocation) const override
      {
        return invocation.parameters.results_path("_frequency_sweep");
      }

      int run(Invocation &invocation) override
      {
        const bool root = invocation.root, distributed = mpi::size() > 1;
        if (root)
          print_work();
        if (root && !distributed)
          print_header();
        const auto  start = std::chrono::steady_clock::now();
        std::size_t done  = 0;
        // Several ranks: a progress report on rank 0, the rows after the gather.
        Progress             progress(settings.frequencies.size(), root && distributed,
                                      "frequencies");
        FrequencySweepResult r;
        try
          {
            r = frequency_sweep(input, settings, [&](const SteadyPeriod *s) {
              if (distributed)
                return progress.add(1);
              const double elapsed =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
              print_row(*s, ++done, elapsed);
            });
          }
        catch (const std::runtime_error &e)
          {
            if (root)
              std::cerr << "cdea: " << e.what() << '\n';
            invocation.output.give_up();
            return exit_not_complete;
          }
        if (distributed)
          progress.finish();
        if (!root)
          return exit_success;
        if (distributed)
          {
            print_header();
            for (const SteadyPeriod &s : r.periods)
              print_row(s, 0, 0.);
          }
        print_summary(r);
        return write_and_report(invocation, r);
      }

    private:
      RunInput               input;
      FrequencySweepSettings settings;

      /// The file (the frequencies done, beside an older file if stopped:
      /// <stem>.partial.h5), and how the sweep ended.
      int write_and_report(Invocation &invocation, const FrequencySweepResult &r) const
      {
        const std::string &path = invocation.output.path;
        if (r.not_computed == r.periods.size())
          {
            std::cerr << "cdea: " << r.stop_reason
                      << " before any frequency was done; nothing was written\n";
            invocation.output.give_up();
            return exit_not_complete;
          }
        std::string wrote;
        try
          {
            ReplaceTogether file({path});
            write_product_file(frequency_sweep_product(invocation.parameter_text, r), path);
            wrote = file.commit(r.not_computed > 0).front();
          }
        catch (const std::exception &e)
          {
            std::cerr << "cdea: the results cannot be written: " << e.what()
                      << " (an older file of this name stays as it was)\n";
            return exit_not_complete;
          }
        std::cout << "wrote " << wrote << '\n';
        if (r.not_computed > 0)
          std::cerr << "cdea: " << r.stop_reason << " after " << r.periods.size() - r.not_computed
                    << " of " << r.periods.size() << " frequencies; they are in " << wrote
                    << " (the others are NaN"
                    << (wrote != path ? "; the older " + path + " is kept as it was" : "")
                    << ")\n";
        return r.all_converged ? exit_success : exit_not_complete;
      }

      /// The work before it starts: the frequencies and the file's size
      /// (12 doubles and 5 integers a frequency, 19.5 kB of names and
      /// descriptions: 21.5 kB for prm/frequency-sweep.prm's 17).
      void print_work() const
      {
        const std::size_t n = settings.frequencies.size();
        // (flushed: seen before the work starts, also through a pipe or in a file)
        std::cout << "work: " << n << " periodic steady states (seconds each; the time left "
                  << "is shown as they are done), results about "
                  << format_bytes(19.5e3 + 116. * double(n)) << std::endl;
      }

      /// The table's columns: the rows of /sweep.
      static const std::vector<TableColumn> &columns()
      {
        using namespace frequency_sweep_quantity;
        static const std::vector<TableColumn> all = {
          {&frequency, "f (Hz)", 10, CellStyle::number, 5},
          {&stroke_amplitude, "stroke (mm)", 13, CellStyle::fixed, 5},
          {&mean_displacement, "mean (mm)", 12, CellStyle::fixed, 4},
          {&swept_volume, "volume (mm^3)", 15, CellStyle::number, 6},
          {&dissipated, "dissip. (mJ)", 15, CellStyle::number, 5},
          {&s2_min, "min s2 (kPa)", 13, CellStyle::fixed, 3},
          {&newton_iterations, "Newton", 8, CellStyle::integer},
          {&period_maps, "maps", 7, CellStyle::integer},
          {&frequency_seconds, "time (s)", 9, CellStyle::fixed, 2}};
        return all;
      }

      void print_header() const
      {
        std::cout << "Periodic steady states of the " << to_string(input.parameters.time.waveform)
                  << " wave at " << settings.frequencies.size()
                  << " frequencies (tolerance " << format_number(settings.steady.tolerance, 3)
                  << ")";
        if (mpi::size() > 1)
          std::cout << " on " << mpi::size() << " ranks (frequencies round-robin)";
        std::cout << '\n';
        print_table_cells(std::cout, columns());
        std::cout << (mpi::size() > 1 ? "\n" : "  progress\n");
      }

      /// A row of the table; with the progress column if @p done > 0.
      void print_row(const SteadyPeriod &s, const std::size_t done, const double elapsed) const
      {
        const std::size_t n = settings.frequencies.size();
        print_table_cells(std::cout, periods_product({s}).at("/sweep"), columns(), 0);
        if (done > 0)
          std::cout << "  " << done << "/" << n << ", "
                    << format_duration(elapsed / done * (n - done)) << " left";
        std::cout << (s.loss_of_tension ? "  LOSS OF TENSION" : "") << std::endl;
        if (!s.converged)
          std::cerr << "cdea: " << s.message << '\n';
      }

      void print_summary(const FrequencySweepResult &r) const
      {
        std::cout << "quasi-static stroke amplitude (film relaxed): "
                  << format_number(units::mm.from_si(r.quasi_static_amplitude), 6) << " mm\n"
                  << "usable band (taut, stroke within a factor "
                  << format_number(r.usable_factor) << " of the quasi-static one): ";
        if (std::isnan(r.band_low))
          std::cout << "none\n";
        else
          std::cout << format_number(r.band_low, 5) << " to " << format_number(r.band_high, 5)
                    << " Hz\n";
        std::cout << r.periods.size() << " frequencies in " << std::setprecision(3) << r.seconds
                  << " s\n";
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> frequency_sweep_job()
  {
    return std::make_unique<FrequencySweepJob>();
  }
} // namespace cdea
