// ResultsFile: writes a 3-step, 2-ring file, reads it back with the plain HDF5
// C API and checks names, shapes, types, units, unit conversions, values and
// attributes; checks that the journal of a process killed right after an
// append rebuilds a complete file (also with a torn or corrupted last
// record) and that an older file stays untouched until finish() while a
// second writer is refused. Limits and bad input: test_results_file_limits.cc.

#include <cdea/output/results_file.h>
#include <cdea/output/safe_files.h>

#include <hdf5.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "check.h"

#include "results_file_demo.h"

using namespace cdea_test;
using namespace results_file_demo;

namespace
{
  // ---------------------------------------------------------------- reading
  struct Array
  {
    std::vector<hsize_t> dims;
    std::vector<double>  values;
    H5T_class_t          type_class = H5T_NO_CLASS;
    bool                 ok         = false;
  };

  Array read_dataset(const hid_t file, const std::string &name)
  {
    Array a;
    if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0)
      return a;
    const hid_t dataset = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    const hid_t space   = H5Dget_space(dataset);
    const int   rank    = H5Sget_simple_extent_ndims(space);
    a.dims.resize(rank);
    H5Sget_simple_extent_dims(space, a.dims.data(), nullptr);
    hsize_t size = 1;
    for (const auto d : a.dims)
      size *= d;
    a.values.resize(size);
    const hid_t type = H5Dget_type(dataset);
    a.type_class     = H5Tget_class(type);
    a.ok = size == 0 || H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                                a.values.data()) >= 0;
    H5Tclose(type);
    H5Sclose(space);
    H5Dclose(dataset);
    return a;
  }

  Array read_attribute(const hid_t file, const std::string &object, const std::string &name)
  {
    Array a;
    if (H5Aexists_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0)
      return a;
    const hid_t attribute = H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT,
                                            H5P_DEFAULT);
    const hid_t space     = H5Aget_space(attribute);
    const int   rank      = H5Sget_simple_extent_ndims(space);
    a.dims.resize(rank);
    H5Sget_simple_extent_dims(space, a.dims.data(), nullptr);
    hsize_t size = 1;
    for (const auto d : a.dims)
      size *= d;
    a.values.resize(size);
    const hid_t type = H5Aget_type(attribute);
    a.type_class     = H5Tget_class(type);
    a.ok             = H5Aread(attribute, H5T_NATIVE_DOUBLE, a.values.data()) >= 0;
    H5Tclose(type);
    H5Sclose(space);
    H5Aclose(attribute);
    return a;
  }

  /// A string attribute (variable or fixed length); "<missing>" if absent.
  std::string read_string_attribute(const hid_t        file,
                                    const std::string &object,
                                    const std::string &name)
  {
    if (H5Aexists_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0)
      return "<missing>";
    const hid_t attribute = H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT,
                                            H5P_DEFAULT);
    const hid_t type      = H5Aget_type(attribute);
    std::string result    = "<not a string>";
    if (H5Tget_class(type) == H5T_STRING)
      {
        if (H5Tis_variable_str(type) > 0)
          {
            const hid_t memory_type = H5Tcopy(H5T_C_S1);
            H5Tset_size(memory_type, H5T_VARIABLE);
            H5Tset_cset(memory_type, H5Tget_cset(type));
            char *pointer = nullptr;
            if (H5Aread(attribute, memory_type, &pointer) >= 0 && pointer != nullptr)
              {
                result = pointer;
                H5free_memory(pointer);
              }
            H5Tclose(memory_type);
          }
        else
          {
            std::vector<char> buffer(H5Tget_size(type) + 1, '\0');
            H5Aread(attribute, type, buffer.data());
            result = buffer.data();
          }
      }
    H5Tclose(type);
    H5Aclose(attribute);
    return result;
  }

  std::set<std::string> members(const hid_t file, const std::string &group_name)
  {
    std::set<std::string> names;
    const hid_t           group = H5Gopen2(file, group_name.c_str(), H5P_DEFAULT);
    if (group < 0)
      return names;
    H5G_info_t info;
    H5Gget_info(group, &info);
    for (hsize_t k = 0; k < info.nlinks; ++k)
      {
        char buffer[256];
        H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, k, buffer, sizeof(buffer),
                           H5P_DEFAULT);
        names.insert(buffer);
      }
    H5Gclose(group);
    return names;
  }

  bool same(const double a, const double b)
  {
    if (std::isnan(a) || std::isnan(b))
      return std::isnan(a) && std::isnan(b);
    return std::abs(a - b) <= 1e-13 * std::max(1., std::abs(b));
  }

  /// One check per array: shape and every value (NaN matches NaN).
  void check_array(const Array                &a,
                   const std::vector<hsize_t> &dims,
                   const std::vector<double>  &expected,
                   const H5T_class_t           type_class,
                   const std::string          &what)
  {
    bool        ok = a.ok && a.dims == dims && a.values.size() == expected.size() &&
              a.type_class == type_class;
    std::string detail;
    if (!a.ok)
      detail = " (missing or unreadable)";
    else if (a.dims != dims)
      detail = " (wrong shape)";
    else if (a.type_class != type_class)
      detail = " (wrong type class)";
    if (ok)
      for (std::size_t k = 0; k < expected.size(); ++k)
        if (!same(a.values[k], expected[k]))
          {
            ok     = false;
            detail = " (entry " + std::to_string(k) + ": " + std::to_string(a.values[k]) +
                     " vs " + std::to_string(expected[k]) + ")";
            break;
          }
    check(ok, what + detail);
  }

  std::vector<double> scaled(const std::vector<double> &v, const double factor)
  {
    std::vector<double> r;
    for (const double x : v)
      r.push_back(x * factor);
    return r;
  }

  // ---------------------------------------------------------------- checks
  void check_demo_file(const std::string &path, const unsigned int n_steps, const bool with_onset)
  {
    std::cout << "checking " << path << " (" << n_steps << " steps)\n";
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (!check(file >= 0, "file opens"))
      return;
    const hsize_t n = n_steps;

    // Root attributes.
    check(read_string_attribute(file, "/", "parameters") == parameters_text, "parameters text");
    check(read_string_attribute(file, "/", "code_version") == CDEA_VERSION, "code_version");
    check(read_string_attribute(file, "/", "solver") == "shooting", "extra root attribute solver");
    check(read_string_attribute(file, "/", "prm_file") == "prm/test.prm",
          "extra root attribute prm_file");
    check_array(read_attribute(file, "/", "n_rings"), {}, {2.}, H5T_INTEGER, "n_rings");

    // /summary names, shapes, types, units, values.
    const std::set<std::string> summary_names = {
      "stage",     "load_factor", "voltage_kV", "mass_g",     "displacement_mm",
      "stroke_mm", "s2_min_kPa",  "s2_ring_inner_kPa", "wrinkled", "newton_iterations",
      "volume_mm3", "energy_mJ"};
    check(members(file, "/summary") == summary_names, "/summary holds exactly the expected datasets");
    check(members(file, "/") == std::set<std::string>{"summary", "steps"},
          "root holds summary and steps");

    struct Column
    {
      std::string name, unit;
      bool        per_ring, is_int;
      std::vector<double> (*value)(const cdea::StepSummary &);
    };
    const std::vector<Column> columns = {
      {"stage", "1", false, true, [](const cdea::StepSummary &s) {
         return std::vector<double>{double(static_cast<int>(s.stage))};
       }},
      {"load_factor", "1", false, false, [](const cdea::StepSummary &s) {
         return std::vector<double>{s.load_factor};
       }},
      {"voltage_kV", "kV", true, false, [](const cdea::StepSummary &s) {
         return scaled(s.voltages, 1e-3);
       }},
      {"mass_g", "g", false, false, [](const cdea::StepSummary &s) {
         return std::vector<double>{s.mass * 1e3};
       }},
      {"displacement_mm", "mm", false, false, [](const cdea::StepSummary &s) {
         return std::vector<double>{s.displacement * 1e3};
       }},
      {"stroke_mm", "mm", false, false, [](const cdea::StepSummary &s) {
         return std::vector<double>{s.stroke * 1e3};
       }},
      {"s2_min_kPa", "kPa", false, false, [](const cdea::StepSummary &s) {
         return std::vector<double>{s.s2_min * 1e-3};
       }},
      {"s2_ring_inner_kPa", "kPa", true, false, [](const cdea::StepSummary &s) {
         return scaled(s.s2_ring_inner, 1e-3);
       }},
      {"wrinkled", "1", false, true, [](const cdea::StepSummary &s) {
         return std::vector<double>{s.wrinkled ? 1. : 0.};
       }},
      {"newton_iterations", "1", false, true, [](const cdea::StepSummary &s) {
         return std::vector<double>{double(s.newton_iterations)};
       }}};
    for (const auto &c : columns)
      {
        std::vector<double> expected;
        for (unsigned int i = 0; i < n_steps; ++i)
          for (const double v : c.value(demo_summary(i)))
            expected.push_back(v);
        const std::vector<hsize_t> dims =
          c.per_ring ? std::vector<hsize_t>{n, 2} : std::vector<hsize_t>{n};
        const std::string name = "/summary/" + c.name;
        check_array(read_dataset(file, name), dims, expected,
                    c.is_int ? H5T_INTEGER : H5T_FLOAT, name);
        check(read_string_attribute(file, name, "unit") == c.unit, name + " unit " + c.unit);
        check(read_string_attribute(file, name, "description").size() > 5,
              name + " has a description");
      }
    // Extra columns: NaN padding before first appearance and where left out.
    {
      std::vector<double> volume, energy;
      for (unsigned int i = 0; i < n_steps; ++i)
        {
          volume.push_back(i == 0 ? nan_value : 1234.5 + i);
          energy.push_back(i == 0 ? 7.5 : nan_value);
        }
      check_array(read_dataset(file, "/summary/volume_mm3"), {n}, volume, H5T_FLOAT,
                  "/summary/volume_mm3 (NaN-padded)");
      check_array(read_dataset(file, "/summary/energy_mJ"), {n}, energy, H5T_FLOAT,
                  "/summary/energy_mJ (NaN where left out)");
      check(read_string_attribute(file, "/summary/volume_mm3", "unit") == "mm3",
            "volume_mm3 unit from describe_column");
      check(read_string_attribute(file, "/summary/volume_mm3", "description") ==
              "enclosed volume",
            "volume_mm3 description from describe_column");
      check(read_string_attribute(file, "/summary/energy_mJ", "unit") == "",
            "energy_mJ has an (empty) unit attribute");
    }

    // /summary attributes.
    const auto onset = demo_onset();
    check_array(read_attribute(file, "/summary", "onset_found"), {}, {with_onset ? 1. : 0.},
                H5T_INTEGER, "onset_found");
    check_array(read_attribute(file, "/summary", "onset_voltage_kV"), {2},
                with_onset ? scaled(onset.voltages, 1e-3) : std::vector<double>{nan_value, nan_value},
                H5T_FLOAT, "onset_voltage_kV");
    check_array(read_attribute(file, "/summary", "onset_radius_mm"), {},
                {with_onset ? onset.radius * 1e3 : nan_value}, H5T_FLOAT, "onset_radius_mm");
    check_array(read_attribute(file, "/summary", "limit_point_kV"), {2}, {6.5, 7.25}, H5T_FLOAT,
                "limit_point_kV (overwritten)");

    // /steps/NNNNNN
    std::set<std::string> step_names;
    for (unsigned int i = 0; i < n_steps; ++i)
      {
        char buffer[16];
        std::snprintf(buffer, sizeof(buffer), "%06u", i);
        step_names.insert(buffer);
      }
    check(members(file, "/steps") == step_names, "/steps holds exactly the step groups");
    const std::set<std::string> field_names = {"R", "r", "z", "theta", "lambda1", "lambda2",
                                               "s1", "s2", "E", "Phi", "ring"};
    for (unsigned int i = 0; i < n_steps; ++i)
      {
        char buffer[32];
        std::snprintf(buffer, sizeof(buffer), "/steps/%06u", i);
        const std::string group = buffer;
        const auto        s     = demo_summary(i);
        const auto        f     = demo_fields(i);
        const hsize_t     m     = demo_n_samples(i);
        check(members(file, group) == field_names, group + " holds exactly the field datasets");
        struct Field
        {
          std::string         name, unit;
          std::vector<double> expected;
          H5T_class_t         type_class;
        };
        const std::vector<Field> fields = {
          {"R", "mm", scaled(f.R, 1e3), H5T_FLOAT},
          {"r", "mm", scaled(f.r, 1e3), H5T_FLOAT},
          {"z", "mm", scaled(f.z, 1e3), H5T_FLOAT},
          {"theta", "rad", f.theta, H5T_FLOAT},
          {"lambda1", "1", f.lambda1, H5T_FLOAT},
          {"lambda2", "1", f.lambda2, H5T_FLOAT},
          {"s1", "kPa", scaled(f.s1, 1e-3), H5T_FLOAT},
          {"s2", "kPa", scaled(f.s2, 1e-3), H5T_FLOAT},
          {"E", "MV/m", scaled(f.E, 1e-6), H5T_FLOAT},
          {"Phi", "kV", scaled(f.Phi, 1e-3), H5T_FLOAT},
          {"ring", "1", std::vector<double>(f.ring.begin(), f.ring.end()), H5T_INTEGER}};
        for (const auto &field : fields)
          {
            const std::string name = group + "/" + field.name;
            check_array(read_dataset(file, name), {m}, field.expected, field.type_class, name);
            check(read_string_attribute(file, name, "unit") == field.unit,
                  name + " unit " + field.unit);
          }
        check_array(read_attribute(file, group, "stage"), {}, {double(static_cast<int>(s.stage))},
                    H5T_INTEGER, group + " attribute stage");
        check_array(read_attribute(file, group, "load_factor"), {}, {s.load_factor}, H5T_FLOAT,
                    group + " attribute load_factor");
        check_array(read_attribute(file, group, "voltage_kV"), {2}, scaled(s.voltages, 1e-3),
                    H5T_FLOAT, group + " attribute voltage_kV");
        check_array(read_attribute(file, group, "displacement_mm"), {}, {s.displacement * 1e3},
                    H5T_FLOAT, group + " attribute displacement_mm");
      }
    H5Fclose(file);
  }
} // namespace

