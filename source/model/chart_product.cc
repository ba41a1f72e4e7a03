#include <cdea/material/material_chart.h>
#include <cdea/material/membrane_law.h>
#include <cdea/model/chart_product.h>
#include <cdea/model/quantities_chart.h>
#include <cdea/model/quantities_common.h>

#include <optional>

#ifndef CDEA_VERSION
#  define CDEA_VERSION "unknown"
#endif

namespace cdea
{
  namespace
  {
    void add_curve(Product &product, const StressStretchCurve &c)
    {
      using namespace chart_quantity;
      ProductGroup &g = product.group("/" + path_name(c.path));
      g.set(locking_stretch, c.locking_stretch)
        .set(stretch, c.stretch)
        .set(c.path == ChartPath::uniaxial ? uniaxial_transverse_stretch :
                                             equibiaxial_transverse_stretch,
             c.transverse_stretch)
        .set(nominal_stress, c.nominal_stress);
      if (!c.instantaneous_stress.empty())
        g.set(instantaneous_stress, c.instantaneous_stress)
          .set(instantaneous_transverse_stretch, c.instantaneous_transverse_stretch);
    }
  } // namespace

  Product chart_product(const MembraneLaw &law, const ChartSettings &settings,
                        const std::string &parameter_text, const std::string &model)
  {
    using namespace chart_quantity;
    const StressStretchCurve uniaxial = stress_stretch_curve(law, ChartPath::uniaxial, settings);
    const StressStretchCurve equibiaxial =
      stress_stretch_curve(law, ChartPath::equibiaxial, settings);
    std::optional<DmaChart> chart;
    if (law.n_internal_variables() > 0)
      chart = dma_chart(law, settings);
    Product product;
    product.root()
      .set(common_quantity::parameters, parameter_text)
      .set(common_quantity::code_version, CDEA_VERSION)
      .set(material_model, model)
      .set(voltage, 0.)
      .set(dma, chart ? "small-strain standard linear solid" : "none: the law is elastic");
    add_curve(product, uniaxial);
    add_curve(product, equibiaxial);
    if (chart)
      product.group("/dma")
        .set(relaxed_modulus, chart->moduli.relaxed)
        .set(instantaneous_modulus, chart->moduli.instantaneous)
        .set(relaxation_time, chart->moduli.relaxation_time)
        .set(frequency, chart->frequency)
        .set(storage_modulus, chart->storage)
        .set(loss_modulus, chart->loss)
        .set(loss_factor, chart->loss_factor);
    return product;
  }
} // namespace cdea
