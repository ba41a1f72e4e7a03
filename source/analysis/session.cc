#include <deal.II/base/multithread_info.h>

#include <cdea/analysis/commands.h>
#include <cdea/input/pump.h>
#include <cdea/analysis/session.h>
#include <cdea/analysis/time_run.h>
#include <cdea/output/results_file.h>
#include <cdea/solver/state_check.h>
#include <cdea/shooting/shooting_model.h>

#include <chrono>
#include <memory>

namespace cdea
{
  namespace
  {
    double seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  } // namespace

  void require_shooting_options(const Parameters &p, const std::string &command)
  {
    if (p.reservoir.water_load)
      throw InputError("Reservoir/Water load = true is implemented in the FE model only: use "
                       "'cdea run', or set it to false for 'cdea " +
                       command + "'");
    if (p.wrinkling.model == WrinklingModel::relaxed)
      throw InputError("Wrinkling/Model = relaxed is implemented in the FE model only: use "
                       "'cdea run', or set it to check for 'cdea " +
                       command + "'");
    if (p.time.enabled)
      throw InputError("Time/Enabled = true is implemented for 'cdea run' only: set it to "
                       "false for 'cdea " +
                       command + "'");
  }

  Parameters load_stepping_parameters(const Parameters &p, const std::string &command,
                                      std::string &note)
  {
    Parameters q = p;
    note.clear();
    if (q.solver.continuation != Continuation::load_stepping)
      {
        note = "cdea " + command + ": Solver/Continuation = " +
               to_string(q.solver.continuation) +
               " applies to the FE model of 'cdea run'; both solvers follow the path by load "
               "stepping here";
        q.solver.continuation = Continuation::load_stepping;
      }
    return q;
  }

  RunInput read_run_input(const ParameterInput &input, const RunMethod method, std::string *note)
  {
    RunInput in;
    in.parameters = read_parameters(input, &in.text);
    in.scene      = in.parameters.scene();
    validate_reservoir(in.parameters);
    if (method == RunMethod::shooting)
      {
        require_shooting_options(in.parameters, "shoot");
        std::string line;
        in.parameters = load_stepping_parameters(in.parameters, "shoot", line);
        if (note)
          *note = line;
      }
    return in;
  }

  std::vector<TimeStepper::PostprocessorFactory> run_postprocessors(const Parameters &p,
                                                                    const Scene      &scene)
  {
    const double area = tube_area(p), frame_radius = scene.frame_radius;
    return {[area] { return std::make_unique<EnclosedVolume>(area); },
            [frame_radius] { return std::make_unique<NonPhysicalCheck>(frame_radius); }};
  }

  void add_run_postprocessors(LoadStepper &stepper, const Parameters &p, const Scene &scene)
  {
    for (const auto &make : run_postprocessors(p, scene))
      stepper.add_postprocessor(make());
  }

  void add_run_postprocessors(TimeStepper &stepper, const Parameters &p, const Scene &scene)
  {
    for (const auto &make : run_postprocessors(p, scene))
      stepper.add_postprocessor(make);
  }

  void write_summary_attributes(ResultsFile &file, const std::vector<SummaryAttribute> &attributes)
  {
    for (const SummaryAttribute &a : attributes)
      if (a.rows == 0)
        file.set_summary_attribute(a.name, a.values);
      else
        file.set_summary_attribute(a.name, a.values, a.rows, a.columns);
  }

  RunRecord run_in_memory(const RunInput &input, const RunMethod method)
  {
    const Parameters &p = input.parameters;
    if (p.time.enabled)
      return time_run_in_memory(input);
    RunRecord         record;
    record.n_rings    = input.scene.n_rings();
    record.parameters = input.text;
    std::unique_ptr<EquilibriumModel> model;
    if (method == RunMethod::finite_elements)
      {
        record.method       = "finite elements";
        record.results_path = p.results_path();
        model               = make_fe_model(p, input.scene);
      }
    else
      {
        record.method       = "shooting";
        record.results_path = p.results_path("_shooting");
        model = std::make_unique<shooting::ShootingModel>(input.scene, shooting_options(p));
      }

    LoadStepper stepper(input.scene, *model, stepping_settings(p));
    add_run_postprocessors(stepper, p, input.scene);
    stepper.on_step = [&](const StepSummary &s) {
      record.steps.push_back(s);
      record.fields.push_back(stepper.step_fields());
    };
    run_keeping_steps(record, [&] { return stepper.run(); });
    return record;
  }

  void run_keeping_steps(RunRecord &record, const std::function<RunResult()> &run)
  {
    const auto start = std::chrono::steady_clock::now();
    try
      {
        record.result = run();
      }
    catch (const std::exception &e)
      {
        // The steps so far stay; the run says why it ended.
        record.result.completed = false;
        record.result.message   = std::string("error: ") + e.what();
        record.result.steps     = static_cast<unsigned int>(record.steps.size());
      }
    record.seconds = seconds_since(start);
  }

  void write_run(const RunRecord &record, const std::string &path)
  {
    std::vector<std::pair<std::string, std::string>> root_attributes = {{"method", record.method}};
    root_attributes.insert(root_attributes.end(), record.root_attributes.begin(),
                           record.root_attributes.end());
    ResultsFile file(path, record.parameters, record.n_rings, root_attributes);
    for (std::size_t i = 0; i < record.steps.size(); ++i)
      file.append(record.steps[i], record.fields[i]);
    file.write_onset(record.result.onset);
    if (!record.time_run)
      write_summary_attributes(file,
                               limit_point_attributes(record.result.limit_points, record.n_rings));
    write_summary_attributes(file, breakdown_attributes(record.result.breakdown));
    const std::string status =
      record.result.completed ?
        std::string("complete") :
        "stopped after step " + std::to_string(int(record.steps.size()) - 1) + ": " +
          record.result.message;
    const ResultsFile::Finish done = file.finish(status);
    if (!done.written || done.steps_written != record.steps.size())
      {
        std::string why = "cannot write '" + path + "'";
        for (const std::string &m : done.messages)
          why += "; " + m;
        throw std::runtime_error(why);
      }
  }


  void prepare_in_process_runs()
  {
    dealii::MultithreadInfo::set_thread_limit(1);
  }
} // namespace cdea
