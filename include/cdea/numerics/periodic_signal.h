#pragma once
// One period of a signal x(t) sampled at the ends of time steps (the first
// sample at the period's start, the last one period later), between the
// samples the cubic Hermite interpolant of x and its derivative: the
// extremes, the mean and the first Fourier harmonic of a periodic steady
// state (analysis/periodic_steady_state.h).

#include <complex>
#include <utility>
#include <vector>

namespace cdea
{
  /// Derivatives at the samples of a periodic signal (the last sample is
  /// the first one period later): the parabola through each sample and its
  /// neighbours.
  std::vector<double> periodic_derivative(const std::vector<double> &t,
                                          const std::vector<double> &x);

  /// The cubic Hermite interpolant of (x, dx) on step i at fraction s.
  double hermite(const std::vector<double> &t, const std::vector<double> &x,
                 const std::vector<double> &dx, std::size_t i, double s);

  /// Smallest and largest value of the Hermite interpolant (16 samples a step).
  std::pair<double, double> extremes(const std::vector<double> &t, const std::vector<double> &x,
                                     const std::vector<double> &dx);

  /// The mean and the first harmonic (2/T) int x exp(-i w t) dt, w = 2 pi / T,
  /// of the Hermite interpolant (Gauss-Legendre, 4 points a step).
  std::pair<double, std::complex<double>>
    mean_and_harmonic(const std::vector<double> &t, const std::vector<double> &x,
                      const std::vector<double> &dx);
} // namespace cdea
