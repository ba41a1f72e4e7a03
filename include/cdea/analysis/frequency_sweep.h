#pragma once
// `cdea frequency-sweep FILE.prm` and cdea.frequency_sweep(): the periodic
// steady state (analysis/periodic_steady_state.h) of the prm's waveform at
// each frequency of subsection Frequency sweep, with the stroke amplitude,
// mean displacement, swept (pumped) volume, dissipation per cycle, the
// smallest hoop stress over the period, the loss-of-tension flag and the
// usable band (doc/dynamics.md, "Periodic steady states and the frequency
// sweep").

#include <cdea/analysis/periodic_steady_state.h>
#include <cdea/model/product.h>
#include <cdea/analysis/run_input.h>

#include <functional>
#include <string>
#include <vector>

namespace cdea
{
  struct FrequencySweepSettings
  {
    std::vector<double> frequencies; ///< Hz, increasing
    double              usable_factor = 1.5;
    SteadyStateSettings steady;
  };

  /// The settings of subsections Frequency sweep and Steady state; throws
  /// InputError naming the entry (an empty or non-positive list, a waveform
  /// that is not periodic, a tolerance out of range).
  FrequencySweepSettings frequency_sweep_settings(const Parameters &p);

  struct FrequencySweepResult
  {
    std::vector<SteadyPeriod> periods;
    double quasi_static_amplitude = 0.; ///< m
    std::vector<int> usable;            ///< 1 or 0 per frequency
    /// The usable band: the longest run of consecutive usable frequencies
    /// (NaN if none).
    double band_low = 0., band_high = 0.; ///< Hz
    double usable_factor = 0.;
    double seconds       = 0.;
    bool   all_converged = true;
    /// Frequencies not computed because a stop was asked for (SIGINT,
    /// SIGTERM, SIGHUP in `cdea frequency-sweep`): NaN in their periods, the
    /// message "not computed: interrupted by SIGINT"; stop_reason the part
    /// after "not computed: ".
    std::size_t not_computed = 0;
    std::string stop_reason;
  };

  /// The sweep. Collective over MPI_COMM_WORLD: the frequencies are dealt
  /// round-robin to the ranks (mpi::items_of_rank), each solved from scratch,
  /// and rank 0 gathers them (the other ranks return no periods). On rank 0,
  /// @p on_frequency is called once per frequency as it is done: with its
  /// period if rank 0 computed it, with nullptr if another rank did (its
  /// period comes with the gather). After a stop request
  /// (StopOnSignals::requested()) the frequencies not begun are left out
  /// (FrequencySweepResult::not_computed) and not reported.
  FrequencySweepResult
  frequency_sweep(const RunInput &input, const FrequencySweepSettings &s,
                  const std::function<void(const SteadyPeriod *)> &on_frequency);

  /// The group /sweep of @p periods: a value per frequency
  /// (model/quantities_frequency_sweep.h), in SI.
  Product periods_product(const std::vector<SteadyPeriod> &periods);

  /// The product of @p r: the quasi-static amplitude, the usable band and
  /// /sweep, in SI; written to <Base name>_frequency_sweep.h5 and returned by
  /// cdea.frequency_sweep().
  Product frequency_sweep_product(const std::string          &parameter_text,
                                  const FrequencySweepResult &r);
} // namespace cdea
