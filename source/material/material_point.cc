// The material point of a homogeneous test (material_point.h): the stages
// of the time scheme, the transverse balance of uniaxial tension, and the
// forward sensitivities of every stage.

#include <cdea/base/format.h>
#include <cdea/material/material_point.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cdea
{
  std::string test_kind_name(const TestKind kind)
  {
    switch (kind)
      {
        case TestKind::uniaxial:
          return "uniaxial";
        case TestKind::equibiaxial:
          return "equibiaxial";
        case TestKind::pure_shear:
          return "pure shear";
      }
    return "unknown";
  }

  namespace
  {
    using Matrix = Eigen::MatrixXd;
    using Row    = Eigen::RowVectorXd;

    /// Map of a row-major block of @p data (rows x columns).
    Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>
    row_major(const std::vector<double> &data, const Eigen::Index rows, const Eigen::Index columns)
    {
      return {data.data(), rows, columns};
    }

    /// The transverse balance of uniaxial tension converges when Newton's
    /// update of l2 is below this (relative): s2 is then zero to about
    /// s22 l2 times it.
    constexpr double transverse_tolerance = 1e-13;
    constexpr unsigned int transverse_iterations = 50;

    /// a_10 of the one stage of backward Euler (Yhat = y_n) and of the
    /// trapezoidal rule (Yhat = y_n + h/2 K_n).
    const std::vector<double> backward_euler_row{0.}, trapezoidal_row{0.5};
  } // namespace

  class MaterialPoint::Impl
  {
  public:
    Impl(const MembraneLaw &law, const MaterialPointSettings &settings)
      : law(law)
      , settings(settings)
      , tableau(law.n_evolving() > 0 ? esdirk_tableau(settings.method) : nullptr)
      , n(law.n_internal_variables())
      , ne(law.n_evolving())
      , stages(tableau ? tableau->stages() : 2)
      , stored(stages, std::vector<double>(n))
      , start(n)
      , shifted(n)
      , y(ne)
      , y_j(ne)
      , rate(ne)
      , dK(stages)
    {}

    bool run(const StretchHistory &history, const std::vector<LawParameter> &parameters,
             MaterialPointResult &out, std::string &message);

  private:
    const MembraneLaw          &law;
    const MaterialPointSettings settings;
    const EsdirkTableau        *tableau; ///< nullptr: backward Euler or trapezoidal
    const unsigned int          n, ne, stages;
    TestKind                    kind = TestKind::uniaxial;
    std::vector<LawParameter>   parameters;
    Eigen::Index                P = 0;

    /// Stored numbers of every stage of the step (stored[0]: its start), the
    /// accepted state, a shifted stage start; l2 of the accepted state.
    std::vector<std::vector<double>> stored;
    std::vector<double>              start, shifted, y, y_j, rate;
    double                           l2 = 1.;
    LawResponse                      response;
    unsigned int                     evaluations = 0;

    /// Sensitivities: dy (ne x P) of the accepted state, dK of each stage,
    /// the stage's dY, dl2 and ds1; work storage.
    Matrix                dy, dY, A, ZG, solved, S_p, f_p, S_y, f_y, f_l;
    std::vector<Matrix>   dK;
    Eigen::PartialPivLU<Matrix> lu; ///< of A, its storage kept from stage to stage
    Row                   dl2, ds1;
    InternalLinearization lin;

    bool evaluate(double l1, double l2_trial, const InternalStep &step, unsigned int request);
    bool balance(double l1, double guess, const InternalStep &step, std::string &why);
    bool relaxed_start(double l1, std::string &why);
    bool explicit_derivatives(double l1, const double *state, std::string &why);
    bool linearization(double l1, const double *state, std::string &why);
    bool stage_sensitivity(unsigned int i, const std::vector<double> &a_row, double h, double gh,
                           double l1, const double *state, std::string &why);
    bool step(double h, double l1_start, double l1_end, std::string &why);
    bool interval(const StretchHistory &history, std::size_t k, double change,
                  unsigned int &steps, std::string &why);
    void record(MaterialPointResult &out, std::size_t sample) const;
  };

  MaterialPoint::MaterialPoint(const MembraneLaw &law, const MaterialPointSettings &settings)
    : impl(std::make_unique<Impl>(law, settings))
  {}

  MaterialPoint::~MaterialPoint() = default;

  bool MaterialPoint::run(const StretchHistory &history, const std::vector<LawParameter> &parameters,
                          MaterialPointResult &result, std::string &message)
  {
    return impl->run(history, parameters, result, message);
  }

  bool MaterialPoint::Impl::evaluate(const double l1, const double l2_trial,
                                     const InternalStep &step, const unsigned int request)
  {
    ++evaluations;
    return law.evaluate({l1, l2_trial, 0.}, step, request, response) &&
           std::isfinite(response.stress.s1) && std::isfinite(response.stress.s2);
  }

  // Uniaxial: Newton on s2(l1, l2) = 0 with the consistent tangent s22 (each
  // evaluation the law's whole update over @p step), halving a step that
  // leaves the law's range; the state kept is the last one evaluated, whose
  // update of l2 was below the tolerance. The other tests prescribe l2.
  bool MaterialPoint::Impl::balance(const double l1, const double guess, const InternalStep &step,
                                    std::string &why)
  {
    if (kind != TestKind::uniaxial)
      {
        const double fixed = kind == TestKind::equibiaxial ? l1 : 1.;
        if (evaluate(l1, fixed, step, law_stress))
          {
            l2 = fixed;
            return true;
          }
        why = "the law cannot be evaluated at l1 = " + format_number(l1) + ", l2 = " +
              format_number(fixed) + " (outside its range, or its internal update failed)";
        return false;
      }
    double x = guess, good = 0.;
    for (unsigned int it = 0; it < transverse_iterations; ++it)
      {
        if (!evaluate(l1, x, step, law_stress | law_tangent))
          {
            if (!(good > 0.))
              break;
            x = 0.5 * (x + good);
            continue;
          }
        if (!(response.tangent.s22 > 0.))
          {
            why = "the transverse stiffness ds2/dl2 is not positive at l1 = " + format_number(l1) +
                  ", l2 = " + format_number(x);
            return false;
          }
        const double dx = -response.stress.s2 / response.tangent.s22;
        if (std::abs(dx) <= transverse_tolerance * x)
          {
            l2 = x;
            return true;
          }
        good = x;
        x    = x + dx > 0. ? x + dx : 0.5 * x;
      }
    why = "no transverse stretch with s2 = 0 at l1 = " + format_number(l1) +
          " (outside the law's range, or its internal update failed)";
    return false;
  }

  // S_p (2 x P) and f_p (ne x P) at the state @p state of stretch (l1, l2).
  bool MaterialPoint::Impl::explicit_derivatives(const double l1, const double *state,
                                                 std::string &why)
  {
    S_p.resize(2, P);
    f_p.resize(ne, P);
    rate.resize(ne);
    for (Eigen::Index j = 0; j < P; ++j)
      {
        NominalStress ds{0., 0.};
        if (!law.evolving_parameter_derivative({l1, l2, 0.}, state, parameters[std::size_t(j)], ds,
                                               rate.data()))
          {
            why = "the law gives no derivative with respect to parameter " + std::to_string(j + 1) +
                  " (LawParameter " + std::to_string(int(parameters[std::size_t(j)])) + ")";
            return false;
          }
        S_p(0, j) = ds.s1;
        S_p(1, j) = ds.s2;
        for (unsigned int r = 0; r < ne; ++r)
          f_p(r, j) = rate[r];
      }
    return true;
  }

  // The law's linearization at the state: S_l (in lin.instantaneous), S_y, f_y, f_l.
  bool MaterialPoint::Impl::linearization(const double l1, const double *state, std::string &why)
  {
    if (!law.linearize({l1, l2, 0.}, state, lin))
      {
        why = "the law cannot be linearized at l1 = " + format_number(l1) + ", l2 = " +
              format_number(l2);
        return false;
      }
    S_y = row_major(lin.stress_y, 2, ne);
    f_y = row_major(lin.rate_y, ne, ne);
    f_l = row_major(lin.rate_l, ne, 2);
    return true;
  }

  // The relaxed start at l1: the internal variables in equilibrium with the
  // stretches (dt = infinity), l2 from the relaxed s2 = 0; its derivatives
  // with the relaxed tangent, and f(l, y, p) = 0: dy = -f_y^-1 (f_l dl + f_p).
  bool MaterialPoint::Impl::relaxed_start(const double l1, std::string &why)
  {
    const InternalStep relaxed{nullptr, start.data(), std::numeric_limits<double>::infinity(),
                               TimeScheme::backward_euler};
    if (!balance(l1, 1. / std::sqrt(l1), relaxed, why))
      return false;
    law.relaxed_internal_variables({l1, l2, 0.}, start.data());
    if (P == 0)
      return true;
    const StressTangent relaxed_tangent = response.tangent;
    if (!explicit_derivatives(l1, start.data(), why))
      return false;
    dl2.setZero(P);
    if (kind == TestKind::uniaxial)
      dl2 = -S_p.row(1) / relaxed_tangent.s22;
    ds1 = relaxed_tangent.s12 * dl2 + S_p.row(0);
    dy.setZero(ne, P);
    if (ne > 0)
      {
        if (!linearization(l1, start.data(), why))
          return false;
        dy = -f_y.partialPivLu().solve(f_l.col(1) * dl2 + f_p);
      }
    for (Matrix &k : dK)
      k.setZero(ne, P);
    return true;
  }

  // Stage i's derivatives (material_point.h): Z = A^-1 (dYhat + gh f_p),
  // G = A^-1 gh f_l[:, 2]; uniaxial: dl2 from ds2 = 0.
  bool MaterialPoint::Impl::stage_sensitivity(const unsigned int i, const std::vector<double> &a_row,
                                              const double h, const double gh, const double l1,
                                              const double *state, std::string &why)
  {
    if (!explicit_derivatives(l1, state, why) || !linearization(l1, state, why))
      return false;
    const StressTangent &C0 = lin.instantaneous;
    if (ne == 0)
      {
        dl2 = kind == TestKind::uniaxial ? Row(-S_p.row(1) / C0.s22) : Row::Zero(P);
        ds1 = C0.s12 * dl2 + S_p.row(0);
        return true;
      }
    A = -gh * f_y;
    A.diagonal().array() += 1.;
    ZG.resize(ne, P + 1);
    ZG.leftCols(P) = dy + gh * f_p;
    for (unsigned int j = 0; j < i; ++j)
      if (a_row[j] != 0.)
        ZG.leftCols(P) += h * a_row[j] * dK[j];
    ZG.col(P) = gh * f_l.col(1);
    // Storage kept from stage to stage: no allocation per stage.
    lu.compute(A);
    solved.resize(ne, P + 1);
    solved.noalias() = lu.solve(ZG);
    dY               = solved.leftCols(P);
    if (kind == TestKind::uniaxial)
      {
        const double c22 = C0.s22 + S_y.row(1).dot(solved.col(P));
        if (!(std::abs(c22) > 0.))
          {
            why = "the transverse stiffness of the stage is zero";
            return false;
          }
        dl2.noalias() = -(S_p.row(1) + S_y.row(1) * dY) / c22;
        dY.noalias() += solved.col(P) * dl2;
      }
    else
      dl2.setZero(P);
    ds1.noalias()   = C0.s12 * dl2 + S_y.row(0) * dY + S_p.row(0);
    dK[i].noalias() = f_y * dY;
    dK[i] += f_l.col(1) * dl2 + f_p;
    return true;
  }

  // One step of length h, l1 linear from @p l1_start to @p l1_end: the one
  // stage of backward Euler or the trapezoidal rule (the law's update of that
  // scheme; for the sensitivities Yhat = y_n (+ h/2 K_n), gamma = 1 (1/2)),
  // or the implicit stages of the ESDIRK tableau.
  bool MaterialPoint::Impl::step(const double h, const double l1_start, const double l1_end,
                                 std::string &why)
  {
    stored[0] = start;
    if (!tableau)
      {
        const bool         trapezoidal = settings.method == TimeMethod::trapezoidal;
        const InternalStep s{start.data(), stored[1].data(), h,
                             trapezoidal ? TimeScheme::trapezoidal : TimeScheme::backward_euler};
        // The law's local Newton starts from the current numbers: from
        // y_n + h K_n rather than y_n (the same answer, fewer iterations).
        stored[1] = start;
        law.evolving_state(start.data(), y.data(), rate.data());
        for (unsigned int k = 0; k < ne; ++k)
          y[k] += h * rate[k];
        law.set_evolving_state(y.data(), stored[1].data());
        if (!balance(l1_end, l2 * std::sqrt(l1_start / l1_end), s, why) ||
            (P > 0 && !stage_sensitivity(1, trapezoidal ? trapezoidal_row : backward_euler_row, h,
                                         (trapezoidal ? 0.5 : 1.) * h, l1_end, stored[1].data(),
                                         why)))
          return false;
      }
    else
      for (unsigned int i = 1, previous = 0; i < stages; previous = i++)
        {
          // Yhat_i = y_n + h sum_{j<i} a_ij K_j, K_j the rate stored at stage j.
          law.evolving_state(start.data(), y.data(), rate.data());
          for (unsigned int j = 0; j < i; ++j)
            if (tableau->a[i][j] != 0.)
              {
                law.evolving_state(stored[j].data(), y_j.data(), rate.data());
                for (unsigned int k = 0; k < ne; ++k)
                  y[k] += h * tableau->a[i][j] * rate[k];
              }
          shifted = start;
          law.set_evolving_state(y.data(), shifted.data());
          stored[i]          = shifted;
          const double       gh = tableau->gamma * h;
          const double       l1 = l1_start + tableau->c[i] * (l1_end - l1_start);
          const double       l1_before = l1_start + tableau->c[previous] * (l1_end - l1_start);
          const InternalStep s{shifted.data(), stored[i].data(), gh, TimeScheme::backward_euler};
          if (!balance(l1, l2 * std::sqrt(l1_before / l1), s, why) ||
              (P > 0 && !stage_sensitivity(i, tableau->a[i], h, gh, l1, stored[i].data(), why)))
            return false;
        }
    start = stored[stages - 1];
    if (P > 0)
      {
        if (ne > 0)
          dy = dY;
        dK[0] = dK[stages - 1];
      }
    return true;
  }

  void MaterialPoint::Impl::record(MaterialPointResult &out, const std::size_t sample) const
  {
    out.stress[sample]     = response.stress.s1;
    out.transverse[sample] = l2;
    if (settings.record_internal)
      std::copy(start.begin(), start.end(), out.internal.begin() + std::ptrdiff_t(sample * n));
    if (P > 0)
      out.jacobian.row(Eigen::Index(sample)) = ds1;
  }

  // The steps of interval k - 1 -> k (MaterialPointSettings): equal ones of
  // at most max_step and max_stretch_step, shorter after the last change of
  // the stretch rate at @p change: at most step_growth (t - change), at
  // least the interval over substeps_after_change; the last one at most 1.5
  // times the one before (no sliver at the sample).
  bool MaterialPoint::Impl::interval(const StretchHistory &history, const std::size_t k,
                                     const double change, unsigned int &steps, std::string &why)
  {
    const double t0 = history.time[k - 1], t1 = history.time[k], span = t1 - t0;
    const double l0 = history.stretch[k - 1], dl = history.stretch[k] - l0;
    if (ne == 0)
      return ++steps, step(span, l0, history.stretch[k], why);
    const double cap = span / std::max({1., std::ceil(span / settings.max_step),
                                        std::ceil(std::abs(dl) / settings.max_stretch_step)});
    const double floor = span / std::max(1u, settings.substeps_after_change);
    for (double t = t0; t < t1;)
      {
        double h = cap;
        if (settings.step_growth > 0.)
          h = std::min(cap, std::max(settings.step_growth * (t - change), floor));
        const bool   last = t + 1.5 * h >= t1 - 1e-12 * span;
        const double next = last ? t1 : t + h;
        if (!step(next - t, l0 + dl * (t - t0) / span,
                  last ? history.stretch[k] : l0 + dl * (next - t0) / span, why))
          return false;
        ++steps;
        t = next;
      }
    return true;
  }

  bool MaterialPoint::Impl::run(const StretchHistory &history,
                                const std::vector<LawParameter> &list, MaterialPointResult &out,
                                std::string &message)
  {
    const std::size_t N = history.time.size();
    kind                = history.kind;
    parameters          = list;
    P                   = Eigen::Index(list.size());
    evaluations         = 0;
    out.stress.assign(N, 0.);
    out.transverse.assign(N, 0.);
    out.internal.assign(settings.record_internal ? N * n : 0, 0.);
    out.jacobian.setZero(Eigen::Index(N), P);
    out.steps         = 0;
    out.failed_sample = N;
    if (N == 0 || history.stretch.size() != N)
      {
        message = "the history needs as many stretches as times, at least one";
        return false;
      }
    std::string why;
    const auto  fail = [&](const std::size_t k) {
      message = "sample " + std::to_string(k + 1) + " (t = " + format_number(history.time[k]) +
                " s, stretch " + format_number(history.stretch[k]) + "): " + why;
      out.evaluations   = evaluations;
      out.failed_sample = k;
      return false;
    };
    if (!relaxed_start(history.stretch[0], why))
      return fail(0);
    record(out, 0);
    // A change of the stretch rate by more than a tenth of the largest one
    // restarts the grading (the history starts from rest).
    double largest = 0.;
    for (std::size_t k = 1; k < N; ++k)
      largest = std::max(largest, std::abs(history.stretch[k] - history.stretch[k - 1]) /
                                    (history.time[k] - history.time[k - 1]));
    double change = history.time[0], rate = 0.;
    for (std::size_t k = 1; k < N; ++k)
      {
        const double span = history.time[k] - history.time[k - 1];
        if (!(span > 0.))
          {
            why = "the sample times must increase strictly";
            return fail(k);
          }
        const double next = (history.stretch[k] - history.stretch[k - 1]) / span;
        if (std::abs(next - rate) > 0.1 * largest)
          change = history.time[k - 1];
        rate = next;
        if (!interval(history, k, change, out.steps, why))
          return fail(k);
        record(out, k);
      }
    out.evaluations = evaluations;
    return true;
  }
} // namespace cdea
