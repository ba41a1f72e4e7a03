// The test programs of tests/test_*.cc linked into one (tests/check.h,
// CDEA_TEST_MAIN): `cdea_tests test_NAME [ARGUMENTS]` runs test_NAME's entry
// point with argv = {test_NAME, ARGUMENTS...} and exits with what it returns;
// `cdea_tests --list` prints the names. ctest runs one test per name.

#include "check.h"

#include <cstring>
#include <iostream>

int main(int argc, char **argv)
{
  const auto &mains = cdea_test::test_mains();
  if (argc >= 2 && std::strcmp(argv[1], "--list") == 0)
    {
      for (const auto &[name, entry] : mains)
        std::cout << name << '\n';
      return 0;
    }
  const auto test = argc >= 2 ? mains.find(argv[1]) : mains.end();
  if (test == mains.end())
    {
      std::cerr << "usage: cdea_tests TEST [ARGUMENTS] (TEST one of the names that "
                   "`cdea_tests --list` prints"
                << (argc >= 2 ? std::string("; there is no test '") + argv[1] + "'" : "")
                << ")\n";
      return 2;
    }
  return test->second(argc - 1, argv + 1);
}
