#pragma once
// Parameters of time-dependent runs (doc/time.md): the material model's
// viscous network (entries of subsection Material) and subsection Time. One
// struct each with declare/parse, as in parameters.h; choices are enums.

#include <cdea/material/membrane_law.h>
#include <cdea/solver/time_stepper.h>
#include <cdea/model/waveform.h>

#include <memory>
#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace cdea
{
  struct Parameters;
  struct Scene;

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
      TimeScheme   scheme;
      bool         inertia;
      bool         water_inertia;
      std::string  rest_time_text; ///< "relaxed" or seconds
      double       fields_interval_s;
      static void  declare(dealii::ParameterHandler &prm);
      void         parse(dealii::ParameterHandler &prm);
    };
  } // namespace parameters

  std::string to_string(MaterialModel choice);
  std::string to_string(WaveformKind choice);
  std::string to_string(TimeScheme choice);

  /// Check the Material/Model and Time entries (reads the table file);
  /// throws InputError naming the parameter.
  void validate_time(const Parameters &p);

  /// The material law of the FE model that Material/Model names, from the
  /// factory of material/law_factory.h.
  std::shared_ptr<const MembraneLaw> material_law(const Parameters &p, const Scene &scene);

  /// The time stepper's settings (waveform from the last waypoint or the table).
  TimeSettings time_settings(const Parameters &p, const Scene &scene);
} // namespace cdea
