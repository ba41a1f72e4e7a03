#pragma once
// Parameters of time-dependent runs (doc/time.md): subsection Time, one
// struct with declare/parse as in parameters.h; choices are enums. Its checks
// are validate_time() (validation.h), the stepper's settings time_settings()
// (solver_settings.h). The law with internal variables is Material/Model
// (parameters_plugins.h).

#include <cdea/model/waveform.h>    // WaveformKind
#include <cdea/numerics/esdirk.h>   // TimeMethod, TimeStepControl

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace cdea
{
  namespace parameters
  {
    struct Time
    {
      bool         enabled;
      WaveformKind waveform;
      double       ramp_time_s;
      double       hold_time_s;
      double       frequency_Hz;
      unsigned int cycles;
      double       rise_time_s;
      std::string  table_file;
      double       time_step_s;
      double       min_time_step_s;
      TimeMethod      scheme;
      TimeStepControl step_control;
      double          relative_tolerance;
      double          absolute_tolerance_mm;
      double          internal_tolerance;
      bool         inertia;
      bool         water_inertia;
      std::string  rest_time_text; ///< "relaxed" or seconds
      double       fields_interval_s;
      static void  declare(dealii::ParameterHandler &prm);
      void         parse(dealii::ParameterHandler &prm);

      /// Rest time before voltage (s): infinity for 'relaxed'; throws
      /// InputError naming the entry unless it is 'relaxed' or a time >= 0.
      double rest_time() const;
    };
  } // namespace parameters

  std::string to_string(WaveformKind choice);
  std::string to_string(TimeMethod choice);
  std::string to_string(TimeStepControl choice);
} // namespace cdea
