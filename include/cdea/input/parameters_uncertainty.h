#pragma once
// Subsection Uncertainty: which constants of the scene are uncertain and how
// their uncertainty is carried into the answers of `cdea run` (doc/uncertainty.md).
// The constants come either from a fit's <Base name>_fit.h5 (its free
// parameters and covariance) or as standard deviations given here, with
// correlations between pairs. Registered as a subsection of its own
// (input/parameters_uncertainty.cc) and held by type in Parameters
// (Parameters::subsection()); uncertain_constants() (analysis/uncertainty.h)
// parses and checks the text entries against the scene's law.

#include <cdea/base/parameter_declarations.h>

#include <string>

namespace cdea
{
  /// How a run carries the uncertainty of its constants.
  enum class UncertaintyMode
  {
    none,       ///< not at all: every result as without the subsection
    linear,     ///< sigma_J^2 = g^T C g with the exact gradients g of each output
    monte_carlo ///< seeded samples of the constants, each a full run
  };

  struct UncertaintyEntries
  {
    static constexpr const char *name = "Uncertainty";

    UncertaintyMode mode = UncertaintyMode::none;
    std::string     covariance_file;          ///< a fit's <Base name>_fit.h5
    std::string     standard_deviations_text; ///< "shear modulus: 3%, Jlim: 20"
    std::string     correlations_text;        ///< "shear modulus, Jlim: 0.9"
    unsigned int    samples = 200;
    unsigned int    seed    = 1;

    /// Declares Mode, Covariance file, Standard deviations, Correlations,
    /// Samples and Seed, bound to the members.
    void declare(ParameterDeclarations &prm);
    /// Nothing: the text entries need the scene's law (uncertain_constants()).
    void check() const {}
  };

  /// "none", "linear", "monte carlo".
  std::string to_string(UncertaintyMode mode);
} // namespace cdea
