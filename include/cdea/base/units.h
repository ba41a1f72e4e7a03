#pragma once
// The units of the table of quantities and their factors: the only place a
// unit conversion is written (tests/structure_check.py counts the literal
// factors elsewhere). The rows of the table (model/quantity.h and the
// model/quantities_*.h files) name a unit; every layer converts through
// these, from the material laws' kPa entries up to the Python module. Only
// <cmath>: every folder may use it.

#include <cmath>

namespace cdea
{
  /// A unit and its conversions. A value in the unit is the SI value times
  /// `multiply`, then divided by `divide` where that is not 1: the one
  /// operation each value has always had (x * 1e-3 and x / 1e3 are not the
  /// same double, so both forms exist where both are used). A value given in
  /// the unit (an input) is in SI times `to_si`.
  struct Unit
  {
    const char *name;
    double      multiply = 1.;
    double      divide   = 1.;
    double      to_si    = 1.;

    constexpr double from_si(const double si) const
    {
      return divide == 1. ? si * multiply : si * multiply / divide;
    }
    constexpr double in_si(const double value) const { return value * to_si; }
  };

  /// The units of every file, table and result. Lengths in mm, stresses in
  /// kPa, voltages in kV, fields in MV/m, masses in g, volumes in mm^3,
  /// energies in mJ; `_divided` units convert by a division (the design map).
  namespace units
  {
    // clang-format off
    inline constexpr Unit one{"1"};
    inline constexpr Unit none{""};                 ///< text
    inline constexpr Unit mm{"mm", 1e3, 1., 1e-3};
    inline constexpr Unit kPa{"kPa", 1e-3, 1., 1e3};
    inline constexpr Unit kPa2{"kPa^2", 1e-6, 1., 1e6}; ///< sums of squared stresses
    inline constexpr Unit kV{"kV", 1e-3, 1., 1e3};
    inline constexpr Unit MV_per_m{"MV/m", 1e-6, 1., 1e6};
    inline constexpr Unit GV_per_m{"GV/m", 1e-9, 1., 1e9};
    inline constexpr Unit g{"g", 1e3, 1., 1e-3};
    inline constexpr Unit mm3{"mm^3", 1e9, 1., 1e-9};
    inline constexpr Unit mJ{"mJ", 1e3, 1., 1e-3};
    inline constexpr Unit mm_per_s{"mm/s", 1e3, 1., 1e-3};
    inline constexpr Unit mm_per_kV{"mm/kV", 1e6};  ///< m/V: 1e3 mm/m x 1e3 V/kV
    inline constexpr Unit mm3_per_kV{"mm^3/kV", 1e12};
    inline constexpr Unit kV_divided{"kV", 1., 1e3, 1e3};
    inline constexpr Unit kPa_divided{"kPa", 1., 1e3, 1e3};
    inline constexpr Unit ml{"ml", 1e6, 1., 1e-6};
    inline constexpr Unit degree{"deg", 180., 3.14159265358979323846}; ///< from rad
    inline constexpr Unit s{"s"};
    inline constexpr Unit ms{"ms", 1e3, 1., 1e-3};
    inline constexpr Unit MB{"MB", 1., 1e6, 1e6}; ///< from bytes
    inline constexpr Unit GB{"GB", 1e-9, 1., 1e9}; ///< from bytes
    inline constexpr Unit per_kPa2{"1/kPa^2", 1e6, 1., 1e-6};
    inline constexpr Unit Hz{"Hz"};
    inline constexpr Unit percent{"%"};
    inline constexpr Unit rad{"rad"};
    inline constexpr Unit zero_one{"0/1"}; ///< a flag as a real
    inline constexpr Unit bits{"bits"};    ///< flags as the bits of a whole number
    inline constexpr Unit N_per_m{"N/m"};
    inline constexpr Unit F_per_m{"F/m"};
    inline constexpr Unit kg_per_m3{"kg/m^3"};
    inline constexpr Unit kg_per_m4{"kg/m^4"};
    inline constexpr Unit V{"V"};
    inline constexpr Unit Pa{"Pa"};
    /// The design objective as the optimizer scales it (stroke / mm.to_si,
    /// volume change / thousand_mm3.to_si): values already in the unit.
    inline constexpr Unit thousand_mm3{"1000 mm^3", 1e6, 1., 1e-6};
    inline constexpr Unit objective_mm{"mm"};
    inline constexpr Unit objective_thousand_mm3{"1000 mm^3"};
    /// The optimizer's free variables as it reports them (voltages in kV,
    /// ring edges in r/a): values already in the unit.
    inline constexpr Unit free_variables{"kV, r/a"};
    /// Fit parameters, each in its own SI unit (Pa, kg, F/m, s or 1).
    inline constexpr Unit si{"SI"};
    // clang-format on

    /// The design map's voltage grid: nV per kV and per V.
    inline constexpr double nV_per_kV = 1e12, nV_per_V = 1e9;

    /// A voltage given in kV, in V on the design map's grid of 1 nV:
    /// round(kV nV_per_kV) / nV_per_V, so that from + k step is the same
    /// double however it was reached.
    inline double kV_in_V_on_grid(const double kV)
    {
      return std::round(kV * nV_per_kV) / nV_per_V;
    }
  } // namespace units

} // namespace cdea
