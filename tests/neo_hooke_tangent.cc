// Unit test of the material point (no mesh): the neo-Hooke law of model.md
// (16)/(19).
//  1. Kirchhoff stress of diagonal F against the closed form
//     tau_ii = kappa (J^2 - J) + mu (lambda_i^2 J^{-2/3} - tr(bbar)/3);
//  2. A = dP/dF against central finite differences of P for random F
//     (relative error <= 1e-6);
//  3. at F = I, A equals the small-strain tensor lambda I x I + 2 mu II.
#include <ductile_contact/materials/neo_hooke.h>

#include <fstream>
#include <iomanip>
#include <random>

using namespace dealii;
using namespace DuctileContact;

int
main()
{
  std::ofstream out("output");
  out << std::setprecision(6);
  const double mu = 1.0, kappa = 2.5;

  // 1. Closed form for F = diag(1.3, 0.9, 0.8).
  {
    const double   l[3] = {1.3, 0.9, 0.8};
    Tensor<2, dim> F;
    for (unsigned int i = 0; i < dim; ++i)
      F[i][i] = l[i];
    const double J = l[0] * l[1] * l[2];
    const double tr =
      (l[0] * l[0] + l[1] * l[1] + l[2] * l[2]) * std::pow(J, -2. / 3.);
    const MaterialResponse r     = neo_hooke(F, mu, kappa, false);
    double                 error = 0;
    for (unsigned int i = 0; i < dim; ++i)
      {
        const double exact =
          kappa * (J * J - J) +
          mu * (l[i] * l[i] * std::pow(J, -2. / 3.) - tr / 3.);
        error = std::max(error, std::abs(r.tau[i][i] - exact));
        out << "tau_" << i << i << " / mu = " << r.tau[i][i] / mu << std::endl;
      }
    const double psi_exact =
      0.5 * kappa * (J - 1) * (J - 1) + 0.5 * mu * (tr - 3.);
    out << "psi / mu = " << r.psi_elastic / mu << std::endl;
    out << "stress and energy equal the closed form (1e-12): "
        << (error < 1e-12 && std::abs(r.psi_elastic - psi_exact) < 1e-12 ? "yes"
                                                                         : "no")
        << std::endl;
  }

  // 2. Tangent against central differences.
  {
    std::mt19937                           gen(42);
    std::uniform_real_distribution<double> dist(-0.3, 0.3);
    double                                 worst = 0;
    for (unsigned int sample = 0; sample < 20; ++sample)
      {
        Tensor<2, dim> F = unit_symmetric_tensor<dim>();
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            F[i][j] += dist(gen);
        if (determinant(F) < 0.3)
          continue;
        const MaterialResponse r    = neo_hooke(F, mu, kappa, true);
        const double           h    = 1e-6;
        double                 diff = 0, norm = 0;
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int D = 0; D < dim; ++D)
            {
              Tensor<2, dim> Fp = F, Fm = F;
              Fp[c][D] += h;
              Fm[c][D] -= h;
              const Tensor<2, dim> dP = (neo_hooke(Fp, mu, kappa, false).P -
                                         neo_hooke(Fm, mu, kappa, false).P) /
                                        (2 * h);
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int B = 0; B < dim; ++B)
                  {
                    diff += std::pow(dP[a][B] - r.dP_dF[a][B][c][D], 2);
                    norm += std::pow(r.dP_dF[a][B][c][D], 2);
                  }
            }
        worst = std::max(worst, std::sqrt(diff / norm));
      }
    out << "tangent equals central differences (relative 1e-6): "
        << (worst < 1e-6 ? "yes" : "no") << std::endl;
  }

  // 3. Small-strain limit.
  {
    const MaterialResponse r =
      neo_hooke(unit_symmetric_tensor<dim>(), mu, kappa, true);
    const double lambda = kappa - 2. / 3. * mu;
    double       error  = 0;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double exact =
                lambda * (a == b) * (c == d) +
                mu * ((a == c) * (b == d) + (a == d) * (b == c));
              error = std::max(error, std::abs(r.dP_dF[a][b][c][d] - exact));
            }
    out << "A(F = I) is the small-strain elasticity tensor: "
        << (error < 1e-12 ? "yes" : "no") << std::endl;
  }
}
