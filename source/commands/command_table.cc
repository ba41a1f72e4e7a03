// The table of cdea's commands: one row per command, in the order of --help.
// A new command is its file commands/<name>.cc, which defines the factory of
// its CommandJob, and a row here with that factory's declaration above it
// (doc/architecture.md, "How to add a command").

#include <cdea/commands/command.h>

namespace cdea
{
  // The factories, one per command file.
  std::unique_ptr<CommandJob> run_job();              // commands/run.cc
  std::unique_ptr<CommandJob> shoot_job();            // commands/shoot.cc
  std::unique_ptr<CommandJob> compare_job();          // commands/compare.cc
  std::unique_ptr<CommandJob> sweep_job();            // commands/sweep.cc
  std::unique_ptr<CommandJob> response_job();         // commands/response.cc
  std::unique_ptr<CommandJob> frequency_sweep_job();  // commands/frequency_sweep.cc
  std::unique_ptr<CommandJob> recover_job();          // commands/recover.cc
  std::unique_ptr<CommandJob> optimize_job();         // commands/optimize.cc
  std::unique_ptr<CommandJob> fit_job();              // commands/fit.cc
  std::unique_ptr<CommandJob> chart_job();            // commands/chart.cc
  std::unique_ptr<CommandJob> print_parameters_job(); // commands/print_parameters.cc
  std::unique_ptr<CommandJob> version_job();          // commands/version.cc
  std::unique_ptr<CommandJob> help_job();             // commands/help.cc

  const std::vector<Command> &command_table()
  {
    static const std::vector<Command> table = {
      {"run", {"FILE.prm"},
       {"solve the scene of FILE.prm along its load stages\n"
        "and write <Directory>/<Base name>.h5"},
       reads_parameters | stops_on_signals | time_runs | in_python, Ranks::one,
       Output::claimed_by_run, run_job},
      {"shoot", {"FILE.prm"},
       {"the same with the independent shooting solver,\n"
        "written to <Directory>/<Base name>_shooting.h5"},
       reads_parameters | stops_on_signals | in_python, Ranks::one, Output::claimed_by_run,
       shoot_job},
      {"compare", {"FILE.prm"}, {"run both solvers and print their differences"},
       reads_parameters | stops_on_signals, Ranks::one, Output::none, compare_job},
      {"sweep", {"FILE.prm"},
       {"design map over two-ring layouts and outer voltages\n"
        "(subsection Sweep), <Base name>_map.h5; runs under\n"
        "mpirun -np N as well"},
       reads_parameters | stops_on_signals | in_python, Ranks::all, Output::claimed_first,
       sweep_job},
      {"response", {"FILE.prm"},
       {"small-signal frequency response about the equilibrium\n"
        "at the end of the voltage path: transfer functions,\n"
        "natural frequencies, <Base name>_response.h5"},
       reads_parameters | stops_on_signals | time_runs | in_python, Ranks::one,
       Output::claimed_first, response_job},
      {"frequency-sweep", {"FILE.prm"},
       {"periodic steady states of the waveform over the\n"
        "frequencies of subsection Frequency sweep: stroke,\n"
        "dissipation, loss of tension, the usable band,\n"
        "<Base name>_frequency_sweep.h5"},
       reads_parameters | stops_on_signals | time_runs | in_python, Ranks::all, Output::claimed_first,
       frequency_sweep_job},
      {"recover", {"FILE.h5"},
       {"rebuild the results of a killed run from its\n"
        "journal FILE.h5.journal"},
       stops_on_signals, Ranks::one, Output::claimed_by_run, recover_job},
      {"optimize", {"FILE.prm"},
       {"electrode layout with the largest stroke without\n"
        "wrinkling (subsection Optimization), <Base name>_optimum.h5"},
       reads_parameters | stops_on_signals | in_python, Ranks::all, Output::claimed_first,
       optimize_job},
      {"fit", {"FILE.prm DATA.csv ..."},
       {"calibrate material constants to measured displacements\n"
        "(subsection Calibration), <Base name>_fit.h5; the CSV\n"
        "header tells the data: V1_kV.. + displacement_mm points,\n"
        "time_s + V1_kV.. + displacement_mm a creep curve,\n"
        "frequency_Hz + storage_kPa + loss_kPa a DMA table;\n"
        "material tests (time_s + uniaxial_stretch, equibiaxial_\n"
        "stretch or pure_shear_stretch + nominal_stress_kPa):\n"
        "several files fitted jointly, --predict C.csv ... evaluated"},
       reads_parameters | stops_on_signals | in_python, Ranks::one, Output::claimed_first,
       fit_job},
      {"chart", {"FILE.prm"},
       {"material charts of Material/Model: uniaxial and\n"
        "equibiaxial stress-stretch, the DMA chart of a\n"
        "viscoelastic law, <Base name>_chart.h5"},
       reads_parameters | stops_on_signals, Ranks::one, Output::claimed_first, chart_job},
      {"print-parameters", {"", "--json"},
       {"print a complete, documented parameter file",
        "the same parameters and defaults as JSON"},
       0, Ranks::first_only, Output::none, print_parameters_job},
      {"--version", {""}, {"the version of cdea and of deal.II"}, 0, Ranks::first_only,
       Output::none, version_job},
      {"--help", {"..."}, {"this text"}, 0, Ranks::first_only, Output::none, help_job,
       {"-h", "help"}},
    };
    return table;
  }

  const Command *find_command(const std::string &name)
  {
    for (const Command &command : command_table())
      {
        if (command.name == name)
          return &command;
        for (const std::string &alias : command.aliases)
          if (alias == name)
            return &command;
      }
    return nullptr;
  }
} // namespace cdea
