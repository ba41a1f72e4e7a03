#include <cdea/analysis/frequency_sweep.h>
#include <cdea/base/byte_pack.h>
#include <cdea/base/format.h>
#include <cdea/base/mpi_session.h>
#include <cdea/base/run_control.h>
#include <cdea/base/text.h>
#include <cdea/model/quantities_common.h>
#include <cdea/model/quantities_frequency_sweep.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#ifndef CDEA_VERSION
#  define CDEA_VERSION "unknown"
#endif

namespace cdea
{
  namespace
  {
    /// Frequencies beyond which a sweep needs Frequency sweep/Confirm long
    /// sweep (each is a periodic steady state of seconds or more), and at most.
    constexpr std::size_t long_sweep = 1000, most_frequencies = 100000;

    void check_length(const parameters::FrequencySweep &f, const std::size_t n)
    {
      if (n > most_frequencies)
        throw InputError("Frequency sweep: " + std::to_string(n) + " frequencies are too many "
                         "(at most " + std::to_string(most_frequencies) + ")");
      if (n > long_sweep && !f.confirm_long)
        throw InputError("Frequency sweep: " + std::to_string(n) + " frequencies are more than " +
                         std::to_string(long_sweep) + " (each takes seconds or more: hours in "
                         "all): set Frequency sweep/Confirm long sweep = true to run them");
    }

    std::vector<double> sweep_frequencies(const parameters::FrequencySweep &f)
    {
      std::vector<double> list;
      if (!trim_blanks(f.frequency_list).empty())
        {
          list = parse_number_list(f.frequency_list, "Frequency sweep/Frequencies (Hz)");
          check_length(f, list.size());
          for (std::size_t i = 0; i < list.size(); ++i)
            if (!(list[i] > 0. && list[i] <= 1e6) || (i > 0 && !(list[i] > list[i - 1])))
              throw InputError("Frequency sweep/Frequencies (Hz) must be increasing frequencies "
                               "above 0 and at most 1e6 Hz, got " + f.frequency_list);
          return list;
        }
      require_positive(f.lowest_frequency_Hz, "Frequency sweep/Lowest frequency (Hz)");
      if (f.frequencies < 1 || f.frequencies > int(most_frequencies))
        throw InputError("Frequency sweep/Frequencies must be between 1 and 100000, got " +
                         std::to_string(f.frequencies));
      check_length(f, std::size_t(f.frequencies));
      if (!(f.highest_frequency_Hz >= f.lowest_frequency_Hz && f.highest_frequency_Hz <= 1e6) ||
          (f.frequencies > 1 && !(f.highest_frequency_Hz > f.lowest_frequency_Hz)))
        throw InputError("Frequency sweep/Highest frequency (Hz) must be above Frequency "
                         "sweep/Lowest frequency (Hz) (" + format_number(f.lowest_frequency_Hz) +
                         ") and at most 1e6, got " + format_number(f.highest_frequency_Hz));
      const double lo = f.lowest_frequency_Hz, hi = f.highest_frequency_Hz;
      for (int i = 0; i < f.frequencies; ++i)
        {
          const double s = f.frequencies > 1 ? double(i) / (f.frequencies - 1) : 0.;
          list.push_back(f.log_spacing ? lo * std::pow(hi / lo, s) : lo + s * (hi - lo));
        }
      return list;
    }
  } // namespace

  FrequencySweepSettings frequency_sweep_settings(const Parameters &p)
  {
    if (!p.time.enabled)
      throw InputError("cdea frequency-sweep needs Time/Enabled = true (the waveform, inertia "
                       "and time integration of a time run)");
    if (p.time.waveform != WaveformKind::sine && p.time.waveform != WaveformKind::square)
      throw InputError("Time/Waveform must be sine or square (periodic) for a frequency sweep, "
                       "got " + to_string(p.time.waveform));
    FrequencySweepSettings s;
    s.frequencies = sweep_frequencies(p.frequency_sweep);
    if (p.time.waveform == WaveformKind::square && !(p.time.rise_time_s < 0.5 / s.frequencies.back()))
      throw InputError("Time/Rise time (s) (" + format_number(p.time.rise_time_s) +
                       ") must be below half the period of the highest frequency (" +
                       format_number(s.frequencies.back()) + " Hz) of the square wave");
    s.usable_factor = p.frequency_sweep.usable_factor;
    require_range(s.usable_factor, 1., 1e6, "Frequency sweep/Usable stroke factor", "");
    const auto &st = p.steady_state;
    require_range(st.tolerance, 1e-14, 0.1, "Steady state/Tolerance", "");
    require_range(st.low_fraction, 0., 0.999999, "Steady state/Low voltage (fraction of peak)",
                  "", true);
    s.steady.tolerance     = st.tolerance;
    s.steady.max_newton    = st.max_newton_iterations;
    s.steady.max_krylov    = st.krylov_dimension;
    s.steady.start_periods = st.start_periods;
    s.steady.low_fraction  = st.low_fraction;
    return s;
  }

