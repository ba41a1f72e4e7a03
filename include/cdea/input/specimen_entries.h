#pragma once
// The specimen of a material test's raw machine columns
// (design/material_test_data.h): four entries of subsection Calibration,
// registered as a subsection of their own (input/parameters_specimen.cc)
// and held by type in Parameters (Parameters::subsection()), so that every
// program that reads a parameter file knows them; test_specimen() parses
// and checks them where a fit needs them.

#include <cdea/base/parameter_declarations.h>

namespace cdea
{
  struct SpecimenEntries
  {
    static constexpr const char *name = "Calibration/Specimen";
    /// The entries' values by path ("Calibration/Specimen test", ...).
    ParameterValues values;

    /// Declares "Specimen test" (uniaxial), "Specimen gauge length (mm)",
    /// "Specimen width (mm)" and "Specimen thickness (mm)" (0: not given) in
    /// subsection Calibration, unbound.
    static void declare_entries(ParameterDeclarations &prm);
    /// The same, bound to values.
    void declare(ParameterDeclarations &prm);
    /// Nothing: test_specimen() checks the entries when a fit reads raw columns.
    void check() const {}
  };
} // namespace cdea
