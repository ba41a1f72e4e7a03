// Forward sensitivities through the stages of a quasi-static time run (see
// time_sensitivity.h).

#include <cdea/fe/membrane_model.h>
#include <cdea/fe/model_access.h>
#include <cdea/fe/time_sensitivity.h>

#include <Eigen/Dense>

#include <cmath>

namespace cdea
{
  namespace
  {
    /// B <- A^-1 B for a small square A (overwritten) by Gaussian elimination
    /// with partial pivoting: the points' systems have a few rows, where
    /// Eigen's blocked solvers cost more than the arithmetic. False if A is
    /// singular.
    bool solve_small(Eigen::MatrixXd &A, Eigen::Ref<Eigen::MatrixXd> B)
    {
      const Eigen::Index n = A.rows();
      for (Eigen::Index k = 0; k < n; ++k)
        {
          Eigen::Index pivot = k;
          for (Eigen::Index i = k + 1; i < n; ++i)
            if (std::abs(A(i, k)) > std::abs(A(pivot, k)))
              pivot = i;
          if (!(A(pivot, k) != 0.))
            return false;
          if (pivot != k)
            {
              A.row(k).swap(A.row(pivot));
              B.row(k).swap(B.row(pivot));
            }
          for (Eigen::Index i = k + 1; i < n; ++i)
            {
              const double f = A(i, k) / A(k, k);
              if (f == 0.)
                continue;
              A.row(i).tail(n - k) -= f * A.row(k).tail(n - k);
              B.row(i) -= f * B.row(k);
            }
        }
      for (Eigen::Index k = n - 1; k >= 0; --k)
        {
          for (Eigen::Index j = k + 1; j < n; ++j)
            B.row(k) -= A(k, j) * B.row(j);
          B.row(k) /= A(k, k);
        }
      return true;
    }

    /// "the shear modulus", ..., "the law's own constant 3" (from 0).
    std::string parameter_name(const LawParameter p)
    {
      switch (p)
        {
          case LawParameter::shear_modulus:
            return "the shear modulus";
          case LawParameter::jlim:
            return "Jlim";
          case LawParameter::permittivity:
            return "the permittivity";
          case LawParameter::voltage:
            return "the voltage";
        }
      return "the law's own constant " + std::to_string(own_constant_index(p));
    }
  } // namespace

  class TimeSensitivity::Data
  {
  public:
    using Matrix = Eigen::MatrixXd;

    ModelAccess              &m;
    std::vector<LawParameter> parameters;
    unsigned int              P = 0, ne = 0, n_points = 0;
    double                    voltage_reference = 1.;

    /// The state derivatives: du and dy (points x ne rows) at the accepted
    /// state, dK of each stage of the step being taken (dK[0]: the rate at
    /// its start), and the last stage's du and dY.
    Matrix du, dy, du_trial, dY_trial;
    std::vector<Matrix> dK;

    /// One point of a stage: its variations and what the second pass needs.
    struct Point
    {
      const unsigned int *dofs = nullptr;
      double              w    = 0.;
      std::vector<double> dl1, dl2;
      Matrix              f_y, f_l, f_p, Z, G; ///< G = gamma h A^-1 f_l
    };
    std::vector<Point> points;
    /// Work storage of the points, kept from point to point and stage to stage.
    mutable std::vector<double>           rate;
    mutable InternalLinearization         lin;
    Matrix                                A, ZG, S_p, S_y, dl, dY, dYhat, rhs;

    Data(ModelAccess &m, std::vector<LawParameter> list, const unsigned int stages,
         const double reference)
      : m(m)
      , parameters(std::move(list))
      , P(parameters.size())
      , ne(m.membrane().law().n_evolving())
      , voltage_reference(reference)
      , dK(stages)
    {}

    /// S_p (2 x P) and f_p (ne x P) at @p v; false with @p message.
    bool explicit_derivatives(const VariationPoint &v, Matrix &S_p, Matrix &f_p,
                              std::string &message) const
    {
      const MembraneLaw &law = m.membrane().law();
      rate.resize(ne);
      S_p.setZero(2, P);
      f_p.setZero(ne, P);
      for (unsigned int j = 0; j < P; ++j)
        {
          NominalStress ds{0., 0.};
          if (!law.evolving_parameter_derivative(v.input, v.stored, parameters[j], ds,
                                                 rate.data()))
            {
              message = "the material law gives no derivative with respect to " +
                        parameter_name(parameters[j]) + " at a point of cell " +
                        std::to_string(v.cell) + " (a law with evolving internal variables "
                        "needs evolving_parameter_derivative(); a branch's constants are "
                        "own constants 0 to 2 n - 1)";
              return false;
            }
          // d/dPhi of V(t) Phi / reference is V(t) / reference times d/dV.
          const double factor =
            parameters[j] == LawParameter::voltage ? v.input.voltage / voltage_reference : 1.;
          S_p(0, j) = factor * ds.s1;
          S_p(1, j) = factor * ds.s2;
          for (unsigned int r = 0; r < ne; ++r)
            f_p(r, j) = factor * rate[r];
        }
      return true;
    }

