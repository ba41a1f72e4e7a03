// A run's product against the table of quantities (doc/architecture.md,
// "One table of quantities, one product per study"): a made-up run of two
// rings streamed (model/run_stream.h) into a run kept in memory, then
// written as `cdea run` and the Python module write it (write_run()), and
// streamed into a journal and rebuilt from it as `cdea recover` does
// (replay_journal()). In every file each root attribute, /summary dataset and
// attribute and /steps group's attribute and dataset is a row of
// model/output_fields.h (or a field the law declares) with the row's name,
// unit and description, values the row's conversion of the SI values bit for
// bit, and nothing else is there; the in-memory run (the Python result) has
// the /summary attributes the file has.

#include <cdea/analysis/run_record.h>
#include <cdea/model/output_fields.h>
#include <cdea/model/quantities_common.h>
#include <cdea/output/journal.h>

#include "check.h"
#include "product_file_check.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>

using namespace cdea;
using namespace cdea_test;

namespace
{
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();

  StepSummary step(const unsigned int i)
  {
    StepSummary s;
    s.stage             = i < 2 ? Stage::dead_load : Stage::voltage;
    s.load_factor       = 0.5 * (i + 1);
    s.voltages          = {1e3 * i, 1.5e3 * i};
    s.mass              = 0.28;
    s.displacement      = 0.0182 + 1e-3 * i;
    s.stroke            = i < 2 ? nan : 1e-3 * (i - 1);
    s.s2_min            = 2e3 - 1e3 * i;
    s.s2_ring_inner     = {6.7e4, 1.2e4 - 1e3 * i};
    s.wrinkled          = i == 3;
    s.newton_iterations = 3;
    s.columns.set(summary_column::volume, 1e-5 * (i + 1));
    if (i > 1)
      s.columns.set(summary_column::stable, 1.);
    return s;
  }

  StepFields fields(const unsigned int i)
  {
    StepFields f;
    if (i == 1)
      return f; // a /summary row without a /steps group
    for (const StepField &row : step_fields())
      if (row.values)
        f.*row.values = {0.0056 + 1e-4 * i, 0.01, 0.0168};
    f.ring     = {0, 1, 1};
    f.internal = {{"xi1", "1", "viscous stretch xi1 of branch 1", {1.1, 1.05, 1.}}};
    return f;
  }

  /// The run: four steps streamed with an onset, a limit point and a breakdown.
  RunRecord made_up_run()
  {
    RunRecord record;
    record.n_rings    = 2;
    record.parameters = "subsection Electrodes\nend\n";
    RunStream stream(record, 2, quasi_static_run);
    stream.start();
    for (unsigned int i = 0; i < 4; ++i)
      {
        stream.step(step(i), fields(i));
        if (i == 2)
          stream.onset({true, {2e3, 3e3}, 0.0238, 2.5});
      }
    stream.limit_point({1.9, {3e3, 4.5e3}, 0.0215});
    stream.breakdown({true, {3e3, 4.5e3}, 0.014, 2.});
    record.result.completed = true;
    return record;
  }

  /// The /summary dataset of @p row over the steps, as the file holds it.
  std::vector<double> column(const RunRecord &record, const Quantity &row)
  {
    std::vector<double> v;
    for (const StepSummary &s : record.steps)
      if (row.summary_values)
        for (const double x : row.summary_values(s))
          v.push_back(row.in_file_units(x));
      else
        v.push_back(s.columns.in_file_units(row));
    return v;
  }

  /// @p row's dataset at @p path with its unit, description and values.
  void expect(const hid_t file, const std::string &path, const Quantity &row,
              const std::string &unit, const std::string &description,
              const std::vector<hsize_t> &dims, const std::vector<double> &values,
              std::set<std::string> &expected, std::vector<std::string> &wrong)
  {
    expected.insert({path, path + "@unit", path + "@description"});
    const Read r = read_dataset(file, path);
    if (!r.found || read_attribute(file, path, "unit").texts != std::vector<std::string>{unit} ||
        read_attribute(file, path, "description").texts !=
          std::vector<std::string>{description} ||
        r.dims != dims || !same_values(r.values, values) ||
        r.integer != (row.storage == Storage::integer))
      wrong.push_back(path);
  }

