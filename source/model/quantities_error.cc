#include <cdea/model/quantities_error.h>

namespace cdea
{
  ProductGroup error_estimate_attributes(const OutputErrors &errors, const unsigned int n_rings)
  {
    using namespace summary_attribute;
    std::vector<double> onset(n_rings, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t k = 0; k < errors.onset_voltages.size() && k < n_rings; ++k)
      onset[k] = errors.onset_voltages[k].total();
    ProductGroup g("/summary");
    g.set(displacement_error, errors.displacement.total())
      .set(stroke_error, errors.stroke.total())
      .set(volume_change_error, errors.volume_change.total())
      .set(s2_min_error, errors.s2_min.total())
      .set(onset_voltage_error, onset)
      .set(error_estimate_method, errors.method);
    return g;
  }
} // namespace cdea