    /// The law's linearization at @p v as matrices; false with @p message.
    bool linearization(const VariationPoint &v, Matrix &S_y, Matrix &f_y, Matrix &f_l,
                       std::string &message) const
    {
      if (!m.membrane().law().linearize(v.input, v.stored, lin))
        {
          message = "the material law cannot be linearized at a point of cell " +
                    std::to_string(v.cell);
          return false;
        }
      S_y = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic,
                                           Eigen::RowMajor>>(lin.stress_y.data(), 2, ne);
      f_y = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic,
                                           Eigen::RowMajor>>(lin.rate_y.data(), ne, ne);
      f_l = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic,
                                           Eigen::RowMajor>>(lin.rate_l.data(), ne, 2);
      return true;
    }

    /// Adds -w B^T E (E: 2 x P) of the point to @p rhs.
    static void add_force(const VariationPoint &v, const Matrix &E, Matrix &rhs)
    {
      for (std::size_t i = 0; i < v.dl1.size(); ++i)
        rhs.row(v.dofs[i]) -= v.w * (v.dl1[i] * E.row(0) + v.dl2[i] * E.row(1));
    }

    /// dl = B du of a point (2 x P).
    static void stretch_change(const Point &p, const Matrix &u, Matrix &dl)
    {
      dl.setZero(2, u.cols());
      for (std::size_t i = 0; i < p.dl1.size(); ++i)
        {
          dl.row(0) += p.dl1[i] * u.row(p.dofs[i]);
          dl.row(1) += p.dl2[i] * u.row(p.dofs[i]);
        }
    }

    /// u = K^-1 rhs with the model's factored tangent; false if singular.
    bool solve(const Matrix &rhs, Matrix &u, std::string &message)
    {
      u.resize(rhs.rows(), P);
      Eigen::VectorXd column;
      for (unsigned int j = 0; j < P; ++j)
        {
          m.solve_tangent(rhs.col(j), column);
          if (!column.allFinite())
            {
              message = "the tangent of the state is singular";
              return false;
            }
          u.col(j) = column;
        }
      return true;
    }
  };

  TimeSensitivity::TimeSensitivity(MembraneModel &model, std::vector<LawParameter> parameters,
                                   const unsigned int stages, const double voltage_reference)
    : data(std::make_unique<Data>(model.access(), std::move(parameters), stages, voltage_reference))
  {}

  TimeSensitivity::~TimeSensitivity() = default;

  bool TimeSensitivity::start_relaxed(std::string &message)
  {
    Data        &d = *data;
    ModelAccess &m = d.m;
    // The tangent with the internal variables relaxed (network A alone).
    if (!m.assemble_without_inertia(InternalVariables::relaxed,
                                    assemble_residual | assemble_tangent))
      {
        message = "the start of the run lies outside the material's range";
        return false;
      }
    const Discretization &mesh = m.discretization();
    Data::Matrix rhs = Data::Matrix::Zero(mesh.n_dofs(), d.P), S_p, f_p;
    bool         ok  = true;
    m.for_each_variation_point([&](const VariationPoint &v) {
      if (ok && (ok = d.explicit_derivatives(v, S_p, f_p, message)))
        Data::add_force(v, S_p, rhs);
    });
    for (const unsigned int i : mesh.constrained)
      rhs.row(i).setZero();
    ok = ok && d.solve(rhs, d.du, message);
    if (!ok)
      return false;
    // f(l, y, p) = 0 at every point: dy = -f_y^-1 (f_l dl + f_p).
    std::vector<Data::Matrix> blocks;
    Data::Matrix              S_y, f_y, f_l;
    m.for_each_variation_point([&](const VariationPoint &v) {
      if (!ok)
        return;
      if (d.ne == 0)
        {
          blocks.emplace_back(0, d.P);
          return;
        }
      Data::Point p;
      p.dofs = v.dofs;
      p.dl1  = v.dl1;
      p.dl2  = v.dl2;
      ok     = d.linearization(v, S_y, f_y, f_l, message) &&
           d.explicit_derivatives(v, S_p, f_p, message);
      if (ok)
        {
          Data::stretch_change(p, d.du, d.dl);
          blocks.push_back(-f_y.partialPivLu().solve(f_l * d.dl + f_p));
        }
    });
    if (!ok)
      return false;
    d.n_points = blocks.size();
    d.dy.setZero(Eigen::Index(d.n_points) * d.ne, d.P);
    for (unsigned int q = 0; q < d.n_points; ++q)
      d.dy.middleRows(Eigen::Index(q) * d.ne, d.ne) = blocks[q];
    // The rate is 0 at every relaxed point, and so is its derivative.
    for (Data::Matrix &k : d.dK)
      k.setZero(d.dy.rows(), d.P);
    return true;
  }

