#include <cdea/output/hdf5_support.h>
#include <cdea/output/results_file.h>
#include <cdea/output/results_layout.h>

#include <hdf5.h>

#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <system_error>

#ifndef CDEA_VERSION
#  define CDEA_VERSION "unknown"
#endif

namespace cdea
{
  namespace
  {
    constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();

    constexpr hsize_t summary_chunk_rows = 128;

    using hdf5::ErrorPrintingOff;
    using hdf5::error_text;

    using hdf5::Handle;
  } // namespace

  struct ResultsFile::Impl
  {
    std::string  file_path;
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
      standard_columns.clear();
      extra_columns.clear();
      steps.reset();
      summary.reset();
      file.reset();
    }

    [[noreturn]] void fail(const std::string &what) const
    {
      throw std::runtime_error("ResultsFile '" + file_path + "': " + what + " failed: " +
                               error_text());
    }
    hid_t check(const hid_t id, const std::string &what) const
    {
      if (id < 0)
        fail(what);
      return id;
    }
    void check_status(const herr_t status, const std::string &what) const
    {
      if (status < 0)
        fail(what);
    }

    void flush() const { check_status(H5Fflush(file, H5F_SCOPE_LOCAL), "H5Fflush"); }

    void delete_attribute_if_present(const hid_t object, const std::string &name) const
    {
      const htri_t exists = H5Aexists(object, name.c_str());
      check_status(exists, "H5Aexists(" + name + ")");
      if (exists > 0)
        check_status(H5Adelete(object, name.c_str()), "H5Adelete(" + name + ")");
    }

    void write_attribute(const hid_t        object,
                         const std::string &name,
                         const hid_t        file_type,
                         const hid_t        memory_type,
                         const hid_t        space,
                         const void        *data) const
    {
      delete_attribute_if_present(object, name);
      Handle attribute(check(H5Acreate2(object, name.c_str(), file_type, space,
                                        H5P_DEFAULT, H5P_DEFAULT),
                             "H5Acreate2(" + name + ")"),
                       H5Aclose);
      check_status(H5Awrite(attribute, memory_type, data), "H5Awrite(" + name + ")");
    }

    void write_string_attribute(const hid_t        object,
                                const std::string &name,
                                const std::string &value) const
    {
      // Variable-length UTF-8: h5py reads it as str, no 64 kB header limit.
      Handle type(check(H5Tcopy(H5T_C_S1), "H5Tcopy"), H5Tclose);
      check_status(H5Tset_size(type, H5T_VARIABLE), "H5Tset_size");
      check_status(H5Tset_cset(type, H5T_CSET_UTF8), "H5Tset_cset");
      Handle      space(check(H5Screate(H5S_SCALAR), "H5Screate"), H5Sclose);
      const char *pointer = value.c_str();
      write_attribute(object, name, type, type, space, &pointer);
    }

    void write_int_attribute(const hid_t object, const std::string &name, const int value) const
    {
      Handle space(check(H5Screate(H5S_SCALAR), "H5Screate"), H5Sclose);
      write_attribute(object, name, H5T_STD_I32LE, H5T_NATIVE_INT, space, &value);
    }

