#pragma once
// How a nonlinear solve ended: what Newton and every model's solve() report.

#include <string>

namespace cdea
{
  struct SolveReport
  {
    bool         converged  = false;
    unsigned int iterations = 0;
    std::string  message; ///< why it failed (empty on success)
  };
} // namespace cdea
