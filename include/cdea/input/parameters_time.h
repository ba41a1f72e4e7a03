#pragma once
// Parameters of time-dependent runs (doc/time.md): the material model's
// viscous network (entries of subsection Material) and subsection Time. One
// struct each with declare/parse, as in parameters.h; choices are enums. Their
// checks are validate_time() (validation.h), the stepper's settings
// time_settings() (solver_settings.h).

#include <cdea/model/waveform.h>    // WaveformKind
#include <cdea/numerics/esdirk.h>   // TimeMethod, TimeStepControl

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace cdea
{
  /// Material/Model.
  enum class MaterialModel
  {
    elastic,
    viscoelastic
  };

  namespace parameters
  {
    /// Material/Model and network B (entries of subsection Material).
    struct ViscousMaterial
    {
      MaterialModel model;
      double        network_b_shear_modulus_kPa;
      double        network_b_jlim;
      double        relaxation_time_s;
      static void   declare(dealii::ParameterHandler &prm);
      void          parse(dealii::ParameterHandler &prm);
    };

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

  std::string to_string(MaterialModel choice);
  std::string to_string(WaveformKind choice);
  std::string to_string(TimeMethod choice);
  std::string to_string(TimeStepControl choice);
} // namespace cdea