    void write_double_attribute(const hid_t        object,
                                const std::string &name,
                                const double       value) const
    {
      Handle space(check(H5Screate(H5S_SCALAR), "H5Screate"), H5Sclose);
      write_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space, &value);
    }

    void write_double_array_attribute(const hid_t                object,
                                      const std::string         &name,
                                      const std::vector<double> &values) const
    {
      Handle space;
      if (values.empty())
        space = Handle(check(H5Screate(H5S_NULL), "H5Screate"), H5Sclose);
      else
        {
          const hsize_t dims[1] = {values.size()};
          space = Handle(check(H5Screate_simple(1, dims, nullptr), "H5Screate_simple"), H5Sclose);
        }
      // HDF5 wants a buffer even for an empty (null) dataspace.
      static const double nothing = 0.;
      write_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space,
                      values.empty() ? &nothing : values.data());
    }

    void describe(const hid_t object, const std::string &unit, const std::string &description) const
    {
      write_string_attribute(object, "unit", unit);
      write_string_attribute(object, "description", description);
    }

    /// An empty chunked, unlimited /summary dataset with @p width columns
    /// (1D if width == 0), NaN fill for doubles.
    Handle create_summary_dataset(const std::string &name,
                                  const hid_t        file_type,
                                  const unsigned int width,
                                  const hsize_t      initial_rows) const
    {
      const int     rank       = width == 0 ? 1 : 2;
      const hsize_t dims[2]    = {initial_rows, width};
      const hsize_t maxdims[2] = {H5S_UNLIMITED, width};
      const hsize_t chunk[2]   = {summary_chunk_rows, width};
      Handle space(check(H5Screate_simple(rank, dims, maxdims), "H5Screate_simple"), H5Sclose);
      Handle dcpl(check(H5Pcreate(H5P_DATASET_CREATE), "H5Pcreate"), H5Pclose);
      check_status(H5Pset_chunk(dcpl, rank, chunk), "H5Pset_chunk");
      if (H5Tequal(file_type, H5T_IEEE_F64LE) > 0)
        check_status(H5Pset_fill_value(dcpl, H5T_NATIVE_DOUBLE, &nan_value),
                     "H5Pset_fill_value");
      else
        {
          const int zero = 0;
          check_status(H5Pset_fill_value(dcpl, H5T_NATIVE_INT, &zero), "H5Pset_fill_value");
        }
      check_status(H5Pset_fill_time(dcpl, H5D_FILL_TIME_ALLOC), "H5Pset_fill_time");
      return Handle(check(H5Dcreate2(summary, name.c_str(), file_type, space, H5P_DEFAULT,
                                     dcpl, H5P_DEFAULT),
                          "H5Dcreate2(/summary/" + name + ")"),
                    H5Dclose);
    }

    void add_standard_column(const std::string &name,
                             const bool         is_int,
                             const bool         per_ring,
                             const std::string &unit,
                             const std::string &description)
    {
      Column column;
      column.width       = per_ring ? rings : 1;
      column.memory_type = is_int ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE;
      column.dataset     = create_summary_dataset(name, is_int ? H5T_STD_I32LE : H5T_IEEE_F64LE,
                                                  per_ring ? rings : 0, 0);
      describe(column.dataset, unit, description);
      standard_columns.emplace(name, std::move(column));
    }

    /// Grows @p column to rows_after rows (new rows get the fill value).
    void extend(const std::string &name, const Column &column, const hsize_t rows_after) const
    {
      const hsize_t dims[2] = {rows_after, column.width};
      check_status(H5Dset_extent(column.dataset, dims), "H5Dset_extent(/summary/" + name + ")");
    }

    /// Writes row @p row (already allocated) of @p column.
    void write_row(const std::string &name,
                   const Column      &column,
                   const hsize_t      row,
                   const void        *data) const
    {
      Handle file_space(check(H5Dget_space(column.dataset), "H5Dget_space"), H5Sclose);
      const hsize_t start[2] = {row, 0};
      const hsize_t count[2] = {1, column.width};
      check_status(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr),
                   "H5Sselect_hyperslab");
      const hsize_t memory_dims[1] = {column.width};
      Handle memory_space(check(H5Screate_simple(1, memory_dims, nullptr), "H5Screate_simple"),
                          H5Sclose);
      check_status(H5Dwrite(column.dataset, column.memory_type, memory_space, file_space,
                            H5P_DEFAULT, data),
                   "H5Dwrite(/summary/" + name + ")");
    }

    void write_field(const hid_t                group,
                     const std::string         &name,
                     const hid_t                file_type,
                     const hid_t                memory_type,
                     const void                *data,
                     const std::size_t          n,
                     const std::string         &unit,
                     const std::string         &description) const
    {
      const hsize_t dims[1] = {n};
      Handle space(check(H5Screate_simple(1, dims, nullptr), "H5Screate_simple"), H5Sclose);
      Handle dataset(check(H5Dcreate2(group, name.c_str(), file_type, space, H5P_DEFAULT,
                                      H5P_DEFAULT, H5P_DEFAULT),
                           "H5Dcreate2(" + name + ")"),
                     H5Dclose);
      if (n > 0)
        check_status(H5Dwrite(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                     "H5Dwrite(" + name + ")");
      describe(dataset, unit, description);
    }

    void write_scaled_field(const hid_t                group,
                            const std::string         &name,
                            const std::vector<double> &values,
                            const double               factor,
                            const std::string         &unit,
                            const std::string         &description) const
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
        describe(it->second.dataset, d->second.first, d->second.second);
      else
        describe(it->second.dataset, "",
                 "extra summary column (the unit is part of the name); NaN where not written");
    }
  };

  ResultsFile::ResultsFile(const std::string &path,
                           const std::string &parameters_text,
                           const unsigned int n_rings,
                           const std::vector<std::pair<std::string, std::string>>
                             &extra_root_attributes)
    : impl(std::make_unique<Impl>())
  {
    impl->file_path = path;
    impl->rings     = n_rings;
    if (n_rings == 0)
      throw std::invalid_argument("ResultsFile '" + path + "': n_rings must be at least 1");
    for (const auto &attribute : extra_root_attributes)
      if (attribute.first.empty() || attribute.first == "parameters" ||
          attribute.first == "code_version" || attribute.first == "n_rings")
        throw std::invalid_argument("ResultsFile '" + path + "': extra root attribute name '" +
                                    attribute.first + "' is empty or reserved");

    // Parent directory.
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty())
      {
        std::error_code error;
        std::filesystem::create_directories(parent, error);
        if (error)
          throw std::runtime_error("cannot create results file '" + path +
                                   "': cannot create directory '" + parent.string() +
                                   "': " + error.message());
      }

    ErrorPrintingOff quiet;
    // No file lock: HDF5 1.10 would otherwise hold an exclusive lock for the
    // whole run, and h5dump/h5py/plot_run.py could not read the results of a
    // running job. Between two appends the flushed file is consistent.
    Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
