// Exact sensitivities of a converged state by the direct and the adjoint
// method with the factored tangent of the state (see sensitivities.h).

#include <cdea/fe/membrane_model.h>
#include <cdea/fe/model_access.h>
#include <cdea/fe/sensitivities.h>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace cdea
{
  std::string SceneParameter::name() const
  {
    switch (kind)
      {
        case ParameterKind::voltage:
          return "voltage of ring " + std::to_string(index + 1) + " (V)";
        case ParameterKind::shear_modulus:
          return "shear modulus (Pa)";
        case ParameterKind::jlim:
          return "Jlim";
        case ParameterKind::permittivity:
          return "permittivity (F/m)";
        case ParameterKind::mass:
          return "mass (kg)";
        case ParameterKind::prestretch:
          return "pre-stretch";
        case ParameterKind::ring_edge:
          return "ring edge " + std::to_string(index) + " (r/a)";
        case ParameterKind::law_constant:
          return entry;
      }
    return "unknown";
  }

  std::vector<SceneParameter> all_parameters(const unsigned int n_rings)
  {
    std::vector<SceneParameter> list;
    for (unsigned int k = 0; k < n_rings; ++k)
      list.push_back({ParameterKind::voltage, k});
    for (const auto kind : {ParameterKind::shear_modulus, ParameterKind::jlim,
                            ParameterKind::permittivity, ParameterKind::mass,
                            ParameterKind::prestretch})
      list.push_back({kind, 0});
    for (unsigned int k = 1; k < n_rings; ++k)
      list.push_back({ParameterKind::ring_edge, k});
    return list;
  }

  double parameter_value(const Scene &scene, const SceneParameter &p)
  {
    switch (p.kind)
      {
        case ParameterKind::voltage:
          return scene.path.waypoints().back().at(p.index);
        case ParameterKind::shear_modulus:
          return scene.material.shear_modulus;
        case ParameterKind::jlim:
          return scene.material.jlim;
        case ParameterKind::permittivity:
          return scene.material.permittivity;
        case ParameterKind::mass:
          return scene.mass;
        case ParameterKind::prestretch:
          return scene.prestretch;
        case ParameterKind::ring_edge:
          return scene.ring_edges_over_a.at(p.index);
        case ParameterKind::law_constant:
          {
            const auto it = scene.law_constants.find(p.entry);
            if (it != scene.law_constants.end())
              return it->second;
            // A constant that is no number entry (a branch's modulus): the law's value.
            for (const LawConstant &c : scene.law()->own_constants())
              if (c.entry == p.entry && !std::isnan(c.value))
                return c.value;
            throw std::invalid_argument("the scene's law has no constant '" + p.entry + "'");
          }
      }
    return 0.;
  }

  Scene with_parameter(const Scene &scene, const SceneParameter &p, const double value)
  {
    Scene s = scene;
    switch (p.kind)
      {
        case ParameterKind::voltage:
          {
            auto waypoints               = scene.path.waypoints();
            waypoints.back().at(p.index) = value;
            s.path                       = VoltagePath(waypoints);
            break;
          }
        case ParameterKind::shear_modulus:
          s.material.shear_modulus = value;
          break;
        case ParameterKind::jlim:
          s.material.jlim = value;
          break;
        case ParameterKind::permittivity:
          s.material.permittivity = value;
          break;
        case ParameterKind::mass:
          s.mass = value;
          break;
        case ParameterKind::prestretch:
          s.prestretch = value;
          break;
        case ParameterKind::ring_edge:
          s.ring_edges_over_a.at(p.index) = value;
          break;
        case ParameterKind::law_constant:
          s.law_constants[p.entry] = value;
          break;
      }
    return s;
  }

  namespace
  {
    /// A scene parameter as a combination of the kernel's parameters:
    /// d/dp = sum factor d/dp_kernel. The mass acts through F = m g; lam_pre
    /// scales every reference radius by 1/lam_pre (s = lam0/lam, ds/dlam =
    /// -1/lam at s = 1); an edge r_v/a sits at R_k = (r_v/a) a / lam_pre.
    std::pair<unsigned int, double> kernel_column(const SceneParameter &p,
                                                  const ParameterLayout &layout,
                                                  const Scene &scene, const MembraneLaw &law)
    {
      switch (p.kind)
        {
          case ParameterKind::voltage:
            return {layout.voltage(p.index), 1.};
          case ParameterKind::shear_modulus:
            return {layout.shear_modulus(), 1.};
          case ParameterKind::jlim:
            return {layout.jlim(), 1.};
          case ParameterKind::permittivity:
            return {layout.permittivity(), 1.};
          case ParameterKind::mass:
            return {layout.dead_load(), scene.gravity};
          case ParameterKind::prestretch:
            return {layout.mesh_scale(), -1. / scene.prestretch};
          case ParameterKind::ring_edge:
            if (p.index < 1 || p.index >= layout.n_rings)
              throw std::invalid_argument("StateSensitivity: " + p.name() +
                                          " is not an interior edge of this scene");
            return {layout.ring_edge(p.index), scene.disk_radius / scene.prestretch};
          case ParameterKind::law_constant:
            {
              const auto own = law.own_constants();
              for (unsigned int k = 0; k < own.size(); ++k)
                if (own[k].entry == p.entry)
                  return {layout.law_constant(k), 1.};
              throw std::invalid_argument("StateSensitivity: '" + p.entry +
                                          "' is not a constant of the scene's law");
            }
        }
      return {0, 0.};
    }
  } // namespace

  ModelState predicted_state(const ModelState &state, const Eigen::MatrixXd &dx_dp,
                             const Eigen::VectorXd &dp)
  {
    ModelState            guess = state;
    const Eigen::VectorXd x =
      Eigen::Map<const Eigen::VectorXd>(state.unknowns.data(), state.unknowns.size()) +
      dx_dp * dp;
    guess.unknowns.assign(x.data(), x.data() + x.size());
    return guess;
  }

  StateSensitivity::StateSensitivity(MembraneModel &model_in, std::vector<SceneParameter> list)
    : model(model_in.access())
    , parameters_(std::move(list))
  {
    if (!model.state_tangent())
      throw std::runtime_error("StateSensitivity: the state lies outside the material's range");
    if (!model.factor_tangent())
      throw std::runtime_error("StateSensitivity: the tangent of the state is singular");

    // dR/dp and the volume gradient in one pass, into a system of its own
    // (the stored tangent and its factorization stay).
    AssembledSystem s;
    if (!model.assemble(assemble_parameter_derivatives | assemble_volume, s))
      throw std::runtime_error("StateSensitivity: the state lies outside the material's range");
    const Discretization &mesh = model.discretization();
    const unsigned int    N = mesh.n_dofs(), P = parameters_.size();
    dR_dp.setZero(N, P);
    dx_dp.setZero(N, P);
    Eigen::VectorXd column(N), u(N);
    for (unsigned int j = 0; j < P; ++j)
      {
        const auto [k, factor] = kernel_column(parameters_[j], model.kernel().parameters(),
                                               model.scene(), model.material_law());
        column                 = factor * s.parameter_residual[k];
        for (const unsigned int i : mesh.constrained)
          column[i] = 0.;
        dR_dp.col(j) = column;
        model.solve_tangent(-column, u);
        dx_dp.col(j) = u;
      }

    const Eigen::VectorXd &x  = model.unknowns();
    const double           dz = x[mesh.z_inner] - x[mesh.z_outer];
    displacement_   = std::abs(dz);
    d_displacement_ = (dz >= 0. ? 1. : -1.) *
                      (dx_dp.row(mesh.z_inner) - dx_dp.row(mesh.z_outer)).transpose();
    volume_         = s.volume;
    d_volume_       = dx_dp.transpose() * s.volume_gradient;
  }

  Eigen::VectorXd StateSensitivity::adjoint(const Eigen::VectorXd &dJ_dx,
                                            const Eigen::VectorXd &dJ_dp_explicit) const
  {
    // K is symmetric (the second variation of Pi), so K^T lambda = K lambda.
    Eigen::VectorXd lambda;
    model.solve_tangent(dJ_dx, lambda);
    return dJ_dp_explicit - dR_dp.transpose() * lambda;
  }

  bool StateSensitivity::stable() const
  {
    // The constructor left the tangent of the state in the model.
    return model.tangent_positive_definite();
  }

  namespace
  {
    /// s2 and the true field E at points of a converged state with their
    /// derivatives in the scene parameters p: dq/dp = the explicit part at
    /// fixed nodal values + dq/dx dx/dp, per point.
    class PointDerivatives
    {
    public:
      PointDerivatives(const Discretization &mesh, const CellKernel &kernel,
                       const MembraneTerm &membrane, const MembraneLaw &law,
                       const std::vector<double> &voltages, const double thickness,
                       const Eigen::MatrixXd                              &dx_dp,
                       std::vector<std::pair<unsigned int, double>> columns)
        : mesh(mesh)
        , kernel(kernel)
        , layout(kernel.parameters())
        , membrane(membrane)
        , law(law)
        , voltages(voltages)
        , H(thickness)
        , dx_dp(dx_dp)
        , columns(std::move(columns))
        , n(mesh.dofs_per_cell())
        , gradient_s2(n)
        , gradient_E(n)
        , explicit_s2(layout.size())
        , explicit_E(layout.size())
      {}

      /// Point q of @p table in cell c, where the solution has the
      /// kinematics @p p.
      void add(const unsigned int c, const ShapeTable &table, const unsigned int q,
               const PointKinematics &p)
      {
        const MeshCell &cell = mesh.cells[c];
        const double    Phi  = voltages[cell.ring];
        const LawInput  at   = membrane.law_input(p, cell.ring);
        LawResponse     response;
        if (!law.evaluate(at, {}, law_stress | law_tangent, response))
          throw std::runtime_error("StateSensitivity: a point lies outside the material's range");
        state_gradients(cell, table, q, p, response.tangent, Phi);
        explicit_derivatives(c, table.points[q], p, at, response.tangent, Phi);
        chain(mesh.dofs_of(c));
        out.R.push_back(p.R);
        out.ring.push_back(cell.ring);
        s2.push_back(response.stress.s2);
        field.push_back(Phi * p.l1 * p.l2 / H);
      }

      /// The points added so far, the first @p n_quadrature_points of them
      /// at the quadrature points.
      PointValues values(const unsigned int n_quadrature_points)
      {
        const unsigned int n_points = s2.size(), P = columns.size();
        out.n_quadrature_points     = n_quadrature_points;
        out.s2                      = Eigen::Map<Eigen::VectorXd>(s2.data(), n_points);
        out.field                   = Eigen::Map<Eigen::VectorXd>(field.data(), n_points);
        out.d_s2.resize(n_points, P);
        out.d_field.resize(n_points, P);
        for (unsigned int k = 0; k < n_points; ++k)
          {
            out.d_s2.row(k)    = d_s2[k].transpose();
            out.d_field.row(k) = d_field[k].transpose();
          }
        return out;
      }

      unsigned int n_points() const { return s2.size(); }

    private:
      const Discretization                              &mesh;
      const CellKernel                                  &kernel;
      const ParameterLayout                             &layout;
      const MembraneTerm                                &membrane;
      const MembraneLaw                                 &law;
      const std::vector<double>                         &voltages;
      const double                                       H;
      const Eigen::MatrixXd                             &dx_dp;
      const std::vector<std::pair<unsigned int, double>> columns; ///< of each scene parameter
      const unsigned int                                 n;
      std::vector<double> gradient_s2, gradient_E, explicit_s2, explicit_E;
      std::vector<double> s2, field;
      std::vector<Eigen::VectorXd> d_s2, d_field;
      PointValues                  out;

      /// d/dx: dl1_i = (r' or z') dN_i/dR / l1, dl2_i = N_i / R (r only).
      void state_gradients(const MeshCell &cell, const ShapeTable &table, const unsigned int q,
                           const PointKinematics &p, const StressTangent &t, const double Phi)
      {
        const double *value = &table.value[q * n], *deriv = &table.derivative[q * n];
        for (unsigned int i = 0; i < n; ++i)
          {
            const bool   r_dof = mesh.component[i] == 0;
            const double dl1   = (r_dof ? p.dr : p.dz) * deriv[i] / cell.h / p.l1;
            const double dl2   = r_dof ? value[i] / p.R : 0.;
            gradient_s2[i]     = t.s12 * dl1 + t.s22 * dl2;
            gradient_E[i]      = Phi / H * (p.l2 * dl1 + p.l1 * dl2);
          }
      }

      /// Explicit derivatives at fixed nodal values, per kernel parameter:
      /// the law's constants and the voltage, and the shape by the cell's
      /// motion, R_t = dx0 + xi dh, l1_t = -l1 dh / h, l2_t = -l2 R_t / R.
      void explicit_derivatives(const unsigned int c, const double xi, const PointKinematics &p,
                                const LawInput &at, const StressTangent &t, const double Phi)
      {
        const MeshCell &cell = mesh.cells[c];
        std::fill(explicit_s2.begin(), explicit_s2.end(), 0.);
        std::fill(explicit_E.begin(), explicit_E.end(), 0.);
        for (const auto &[parameter, k] : law_parameter_columns(layout, cell.ring))
          {
            double        dW = 0.;
            NominalStress ds{0., 0.};
            if (law.parameter_derivative(at, {}, parameter, dW, ds))
              explicit_s2[k] = ds.s2;
          }
        explicit_E[layout.voltage(cell.ring)] = p.l1 * p.l2 / H;
        for (unsigned int k = layout.first_shape_parameter(); k < layout.size(); ++k)
          {
            const CellMotion motion = kernel.cell_motion(c, k);
            const double     R_t    = motion.dx0 + xi * motion.dh;
            const double     l1_t   = -p.l1 * motion.dh / cell.h;
            const double     l2_t   = -p.l2 * R_t / p.R;
            explicit_s2[k]          = t.s12 * l1_t + t.s22 * l2_t;
            explicit_E[k]           = Phi / H * (p.l2 * l1_t + p.l1 * l2_t);
          }
      }

      /// The total derivatives of s2 and E at the point (cell dofs @p dofs).
      void chain(const unsigned int *dofs)
      {
        const unsigned int P = columns.size();
        Eigen::VectorXd    ds2(P), dE(P);
        for (unsigned int j = 0; j < P; ++j)
          {
            const auto [k, factor] = columns[j];
            double a = factor * explicit_s2[k], b = factor * explicit_E[k];
            for (unsigned int i = 0; i < n; ++i)
              {
                a += gradient_s2[i] * dx_dp(dofs[i], j);
                b += gradient_E[i] * dx_dp(dofs[i], j);
              }
            ds2[j] = a;
            dE[j]  = b;
          }
        d_s2.push_back(std::move(ds2));
        d_field.push_back(std::move(dE));
      }
    };
  } // namespace

  PointValues StateSensitivity::points() const
  {
    const Discretization &mesh = model.discretization();
    const MembraneLaw    &law  = model.material_law();
    // Each scene parameter as its kernel column.
    std::vector<std::pair<unsigned int, double>> columns;
    for (const auto &p : parameters_)
      columns.push_back(kernel_column(p, model.kernel().parameters(), model.scene(), law));
    PointDerivatives at(mesh, model.kernel(), model.membrane(), law, model.load().voltages,
                        model.scene().material.thickness, dx_dp, std::move(columns));

    for_each_point(mesh, mesh.energy_rule, model.unknowns(),
                   [&](const unsigned int c, const unsigned int q, const PointKinematics &p) {
                     at.add(c, mesh.energy_rule, q, p);
                   });
    const unsigned int n_quadrature_points = at.n_points();
    // Then the inner edge of each ring (the left end of its first cell).
    int previous_ring = -1;
    for_each_point(mesh, mesh.left_end, model.unknowns(),
                   [&](const unsigned int c, const unsigned int q, const PointKinematics &p) {
                     if (int(mesh.cells[c].ring) != previous_ring)
                       {
                         at.add(c, mesh.left_end, q, p);
                         previous_ring = mesh.cells[c].ring;
                       }
                   });
    return at.values(n_quadrature_points);
  }
} // namespace cdea
