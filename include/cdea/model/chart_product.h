#pragma once
// The product of `cdea chart` (model/quantities_chart.h): the material
// charts of a law (material/material_chart.h) at zero voltage, both
// stress-stretch curves and, for a law with internal variables, the DMA chart.

#include <cdea/model/product.h>

#include <string>

namespace cdea
{
  class MembraneLaw;
  struct ChartSettings;

  /// The charts of @p law as a product, with the parameters @p parameter_text
  /// and the name @p model of Material/Model. Throws std::runtime_error as
  /// stress_stretch_curve() and dma_chart() do.
  Product chart_product(const MembraneLaw &law, const ChartSettings &settings,
                        const std::string &parameter_text, const std::string &model);
} // namespace cdea
