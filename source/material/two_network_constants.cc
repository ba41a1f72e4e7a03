// The branches' moduli and relaxation times of the viscoelastic law as law
// constants (MembraneLaw::own_constants()): what a fit frees and what the
// parameter derivatives of the spectrum differentiate. The convention,
// fixed for every user of own_constant(k): [mu_1 (Pa), tau_1 (s), mu_2,
// tau_2, ...], then, with a shear-thinning viscosity, its five constants
// (ShearThinning::own_constants()) at own_constant(2 n) .. own_constant(2 n + 4).

#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/material/two_network_gent.h>

namespace cdea
{
  namespace
  {
    /// The range the list entries allow (check_branch of
    /// two_network_gent.cc): mu_k from 1e-6 to 1e4 times mu_A, tau_k from
    /// 1e-12 to 1e12 s.
    constexpr double lowest_modulus_ratio = 1e-6, highest_modulus_ratio = 1e4;
    constexpr double shortest_time = 1e-12, longest_time = 1e12;
  } // namespace

  std::string branch_constant_entry(const unsigned int k, const bool relaxation_time)
  {
    return "Branch " + std::to_string(k) +
           (relaxation_time ? " relaxation time (s)" : " shear modulus (Pa)");
  }

  void set_branch_constants(const std::map<std::string, double> &constants,
                            const double network_a_shear_modulus,
                            std::vector<ViscousNetwork> &branches)
  {
    for (const auto &[name, value] : constants)
      {
        if (name.compare(0, 7, "Branch ") != 0)
          continue;
        for (unsigned int k = 1; k <= max_viscous_branches; ++k)
          for (const bool is_time : {false, true})
            {
              if (name != branch_constant_entry(k, is_time))
                continue;
              if (k > branches.size())
                throw InputError(name + ": the film has " + std::to_string(branches.size()) +
                                 " branch(es) (Material/Branch shear moduli (kPa))");
              const double low  = is_time ? shortest_time :
                                            lowest_modulus_ratio * network_a_shear_modulus;
              const double high = is_time ? longest_time :
                                            highest_modulus_ratio * network_a_shear_modulus;
              if (!(value >= low && value <= high))
                throw InputError(name + " must be between " + format_number(low) + " and " +
                                 format_number(high) + ", got " + format_number(value));
              (is_time ? branches[k - 1].relaxation_time : branches[k - 1].shear_modulus) = value;
            }
      }
  }

  std::vector<LawConstant> TwoNetworkGentLaw::own_constants() const
  {
    std::vector<LawConstant> list;
    for (unsigned int k = 1; k <= b.size(); ++k)
      {
        const ViscousNetwork &branch = b[k - 1];
        list.push_back({branch_constant_entry(k, false), lowest_modulus_ratio * a.shear_modulus,
                        highest_modulus_ratio * a.shear_modulus, branch.shear_modulus});
        list.push_back(
          {branch_constant_entry(k, true), shortest_time, longest_time, branch.relaxation_time});
      }
    // The shear-thinning viscosity's constants follow the branches'.
    if (thinning.enabled)
      for (const LawConstant &c : ShearThinning::own_constants())
        list.push_back(c);
    return list;
  }
} // namespace cdea
