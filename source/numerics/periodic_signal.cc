// Samples of one period of a signal at step ends (numerics/periodic_signal.h).
#include <cdea/numerics/periodic_signal.h>

#include <algorithm>
#include <cmath>

namespace cdea
{
  /// Derivatives at the samples of a periodic signal (the last sample is
  /// the first one period later): the parabola through each sample and its
  /// neighbours.
  std::vector<double> periodic_derivative(const std::vector<double> &t,
                                          const std::vector<double> &x)
  {
    const std::size_t   n = t.size() - 1;
    std::vector<double> d(n + 1);
    for (std::size_t i = 0; i < n; ++i)
      {
        const std::size_t prev = i == 0 ? n - 1 : i - 1;
        const double      h1 = i == 0 ? t[n] - t[n - 1] : t[i] - t[i - 1];
        const double      h2 = t[i + 1] - t[i];
        const double      x0 = x[prev], x2 = x[i + 1];
        d[i] = (h1 * h1 * (x2 - x[i]) + h2 * h2 * (x[i] - x0)) / (h1 * h2 * (h1 + h2));
      }
    d[n] = d[0];
    return d;
  }

  /// The cubic Hermite interpolant of (x, dx) on step i at fraction s.
  double hermite(const std::vector<double> &t, const std::vector<double> &x,
                 const std::vector<double> &dx, const std::size_t i, const double s)
  {
    const double h = t[i + 1] - t[i];
    const double h00 = (1. + 2. * s) * (1. - s) * (1. - s), h10 = s * (1. - s) * (1. - s);
    const double h01 = s * s * (3. - 2. * s), h11 = s * s * (s - 1.);
    return h00 * x[i] + h10 * h * dx[i] + h01 * x[i + 1] + h11 * h * dx[i + 1];
  }

  /// Largest and smallest value of the Hermite interpolant (16 samples a step).
  std::pair<double, double> extremes(const std::vector<double> &t, const std::vector<double> &x,
                                     const std::vector<double> &dx)
  {
    double lo = x[0], hi = x[0];
    for (std::size_t i = 0; i + 1 < t.size(); ++i)
      for (unsigned int k = 1; k <= 16; ++k)
        {
          const double y = hermite(t, x, dx, i, k / 16.);
          lo             = std::min(lo, y);
          hi             = std::max(hi, y);
        }
    return {lo, hi};
  }

  /// The mean and the first harmonic (2/T) int x exp(-i w t) dt of the
  /// Hermite interpolant (Gauss-Legendre, 4 points a step).
  std::pair<double, std::complex<double>>
    mean_and_harmonic(const std::vector<double> &t, const std::vector<double> &x,
                      const std::vector<double> &dx)
  {
    static const double gx[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281,
                                 0.9305681557970263};
    static const double gw[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731,
                                 0.1739274225687269};
    const double         T = t.back() - t.front(), w = 2. * M_PI / T;
    double               mean = 0.;
    std::complex<double> c    = 0.;
    for (std::size_t i = 0; i + 1 < t.size(); ++i)
      {
        const double h = t[i + 1] - t[i];
        for (unsigned int k = 0; k < 4; ++k)
          {
            const double y = hermite(t, x, dx, i, gx[k]), tk = t[i] + gx[k] * h;
            mean += gw[k] * h * y;
            c += gw[k] * h * y * std::exp(std::complex<double>(0., -w * (tk - t.front())));
          }
      }
    return {mean / T, 2. / T * c};
  }
} // namespace cdea
