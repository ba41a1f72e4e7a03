#pragma once
// `cdea fit FILE.prm DATA.csv` with a DMA table or a creep curve
// (design/viscous_fit.h): the part of the fit command (commands/fit.cc) for
// data whose header names frequency_Hz or time_s.

#include <cdea/commands/command.h>
#include <cdea/design/fit_data.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  /// The job of a DMA or creep fit: check() reads the settings and the data
  /// of @p kind, run() fits, prints and writes as the fit command does.
  class ViscousFitJob
  {
  public:
    virtual ~ViscousFitJob() = default;
    virtual void check(Invocation &invocation) = 0;
    virtual int  run(Invocation &invocation)   = 0;
  };

  std::unique_ptr<ViscousFitJob> viscous_fit_job(FitDataKind kind);

  struct FitResult;
  struct SceneParameter;
  struct Scene;
  class Product;

  /// How the fit ended, and per free parameter its start, fitted value,
  /// standard error and relative error (network A's modulus in kPa, the
  /// others in SI), then the correlations.
  void print_fitted_values(const std::vector<SceneParameter> &free, const FitResult &r);

  /// The fit's correlation matrix, a row per free parameter labelled in a
  /// column @p label_width wide (nothing for fewer than two parameters).
  void print_correlation(const std::vector<SceneParameter> &free, const FitResult &r,
                         int label_width);

  /// How every fit ends: @p write_results (the files at @p paths, the fit
  /// file first, then the parameter file with the fitted values if any and
  /// any others, replaced together or not at all; after a stop beside older
  /// ones, to their partial names), "wrote ...", and the exit code: 2 if
  /// writing failed (older files stay), a stop was asked for or the fit did
  /// not converge (each said on stderr), else 0.
  int finish_fit(const std::function<void()> &write_results, const std::vector<std::string> &paths,
                 const FitResult &r);

  /// A further product a fit writes with its pair of files, and where.
  struct ProductPath
  {
    const Product *product;
    std::string    path;
  };

  /// Writes @p product to the claimed fit file and, if the fit has fitted
  /// values, <Base name>_fit.prm with the @p values of @p free over the
  /// parameter file (@p base its scene), and the products @p more, together,
  /// and ends as finish_fit().
  int write_fit_files(const Invocation &invocation, const Scene &base,
                      const std::vector<SceneParameter> &free, const FitResult &r,
                      const Product &product, const std::vector<ProductPath> &more = {});

  /// A fit that could not start (its start values failed, or a stop was
  /// asked for during the start's evaluation): nothing is written (an older
  /// fit stays), @p status said; exit 1, or 2 after a stop.
  int fit_not_started(Invocation &invocation, const std::string &status, const std::string &hint);
} // namespace cdea
