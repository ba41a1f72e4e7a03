// The model selection's rules (design/model_selection.h) on numbers worked
// by hand (its fits on real histories: tests/fit_models.sh):
//
// 1. Calibration/Candidate models parsed: laws, branch counts, blanks; the
//    refusals name the entry and the item.
// 2. recommend(): two files of n samples, models A (held-out relative rms
//    0.010, 0.012) and B (0.011, 0.013): the gap 0.001 against the spread
//    sqrt(SE_A^2 + SE_B^2), SE = sqrt(sum e_i^2 / (2 n)) / 2 (the paired
//    differences are equal, their standard error 0): n = 100 gives 8.17e-4,
//    decided; n = 50 gives 1.155e-3, undecided; a third model worse on one
//    file and better on the other gives the differences' standard error;
//    one file: no held-out error, the lowest BIC, undecided.

#include <cdea/base/text.h>
#include <cdea/design/model_selection.h>

#include "check.h"

#include <cmath>
#include <limits>

using namespace cdea;
using cdea_test::check;
using cdea_test::check_close;

namespace
{
  std::string refusal(const std::string &text)
  {
    try
      {
        candidate_models(text);
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }

  void parsing()
  {
    const auto c = candidate_models(" elastic 0,elastic   2 , neo-hooke 0");
    check(c.size() == 3 && c[0].name() == "elastic 0" && c[1].branches == 2 &&
            c[2].law == "neo-hooke" && c[2].branches == 0,
          "three candidates with blanks anywhere");
    check(candidate_models("  ").empty(), "an empty entry: no candidates");
    for (const auto &[text, message] :
         std::vector<std::pair<std::string, std::string>>{
           {"elastic 1, gent 2", "Calibration/Candidate models: 'gent 2' does not name a law"},
           {"mooney-rivlin 1", "'mooney-rivlin 1' puts branches beside mooney-rivlin"},
           {"elastic -1", "'elastic -1' has no branch count from 0 to 20"},
           {"elastic 1 2", "'elastic 1 2' is not 'LAW N'"},
           {"elastic 0, elastic 0", "'elastic 0' is given twice"}})
      {
        const std::string got = refusal(text);
        check(got.find(message) != std::string::npos, "'" + text + "' refused: " + got);
      }
  }

  ModelAssessment model(const std::string &law, const unsigned int branches,
                        const std::vector<double> &held_out, const std::size_t samples,
                        const double bic)
  {
    ModelAssessment m;
    m.setup.candidate = {law, branches};
    m.bic             = bic;
    double sum        = 0.;
    for (const double e : held_out)
      {
        TestMeasures t;
        t.samples  = samples;
        t.relative = e;
        m.held_out.push_back(t);
        sum += e;
      }
    m.held_out_error = sum / double(held_out.size());
    return m;
  }

  void decisions()
  {
    for (const std::size_t n : {100u, 50u})
      {
        ModelSelection s;
        s.models = {model("elastic", 2, {0.011, 0.013}, n, 5.), model("elastic", 1, {0.010, 0.012}, n, 1.)};
        recommend(s);
        const double se_a = std::sqrt((0.010 * 0.010 + 0.012 * 0.012) / (2. * double(n))) / 2.,
                     se_b = std::sqrt((0.011 * 0.011 + 0.013 * 0.013) / (2. * double(n))) / 2.;
        const double spread = std::hypot(se_a, se_b);
        check(s.recommended == 1, "the lowest held-out error recommended (n = " + std::to_string(n) + ")");
        check_close(s.spread, spread, 1e-12, "spread sqrt(SE_A^2 + SE_B^2) = " + std::to_string(spread));
        check(s.decided == (n == 100), "decided with n = 100 (gap 0.001 > 8.17e-4), not with 50 "
                                       "(1.155e-3): " + s.verdict);
      }
    // Paired differences -0.004 and +0.006: mean 0.001, standard error 0.005.
    ModelSelection s;
    s.models = {model("elastic", 1, {0.010, 0.012}, 100000, 1.), model("elastic", 2, {0.006, 0.018}, 100000, 2.)};
    recommend(s);
    check_close(s.spread, 0.005, 1e-12, "the paired differences' standard error where it is larger");
    check(!s.decided && s.verdict.find("cannot decide") != std::string::npos, s.verdict);
    // Undecided with the richer model ahead by held-out error: the simpler
    // one recommended (fewer branches), and the verdict says so.
    ModelSelection rich;
    rich.models = {model("elastic", 2, {0.0100, 0.0120}, 50, 5.), model("elastic", 1, {0.0101, 0.0121}, 50, 1.)};
    recommend(rich);
    check(!rich.decided && rich.recommended == 1 &&
            rich.verdict.find("recommended: the simpler, elastic 1") != std::string::npos,
          "undecided: the simpler model recommended: " + rich.verdict);
    // Decided: the better one, however many constants it has.
    ModelSelection clear;
    clear.models = {model("elastic", 2, {0.010, 0.012}, 100000, 5.), model("elastic", 1, {0.020, 0.024}, 100000, 1.)};
    recommend(clear);
    check(clear.decided && clear.recommended == 0, "decided: the lower held-out error: " + clear.verdict);
    // One file: no held-out error; the lowest BIC.
    const double   nan = std::numeric_limits<double>::quiet_NaN();
    ModelSelection one;
    one.models = {model("elastic", 0, {nan}, 10, 3.), model("elastic", 1, {nan}, 10, -2.)};
    recommend(one);
    check(one.recommended == 1 && !one.decided && std::isnan(one.spread) &&
            one.verdict.find("one file") != std::string::npos,
          "one file: the lowest BIC, undecided: " + one.verdict);
  }
} // namespace

CDEA_TEST_MAIN()
{
  parsing();
  decisions();
  return cdea_test::finish();
}
