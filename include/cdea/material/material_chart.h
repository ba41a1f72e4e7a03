#pragma once
// Material charts of a membrane law (`cdea chart`, doc/materials.md,
// "Material charts"), computed from the law alone at zero voltage:
//
// - stress-stretch curves: uniaxial tension (l1 = L, l2 from the zero
//   transverse stress s2(L, l2) = 0 by the bracketed root finder) and
//   equibiaxial tension (l1 = l2 = L), nominal stress s1 = dW/dl1 against L
//   from 1 to min(max_stretch, a stretch just below the law's locking
//   stretch on that path). A law with internal variables gives two curves:
//   the relaxed one (internal variables in equilibrium with the stretches,
//   the long-time response) and the instantaneous one (internal variables
//   held at the undeformed state, the glassy response);
// - the small-strain DMA chart of a law with internal variables: storage
//   and loss modulus and loss factor of uniaxial tension against frequency.
//   The law's consistent tangent over one backward-Euler step dt from the
//   undeformed, relaxed state, condensed to uniaxial stress
//   (E = k11 - k12^2 / k22), is the Laplace-domain modulus E^(s) at s = 1/dt;
//   for one relaxation time (the standard linear solid)
//     E^(s) = E_A + E_B s tau / (1 + s tau),
//   so dt -> 0 gives E_A + E_B, dt -> infinity E_A and one finite dt tau.
//   At s = i w:
//     E'(w) = E_A + E_B w^2 tau^2 / (1 + w^2 tau^2),
//     E''(w) = E_B w tau / (1 + w^2 tau^2),   tan delta = E'' / E'.
//   The identification is checked at further steps; a law whose response is
//   not of that form is refused (std::runtime_error).

#include <memory>
#include <complex>
#include <string>
#include <vector>

namespace cdea
{
  class MembraneLaw;

  /// The ranges of the charts.
  struct ChartSettings
  {
    double       max_stretch     = 6.;   ///< the curves end here or below the locking stretch
    unsigned int stretch_points  = 51;   ///< per curve, evenly spaced from 1
    double       min_frequency   = 1e-3; ///< Hz
    double       max_frequency   = 1e3;  ///< Hz
    unsigned int frequency_points = 61;  ///< log-spaced
  };

  /// Which loading path.
  enum class ChartPath
  {
    uniaxial,
    equibiaxial
  };

  /// A stress-stretch curve (SI units).
  struct StressStretchCurve
  {
    ChartPath           path = ChartPath::uniaxial;
    std::vector<double> stretch;            ///< L = l1
    std::vector<double> transverse_stretch; ///< l2 (uniaxial: of the relaxed curve)
    std::vector<double> nominal_stress;     ///< s1 (Pa), relaxed (the elastic law's)
    /// s1 (Pa) with the internal variables at the undeformed state; empty
    /// for an elastic law.
    std::vector<double> instantaneous_stress;
    std::vector<double> instantaneous_transverse_stretch; ///< uniaxial l2 of that curve
    /// Where the path leaves the law's range (the smaller of the relaxed and
    /// instantaneous paths); infinity if not below max_stretch.
    double locking_stretch = 0.;
  };

  /// Small-strain moduli of uniaxial tension identified from the law.
  struct SmallStrainModuli
  {
    double relaxed       = 0.; ///< E_A (Pa): dt -> infinity
    double instantaneous = 0.; ///< E_A + E_B (Pa): dt = 0
    /// tau (s); 0 for an elastic law and for a relaxation spectrum (several branches)
    double relaxation_time = 0.;
  };

  /// The complex small-strain uniaxial modulus E' + i E'' (Pa) at @p f (Hz)
  /// from the law's linearization at the undeformed relaxed state
  /// (linear_response.h): C11 - C12^2 / C22 of C(2 pi f). For a Prony series
  /// E' = E_A + sum_k E_k x_k^2 / (1 + x_k^2), E'' = sum_k E_k x_k / (1 + x_k^2),
  /// x_k = 2 pi f tau_k, E_k = 3 mu_k.
  std::complex<double> complex_modulus(const MembraneLaw &law, double f);

  /// The DMA chart (SI units, frequency in Hz).
  struct DmaChart
  {
    SmallStrainModuli   moduli;
    std::vector<double> frequency;
    std::vector<double> storage;
    std::vector<double> loss;
    std::vector<double> loss_factor;
  };

  /// The stress-stretch curve of @p path. Throws std::runtime_error if the
  /// law cannot be evaluated at the undeformed state or the uniaxial root
  /// is not found.
  StressStretchCurve stress_stretch_curve(const MembraneLaw &law, ChartPath path,
                                          const ChartSettings &settings);

  /// Nominal stress s1 (Pa) of the path at stretch L and the transverse
  /// stretch l2; @p instantaneous: internal variables at the undeformed
  /// state. False outside the law's range.
  bool path_stress(const MembraneLaw &law, ChartPath path, double L, bool instantaneous,
                   double &s1, double &l2);

  /// The uniaxial modulus of one backward-Euler step @p dt from the
  /// undeformed relaxed state (Pa): E^(1/dt) above; dt = 0 the instantaneous
  /// modulus, dt = infinity the relaxed one.
  double step_modulus(const MembraneLaw &law, double dt);

  /// E_A, E_A + E_B and tau from step_modulus(); tau = 0 when the law has no
  /// internal variables. Throws std::runtime_error if the law's response is
  /// not a standard linear solid.
  SmallStrainModuli small_strain_moduli(const MembraneLaw &law);

  /// The standard linear solid at frequency @p f (Hz): E' and E'' (Pa).
  void standard_linear_solid(const SmallStrainModuli &m, double f, double &storage,
                             double &loss);

  /// The DMA chart of a law with internal variables (throws
  /// std::invalid_argument for an elastic law): the standard linear solid of
  /// small_strain_moduli() for one relaxation time, complex_modulus() for a
  /// spectrum.
  DmaChart dma_chart(const MembraneLaw &law, const ChartSettings &settings);

  /// "uniaxial" or "equibiaxial".
  std::string path_name(ChartPath path);
} // namespace cdea
