// The table of output fields (model/output_fields.h):
//  - its rows: names unique, units and descriptions given, the standard
//    columns and the /steps fields in the file's order;
//  - ColumnValues: set by handle, read by handle, NaN where not set, in the
//    order set, in the file's unit by the row's factor;
//  - which runs have it: the postprocessors' columns of an in-process
//    quasi-static run, shooting run and time run are exactly the rows whose
//    `runs` name that kind of run;
//  - the results file and its journal: a step with columns of the table and
//    an internal variable of the law, written directly and replayed from the
//    journal, gives the same /summary datasets (names, units, descriptions,
//    values in the file's units) and /steps fields.

#include <cdea/analysis/session.h>
#include <cdea/model/output_fields.h>
#include <cdea/output/journal.h>
#include <cdea/output/results_file.h>
#include <cdea/output/safe_files.h>

#include <hdf5.h>

#include "check.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// Every postprocessor column of the table.
  const std::vector<const Quantity *> postprocessor_columns = {
    &summary_column::wrinkled_zone_inner,  &summary_column::wrinkled_zone_outer,
    &summary_column::min_eigenvalue,       &summary_column::stable,
    &summary_column::max_field,            &summary_column::volume,
    &summary_column::volume_change,        &summary_column::level_drop,
    &summary_column::nonphysical,          &summary_column::waveform_time,
    &summary_column::disk_velocity,        &summary_column::electrical_work,
    &summary_column::stored_energy_change, &summary_column::dissipated_energy};

  void check_rows()
  {
    std::set<std::string> names;
    bool                  described = true;
    for (const auto *list : {&standard_summary_columns(), &postprocessor_columns})
      for (const Quantity *c : *list)
        {
          names.insert(c->name);
          described = described && *c->unit.name && std::string(c->description).size() > 5 &&
                      (c->runs & every_run) != 0 && c->unit.multiply > 0.;
        }
    check(names.size() == standard_summary_columns().size() + postprocessor_columns.size(),
          "every /summary column has a name of its own");
    check(described, "every /summary column has a unit, a description, runs and a factor");
    std::vector<std::string> standard;
    for (const Quantity *c : standard_summary_columns())
      standard.push_back(c->name);
    check(standard == std::vector<std::string>{"stage", "load_factor", "voltage_kV", "mass_g",
                                               "displacement_mm", "stroke_mm", "s2_min_kPa",
                                               "s2_ring_inner_kPa", "wrinkled",
                                               "newton_iterations"},
          "the standard columns in the file's order");
    bool with_values = true;
    for (const Quantity *c : standard_summary_columns())
      with_values = with_values && c->summary_values;
    for (const Quantity *c : postprocessor_columns)
      with_values = with_values && !c->summary_values;
    check(with_values, "standard columns read the summary, postprocessor columns are set");
    std::vector<std::string> in_file, in_paraview;
    for (const StepField &f : step_fields())
      {
        if (f.in_file)
          in_file.push_back(f.field.name);
        if (f.in_paraview)
          in_paraview.push_back(f.field.name);
      }
    check(in_file == std::vector<std::string>{"R", "r", "z", "theta", "lambda1", "lambda2", "s1",
                                              "s2", "E", "Phi", "ring"},
          "the /steps fields in the file's order");
    check(in_paraview == std::vector<std::string>{"R", "r", "z", "lambda1", "lambda2", "s1", "s2",
                                                  "sigma1", "sigma2", "E", "Phi", "ring"},
          "ParaView's point data in its order");
  }

  void check_column_values()
  {
    ColumnValues v;
    check(std::isnan(v.get(summary_column::volume)) && !v.has(summary_column::volume),
          "a column not set is NaN");
    v.set(summary_column::volume, 2e-6);
    v.set(summary_column::waveform_time, 0.5);
    v.set(summary_column::volume, 3e-6);
    check(v.get(summary_column::volume) == 3e-6 && v.has(summary_column::waveform_time),
          "set() overwrites, get() reads by handle");
    check(v.in_file_units(summary_column::volume) == 3e-6 * 1e9,
          "in the file's unit: mm^3 from m^3");
    std::vector<const Quantity *> order;
    for (const auto &entry : v)
      order.push_back(entry.first);
    check(order == std::vector<const Quantity *>{&summary_column::volume,
                                                    &summary_column::waveform_time},
          "in the order first set");
  }

  /// The postprocessor columns the steps of @p record have.
  std::set<const Quantity *> columns_of(const RunRecord &record)
  {
    std::set<const Quantity *> seen;
    for (const StepSummary &s : record.steps)
      for (const auto &entry : s.columns)
        seen.insert(entry.first);
    return seen;
  }

  void check_runs(const std::string &what, const unsigned int kind, const RunRecord &record)
  {
    check(!record.steps.empty() && record.result.completed, what + " run completes");
    const std::set<const Quantity *> seen = columns_of(record);
    std::set<const Quantity *>       expected;
    for (const Quantity *c : postprocessor_columns)
      if (c->runs & kind)
        expected.insert(c);
    check(seen == expected, what + ": its columns are the rows that name it (" +
                              std::to_string(seen.size()) + " columns)");
  }

  void check_which_runs()
  {
    const std::string fast = "subsection Discretization\n  set Elements per ring = 4\nend\n"
                             "subsection Electrodes\n  set Voltage path (kV) = 0; 3\nend\n";
    const RunInput quasi_static = read_run_input(ParameterInput::text(fast),
                                                 RunMethod::finite_elements);
    check_runs("quasi-static", quasi_static_run,
               run_in_memory(quasi_static, RunMethod::finite_elements));
    const RunInput shooting = read_run_input(ParameterInput::text(fast), RunMethod::shooting);
    check_runs("shooting", shooting_run, run_in_memory(shooting, RunMethod::shooting));
    const std::string in_time =
      fast + "subsection Material\n  set Model = viscoelastic\nend\n"
             "subsection Time\n  set Enabled = true\n  set Ramp time (s) = 0.05\n"
             "  set Hold time (s) = 0.05\n  set Time step (s) = 0.025\nend\n";
    const RunInput  time_input = read_run_input(ParameterInput::text(in_time),
                                               RunMethod::finite_elements);
    const RunRecord time_record = run_in_memory(time_input, RunMethod::finite_elements);
    check_runs("time", time_run, time_record);
    std::vector<std::string> internal;
    for (const StepFields &f : time_record.fields)
      for (const InternalField &v : f.internal)
        if (std::find(internal.begin(), internal.end(), v.name) == internal.end())
          internal.push_back(v.name);
    check(internal == std::vector<std::string>{"xi1", "xi2"},
          "the viscous law writes xi1 and xi2, not their rates");
  }

  // ---------------------------------------------------------------- files
  std::string text_attribute(const hid_t file, const std::string &object, const std::string &name)
  {
    const hid_t attribute = H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT,
                                            H5P_DEFAULT);
    if (attribute < 0)
      return "(missing)";
    const hid_t type  = H5Aget_type(attribute);
    char       *value = nullptr;
    std::string text  = "(unreadable)";
    if (H5Aread(attribute, type, &value) >= 0 && value)
      text = value;
    if (value)
      H5free_memory(value);
    H5Tclose(type);
    H5Aclose(attribute);
    return text;
  }

  std::vector<double> doubles(const hid_t file, const std::string &name)
  {
    const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    if (set < 0)
      return {};
    const hid_t   space = H5Dget_space(set);
    const hssize_t n    = H5Sget_simple_extent_npoints(space);
    std::vector<double> values(std::size_t(std::max<hssize_t>(n, 0)));
    H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Sclose(space);
    H5Dclose(set);
    return values;
  }

  StepSummary demo_step(const unsigned int i)
  {
    StepSummary s;
    s.stage         = Stage::voltage;
    s.load_factor   = 0.5 * i;
    s.voltages      = {1000. * i};
    s.s2_ring_inner = {2000.};
    s.columns.set(summary_column::volume, 1e-6 * (i + 1));
    if (i > 0)
      s.columns.set(summary_column::waveform_time, 0.25 * i);
    return s;
  }

  StepFields demo_fields()
  {
    StepFields f;
    for (const StepField &row : step_fields())
      if (row.values)
        f.*row.values = {1., 2.};
    f.ring     = {0, 0};
    f.internal = {{"xi1", "1", "viscous (dashpot) stretch xi1", {1.25, 1.5}}};
    return f;
  }

  /// The /summary columns of the table and the internal field of @p path.
  void check_file(const std::string &path, const std::string &what)
  {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (!check(file >= 0, what + ": the file opens"))
      return;
    const std::string volume = "/summary/volume_mm3", time = "/summary/time_s";
    check(doubles(file, volume) == std::vector<double>{1e-6 * 1e9, 2e-6 * 1e9},
          what + ": volume_mm3 in mm^3");
    const std::vector<double> t = doubles(file, time);
    check(t.size() == 2 && std::isnan(t[0]) && t[1] == 0.25, what + ": time_s NaN before it is set");
    check(text_attribute(file, volume, "unit") == summary_column::volume.unit.name &&
            text_attribute(file, volume, "description") == summary_column::volume.description &&
            text_attribute(file, time, "description") == summary_column::waveform_time.description,
          what + ": units and descriptions from the table");
    check(doubles(file, "/steps/000001/xi1") == std::vector<double>{1.25, 1.5} &&
            text_attribute(file, "/steps/000001/xi1", "description") ==
              "viscous (dashpot) stretch xi1",
          what + ": the law's internal variable with its description");
    H5Fclose(file);
  }

  void check_results_and_journal()
  {
    namespace fs = std::filesystem;
    const fs::path base = "test_output_fields_out";
    fs::remove_all(base);
    const std::string path = (base / "table.h5").string(), replayed = (base / "replay.h5").string();
    {
      ResultsFile file(path, "", 1);
      for (unsigned int i = 0; i < 2; ++i)
        file.append(demo_step(i), demo_fields());
      const JournalReplay replay = replay_journal(file.journal_path(), replayed);
      check(replay.document && replay.steps == 2, "the journal replays both steps");
      if (replay.document)
        check(replace_file(replayed, replay.document->image(), true).ok, "replayed file written");
      check(file.finish("complete").written, "the file is written");
    }
    check_file(path, "written");
    check_file(replayed, "replayed from the journal");
  }
} // namespace

CDEA_TEST_MAIN()
{
  check_rows();
  check_column_values();
  check_which_runs();
  check_results_and_journal();
  return failures() ? 1 : 0;
}