#if H5_VERSION_GE(1, 10, 7)
    if (fapl.get() >= 0)
      H5Pset_file_locking(fapl, false, true);
#endif
    const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT,
                                 fapl.get() >= 0 ? fapl.get() : H5P_DEFAULT);
    if (file < 0)
      throw std::runtime_error("cannot create results file '" + path +
                               "': " + error_text());
    impl->file = Handle(file, H5Fclose);

    impl->write_string_attribute(file, "parameters", parameters_text);
    impl->write_string_attribute(file, "code_version", CDEA_VERSION);
    impl->write_int_attribute(file, "n_rings", static_cast<int>(n_rings));
    for (const auto &attribute : extra_root_attributes)
      impl->write_string_attribute(file, attribute.first, attribute.second);

    impl->summary = Handle(impl->check(H5Gcreate2(file, "summary", H5P_DEFAULT, H5P_DEFAULT,
                                                  H5P_DEFAULT),
                                       "H5Gcreate2(/summary)"),
                           H5Gclose);
    impl->steps   = Handle(impl->check(H5Gcreate2(file, "steps", H5P_DEFAULT, H5P_DEFAULT,
                                                  H5P_DEFAULT),
                                       "H5Gcreate2(/steps)"),
                           H5Gclose);

    for (const StandardColumn &c : standard_summary_columns())
      impl->add_standard_column(c.name, c.integer, c.per_ring, c.unit, c.description);

    write_onset(OnsetRecord{});
  }

  ResultsFile::~ResultsFile()
  {
    if (impl)
      {
        ErrorPrintingOff quiet;
        impl.reset();
      }
  }

  ResultsFile::ResultsFile(ResultsFile &&) noexcept            = default;
  ResultsFile &ResultsFile::operator=(ResultsFile &&) noexcept = default;

  void ResultsFile::append(const StepSummary &summary,
                           const StepFields  &fields,
                           const std::vector<std::pair<std::string, double>> &extra_columns)
  {
    if (!impl)
      throw std::logic_error("ResultsFile: append() on a moved-from object");
    Impl             &d      = *impl;
    const std::string prefix = "ResultsFile '" + d.file_path + "': ";

    // Validate everything before touching the file.
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
      {"r", fields.r.size()},           {"z", fields.z.size()},
      {"theta", fields.theta.size()},   {"lambda1", fields.lambda1.size()},
      {"lambda2", fields.lambda2.size()}, {"s1", fields.s1.size()},
      {"s2", fields.s2.size()},         {"E", fields.E.size()},
      {"Phi", fields.Phi.size()},       {"ring", fields.ring.size()}};
    for (const auto &s : sizes)
      if (s.second != n)
        throw std::invalid_argument(prefix + "StepFields::" + s.first + " has " +
                                    std::to_string(s.second) + " entries but R has " +
                                    std::to_string(n));
    {
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

    ErrorPrintingOff quiet;
    const hsize_t    row = d.rows;

    // /summary row.
    const std::vector<std::vector<double>> values = standard_summary_values(summary);
    for (std::size_t c = 0; c < values.size(); ++c)
      {
        const StandardColumn   &layout = standard_summary_columns()[c];
        const Impl::Column     &column = d.standard_columns.at(layout.name);
        const std::vector<int>  integers(values[c].begin(), values[c].end());
        d.extend(layout.name, column, row + 1);
        d.write_row(layout.name, column, row,
                    layout.integer ? static_cast<const void *>(integers.data()) : values[c].data());
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

    // /steps/NNNNNN
    char group_name[32];
    std::snprintf(group_name, sizeof(group_name), "%06llu", static_cast<unsigned long long>(row));
    Handle group(d.check(H5Gcreate2(d.steps, group_name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                         std::string("H5Gcreate2(/steps/") + group_name + ")"),
                 H5Gclose);
    const std::vector<double> voltage_kV = scaled(summary.voltages, file_units::kV);
    d.write_int_attribute(group, "stage", static_cast<int>(summary.stage));
    d.write_double_attribute(group, "load_factor", summary.load_factor);
    d.write_double_array_attribute(group, "voltage_kV", voltage_kV);
    d.write_double_attribute(group, "displacement_mm", summary.displacement * file_units::mm);
    for (const FieldDataset &f : field_datasets())
      if (f.values)
        d.write_scaled_field(group, f.name, fields.*f.values, f.factor, f.unit, f.description);
      else
        d.write_field(group, f.name, H5T_STD_I32LE, H5T_NATIVE_INT, fields.ring.data(),
                      fields.ring.size(), f.unit, f.description);
    group.reset();

    d.rows = row + 1;
    d.flush();
  }

  void ResultsFile::describe_column(const std::string &name,
                                    const std::string &unit,
                                    const std::string &description)
  {
    if (!impl)
      throw std::logic_error("ResultsFile: describe_column() on a moved-from object");
    ErrorPrintingOff quiet;
    impl->extra_descriptions[name] = {unit, description};
    if (impl->extra_columns.count(name) > 0)
      {
        impl->write_extra_description(name);
        impl->flush();
      }
  }

  void ResultsFile::write_onset(const OnsetRecord &onset)
  {
    if (!impl)
      throw std::logic_error("ResultsFile: write_onset() on a moved-from object");
    Impl &d = *impl;
    if (onset.found && onset.voltages.size() != d.rings)
      throw std::invalid_argument("ResultsFile '" + d.file_path + "': OnsetRecord::voltages has " +
                                  std::to_string(onset.voltages.size()) + " entries, expected " +
                                  std::to_string(d.rings));
    ErrorPrintingOff quiet;
    for (const SummaryAttribute &a : onset_attributes(onset, d.rings))
      if (a.integer)
        d.write_int_attribute(d.summary, a.name, static_cast<int>(a.values[0]));
      else if (a.scalar)
        d.write_double_attribute(d.summary, a.name, a.values[0]);
      else
        d.write_double_array_attribute(d.summary, a.name, a.values);
    d.flush();
  }

  void ResultsFile::set_summary_attribute(const std::string         &name,
                                          const std::vector<double> &values)
  {
    if (!impl)
      throw std::logic_error("ResultsFile: set_summary_attribute() on a moved-from object");
    if (name.empty())
      throw std::invalid_argument("ResultsFile '" + impl->file_path +
                                  "': empty summary attribute name");
    ErrorPrintingOff quiet;
    impl->write_double_array_attribute(impl->summary, name, values);
    impl->flush();
  }

  void ResultsFile::set_summary_attribute(const std::string         &name,
                                          const std::vector<double> &values,
                                          const unsigned int         rows,
                                          const unsigned int         columns)
  {
    if (!impl)
      throw std::logic_error("ResultsFile: set_summary_attribute() on a moved-from object");
    if (name.empty() || std::size_t(rows) * columns != values.size())
      throw std::invalid_argument("ResultsFile '" + impl->file_path + "': summary attribute '" +
                                  name + "' needs rows x columns values");
    ErrorPrintingOff quiet;
    if (rows == 0)
      impl->write_double_array_attribute(impl->summary, name, values);
    else
      {
        const hsize_t dims[2] = {rows, columns};
        Handle        space(impl->check(H5Screate_simple(2, dims, nullptr), "H5Screate_simple"),
                            H5Sclose);
        impl->write_attribute(impl->summary, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space,
                              values.data());
      }
    impl->flush();
  }

  unsigned int ResultsFile::n_steps() const
  {
    return impl ? static_cast<unsigned int>(impl->rows) : 0;
  }

  unsigned int ResultsFile::n_rings() const { return impl ? impl->rings : 0; }

  const std::string &ResultsFile::path() const
  {
    static const std::string empty;
    return impl ? impl->file_path : empty;
  }
} // namespace cdea