  /// /summary: the standard columns, the postprocessors' columns of the
  /// steps, the streamed attributes.
  void expect_summary(const hid_t file, const RunRecord &record, std::set<std::string> &expected,
                      std::vector<std::string> &wrong)
  {
    std::vector<const Quantity *> rows = standard_summary_columns();
    for (const StepSummary &s : record.steps)
      for (const auto &[row, value] : s.columns)
        if (std::find(rows.begin(), rows.end(), row) == rows.end())
          rows.push_back(row);
    const hsize_t n = record.steps.size();
    expected.insert("/summary");
    for (const Quantity *row : rows)
      {
        std::vector<hsize_t> dims = {n};
        if (row->shape == shape::step_ring)
          dims.push_back(record.n_rings);
        expect(file, std::string("/summary/") + row->name, *row, row->unit.name,
               row->description, dims, column(record, *row), expected, wrong);
      }
    for (const ProductEntry &e : record.attributes.attributes)
      {
        expected.insert(std::string("/summary@") + e.name());
        if (!attribute_agrees(file, "/summary", e) || !row_described(*e.quantity))
          wrong.push_back(std::string("/summary@") + e.name());
      }
  }

  /// /steps/NNNNNN of the steps with fields: the step's attributes, the
  /// table's fields and the law's.
  void expect_steps(const hid_t file, const RunRecord &record, std::set<std::string> &expected,
                    std::vector<std::string> &wrong)
  {
    expected.insert("/steps");
    for (std::size_t i = 0; i < record.steps.size(); ++i)
      {
        const StepFields &f = record.fields[i];
        if (f.R.empty())
          continue;
        char group[32];
        std::snprintf(group, sizeof group, "/steps/%06zu", i);
        expected.insert(group);
        for (const Quantity *row : step_attributes())
          {
            const std::string name = std::string(group) + "@" + row->name;
            expected.insert(name);
            const Read a = read_attribute(file, group, row->name);
            if (!same_values(a.values, in_unit(row->summary_values(record.steps[i]), row->unit)))
              wrong.push_back(name);
          }
        const hsize_t n = f.R.size();
        for (const StepField &row : step_fields())
          if (row.in_file)
            expect(file, std::string(group) + "/" + row.field.name, row.field,
                   row.field.unit.name, row.field.description, {n},
                   in_unit(step_field_values(row, f), row.field.unit), expected, wrong);
        for (const InternalField &x : f.internal)
          expect(file, std::string(group) + "/" + x.name, step_fields().front().field, x.unit,
                 x.description, {n}, x.values, expected, wrong);
      }
  }

  void check_run_file(const std::string &path, const RunRecord &record, const std::string &what)
  {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (!check(file >= 0, what + ": the file opens"))
      return;
    std::set<std::string>    expected;
    std::vector<std::string> wrong;
    for (const Quantity *row : {&common_quantity::parameters, &common_quantity::code_version,
                                &run_attribute::n_rings, &run_attribute::run_status,
                                &run_attribute::method})
      expected.insert(std::string("/@") + row->name);
    for (const auto &[name, value] : record.root_attributes)
      expected.insert("/@" + name);
    if (read_attribute(file, "/", run_attribute::method.name).texts !=
        std::vector<std::string>{to_string(record.method)})
      wrong.push_back(std::string("/@") + run_attribute::method.name);
    expect_summary(file, record, expected, wrong);
    expect_steps(file, record, expected, wrong);
    const std::set<std::string> found = file_contents(file);
    H5Fclose(file);
    check_contents(found, expected, wrong, what);
  }

  /// The run's stream into a journal, rebuilt as `cdea recover` does.
  void check_journal(const RunRecord &record)
  {
    // The journal is created exclusively (O_EXCL): a leftover of an earlier
    // run of this test would be in the way.
    const std::string journal = "test_run_products.journal";
    std::remove(journal.c_str());
    {
      JournalWriter writer;
      writer.open(journal, record.parameters, record.n_rings,
                  {{run_attribute::method.name, to_string(record.method)}});
      for (std::size_t i = 0; i < record.steps.size(); ++i)
        writer.append(record.steps[i], record.fields[i], {});
      for (const ProductEntry &e : record.attributes.attributes)
        writer.summary_attribute(file_attribute(e));
    }
    const JournalReplay replay = replay_journal(journal, "replayed");
    check(replay.document && replay.steps == record.steps.size(),
          "journal: every step replayed");
    if (!replay.document)
      return;
    replay.document->set_root_attribute(run_attribute::run_status.name, "rebuilt");
    const std::vector<char> image = replay.document->image();
    std::ofstream("test_run_products_recovered.h5", std::ios::binary)
      .write(image.data(), std::streamsize(image.size()));
    check_run_file("test_run_products_recovered.h5", record, "recovered from the journal");
    std::remove(journal.c_str());
  }
} // namespace

CDEA_TEST_MAIN()
{
  const RunRecord record = made_up_run();
  check(record.attributes.find(summary_attribute::limit_point_voltage) &&
          record.attributes.find(summary_attribute::breakdown_radius) &&
          record.attributes.at(summary_attribute::onset_found).values == std::vector<double>{1.},
        "the run kept in memory has the streamed /summary attributes");
  write_run(record, "test_run_products.h5");
  check_run_file("test_run_products.h5", record, "written run");
  check_journal(record);
  return failures() ? 1 : 0;
}
