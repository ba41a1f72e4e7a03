#include <cdea/output/hdf5_support.h>
#include <cdea/output/results_document.h>

#include <hdf5.h>

#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

#ifndef CDEA_VERSION
#  define CDEA_VERSION "unknown"
#endif

namespace cdea
{
  namespace
  {
    constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();

    // Unit conversions from SI to the file's units.
    constexpr double to_mm   = 1e3;
    constexpr double to_kPa  = 1e-3;
    constexpr double to_kV   = 1e-3;
    constexpr double to_MV_m = 1e-6;
    constexpr double to_g    = 1e3;

    constexpr hsize_t summary_chunk_rows = 128;

    using hdf5::ErrorPrintingOff;
    using hdf5::Handle;

    const char *const standard_column_names[] = {"stage",
                                                 "load_factor",
                                                 "voltage_kV",
                                                 "mass_g",
                                                 "displacement_mm",
                                                 "stroke_mm",
                                                 "s2_min_kPa",
                                                 "s2_ring_inner_kPa",
                                                 "wrinkled",
                                                 "newton_iterations"};

    std::vector<double> scaled(const std::vector<double> &values, const double factor)
    {
      std::vector<double> result(values.size());
      for (std::size_t i = 0; i < values.size(); ++i)
        result[i] = values[i] * factor;
      return result;
    }
  } // namespace

  struct ResultsDocument::Impl
  {
    explicit Impl(const std::string &name)
      : w("results file '" + name + "'")
    {}

    hdf5::Writer w;
    unsigned int rings = 0;
    hsize_t      rows  = 0;

    Handle file, summary, steps;

    struct Column
    {
      Handle       dataset;
      unsigned int width = 1; // 1 for 1D, n_rings for 2D
      hid_t        memory_type;
    };
    std::map<std::string, Column> standard_columns;
    std::map<std::string, Column> extra_columns;
    std::map<std::string, std::pair<std::string, std::string>> extra_descriptions;

    ~Impl()
    {
      // Objects before the file; Handle::reset() never throws.
      ErrorPrintingOff quiet;
      standard_columns.clear();
      extra_columns.clear();
      steps.reset();
      summary.reset();
      file.reset();
    }

    /// An empty chunked, unlimited /summary dataset with @p width columns
    /// (1D if width == 0), NaN fill for doubles.
    Handle create_summary_dataset(const std::string &name, const hid_t file_type,
                                  const unsigned int width, const hsize_t initial_rows) const
    {
      const int     rank       = width == 0 ? 1 : 2;
      const hsize_t dims[2]    = {initial_rows, width};
      const hsize_t maxdims[2] = {H5S_UNLIMITED, width};
      const hsize_t chunk[2]   = {summary_chunk_rows, width};
      Handle space(w.check(H5Screate_simple(rank, dims, maxdims), "H5Screate_simple"), H5Sclose);
      Handle dcpl(w.check(H5Pcreate(H5P_DATASET_CREATE), "H5Pcreate"), H5Pclose);
      w.check_status(H5Pset_chunk(dcpl, rank, chunk), "H5Pset_chunk");
      if (H5Tequal(file_type, H5T_IEEE_F64LE) > 0)
        w.check_status(H5Pset_fill_value(dcpl, H5T_NATIVE_DOUBLE, &nan_value),
                       "H5Pset_fill_value");
      else
        {
          const int zero = 0;
          w.check_status(H5Pset_fill_value(dcpl, H5T_NATIVE_INT, &zero), "H5Pset_fill_value");
        }
      w.check_status(H5Pset_fill_time(dcpl, H5D_FILL_TIME_ALLOC), "H5Pset_fill_time");
      return Handle(w.check(H5Dcreate2(summary, name.c_str(), file_type, space, H5P_DEFAULT,
                                       dcpl, H5P_DEFAULT),
                            "H5Dcreate2(/summary/" + name + ")"),
                    H5Dclose);
    }

