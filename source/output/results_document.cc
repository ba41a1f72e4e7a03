#include <cdea/model/output_fields.h>
#include <cdea/model/quantities_common.h>
#include <cdea/output/file_attribute.h>
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

    constexpr hsize_t summary_chunk_rows = 128;

    using hdf5::ErrorPrintingOff;
    using hdf5::Handle;

    std::vector<int> as_integers(const std::vector<double> &values)
    {
      return std::vector<int>(values.begin(), values.end());
    }

    /// The values of a row of the table in the file's unit.
    std::vector<double> file_values(const Quantity &row, const StepSummary &summary)
    {
      return in_unit(row.summary_values(summary), row.unit);
    }
  } // namespace

  std::vector<NamedColumn> named_columns(const StepSummary              &summary,
                                         const std::vector<NamedColumn> &extra)
  {
    std::vector<NamedColumn> all;
    for (const auto &[column, value] : summary.columns)
      all.emplace_back(column->name, column->in_file_units(value));
    all.insert(all.end(), extra.begin(), extra.end());
    return all;
  }

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
    /// The standard columns, in the order of standard_summary_columns().
    std::vector<Column>           standard_columns;
    std::set<std::string>         standard_names;
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

    void add_standard_column(const Quantity &row)
    {
      const bool is_int   = row.storage == Storage::integer;
      const bool per_ring = row.shape == shape::step_ring;
      Column     column;
      column.width       = per_ring ? rings : 1;
      column.memory_type = is_int ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE;
      column.dataset     = create_summary_dataset(row.name, is_int ? H5T_STD_I32LE : H5T_IEEE_F64LE,
                                                  per_ring ? rings : 0, 0);
      w.describe(column.dataset, row.unit.name, row.description);
      standard_columns.push_back(std::move(column));
      standard_names.insert(row.name);
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

    void write_real_field(const hid_t group, const std::string &name,
                          const std::vector<double> &values, const std::string &unit,
                          const std::string &description) const
    {
      write_field(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data(), values.size(),
                  unit, description);
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

    /// The summary attribute @p a: a scalar, a whole number, a list or
    /// rows x columns.
    void write_summary_attribute(const FileAttribute &a) const
    {
      if (a.kind == FileAttribute::Kind::text)
        w.string_attribute(summary, a.name, a.text);
      else if (a.kind == FileAttribute::Kind::integer)
        w.int_attribute(summary, a.name, static_cast<int>(a.values.at(0)));
      else if (a.dims.empty())
        w.double_attribute(summary, a.name, a.values.at(0));
      else if (a.dims.size() == 2 && !a.values.empty())
        w.double_array_attribute(summary, a.name, a.values, unsigned(a.dims[0]),
                                 unsigned(a.dims[1]));
      else
        w.double_array_attribute(summary, a.name, a.values);
    }

    void write_standard_row(const StepSummary &s);
    void write_extra_row(const std::vector<NamedColumn> &columns);
    void write_step_group(const StepSummary &s, const StepFields &fields);
  };

  /// The standard /summary columns of row `rows`, from the table.
  void ResultsDocument::Impl::write_standard_row(const StepSummary &s)
  {
    const std::vector<const Quantity *> &rows_of_table = standard_summary_columns();
    for (std::size_t c = 0; c < rows_of_table.size(); ++c)
      {
        const Quantity  &row    = *rows_of_table[c];
        const Column       &column = standard_columns[c];
        const std::vector<double> values = file_values(row, s);
        extend(row.name, column, rows + 1);
        if (row.storage == Storage::integer)
          write_row(row.name, column, rows, as_integers(values).data());
        else
          write_row(row.name, column, rows, values.data());
      }
  }

  /// The further /summary columns of row `rows`: a column first seen now
  /// starts NaN-filled up to this row; a known one left out is NaN here.
  void ResultsDocument::Impl::write_extra_row(const std::vector<NamedColumn> &columns)
  {
    for (const auto &[name, value] : columns)
      if (extra_columns.count(name) == 0)
        {
          Column column;
          column.width       = 1;
          column.memory_type = H5T_NATIVE_DOUBLE;
          column.dataset     = create_summary_dataset(name, H5T_IEEE_F64LE, 0, rows);
          extra_columns.emplace(name, std::move(column));
          write_extra_description(name);
        }
    for (const auto &[name, column] : extra_columns)
      extend(name, column, rows + 1); // NaN unless written below
    for (const auto &[name, value] : columns)
      write_row(name, extra_columns.at(name), rows, &value);
  }

  /// /steps/NNNNNN of row `rows`: the step's attributes, the fields of the
  /// table, then the law's internal variables (time runs, doc/time.md).
  void ResultsDocument::Impl::write_step_group(const StepSummary &s, const StepFields &fields)
  {
    char group_name[32];
    std::snprintf(group_name, sizeof(group_name), "%06llu", static_cast<unsigned long long>(rows));
    Handle group(w.check(H5Gcreate2(steps, group_name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                         std::string("H5Gcreate2(/steps/") + group_name + ")"),
                 H5Gclose);
    for (const Quantity *row : step_attributes())
      {
        const std::vector<double> values = file_values(*row, s);
        if (row->storage == Storage::integer)
          w.int_attribute(group, row->name, static_cast<int>(values[0]));
        else if (row->shape == shape::step_ring)
          w.double_array_attribute(group, row->name, values);
        else
          w.double_attribute(group, row->name, values[0]);
      }
    for (const StepField &row : step_fields())
      if (row.in_file && row.field.storage == Storage::integer)
        {
          const std::vector<int> values = as_integers(step_field_values(row, fields));
          write_field(group, row.field.name, H5T_STD_I32LE, H5T_NATIVE_INT, values.data(),
                      values.size(), row.field.unit.name, row.field.description);
        }
      else if (row.in_file)
        write_real_field(group, row.field.name,
                         in_unit(step_field_values(row, fields), row.field.unit), row.field.unit.name,
                         row.field.description);
    for (const InternalField &f : fields.internal)
      write_real_field(group, f.name, f.values, f.unit, f.description);
  }

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
      if (attribute.first.empty() || attribute.first == common_quantity::parameters.name ||
          attribute.first == common_quantity::code_version.name ||
          attribute.first == run_attribute::n_rings.name ||
          attribute.first == run_attribute::run_status.name)
        throw std::invalid_argument(d.w.name() + ": extra root attribute name '" +
                                    attribute.first + "' is empty or reserved");

    ErrorPrintingOff quiet;
    d.file = hdf5::create_memory_file(name);
    d.w.string_attribute(d.file, common_quantity::parameters.name, parameters_text);
    d.w.string_attribute(d.file, common_quantity::code_version.name, CDEA_VERSION);
    d.w.int_attribute(d.file, run_attribute::n_rings.name, static_cast<int>(n_rings));
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

    for (const Quantity *row : standard_summary_columns())
      d.add_standard_column(*row);

    write_onset(OnsetRecord{});
  }

  ResultsDocument::~ResultsDocument()                                    = default;
  ResultsDocument::ResultsDocument(ResultsDocument &&) noexcept            = default;
  ResultsDocument &ResultsDocument::operator=(ResultsDocument &&) noexcept = default;

  void ResultsDocument::check_append(const StepSummary &summary, const StepFields &fields,
                                     const std::vector<NamedColumn> &extra_columns) const
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
    const auto        same_length = [&](const std::string &name, const std::size_t size) {
      if (size != n)
        throw std::invalid_argument(prefix + "StepFields::" + name + " has " +
                                    std::to_string(size) + " entries but R has " +
                                    std::to_string(n));
    };
    for (const StepField &row : step_fields())
      if (row.values)
        same_length(row.field.name, (fields.*row.values).size());
    same_length("ring", fields.ring.size());
    for (const InternalField &f : fields.internal)
      same_length(f.name, f.values.size());
    std::set<std::string> seen;
    for (const auto &column : named_columns(summary, extra_columns))
      {
        const std::string &name = column.first;
        if (name.empty() || name.find('/') != std::string::npos || name == "." ||
            d.standard_names.count(name) > 0 || !seen.insert(name).second)
          throw std::invalid_argument(prefix + "extra summary column name '" + name +
                                      "' is empty, contains '/', repeats or is reserved");
      }
  }

  void ResultsDocument::append(const StepSummary &summary, const StepFields &fields,
                               const std::vector<NamedColumn> &extra_columns)
  {
    check_append(summary, fields, extra_columns);
    Impl            &d = *impl;
    ErrorPrintingOff quiet;
    for (const auto &entry : summary.columns)
      d.extra_descriptions[entry.first->name] = {entry.first->unit.name, entry.first->description};
    d.write_standard_row(summary);
    d.write_extra_row(named_columns(summary, extra_columns));
    // A /summary row alone has no /steps group (time-dependent runs, doc/time.md).
    if (!fields.R.empty())
      d.write_step_group(summary, fields);
    d.rows += 1;
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
    ErrorPrintingOff quiet;
    for (const ProductEntry &a : onset_attributes(onset, impl->rings).attributes)
      impl->write_summary_attribute(file_attribute(a));
  }

  void ResultsDocument::set_summary_attribute(const std::string         &name,
                                              const std::vector<double> &values,
                                              const unsigned int         rows,
                                              const unsigned int         columns)
  {
    if (name.empty() || (rows > 0 && std::size_t(rows) * columns != values.size()))
      throw std::invalid_argument(impl->w.name() + ": summary attribute '" + name +
                                  "' needs a name and rows x columns values");
    set_summary_attribute(real_attribute(name, values, rows, columns));
  }

  void ResultsDocument::set_summary_attribute(const FileAttribute &a)
  {
    check_summary_attribute(a);
    ErrorPrintingOff quiet;
    impl->write_summary_attribute(a);
  }

  void ResultsDocument::check_summary_attribute(const FileAttribute &a) const
  {
    std::size_t size = 1;
    for (const std::size_t d : a.dims)
      size *= d;
    const bool numbers = a.kind != FileAttribute::Kind::text;
    if (a.name.empty() || (numbers && a.dims.empty() && a.values.size() != 1) ||
        (numbers && a.dims.size() == 2 && !a.values.empty() && size != a.values.size()) ||
        (a.kind == FileAttribute::Kind::integer && !a.dims.empty()))
      throw std::invalid_argument(impl->w.name() + ": summary attribute '" + a.name +
                                  "' needs a name and values of its dimensions");
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