CDEA_TEST_MAIN()
{
  namespace fs = std::filesystem;
  const fs::path base = "test_results_file_out";
  fs::remove_all(base);

  // 1. Normal run; the parent directory does not exist yet.
  const std::string path = (base / "nested" / "results.h5").string();
  write_demo(path, 3, true);
  check_demo_file(path, 3, true);

  // 2. A process killed (SIGKILL, no destructor, no atexit) right after its
  //    second append leaves a journal that rebuilds a complete file with
  //    both steps; the path itself is not written before finish().
  const std::string killed_path = (base / "killed.h5").string();
  const auto        killed_child = [&](const std::string &target, const unsigned int steps) {
    std::cout.flush();
    const pid_t child = fork();
    if (child == 0)
      {
        cdea::ResultsFile file(target, parameters_text, 2, demo_root_attributes);
        file.describe_column("volume_mm3", "mm3", "enclosed volume");
        for (unsigned int i = 0; i < steps; ++i)
          file.append(demo_summary(i), demo_fields(i), demo_extra(i));
        file.set_summary_attribute("limit_point_kV", {6.5, 7.25});
        std::raise(SIGKILL);
        _exit(0); // not reached
      }
    int status = 0;
    waitpid(child, &status, 0);
    return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
  };
  check(killed_child(killed_path, 2), "child was killed by SIGKILL");
  check(!fs::exists(killed_path) && fs::exists(killed_path + ".journal"),
        "a killed run leaves its journal and no file at the path");
  {
    const cdea::Recovery r = cdea::recover_results(killed_path, true);
    check(r.found && r.file == killed_path && r.steps == 2, "recovery: 2 steps into the path");
    check(!fs::exists(killed_path + ".journal"), "recovery removes the journal");
    check_demo_file(killed_path, 2, false);
  }

  // 2b. A torn last record (the kill cut the write) and a corrupted one are
  //     dropped: the steps before them are rebuilt.
  for (const bool tear : {true, false})
    {
      const std::string torn = (base / (tear ? "torn.h5" : "corrupt.h5")).string();
      check(killed_child(torn, 3), "child with 3 steps killed");
      const std::string journal = torn + ".journal";
      // The last record is the limit_point_kV attribute; the one before it
      // is step 2. Cut or flip a byte inside step 2's record.
      const auto size = fs::file_size(journal);
      if (tear)
        fs::resize_file(journal, size - 200);
      else
        {
          std::fstream f(journal, std::ios::in | std::ios::out | std::ios::binary);
          f.seekp(std::streamoff(size - 200));
          f.put('\x5a');
        }
      const cdea::Recovery r = cdea::recover_results(torn, true);
      check(r.steps == 2, std::string(tear ? "torn" : "corrupted") +
                            " step record dropped: 2 steps recovered (" + r.message + ")");
      // Damage with a record after it is not taken for the end: the journal stays.
      check(r.damaged == !tear && fs::exists(journal) == !tear,
            tear ? "a torn last record: journal removed" : "a damaged record: journal kept");
      const hid_t file = H5Fopen(torn.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
      check(file >= 0 && read_dataset(file, "/summary/stage").dims == std::vector<hsize_t>{2} &&
              H5Lexists(file, "/steps/000001", H5P_DEFAULT) > 0 &&
              H5Lexists(file, "/steps/000002", H5P_DEFAULT) == 0,
            "the rebuilt file has steps 0 and 1 only");
      if (file >= 0)
        H5Fclose(file);
    }

  // 2c. An older file stays byte for byte until the new run's finish(); a
  //     second writer of the same path is refused; the next run saves a
  //     killed run's journal beside the path.
  {
    const std::string older = (base / "older.h5").string();
    write_demo(older, 3, true);
    const auto read_bytes = [](const std::string &p) {
      std::ifstream in(p, std::ios::binary);
      return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    const std::string before = read_bytes(older);
    check(killed_child(older, 1), "a re-run killed after one step");
    check(read_bytes(older) == before, "the killed re-run left the older file byte for byte");
    {
      cdea::ResultsFile rerun(older, parameters_text, 2, demo_root_attributes);
      check(rerun.notes().size() == 1 && fs::exists((base / "older.recovered.h5").string()),
            "the next run saved the killed run's step in older.recovered.h5");
      rerun.append(demo_summary(0), demo_fields(0));
      bool refused = false;
      try
        {
          cdea::ResultsFile second(older, parameters_text, 2);
        }
      catch (const cdea::OutputError &e)
        {
          refused = std::string(e.what()).find("another cdea process") != std::string::npos;
          std::cout << "  (message: " << e.what() << ")\n";
        }
      check(refused, "a second writer of the same file is refused, naming the other process");
      check(read_bytes(older) == before, "the older file is unchanged while the re-run writes");
      rerun.finish("complete");
    }
    check(read_bytes(older) != before && !fs::exists(older + ".lock") &&
            !fs::exists(older + ".journal"),
          "finish() replaced the older file and removed the lock and journal");
  }

  return finish();
}
