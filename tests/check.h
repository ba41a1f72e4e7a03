#pragma once
// Minimal assertion helpers for the test programs: each failed check prints
// what was compared and the test exits non-zero at the end.
//
// The tests/test_NAME.cc are linked into one program, cdea_tests
// (tests/cdea_tests.cc), so that the suite links against deal.II once
// instead of once per test; a file that registers a plugin of its own is a
// program of its own, test_NAME (tests/CMakeLists.txt). A test file names
// its entry point
//     CDEA_TEST_MAIN()                       or
//     CDEA_TEST_MAIN(int argc, char **argv)
// where a program has `int main(...)`; it is registered under the file's
// name, and `cdea_tests test_NAME [ARGUMENTS]` runs it in a process of its
// own with argv[0] = "test_NAME" (ctest: one test per file, as before).

#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
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

  /// The entry point of each test file, by the file's name without folder
  /// and extension ("test_sweep").
  using TestMain = std::function<int(int, char **)>;
  inline std::map<std::string, TestMain> &test_mains()
  {
    static std::map<std::string, TestMain> mains;
    return mains;
  }

  inline std::string test_name(const std::string &file)
  {
    const std::string base = file.substr(file.find_last_of('/') + 1);
    return base.substr(0, base.rfind('.'));
  }

  inline bool register_test(const char *file, int (*entry)(int, char **))
  {
    return test_mains().emplace(test_name(file), entry).second;
  }

  inline bool register_test(const char *file, int (*entry)())
  {
    return test_mains().emplace(test_name(file), [entry](int, char **) { return entry(); }).second;
  }
} // namespace cdea_test

/// In place of `int main(...)` in a test file: the file's entry point in
/// cdea_tests, with the same body and return value.
#define CDEA_TEST_MAIN(...)                                                      \
  static int cdea_test_main(__VA_ARGS__);                                        \
  [[maybe_unused]] static const bool cdea_test_registered =                      \
    cdea_test::register_test(__FILE__, &cdea_test_main);                         \
  static int cdea_test_main(__VA_ARGS__)
