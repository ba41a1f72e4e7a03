#include <cdea/model/waveform.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cdea
{
  Waveform Waveform::ramp_hold(const std::vector<double> &peak, const double ramp_time,
                               const double hold_time)
  {
    if (!(ramp_time > 0.) || !(hold_time >= 0.))
      throw std::invalid_argument("Waveform::ramp_hold: ramp time > 0 and hold time >= 0");
    Waveform w;
    w.kind_         = WaveformKind::ramp_hold;
    w.peak_         = peak;
    w.end           = ramp_time + hold_time;
    w.knot_times    = {0., ramp_time, w.end};
    w.knot_voltages = {std::vector<double>(peak.size(), 0.), peak, peak};
    return w;
  }

  Waveform Waveform::square(const std::vector<double> &peak, const double frequency,
                            const unsigned int cycles, const double rise_time,
                            const double low_fraction)
  {
    const double period = 1. / frequency;
    if (!(frequency > 0.) || cycles == 0 || !(rise_time > 0.) || !(rise_time < 0.5 * period))
      throw std::invalid_argument("Waveform::square: frequency > 0, cycles > 0, "
                                  "0 < rise time < half a period");
    Waveform w;
    w.kind_      = WaveformKind::square;
    w.peak_      = peak;
    w.frequency_ = frequency;
    w.low_       = low_fraction;
    w.end        = cycles * period;
    std::vector<double> low(peak.size(), 0.);
    for (std::size_t i = 0; i < peak.size(); ++i)
      low[i] = low_fraction == 0. ? 0. : low_fraction * peak[i];
    const std::vector<double> &zero = low;
    for (unsigned int k = 0; k < cycles; ++k)
      {
        const double t0 = k * period;
        for (const auto &[t, v] : {std::pair{t0, &zero}, std::pair{t0 + rise_time, &peak},
                                   std::pair{t0 + 0.5 * period, &peak},
                                   std::pair{t0 + 0.5 * period + rise_time, &zero}})
          {
            w.knot_times.push_back(t);
            w.knot_voltages.push_back(*v);
          }
      }
    w.knot_times.push_back(w.end);
    w.knot_voltages.push_back(zero);
    return w;
  }

  Waveform Waveform::sine(const std::vector<double> &peak, const double frequency,
                          const unsigned int cycles, const double low_fraction)
  {
    if (!(frequency > 0.) || cycles == 0)
      throw std::invalid_argument("Waveform::sine: frequency > 0 and cycles > 0");
    Waveform w;
    w.kind_      = WaveformKind::sine;
    w.peak_      = peak;
    w.frequency_ = frequency;
    w.low_       = low_fraction;
    w.end        = cycles / frequency;
    w.knot_times = {0., w.end};
    return w;
  }

  Waveform Waveform::table(const std::vector<double>              &times,
                           const std::vector<std::vector<double>> &voltages)
  {
    if (times.empty() || times.size() != voltages.size())
      throw std::invalid_argument("Waveform::table: one row of voltages per time");
    Waveform w;
    w.kind_ = WaveformKind::table;
    w.peak_.assign(voltages.front().size(), 0.);
    if (times.front() > 0.)
      {
        w.knot_times.push_back(0.);
        w.knot_voltages.emplace_back(w.peak_.size(), 0.);
      }
    for (std::size_t i = 0; i < times.size(); ++i)
      {
        if (voltages[i].size() != w.peak_.size() || times[i] < 0. ||
            (!w.knot_times.empty() && !(times[i] > w.knot_times.back())))
          throw std::invalid_argument("Waveform::table: times must increase strictly from >= 0, "
                                      "each row with one voltage per ring");
        w.knot_times.push_back(times[i]);
        w.knot_voltages.push_back(voltages[i]);
        for (std::size_t k = 0; k < w.peak_.size(); ++k)
          w.peak_[k] = std::max(w.peak_[k], voltages[i][k]);
      }
    w.end = w.knot_times.back();
    return w;
  }

  std::vector<double> Waveform::voltages(const double t) const
  {
    if (kind_ == WaveformKind::sine)
      {
        // low + (peak - low) (1 - cos(2 pi f t)) / 2, low = low_ peak
        std::vector<double> v = peak_;
        const double        s = 0.5 * (1. - std::cos(2. * M_PI * frequency_ * t));
        for (double &x : v)
          x *= low_ + (1. - low_) * s;
        return v;
      }
    if (t <= knot_times.front())
      return knot_voltages.front();
    if (t >= knot_times.back())
      return knot_voltages.back();
    const std::size_t k =
      std::upper_bound(knot_times.begin(), knot_times.end(), t) - knot_times.begin() - 1;
    const double s = (t - knot_times[k]) / (knot_times[k + 1] - knot_times[k]);
    std::vector<double> v(knot_voltages[k].size());
    for (std::size_t i = 0; i < v.size(); ++i)
      v[i] = (1. - s) * knot_voltages[k][i] + s * knot_voltages[k + 1][i];
    return v;
  }

  double Waveform::next_breakpoint(const double t) const
  {
    const auto k = std::upper_bound(knot_times.begin(), knot_times.end(), t);
    return k == knot_times.end() ? end : *k;
  }

  namespace
  {
    /// The knot k with knot_times[k] <= inside < knot_times[k + 1], clamped
    /// to a piece that exists.
    std::size_t piece_of(const std::vector<double> &knot_times, const double inside)
    {
      const std::size_t k =
        std::upper_bound(knot_times.begin(), knot_times.end(), inside) - knot_times.begin();
      return std::min(k == 0 ? 0 : k - 1, knot_times.size() - 2);
    }
  } // namespace

  std::vector<double> Waveform::voltages_on_piece(const double t, const double inside) const
  {
    if (kind_ == WaveformKind::sine || knot_times.size() < 2)
      return voltages(t);
    const std::size_t k = piece_of(knot_times, inside);
    const double      s = (t - knot_times[k]) / (knot_times[k + 1] - knot_times[k]);
    std::vector<double> v(knot_voltages[k].size());
    for (std::size_t i = 0; i < v.size(); ++i)
      v[i] = (1. - s) * knot_voltages[k][i] + s * knot_voltages[k + 1][i];
    return v;
  }

  std::vector<double> Waveform::rates_on_piece(const double t, const double inside) const
  {
    std::vector<double> v(peak_.size(), 0.);
    if (kind_ == WaveformKind::sine)
      {
        const double s = M_PI * frequency_ * std::sin(2. * M_PI * frequency_ * t);
        for (std::size_t i = 0; i < v.size(); ++i)
          v[i] = (1. - low_) * peak_[i] * s;
        return v;
      }
    if (knot_times.size() < 2)
      return v;
    const std::size_t k = piece_of(knot_times, inside);
    for (std::size_t i = 0; i < v.size(); ++i)
      v[i] = (knot_voltages[k + 1][i] - knot_voltages[k][i]) / (knot_times[k + 1] - knot_times[k]);
    return v;
  }
} // namespace cdea
