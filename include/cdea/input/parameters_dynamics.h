#pragma once
// Parameters of the small-signal frequency response (subsection Response,
// `cdea response`, doc/dynamics.md), with declare/parse as in parameters.h;
// checked by validate_dynamics() (validation.h). The periodic steady states
// (subsection Steady state) and the frequency sweep (subsection Frequency
// sweep) of `cdea frequency-sweep`, checked by that command
// (analysis/frequency_sweep.h, frequency_sweep_settings()).

#include <string>
#include <vector>

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

    struct SteadyState
    {
      double       tolerance;
      unsigned int max_newton_iterations;
      unsigned int krylov_dimension;
      unsigned int start_periods;
      double       low_fraction;
      static void  declare(dealii::ParameterHandler &prm);
      void         parse(dealii::ParameterHandler &prm);
    };

    struct FrequencySweep
    {
      double       lowest_frequency_Hz;
      double       highest_frequency_Hz;
      int          frequencies; ///< as given (checked by the command)
      bool         log_spacing;
      std::string  frequency_list; ///< "Frequencies (Hz)" as given; empty: the range
      double       usable_factor;
      bool         confirm_long; ///< more than 1000 frequencies allowed
      static void  declare(dealii::ParameterHandler &prm);
      void         parse(dealii::ParameterHandler &prm);
    };
  } // namespace parameters
} // namespace cdea