  bool TimeSensitivity::stage(const unsigned int i, const std::vector<double> &a_row,
                              const double h, const double gh, std::string &message)
  {
    Data        &d = *data;
    ModelAccess &m = d.m;
    if (!m.state_tangent())
      {
        message = "the stage lies outside the material's range";
        return false;
      }
    const Discretization &mesh = m.discretization();
    // dYhat = dy_n + h sum_j a_ij dK_j.
    d.dYhat = d.dy;
    for (unsigned int j = 0; j < i; ++j)
      if (a_row[j] != 0.)
        d.dYhat += h * a_row[j] * d.dK[j];

    d.rhs.setZero(mesh.n_dofs(), d.P);
    d.points.resize(d.n_points);
    unsigned int q  = 0;
    bool         ok = true;
    m.for_each_variation_point([&](const VariationPoint &v) {
      if (!ok)
        return;
      Data::Point &p = d.points[q];
      p.dofs         = v.dofs;
      p.w            = v.w;
      p.dl1          = v.dl1;
      p.dl2          = v.dl2;
      ok             = d.explicit_derivatives(v, d.S_p, p.f_p, message) &&
           (d.ne == 0 || d.linearization(v, d.S_y, p.f_y, p.f_l, message));
      if (!ok)
        return;
      if (d.ne > 0)
        {
          // A = I - gamma h f_y; Z = A^-1 (dYhat + gamma h f_p), G = gamma h A^-1 f_l.
          d.A = -gh * p.f_y;
          d.A.diagonal().array() += 1.;
          d.ZG.resize(d.ne, d.P + 2);
          d.ZG.leftCols(d.P)  = d.dYhat.middleRows(Eigen::Index(q) * d.ne, d.ne) + gh * p.f_p;
          d.ZG.rightCols(2)   = gh * p.f_l;
          if (!(ok = solve_small(d.A, d.ZG)))
            {
              message = "the stage's update of the internal variables is singular";
              return;
            }
          p.Z = d.ZG.leftCols(d.P);
          p.G = d.ZG.rightCols(2);
          d.S_p += d.S_y.lazyProduct(p.Z);
        }
      Data::add_force(v, d.S_p, d.rhs);
      ++q;
    });
    for (const unsigned int c : mesh.constrained)
      d.rhs.row(c).setZero();
    if (!ok || !d.solve(d.rhs, d.du_trial, message))
      return false;
    // The internal variables and their rates, point by point.
    d.dY_trial.resize(d.dy.rows(), d.P);
    Data::Matrix &dK = d.dK[i];
    dK.resize(d.dy.rows(), d.P);
    for (unsigned int k = 0; k < d.n_points && d.ne > 0; ++k)
      {
        const Data::Point &p = d.points[k];
        Data::stretch_change(p, d.du_trial, d.dl);
        d.dY = p.Z + p.G.lazyProduct(d.dl);
        d.dY_trial.middleRows(Eigen::Index(k) * d.ne, d.ne) = d.dY;
        dK.middleRows(Eigen::Index(k) * d.ne, d.ne) =
          p.f_p + p.f_y.lazyProduct(d.dY) + p.f_l.lazyProduct(d.dl);
      }
    return true;
  }

  void TimeSensitivity::accept(const unsigned int last)
  {
    Data &d = *data;
    d.du    = d.du_trial;
    d.dy    = d.dY_trial;
    d.dK[0] = d.dK[last];
  }

  double TimeSensitivity::displacement(Eigen::VectorXd &gradient) const
  {
    const Data            &d    = *data;
    const Discretization  &mesh = d.m.discretization();
    const Eigen::VectorXd &x    = d.m.unknowns();
    const double           dz   = x[mesh.z_inner] - x[mesh.z_outer];
    gradient =
      (dz >= 0. ? 1. : -1.) * (d.du.row(mesh.z_inner) - d.du.row(mesh.z_outer)).transpose();
    return std::abs(dz);
  }
} // namespace cdea
