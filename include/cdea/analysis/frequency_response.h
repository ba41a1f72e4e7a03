#pragma once
// `cdea response FILE.prm` and cdea.response(): the small-signal frequency
// response about the equilibrium at the end of the prm's voltage path
// (doc/dynamics.md). The load path is followed quasi-statically with the
// material relaxed (a viscoelastic film's network B carries nothing there,
// as after a long hold); the linearized dynamics (fe/linear_dynamics.h)
// then give the transfer functions of the disk's displacement and of the
// enclosed volume per volt of each ring and of the drive (every ring in
// proportion to its bias voltage, as a waveform scales them), and the
// natural frequencies with their damping and mode shapes.

#include <cdea/analysis/run_input.h>
#include <cdea/model/product.h>

#include <Eigen/Core>

#include <complex>
#include <string>
#include <vector>

namespace cdea
{
  struct FrequencyResponse
  {
    std::vector<double> frequency;             ///< Hz
    std::vector<double> bias;                  ///< V per ring
    double              displacement = 0.;     ///< m, at the equilibrium
    double              volume       = 0.;     ///< m^3
    double              drive_scale  = 0.;     ///< V: the largest bias voltage
    Eigen::MatrixXcd    disk;                  ///< frequencies x rings, dz(A) per volt (m/V)
    Eigen::MatrixXcd    volume_per_volt;       ///< frequencies x rings, dV per volt (m^3/V)
    /// The drive: every ring's voltage Phi_k (1 + e exp(i omega t)), per
    /// volt of drive_scale e (m/V and m^3/V).
    Eigen::VectorXcd disk_drive, volume_drive;
    std::vector<double> mode_frequency;        ///< Hz
    std::vector<double> mode_damping;          ///< damping ratio
    std::vector<double> sample_R;              ///< m, reference radii of the shapes
    Eigen::MatrixXd     mode_r, mode_z;        ///< modes x samples, disk's z(A) = 1
    double              disk_mass  = 0.;       ///< kg (0 without inertia)
    double              water_mass = 0.;       ///< kg/m^4 on V
    double              density    = 0.;       ///< kg/m^3, the membrane's
    double              seconds    = 0.;       ///< the transfer functions' computation
  };

  /// The response for @p input (its parameters and scene, Response subsection).
  FrequencyResponse frequency_response(const RunInput &input);

  /// The product of @p r (model/quantities_response.h): the equilibrium,
  /// /transfer and /modes, in SI; written to <Base name>_response.h5 and
  /// returned by cdea.response().
  Product response_product(const std::string &parameter_text, const FrequencyResponse &r);
} // namespace cdea
