#pragma once
// Small helpers shared by the benchmark programs.

#include <algorithm>
#include <vector>

namespace cdea_bench
{
  /// Median of the samples (the mean of the two middle ones for an even count).
  inline double median(std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  }
} // namespace cdea_bench
