#pragma once
// Parameters of the small-signal frequency response (subsection Response,
// `cdea response`, doc/dynamics.md), with declare/parse as in parameters.h;
// checked by validate_dynamics() (validation.h).

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace cdea
{
  namespace parameters
  {
    struct Response
    {
      double       lowest_frequency_Hz;
      double       highest_frequency_Hz;
      unsigned int frequencies;
      unsigned int modes;
      double       membrane_density;
      static void  declare(dealii::ParameterHandler &prm);
      void         parse(dealii::ParameterHandler &prm);
    };
  } // namespace parameters
} // namespace cdea
