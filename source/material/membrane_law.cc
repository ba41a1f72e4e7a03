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
} // namespace cdea