  namespace
  {
    /// Usable: taut, and the stroke within the factor of the quasi-static one;
    /// the band: the longest run of consecutive usable frequencies.
    void usable_band(FrequencySweepResult &r)
    {
      const double qs = r.quasi_static_amplitude, F = r.usable_factor;
      std::size_t  best_start = 0, best_length = 0, start = 0, length = 0;
      for (std::size_t i = 0; i < r.periods.size(); ++i)
        {
          const SteadyPeriod &s = r.periods[i];
          const bool ok = s.converged && !s.loss_of_tension && s.stroke_amplitude <= F * qs &&
                          s.stroke_amplitude >= qs / F;
          r.usable.push_back(ok ? 1 : 0);
          length = ok ? length + 1 : 0;
          start  = ok && length == 1 ? i : start;
          if (length > best_length)
            {
              best_length = length;
              best_start  = start;
            }
        }
      const double nan = std::numeric_limits<double>::quiet_NaN();
      r.band_low       = best_length ? r.periods[best_start].frequency : nan;
      r.band_high      = best_length ? r.periods[best_start + best_length - 1].frequency : nan;
    }
  } // namespace

  namespace
  {
    // Periods as bytes for the gather (base/byte_pack.h).

    void pack(BytePacker &out, const std::size_t index, const SteadyPeriod &s)
    {
      out.put(std::uint64_t(index));
      for (const double x : {s.frequency, s.defect, s.check_move, s.stroke_amplitude,
                             s.mean_displacement, s.first_harmonic.real(),
                             s.first_harmonic.imag(), s.volume_swing, s.electrical_work,
                             s.weight_work, s.dissipated, s.stored_change, s.s2_min, s.seconds})
        out.put(x);
      for (const unsigned int c : {unsigned(s.converged), unsigned(s.loss_of_tension),
                                   s.newton_iterations, s.krylov_iterations, s.period_maps,
                                   s.steps_per_period})
        out.put(std::uint64_t(c));
      out.put(s.message);
    }

    std::pair<std::size_t, SteadyPeriod> unpack(ByteUnpacker &in)
    {
      SteadyPeriod      s;
      const std::size_t index = in.get_uint();
      for (double *x : {&s.frequency, &s.defect, &s.check_move, &s.stroke_amplitude,
                        &s.mean_displacement})
        *x = in.get_double();
      const double re = in.get_double(), im = in.get_double();
      s.first_harmonic = {re, im};
      for (double *x : {&s.volume_swing, &s.electrical_work, &s.weight_work, &s.dissipated,
                        &s.stored_change, &s.s2_min, &s.seconds})
        *x = in.get_double();
      s.converged       = in.get_uint() != 0;
      s.loss_of_tension = in.get_uint() != 0;
      for (unsigned int *c :
           {&s.newton_iterations, &s.krylov_iterations, &s.period_maps, &s.steps_per_period})
        *c = static_cast<unsigned int>(in.get_uint());
      s.message = in.get_string();
      return {index, std::move(s)};
    }

    /// Rank 0: every rank's periods, @p n of them in frequency order; the
    /// other ranks get none. Collective.
    std::vector<SteadyPeriod> gather_periods(const BytePacker &local, const std::size_t n)
    {
      const std::vector<std::string> packed = mpi::gather_bytes(local.bytes);
      if (mpi::rank() != 0)
        return {};
      std::vector<SteadyPeriod> periods(n);
      std::vector<bool>         seen(n, false);
      for (const std::string &bytes : packed)
        for (ByteUnpacker in(bytes); !in.done();)
          {
            auto [index, period] = unpack(in);
            if (index >= n || seen[index])
              throw std::runtime_error("bad frequency index in the gather of the ranks' results");
            seen[index]    = true;
            periods[index] = std::move(period);
          }
      if (std::find(seen.begin(), seen.end(), false) != seen.end())
        throw std::runtime_error("a frequency is missing after the gather of the ranks' results");
      return periods;
    }

    constexpr int progress_tag = 7402;

    constexpr const char *not_computed_prefix = "not computed: ";

    /// A frequency left out after a stop request: NaN, not converged.
    SteadyPeriod not_computed(const double frequency, const int signal)
    {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      SteadyPeriod p;
      p.frequency = frequency;
      for (double *x : {&p.defect, &p.check_move, &p.stroke_amplitude, &p.mean_displacement,
                        &p.volume_swing, &p.electrical_work, &p.weight_work, &p.dissipated,
                        &p.stored_change, &p.s2_min})
        *x = nan;
      p.first_harmonic = {nan, nan};
      p.message        = not_computed_prefix + std::string(RunInterrupted(signal).what());
      return p;
    }
  } // namespace

