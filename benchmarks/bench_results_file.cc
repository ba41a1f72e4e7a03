// Cost of crash-safe results (doc/usage.md, "What survives what"): per step,
// the journal record and the in-memory HDF5 append; the checkpoint and the
// final file (written whole, fsync, rename) as the file grows; rebuilding a
// file from its journal. Steps shaped like the default run's (65 samples,
// one ring, eight of the postprocessors' columns of cdea run). Medians of 5
// repetitions.
//
//   build/benchmarks/bench_results_file [STEPS [SAMPLES]]
//
// Exits with 1 if the replay of the journal does not give back every step
// it holds, undamaged (the count it prints is checked).

#include <cdea/model/output_fields.h>
#include <cdea/output/journal.h>
#include <cdea/output/results_document.h>
#include <cdea/output/results_file.h>
#include <cdea/output/safe_files.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "bench_common.h"

namespace
{
  using Clock = std::chrono::steady_clock;
  double since(const Clock::time_point t)
  {
    return std::chrono::duration<double>(Clock::now() - t).count();
  }

  cdea::StepSummary summary(const unsigned int i)
  {
    cdea::StepSummary s;
    s.stage         = cdea::Stage::voltage;
    s.load_factor   = 1e-3 * i;
    s.voltages      = {1.0 * i};
    s.mass          = 0.28;
    s.displacement  = 0.018 + 1e-6 * i;
    s.stroke        = 1e-6 * i;
    s.s2_min        = 6e4;
    s.s2_ring_inner = {6.5e4};
    // Eight of the postprocessors' columns of a quasi-static cdea run.
    using namespace cdea::summary_column;
    double value = 0.;
    for (const cdea::Quantity *c :
         {&volume, &volume_change, &level_drop, &min_eigenvalue, &stable, &wrinkled_zone_inner,
          &wrinkled_zone_outer, &max_field})
      s.columns.set(*c, ++value);
    return s;
  }

  /// Samples per step: the default run's (prm/default.prm) unless given.
  unsigned int samples = 65;

  cdea::StepFields fields(const unsigned int i)
  {
    cdea::StepFields f;
    for (unsigned int j = 0; j < samples; ++j)
      {
        for (auto *v : {&f.R, &f.r, &f.z, &f.theta, &f.lambda1, &f.lambda2, &f.s1, &f.s2, &f.E,
                        &f.Phi})
          v->push_back(1e-3 * j + 1e-6 * i);
        f.ring.push_back(0);
      }
    return f;
  }

} // namespace

int main(int argc, char **argv)
{
  namespace fs          = std::filesystem;
  const unsigned int n  = argc > 1 ? std::atoi(argv[1]) : 5000;
  if (argc > 2)
    samples = static_cast<unsigned int>(std::atoi(argv[2]));
  const fs::path     out = fs::temp_directory_path() / "cdea_bench_results_file";
  fs::remove_all(out);
  fs::create_directories(out);
  const std::string path = (out / "bench.h5").string();
  setenv("CDEA_CHECKPOINT_SECONDS", "1e9", 1); // checkpoints timed separately below

  std::vector<double> append_us, journal_us, document_us, checkpoint_ms[3], finish_ms, replay_ms;
  std::size_t         file_bytes = 0, journal_bytes = 0;
  unsigned int        replayed   = 0;
  const unsigned int  marks[3] = {n / 5, n / 2, n};
  for (int repetition = 0; repetition < 5; ++repetition)
    {
      {
        // The whole path of a step through ResultsFile (journal + memory).
        cdea::ResultsFile file(path, "parameters", 1);
        const auto        start = Clock::now();
        for (unsigned int i = 0; i < n; ++i)
          file.append(summary(i), fields(i));
        append_us.push_back(since(start) / n * 1e6);
        const auto finish = Clock::now();
        const auto done   = file.finish("complete");
        finish_ms.push_back(since(finish) * 1e3);
        file_bytes = fs::file_size(done.file);
      }
      {
        // The two halves, and the checkpoint as the file grows.
        cdea::JournalWriter journal;
        journal.open(path + ".journal", "parameters", 1, {});
        cdea::ResultsDocument document(path, "parameters", 1);
        double                in_journal = 0., in_document = 0.;
        unsigned int          mark       = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            auto t = Clock::now();
            journal.append(summary(i), fields(i), {});
            in_journal += since(t);
            t = Clock::now();
            document.append(summary(i), fields(i));
            in_document += since(t);
            if (i + 1 == marks[mark])
              {
                t = Clock::now();
                cdea::replace_file(path + ".checkpoint", document.image(), false);
                checkpoint_ms[mark++].push_back(since(t) * 1e3);
              }
          }
        journal_us.push_back(in_journal / n * 1e6);
        document_us.push_back(in_document / n * 1e6);
        journal_bytes = journal.size();
        journal.close();
        const auto t = Clock::now();
        const auto replay = cdea::replay_journal(path + ".journal", path);
        replay_ms.push_back(since(t) * 1e3);
        // The replay must give back every step the journal holds, undamaged.
        if (replay.steps != n || replay.journal_steps != n || !replay.document ||
            replay.damaged_at != cdea::no_damage || replay.dropped_bytes != 0)
          {
            std::fprintf(stderr,
                         "bench_results_file: the replay of %u steps gave %u steps (%u step "
                         "records in the journal, %zu bytes dropped%s)\n",
                         n, replay.steps, replay.journal_steps, replay.dropped_bytes,
                         replay.damaged_at != cdea::no_damage ? ", damaged" : "");
            return 1;
          }
        replayed = replay.steps;
      }
      fs::remove_all(out);
      fs::create_directories(out);
    }
  using cdea_bench::median;
  std::printf("%u steps of %u samples, medians of 5 repetitions\n", n, samples);
  std::printf("  append (journal + in-memory HDF5)   %8.1f us per step\n", median(append_us));
  std::printf("    of it the journal record          %8.1f us\n", median(journal_us));
  std::printf("    of it the in-memory HDF5          %8.1f us\n", median(document_us));
  for (int k = 0; k < 3; ++k)
    std::printf("  checkpoint after %6u steps         %8.1f ms\n", marks[k],
                median(checkpoint_ms[k]));
  std::printf("  finish (image, write, fsync, rename) %7.1f ms\n", median(finish_ms));
  std::printf("  rebuild from the journal             %7.1f ms (%u of %u steps replayed)\n",
              median(replay_ms), replayed, n);
  std::printf("  file %.0f bytes per step, journal %.0f bytes per step\n",
              double(file_bytes) / n, double(journal_bytes) / n);
  fs::remove_all(out);
  return 0;
}
