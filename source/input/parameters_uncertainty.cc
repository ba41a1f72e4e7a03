// Subsection Uncertainty (input/parameters_uncertainty.h), a subsection of its
// own after the specimen entries (position 210).

#include <cdea/input/parameters.h>
#include <cdea/input/parameters_uncertainty.h>

namespace cdea
{
  namespace
  {
    const Choices<UncertaintyMode> mode_choices{{"none", UncertaintyMode::none},
                                                {"linear", UncertaintyMode::linear},
                                                {"monte carlo", UncertaintyMode::monte_carlo}};
  } // namespace

  std::string to_string(const UncertaintyMode mode)
  {
    return mode_choices.name(mode);
  }

  void UncertaintyEntries::declare(ParameterDeclarations &prm)
  {
    prm.enter_subsection(name);
    prm.add("Mode", "none", mode, mode_choices,
            "How cdea run carries the uncertainty of the constants below into its "
            "answers: none (every result as without this subsection); linear (one "
            "standard deviation beside the final displacement, stroke, volume change, "
            "onset voltage and the voltages of limit points, sigma^2 = g^T C g with their "
            "exact gradients g); monte carlo "
            "(Samples runs with the constants drawn from their normal distribution: mean, "
            "standard deviation and the 5, 50 and 95 % percentiles of the same outputs).");
    prm.add("Covariance file", "", covariance_file,
            "A fit's <Base name>_fit.h5: its free parameters are the uncertain constants, "
            "its covariance theirs. Give this or Standard deviations, not both.");
    prm.add("Standard deviations", "", standard_deviations_text,
            "The uncertain constants and one standard deviation of each, separated by ',': "
            "NAME: VALUE, the value absolute in the entry's unit (shear modulus in kPa, "
            "mass in g, permittivity in F/m) or relative with '%' (shear modulus: 3%, "
            "Jlim: 20). NAME is any of shear modulus, Jlim, permittivity, mass, "
            "pre-stretch and the law's own constants (their entries of subsection "
            "Material).");
    prm.add("Correlations", "", correlations_text,
            "Correlation coefficients between pairs of the constants of Standard "
            "deviations, separated by ';': NAME, NAME: VALUE (shear modulus, Jlim: 0.9). "
            "Pairs not given are uncorrelated; the matrix must be positive semidefinite.");
    prm.add("Samples", "200", samples,
            "Runs of Mode = monte carlo (each a full run of the scene with sampled "
            "constants).",
            between(2, 1000000));
    prm.add("Seed", "1", seed,
            "Seed of the random samples of Mode = monte carlo: the same seed draws the "
            "same constants.",
            between(0, 4294967295.));
    prm.leave_subsection();
  }

  CDEA_REGISTER_OWN_SUBSECTION(uncertainty, UncertaintyEntries, 210)
} // namespace cdea
