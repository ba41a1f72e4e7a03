#pragma once
// Ring voltages as functions of time for time-dependent runs (Time/Waveform):
//
//   ramp-hold  linear from 0 to the peak in the ramp time, then held;
//   square     0.5 duty square wave between 0 and the peak, starting on,
//              each edge a linear ramp of the rise time;
//   sine       peak (1 - cos(2 pi f t)) / 2: between 0 and the peak, from rest;
//   table      piecewise linear through rows (t, one voltage per ring), from
//              0 V at t = 0 when the first row is later.
//
// All but the sine are piecewise linear through knots; the time stepper lands
// on every knot (breakpoint) so that no kink or edge falls inside a step.

#include <vector>

namespace cdea
{
  enum class WaveformKind
  {
    ramp_hold,
    square,
    sine,
    table
  };

  class Waveform
  {
  public:
    Waveform() = default;

    /// Volts per ring; times in seconds.
    static Waveform ramp_hold(const std::vector<double> &peak, double ramp_time, double hold_time);
    /// The square wave and the sine swing between @p low_fraction times the
    /// peak and the peak (0: from 0 V, as the time runs drive them; the
    /// periodic steady states of analysis/periodic_steady_state.h drive a
    /// small swing about a bias with a fraction close to 1).
    static Waveform square(const std::vector<double> &peak, double frequency, unsigned int cycles,
                           double rise_time, double low_fraction = 0.);
    static Waveform sine(const std::vector<double> &peak, double frequency, unsigned int cycles,
                         double low_fraction = 0.);
    /// Rows of strictly increasing times >= 0 with one voltage per ring each.
    static Waveform table(const std::vector<double> &times,
                          const std::vector<std::vector<double>> &voltages);

    WaveformKind kind() const { return kind_; }
    unsigned int n_rings() const { return peak_.size(); }
    /// Largest voltage of each ring (V).
    const std::vector<double> &peak() const { return peak_; }
    double       end_time() const { return end; }
    /// Drive frequency (Hz) of a periodic waveform, 0 otherwise.
    double frequency() const { return frequency_; }
    /// The square wave's and the sine's low voltage over the peak (0 else).
    double low_fraction() const { return low_; }

    std::vector<double> voltages(double t) const;
    /// The voltages at @p t on the piece between knots that holds @p inside,
    /// extended linearly beyond its knots (the sine: voltages(t)): the
    /// stages of a step inside one piece see no kink, even those beyond its end.
    std::vector<double> voltages_on_piece(double t, double inside) const;
    /// d(voltages)/dt at @p t on that piece (V/s).
    std::vector<double> rates_on_piece(double t, double inside) const;
    /// The first knot strictly after @p t (end_time() at the latest).
    double next_breakpoint(double t) const;

  private:
    WaveformKind                     kind_      = WaveformKind::ramp_hold;
    std::vector<double>              peak_;
    double                           frequency_ = 0.;
    double                           low_       = 0.;
    double                           end        = 0.;
    std::vector<double>              knot_times;
    std::vector<std::vector<double>> knot_voltages;
  };
} // namespace cdea
