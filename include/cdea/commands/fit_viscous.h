#pragma once
// `cdea fit FILE.prm DATA.csv` with a DMA table or a creep curve
// (design/viscous_fit.h): the part of the fit command (commands/fit.cc) for
// data whose header names frequency_Hz or time_s.

#include <cdea/commands/command.h>
#include <cdea/design/fit_data.h>

#include <memory>

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
} // namespace cdea
