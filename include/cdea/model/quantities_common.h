#pragma once
// Rows of the table of quantities that every product file has: where it
// came from (model/quantity.h).

#include <cdea/model/quantity.h>

namespace cdea::common_quantity
{
  // clang-format off
  inline constexpr Quantity parameters = text_attribute(
    "parameters", "every parameter of the command, as a parameter file").file_only();
  inline constexpr Quantity code_version = text_attribute(
    "code_version", "the version of cdea that wrote the file").file_only();
  // clang-format on
} // namespace cdea::common_quantity