    void add_standard_column(const std::string &name, const bool is_int, const bool per_ring,
                             const std::string &unit, const std::string &description)
    {
      Column column;
      column.width       = per_ring ? rings : 1;
      column.memory_type = is_int ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE;
      column.dataset     = create_summary_dataset(name, is_int ? H5T_STD_I32LE : H5T_IEEE_F64LE,
                                                  per_ring ? rings : 0, 0);
      w.describe(column.dataset, unit, description);
      standard_columns.emplace(name, std::move(column));
    }

    /// Grows @p column to rows_after rows (new rows get the fill value).
    void extend(const std::string &name, const Column &column, const hsize_t rows_after) const
    {
      const hsize_t dims[2] = {rows_after, column.width};
      w.check_status(H5Dset_extent(column.dataset, dims), "H5Dset_extent(/summary/" + name + ")");
    }

    /// Writes row @p row (already allocated) of @p column.
    void write_row(const std::string &name, const Column &column, const hsize_t row,
                   const void *data) const
    {
      Handle file_space(w.check(H5Dget_space(column.dataset), "H5Dget_space"), H5Sclose);
      const hsize_t start[2] = {row, 0};
      const hsize_t count[2] = {1, column.width};
      w.check_status(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count,
                                         nullptr),
                     "H5Sselect_hyperslab");
      const hsize_t memory_dims[1] = {column.width};
      Handle memory_space(w.check(H5Screate_simple(1, memory_dims, nullptr), "H5Screate_simple"),
                          H5Sclose);
      w.check_status(H5Dwrite(column.dataset, column.memory_type, memory_space, file_space,
                              H5P_DEFAULT, data),
                     "H5Dwrite(/summary/" + name + ")");
    }

    void write_field(const hid_t group, const std::string &name, const hid_t file_type,
                     const hid_t memory_type, const void *data, const std::size_t n,
                     const std::string &unit, const std::string &description) const
    {
      const hsize_t dims[1] = {n};
      Handle space(w.check(H5Screate_simple(1, dims, nullptr), "H5Screate_simple"), H5Sclose);
      Handle dataset(w.check(H5Dcreate2(group, name.c_str(), file_type, space, H5P_DEFAULT,
                                        H5P_DEFAULT, H5P_DEFAULT),
                             "H5Dcreate2(" + name + ")"),
                     H5Dclose);
      if (n > 0)
        w.check_status(H5Dwrite(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                       "H5Dwrite(" + name + ")");
      w.describe(dataset, unit, description);
    }

    void write_scaled_field(const hid_t group, const std::string &name,
                            const std::vector<double> &values, const double factor,
                            const std::string &unit, const std::string &description) const
    {
      const std::vector<double> v = scaled(values, factor);
      write_field(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, v.data(), v.size(), unit,
                  description);
    }

    void write_extra_description(const std::string &name) const
    {
      const auto it = extra_columns.find(name);
      if (it == extra_columns.end())
        return;
      const auto d = extra_descriptions.find(name);
      if (d != extra_descriptions.end())
        w.describe(it->second.dataset, d->second.first, d->second.second);
      else
        w.describe(it->second.dataset, "",
                   "extra summary column (the unit is part of the name); NaN where not written");
    }
  };

