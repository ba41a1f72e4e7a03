#pragma once
// Small helpers shared by the benchmark programs.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
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

  /// Copy the parameter file @p file into the folder @p out (created) as
  /// bench.prm with its Output/Directory pointing there, so that benchmark
  /// runs of the program write nothing into the working directory.
  inline std::string prm_writing_to(const std::string &file, const std::filesystem::path &out)
  {
    std::filesystem::create_directories(out);
    const std::string prm = (out / "bench.prm").string();
    std::ifstream     in(file);
    std::ofstream     copy(prm);
    copy << in.rdbuf() << "\nsubsection Output\n  set Directory = " << out.string()
         << "\nend\n";
    return prm;
  }
} // namespace cdea_bench
