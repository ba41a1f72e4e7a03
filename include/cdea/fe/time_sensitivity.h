#pragma once
// Forward sensitivities of a quasi-static time run's discrete solution with
// respect to material parameters p (doc/materials.md, "Sensitivities through
// time"). The run is a DAE: equilibrium R(u, Y, p) = 0 of the unknowns u at
// every point's evolving internal variables Y, which follow Y' = f(l(u), Y, p).
// Every implicit stage i of a step of length h (an ESDIRK stage, or the one
// stage of backward Euler, gamma = 1, or of the trapezoidal rule, gamma = 1/2
// and a_10 = 1/2) solves
//
//   Y_i = Yhat_i + gamma h f(l_i, Y_i, p),   Yhat_i = y_n + h sum_{j<i} a_ij K_j,
//   R(u_i, Y_i, p) = 0,                      K_i = f(l_i, Y_i, p).
//
// Differentiated with the steps held fixed, per point with A = I - gamma h f_y:
//
//   dY_i = A^-1 (dYhat_i + gamma h (f_l dl + f_p)),
//   dS   = C dl + S_Y A^-1 (dYhat_i + gamma h f_p) + S_p,
//
// C = S_l + gamma h S_Y A^-1 f_l being the law's consistent tangent of the
// stage, so that the stage's converged tangent K (the one Newton factored)
// gives the unknowns' derivative:  K du_i = -sum_points w B^T (S_Y A^-1
// (dYhat_i + gamma h f_p) + S_p),  then dl = B du_i, dY_i and
// dK_i = f_y dY_i + f_l dl + f_p point by point. The partial derivatives are
// the law's linearize() (S_l, S_Y, f_y, f_l) and
// evolving_parameter_derivative() (S_p, f_p). The start of a run is the
// relaxed film's equilibrium (internal variables relaxed, f = 0): the tangent
// with the internal variables relaxed (dt = infinity) gives du_0, and
// f(l, y, p) = 0 gives dy_0 = -f_y^-1 (f_l dl + f_p).

#include <cdea/material/membrane_law.h>

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  class MembraneModel;

  class TimeSensitivity
  {
  public:
    /// For @p parameters of the model's law (SI units; LawParameter::voltage:
    /// every voltage of the waveform scaled with a peak of @p voltage_reference
    /// volts, per volt), over steps of at most @p stages stages (the first
    /// explicit: the rate at the step's start).
    TimeSensitivity(MembraneModel &model, std::vector<LawParameter> parameters,
                    unsigned int stages, double voltage_reference);
    ~TimeSensitivity();

    /// At the model's current state, an equilibrium with the internal
    /// variables relaxed: du_0 and dy_0. False with @p message if not possible.
    bool start_relaxed(std::string &message);
    /// Implicit stage @p i of a step of length @p h, the model holding its
    /// converged state and tangent: @p a_row = a_ij (j < i) and @p gh the
    /// stage's gamma h. False with @p message if not possible.
    bool stage(unsigned int i, const std::vector<double> &a_row, double h, double gh,
               std::string &message);
    /// The step whose last stage was @p last is accepted: it is the next start.
    void accept(unsigned int last);

    /// |z(A) - z(B)| (m) at the model's state and its derivative at the last
    /// accepted state (one entry per parameter).
    double displacement(Eigen::VectorXd &gradient) const;

  private:
    class Data;
    std::unique_ptr<Data> data;
  };
} // namespace cdea