  ResultsDocument::ResultsDocument(const std::string &name, const std::string &parameters_text,
                                   const unsigned int n_rings,
                                   const std::vector<std::pair<std::string, std::string>>
                                     &extra_root_attributes)
    : impl(std::make_unique<Impl>(name))
  {
    Impl &d = *impl;
    d.rings = n_rings;
    if (n_rings == 0)
      throw std::invalid_argument(d.w.name() + ": n_rings must be at least 1");
    for (const auto &attribute : extra_root_attributes)
      if (attribute.first.empty() || attribute.first == "parameters" ||
          attribute.first == "code_version" || attribute.first == "n_rings" ||
          attribute.first == "run_status")
        throw std::invalid_argument(d.w.name() + ": extra root attribute name '" +
                                    attribute.first + "' is empty or reserved");

    ErrorPrintingOff quiet;
    d.file = hdf5::create_memory_file(name);
    d.w.string_attribute(d.file, "parameters", parameters_text);
    d.w.string_attribute(d.file, "code_version", CDEA_VERSION);
    d.w.int_attribute(d.file, "n_rings", static_cast<int>(n_rings));
    for (const auto &attribute : extra_root_attributes)
      d.w.string_attribute(d.file, attribute.first, attribute.second);

    d.summary = Handle(d.w.check(H5Gcreate2(d.file, "summary", H5P_DEFAULT, H5P_DEFAULT,
                                            H5P_DEFAULT),
                                 "H5Gcreate2(/summary)"),
                       H5Gclose);
    d.steps   = Handle(d.w.check(H5Gcreate2(d.file, "steps", H5P_DEFAULT, H5P_DEFAULT,
                                            H5P_DEFAULT),
                                 "H5Gcreate2(/steps)"),
                       H5Gclose);

    d.add_standard_column("stage", true, false, "1",
                          "stage of the run: 0 pre-stretch, 1 dead load, 2 voltage");
    d.add_standard_column("load_factor", false, false, "1",
                          "stage parameter (voltage path parameter in stage 2)");
    d.add_standard_column("voltage_kV", false, true, "kV",
                          "voltage of each ring (steps x rings)");
    d.add_standard_column("mass_g", false, false, "g", "dead-load mass on the disk");
    d.add_standard_column("displacement_mm", false, false, "mm",
                          "disk deflection from the frame plane |z(disk) - z(frame)|");
    d.add_standard_column("stroke_mm", false, false, "mm",
                          "displacement minus its zero-voltage value under the same load "
                          "(NaN before the end of the load stage)");
    d.add_standard_column("s2_min_kPa", false, false, "kPa",
                          "smallest nominal hoop stress s2 anywhere");
    d.add_standard_column("s2_ring_inner_kPa", false, true, "kPa",
                          "nominal hoop stress s2 at the inner edge of each ring "
                          "(steps x rings)");
    d.add_standard_column("wrinkled", true, false, "1",
                          "1 if the hoop stress is negative somewhere (loss of tension)");
    d.add_standard_column("newton_iterations", true, false, "1",
                          "Newton iterations of the converged step");

    write_onset(OnsetRecord{});
  }

  ResultsDocument::~ResultsDocument()                                    = default;
  ResultsDocument::ResultsDocument(ResultsDocument &&) noexcept            = default;
  ResultsDocument &ResultsDocument::operator=(ResultsDocument &&) noexcept = default;

  void ResultsDocument::check_append(
    const StepSummary &summary, const StepFields &fields,
    const std::vector<std::pair<std::string, double>> &extra_columns) const
  {
    const Impl       &d      = *impl;
    const std::string prefix = d.w.name() + ": ";
    if (summary.voltages.size() != d.rings)
      throw std::invalid_argument(prefix + "StepSummary::voltages has " +
                                  std::to_string(summary.voltages.size()) + " entries, expected " +
                                  std::to_string(d.rings));
    if (summary.s2_ring_inner.size() != d.rings)
      throw std::invalid_argument(prefix + "StepSummary::s2_ring_inner has " +
                                  std::to_string(summary.s2_ring_inner.size()) +
                                  " entries, expected " + std::to_string(d.rings));
    const std::size_t n = fields.R.size();
    const std::pair<const char *, std::size_t> sizes[] = {
      {"r", fields.r.size()},             {"z", fields.z.size()},
      {"theta", fields.theta.size()},     {"lambda1", fields.lambda1.size()},
      {"lambda2", fields.lambda2.size()}, {"s1", fields.s1.size()},
      {"s2", fields.s2.size()},           {"E", fields.E.size()},
      {"Phi", fields.Phi.size()},         {"ring", fields.ring.size()}};
    for (const auto &s : sizes)
      if (s.second != n)
        throw std::invalid_argument(prefix + "StepFields::" + s.first + " has " +
                                    std::to_string(s.second) + " entries but R has " +
                                    std::to_string(n));
    if ((!fields.xi1.empty() || !fields.xi2.empty()) &&
        (fields.xi1.size() != n || fields.xi2.size() != n))
      throw std::invalid_argument(prefix + "StepFields::xi1, xi2 must be empty or as long as R");
    std::set<std::string> seen;
    for (const auto &column : extra_columns)
      {
        const std::string &name = column.first;
        if (name.empty() || name.find('/') != std::string::npos || name == "." ||
            d.standard_columns.count(name) > 0 || !seen.insert(name).second)
          throw std::invalid_argument(prefix + "extra summary column name '" + name +
                                      "' is empty, contains '/', repeats or is reserved");
      }
  }

