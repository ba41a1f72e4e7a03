#include <cdea/material/linear_response.h>

#include <Eigen/Dense>

namespace cdea
{
  ComplexTangent frequency_tangent(const InternalLinearization &lin, const double omega)
  {
    ComplexTangent c{lin.instantaneous.s11, lin.instantaneous.s12, lin.instantaneous.s22};
    const int n = static_cast<int>(lin.n);
    if (n == 0)
      return c;
    using Matrix = Eigen::MatrixXcd;
    Matrix system(n, n), rate_l(n, 2), stress_y(2, n);
    for (int i = 0; i < n; ++i)
      {
        for (int j = 0; j < n; ++j)
          system(i, j) = -lin.rate_y[i * n + j];
        system(i, i) += std::complex<double>(0., omega);
        rate_l(i, 0) = lin.rate_l[i * 2];
        rate_l(i, 1) = lin.rate_l[i * 2 + 1];
        stress_y(0, i) = lin.stress_y[i];
        stress_y(1, i) = lin.stress_y[n + i];
      }
    const Matrix viscous = stress_y * system.partialPivLu().solve(rate_l);
    c.s11 += viscous(0, 0);
    c.s12 += 0.5 * (viscous(0, 1) + viscous(1, 0));
    c.s22 += viscous(1, 1);
    return c;
  }
} // namespace cdea
