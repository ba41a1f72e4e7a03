#pragma once
// A row of the table of quantities: a value that a command prints, writes or
// returns (or a parameter a fit fits), with its name, its unit (base/units.h:
// the units and their factors, the table's first part), its description, its shape, how it is
// stored and where (an attribute or a dataset), and its key in the Python
// results. The rows themselves stand in model/output_fields.h (a run) and
// model/quantities_*.h (the other studies); a study sets them on its Product
// (model/product.h) with SI values, and the HDF5 writer, the Python converter
// and the table printer convert them by the row. No HDF5, no deal.II: every
// study includes it.

#include <cdea/base/units.h>

#include <vector>

namespace cdea
{
  /// How a value is stored: a real, a whole number (32-bit in files), a
  /// text, or a complex number (two real datasets in files, the rows
  /// Quantity::real_part and Quantity::imaginary_part).
  enum class Storage : unsigned char
  {
    real,
    integer,
    text,
    complex
  };

  /// Where a value goes in its group.
  enum class Place : unsigned char
  {
    attribute,
    dataset
  };

  /// The dimensions of a value, by name, outermost first (none: a scalar).
  struct Shape
  {
    const char *dims[3] = {nullptr, nullptr, nullptr};

    constexpr unsigned int rank() const
    {
      return dims[0] == nullptr ? 0 : dims[1] == nullptr ? 1 : dims[2] == nullptr ? 2 : 3;
    }
    constexpr bool operator==(const Shape &o) const
    {
      return same(dims[0], o.dims[0]) && same(dims[1], o.dims[1]) && same(dims[2], o.dims[2]);
    }
    constexpr bool operator!=(const Shape &o) const { return !(*this == o); }

  private:
    static constexpr bool same(const char *a, const char *b)
    {
      if (a == nullptr || b == nullptr)
        return a == b;
      while (*a != '\0' && *a == *b)
        ++a, ++b;
      return *a == *b;
    }
  };

  /// The shapes in use.
  namespace shape
  {
    inline constexpr Shape scalar{};
    inline constexpr Shape ring{{"ring"}};             ///< one per electrode ring
    inline constexpr Shape edge{{"edge"}};             ///< ring edges (rings + 1)
    inline constexpr Shape point{{"point"}};           ///< along the meridian, or data points
    inline constexpr Shape point_ring{{"point", "ring"}};
    inline constexpr Shape stretch{{"stretch"}};       ///< along a stress-stretch curve
    inline constexpr Shape frequency{{"frequency"}};
    inline constexpr Shape frequency_ring{{"frequency", "ring"}};
    inline constexpr Shape mode{{"mode"}};
    inline constexpr Shape sample{{"sample"}};
    inline constexpr Shape mode_sample{{"mode", "sample"}};
    inline constexpr Shape layout{{"layout"}};         ///< rows of a design map
    inline constexpr Shape outer_voltage{{"outer voltage"}};
    inline constexpr Shape layout_outer{{"layout", "outer voltage"}};
    inline constexpr Shape layout_edge2{{"layout", "inner edge"}};
    inline constexpr Shape layout_outer_edge2{{"layout", "outer voltage", "inner edge"}};
    inline constexpr Shape evaluation{{"evaluation"}};
    inline constexpr Shape evaluation_free{{"evaluation", "free variable"}};
    inline constexpr Shape start{{"start"}};
    inline constexpr Shape start_ring{{"start", "ring"}};
    inline constexpr Shape start_edge{{"start", "edge"}};
    inline constexpr Shape parameter{{"parameter"}};
    inline constexpr Shape parameter2{{"parameter", "parameter"}};
    inline constexpr Shape limit_ring{{"limit point", "ring"}};
    inline constexpr Shape limit{{"limit point"}};
  } // namespace shape

  struct StepSummary;

  /// One row of the table. Rows are constexpr; a study sets a row's value
  /// on its product (Product::Group::set), and every reader takes the name,
  /// unit, description and conversion from here.
  struct Quantity
  {
    const char *name;        ///< dataset or attribute name (with the unit where it is not 1)
    Unit        unit;        ///< the dataset's `unit` attribute and the conversion from SI
    const char *description; ///< the dataset's `description` attribute
    Shape       shape   = {};
    Storage     storage = Storage::real;
    Place       place   = Place::dataset;
    /// The key of the value in the Python results; null: not returned there.
    const char *python = name;
    /// A complex row's real and imaginary parts as files store them.
    const Quantity *real_part = nullptr, *imaginary_part = nullptr;
    /// The numpy type the Python result casts an array to (null: its own).
    const char *python_dtype = nullptr;
    /// A run's quantity (model/output_fields.h): the runs that have it
    /// (RunKind bits; 0 for the other studies), and for a standard /summary
    /// column its SI values from a StepSummary (one per ring if per ring).
    unsigned int runs = 0;
    std::vector<double> (*summary_values)(const StepSummary &) = nullptr;

    /// @p si_value in the unit.
    constexpr double in_file_units(const double si_value) const { return unit.from_si(si_value); }

    // Variations of a row, for the tables' definitions.
    constexpr Quantity with(const Storage s) const { return copy([&](Quantity &q) { q.storage = s; }); }
    constexpr Quantity as_attribute() const { return copy([](Quantity &q) { q.place = Place::attribute; }); }
    constexpr Quantity in_python(const char *key) const { return copy([&](Quantity &q) { q.python = key; }); }
    constexpr Quantity file_only() const { return in_python(nullptr); }
    constexpr Quantity python_as(const char *dtype) const
    {
      return copy([&](Quantity &q) { q.python_dtype = dtype; });
    }
    constexpr Quantity parts(const Quantity &re, const Quantity &im) const
    {
      return copy([&](Quantity &q) {
        q.storage        = Storage::complex;
        q.real_part      = &re;
        q.imaginary_part = &im;
      });
    }

  private:
    template <typename Change>
    constexpr Quantity copy(const Change &change) const
    {
      Quantity q = *this;
      change(q);
      return q;
    }
  };

  /// A row for a dataset (the default) and for an attribute.
  constexpr Quantity dataset(const char *name, const Unit &unit, const char *description,
                             const Shape &shape = {})
  {
    return Quantity{name, unit, description, shape};
  }
  constexpr Quantity attribute(const char *name, const Unit &unit, const char *description,
                               const Shape &shape = {})
  {
    return Quantity{name, unit, description, shape, Storage::real, Place::attribute};
  }
  /// A text attribute (no unit).
  constexpr Quantity text_attribute(const char *name, const char *description)
  {
    return Quantity{name, units::none, description, {}, Storage::text, Place::attribute};
  }
  /// A whole-number attribute.
  constexpr Quantity integer_attribute(const char *name, const char *description)
  {
    return Quantity{name, units::one, description, {}, Storage::integer, Place::attribute};
  }
} // namespace cdea