  void ResultsDocument::append(const StepSummary &summary, const StepFields &fields,
                               const std::vector<std::pair<std::string, double>> &extra_columns)
  {
    check_append(summary, fields, extra_columns);
    Impl            &d = *impl;
    ErrorPrintingOff quiet;
    const hsize_t    row = d.rows;

    // /summary row.
    const int                 stage           = static_cast<int>(summary.stage);
    const int                 wrinkled        = summary.wrinkled ? 1 : 0;
    const int                 iterations      = static_cast<int>(summary.newton_iterations);
    const double              mass_g          = summary.mass * to_g;
    const double              displacement_mm = summary.displacement * to_mm;
    const double              stroke_mm       = summary.stroke * to_mm;
    const double              s2_min_kPa      = summary.s2_min * to_kPa;
    const std::vector<double> voltage_kV      = scaled(summary.voltages, to_kV);
    const std::vector<double> s2_ring_kPa     = scaled(summary.s2_ring_inner, to_kPa);
    const std::map<std::string, const void *> row_data = {
      {"stage", &stage},
      {"load_factor", &summary.load_factor},
      {"voltage_kV", voltage_kV.data()},
      {"mass_g", &mass_g},
      {"displacement_mm", &displacement_mm},
      {"stroke_mm", &stroke_mm},
      {"s2_min_kPa", &s2_min_kPa},
      {"s2_ring_inner_kPa", s2_ring_kPa.data()},
      {"wrinkled", &wrinkled},
      {"newton_iterations", &iterations}};
    for (const char *name : standard_column_names)
      {
        const Impl::Column &column = d.standard_columns.at(name);
        d.extend(name, column, row + 1);
        d.write_row(name, column, row, row_data.at(name));
      }

    // Extra columns: new ones start NaN-filled up to this row.
    for (const auto &[name, value] : extra_columns)
      if (d.extra_columns.count(name) == 0)
        {
          Impl::Column column;
          column.width       = 1;
          column.memory_type = H5T_NATIVE_DOUBLE;
          column.dataset     = d.create_summary_dataset(name, H5T_IEEE_F64LE, 0, row);
          d.extra_columns.emplace(name, std::move(column));
          d.write_extra_description(name);
        }
    for (const auto &[name, column] : d.extra_columns)
      d.extend(name, column, row + 1); // NaN unless written below
    for (const auto &[name, value] : extra_columns)
      d.write_row(name, d.extra_columns.at(name), row, &value);

    if (fields.R.empty()) // a /summary row alone (time-dependent runs, doc/time.md)
      {
        d.rows = row + 1;
        return;
      }

    // /steps/NNNNNN
    char group_name[32];
    std::snprintf(group_name, sizeof(group_name), "%06llu", static_cast<unsigned long long>(row));
    Handle group(d.w.check(H5Gcreate2(d.steps, group_name, H5P_DEFAULT, H5P_DEFAULT,
                                      H5P_DEFAULT),
                           std::string("H5Gcreate2(/steps/") + group_name + ")"),
                 H5Gclose);
    d.w.int_attribute(group, "stage", stage);
    d.w.double_attribute(group, "load_factor", summary.load_factor);
    d.w.double_array_attribute(group, "voltage_kV", voltage_kV);
    d.w.double_attribute(group, "displacement_mm", displacement_mm);

    d.write_scaled_field(group, "R", fields.R, to_mm, "mm",
                         "undeformed (reference) radius of the material point");
    d.write_scaled_field(group, "r", fields.r, to_mm, "mm", "deformed radius");
    d.write_scaled_field(group, "z", fields.z, to_mm, "mm",
                         "deformed height (same sign convention as the solver)");
    d.write_scaled_field(group, "theta", fields.theta, 1., "rad", "meridian slope angle");
    d.write_scaled_field(group, "lambda1", fields.lambda1, 1., "1", "meridian stretch");
    d.write_scaled_field(group, "lambda2", fields.lambda2, 1., "1", "hoop stretch r/R");
    d.write_scaled_field(group, "s1", fields.s1, to_kPa, "kPa", "nominal meridian stress");
    d.write_scaled_field(group, "s2", fields.s2, to_kPa, "kPa", "nominal hoop stress");
    d.write_scaled_field(group, "E", fields.E, to_MV_m, "MV/m",
                         "true electric field in the thickness direction");
    d.write_scaled_field(group, "Phi", fields.Phi, to_kV, "kV", "voltage across the film");
    d.write_field(group, "ring", H5T_STD_I32LE, H5T_NATIVE_INT, fields.ring.data(),
                  fields.ring.size(), "1", "index of the electrode ring (0 = innermost)");
    if (!fields.xi1.empty()) // viscous stretches of a time-dependent run (doc/time.md)
      for (const auto &[name, xi] : {std::pair{"xi1", &fields.xi1}, std::pair{"xi2", &fields.xi2}})
        d.write_scaled_field(group, name, *xi, 1., "1",
                             "viscous (dashpot) stretch " + std::string(name));
    d.rows = row + 1;
  }