  // Each frequency is solved from scratch (PeriodicSteadyState::solve builds
  // a new model, start and step sequence), so the ranks can take any of them
  // and give the serial run's numbers bit for bit.
  FrequencySweepResult
  frequency_sweep(const RunInput &input, const FrequencySweepSettings &s,
                  const std::function<void(const SteadyPeriod *)> &on_frequency)
  {
    const auto           clock_start = std::chrono::steady_clock::now();
    FrequencySweepResult r;
    r.usable_factor = s.usable_factor;
    PeriodicSteadyState steady(input.parameters, input.scene, s.steady);
    // On every rank (the same numbers there): an error here ends every rank alike.
    r.quasi_static_amplitude = steady.quasi_static_amplitude();
    const std::size_t n = s.frequencies.size();
    const std::vector<std::size_t> mine = mpi::items_of_rank(n, mpi::rank(), mpi::size());
    const bool distributed = mpi::size() > 1, root = mpi::rank() == 0;
    mpi::CountChannel progress(progress_tag);
    std::uint64_t     others = n - mine.size();
    // Rank 0: the other ranks' finished frequencies, as they are counted.
    auto take_counts = [&](const bool wait) {
      std::uint64_t count = 0;
      while (others > 0)
        {
          if (wait)
            count = progress.receive();
          else if (!progress.try_receive(count))
            return;
          others -= std::min(count, others);
          for (; count > 0; --count)
            if (on_frequency)
              on_frequency(nullptr);
        }
    };
    BytePacker local;
    for (const std::size_t i : mine)
      {
        // After a stop request the frequencies left are not computed (NaN,
        // flagged), as a sweep keeps the rows it has.
        const int    signal = StopOnSignals::requested();
        SteadyPeriod period = signal ? not_computed(s.frequencies[i], signal) :
                                       steady.solve(s.frequencies[i]);
        if (root && on_frequency && !signal)
          on_frequency(&period);
        if (!distributed)
          {
            r.periods.push_back(std::move(period));
            continue;
          }
        pack(local, i, period);
        if (root)
          take_counts(false);
        else
          progress.send(1);
      }
    if (distributed)
      {
        if (root)
          take_counts(true);
        else
          progress.wait_for_sends();
        r.periods = gather_periods(local, n);
      }
    for (const SteadyPeriod &period : r.periods)
      {
        r.all_converged = r.all_converged && period.converged;
        if (period.message.rfind(not_computed_prefix, 0) == 0)
          {
            r.stop_reason = period.message.substr(std::strlen(not_computed_prefix));
            ++r.not_computed;
          }
      }
    usable_band(r);
    r.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
    return r;
  }

  Product periods_product(const std::vector<SteadyPeriod> &periods)
  {
    using namespace frequency_sweep_quantity;
    Product       product;
    ProductGroup &sweep  = product.group("/sweep");
    const auto    column = [&](const Quantity &row, const auto &value) {
      std::vector<double> v;
      for (const SteadyPeriod &s : periods)
        v.push_back(value(s));
      sweep.set(row, v);
    };
    std::vector<std::complex<double>> harmonics;
    for (const SteadyPeriod &s : periods)
      harmonics.push_back(s.first_harmonic);
    column(frequency, [](auto &s) { return s.frequency; });
    column(stroke_amplitude, [](auto &s) { return s.stroke_amplitude; });
    column(mean_displacement, [](auto &s) { return s.mean_displacement; });
    sweep.set(harmonic, harmonics);
    column(swept_volume, [](auto &s) { return s.volume_swing; });
    column(dissipated, [](auto &s) { return s.dissipated; });
    column(electrical_work, [](auto &s) { return s.electrical_work; });
    column(energy_defect, [](auto &s) { return s.energy_defect(); });
    column(s2_min, [](auto &s) { return s.s2_min; });
    column(periodicity_defect, [](auto &s) { return std::max(s.defect, s.check_move); });
    column(frequency_seconds, [](auto &s) { return s.seconds; });
    column(loss_of_tension, [](auto &s) { return s.loss_of_tension ? 1. : 0.; });
    column(converged, [](auto &s) { return s.converged ? 1. : 0.; });
    column(newton_iterations, [](auto &s) { return double(s.newton_iterations); });
    column(period_maps, [](auto &s) { return double(s.period_maps); });
    return product;
  }

  Product frequency_sweep_product(const std::string          &parameter_text,
                                  const FrequencySweepResult &r)
  {
    using namespace frequency_sweep_quantity;
    Product product = periods_product(r.periods);
    product.root()
      .set(common_quantity::parameters, parameter_text)
      .set(common_quantity::code_version, CDEA_VERSION)
      .set(quasi_static_amplitude, r.quasi_static_amplitude)
      .set(usable_factor, r.usable_factor)
      .set(band_low, r.band_low)
      .set(band_high, r.band_high)
      .set(seconds, r.seconds);
    product.group("/sweep").set(usable, std::vector<double>(r.usable.begin(), r.usable.end()));
    return product;
  }
} // namespace cdea
