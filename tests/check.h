#pragma once
// Minimal assertion helpers for the test programs: each failed check prints
// what was compared and the test exits non-zero at the end.

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>

namespace cdea_test
{
  /// Ten significant digits in every printed comparison.
  inline std::ostream &out()
  {
    static const bool once = [] {
      std::cout << std::setprecision(10);
      return true;
    }();
    (void)once;
    return std::cout;
  }

  inline int &failures()
  {
    static int n = 0;
    return n;
  }

  /// |a - b| <= tol (absolute).
  inline bool check_close(const double a, const double b, const double tol,
                          const std::string &what)
  {
    const bool ok = std::abs(a - b) <= tol;
    out() << (ok ? "  ok   " : "  FAIL ") << what << ": " << a << " vs " << b
              << " (|diff| " << std::abs(a - b) << ", tol " << tol << ")\n";
    if (!ok)
      ++failures();
    return ok;
  }

  /// |a - b| <= tol |b| (relative).
  inline bool check_rel(const double a, const double b, const double tol,
                        const std::string &what)
  {
    const double rel = std::abs(a - b) / std::abs(b);
    const bool   ok  = rel <= tol;
    out() << (ok ? "  ok   " : "  FAIL ") << what << ": " << a << " vs " << b
              << " (rel " << rel << ", tol " << tol << ")\n";
    if (!ok)
      ++failures();
    return ok;
  }

  inline bool check(const bool condition, const std::string &what)
  {
    out() << (condition ? "  ok   " : "  FAIL ") << what << "\n";
    if (!condition)
      ++failures();
    return condition;
  }

  inline int finish()
  {
    std::cout << (failures() == 0 ? "all checks passed" : "checks failed: ") ;
    if (failures() != 0)
      std::cout << failures();
    std::cout << "\n";
    return failures() == 0 ? 0 : 1;
  }
} // namespace cdea_test
