#include <cdea/material/membrane_law.h>

namespace cdea
{
  bool MembraneLaw::linearize(const LawInput &input, const double *stored,
                              InternalLinearization &out) const
  {
    std::vector<double> scratch(stored ? stored : nullptr,
                                stored ? stored + n_internal_variables() : nullptr);
    const InternalStep step{stored, scratch.data(), 0., TimeScheme::backward_euler};
    LawResponse        response;
    if (!evaluate(input, step, law_stress | law_tangent, response))
      return false;
    out.instantaneous = response.tangent;
    out.n             = 0;
    out.stress_y.clear();
    out.rate_y.clear();
    out.rate_l.clear();
    return true;
  }

  bool MembraneLaw::evolving_parameter_derivative(const LawInput &input, const double *stored,
                                                  const LawParameter parameter,
                                                  NominalStress &d_stress, double *d_rate) const
  {
    (void)d_rate;
    if (n_evolving() > 0)
      return false;
    std::vector<double> scratch(stored ? stored : nullptr,
                                stored ? stored + n_internal_variables() : nullptr);
    const InternalStep step{stored, scratch.data(), 0., TimeScheme::backward_euler};
    double             d_energy = 0.;
    return parameter_derivative(input, step, parameter, d_energy, d_stress);
  }
} // namespace cdea