  void ResultsDocument::describe_column(const std::string &name, const std::string &unit,
                                        const std::string &description)
  {
    ErrorPrintingOff quiet;
    impl->extra_descriptions[name] = {unit, description};
    impl->write_extra_description(name);
  }

  void ResultsDocument::check_onset(const OnsetRecord &onset) const
  {
    if (onset.found && onset.voltages.size() != impl->rings)
      throw std::invalid_argument(impl->w.name() + ": OnsetRecord::voltages has " +
                                  std::to_string(onset.voltages.size()) + " entries, expected " +
                                  std::to_string(impl->rings));
  }

  void ResultsDocument::write_onset(const OnsetRecord &onset)
  {
    check_onset(onset);
    Impl            &d = *impl;
    ErrorPrintingOff quiet;
    d.w.int_attribute(d.summary, "onset_found", onset.found ? 1 : 0);
    d.w.double_array_attribute(d.summary, "onset_voltage_kV",
                               onset.found ? scaled(onset.voltages, to_kV) :
                                             std::vector<double>(d.rings, nan_value));
    d.w.double_attribute(d.summary, "onset_radius_mm",
                         onset.found ? onset.radius * to_mm : nan_value);
    d.w.double_attribute(d.summary, "onset_load_factor",
                         onset.found ? onset.load_factor : nan_value);
  }

  void ResultsDocument::set_summary_attribute(const std::string         &name,
                                              const std::vector<double> &values,
                                              const unsigned int         rows,
                                              const unsigned int         columns)
  {
    if (name.empty() || (rows > 0 && std::size_t(rows) * columns != values.size()))
      throw std::invalid_argument(impl->w.name() + ": summary attribute '" + name +
                                  "' needs a name and rows x columns values");
    ErrorPrintingOff quiet;
    impl->w.double_array_attribute(impl->summary, name, values, rows, columns);
  }

  void ResultsDocument::set_root_attribute(const std::string &name, const std::string &value)
  {
    ErrorPrintingOff quiet;
    impl->w.string_attribute(impl->file, name, value);
  }

  unsigned int ResultsDocument::n_steps() const { return static_cast<unsigned int>(impl->rows); }

  unsigned int ResultsDocument::n_rings() const { return impl->rings; }

  std::vector<char> ResultsDocument::image() const
  {
    ErrorPrintingOff quiet;
    return hdf5::file_image(impl->file, impl->w.name());
  }

  std::size_t ResultsDocument::image_size() const
  {
    ErrorPrintingOff quiet;
    return hdf5::file_image_size(impl->file, impl->w.name());
  }
} // namespace cdea
