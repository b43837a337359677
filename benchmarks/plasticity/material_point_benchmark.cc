// Cost of one material-point evaluation (the work per quadrature point of
// an assembly): neo-Hooke (16)/(19) against the visco-plastic update of
// model.md section 3, elastic and plastic branch, intact (s = 0) and damaged
// (s = 0.3), with and without the exact tangent (Sacado DFad, 11
// directions). Prints microseconds per call (median of 5 repetitions).
#include <deal.II/base/timer.h>

#include <ductile_contact/materials/neo_hooke.h>
#include <ductile_contact/materials/plasticity.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <vector>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  double
  microseconds(const std::function<double()> &work, const unsigned int n)
  {
    std::vector<double> times;
    double              sink = 0;
    for (unsigned int rep = 0; rep < 5; ++rep)
      {
        Timer timer;
        for (unsigned int i = 0; i < n; ++i)
          sink += work();
        times.push_back(timer.wall_time() / n * 1e6);
      }
    std::sort(times.begin(), times.end());
    if (sink == 42.)
      std::cout << "";
    return times[2];
  }
} // namespace

int
main()
{
  // The dimensionless values of the unit tests (Testing::unit_plasticity).
  PlasticityParameters p;
  p.shear_modulus       = 1.;
  p.bulk_modulus        = 2.5;
  p.initial_yield       = 0.005;
  p.saturation_yield    = 0.006;
  p.saturation_exponent = 25.;
  p.viscosity           = 1e-3;
  PlasticHistory h;
  h.alpha          = 0.01;
  Tensor<2, dim> F = unit_symmetric_tensor<dim>();
  F[0][0] += 0.02;
  F[0][1] += 0.005;
  F[1][1] -= 0.008;
  const unsigned int n = 20000;
  std::cout << "evaluation tangent damage microseconds_per_call\n";
  std::cout
    << "neo-Hooke no - "
    << microseconds([&] { return neo_hooke(F, 1., 2.5, false).psi_elastic; }, n)
    << "\n";
  std::cout
    << "neo-Hooke yes - "
    << microseconds([&] { return neo_hooke(F, 1., 2.5, true).psi_elastic; }, n)
    << "\n";
  for (const double s : {0., 0.3})
    for (const bool tangent : {false, true})
      {
        // elastic branch: alpha = alpha_n and a small strain
        const double t_el = microseconds(
          [&] {
            return plastic_update(unit_symmetric_tensor<dim>() +
                                    1e-4 * (F - unit_symmetric_tensor<dim>()),
                                  h,
                                  h.alpha,
                                  s,
                                  0.1,
                                  p,
                                  tangent)
              .psi_elastic;
          },
          n / (tangent ? 10 : 1));
        const double t_pl = microseconds(
          [&] {
            return plastic_update(F, h, h.alpha + 0.001, s, 0.1, p, tangent)
              .psi_elastic;
          },
          n / (tangent ? 10 : 1));
        std::cout << "plastic-update(elastic-branch) "
                  << (tangent ? "yes" : "no") << " " << s << " " << t_el
                  << "\n";
        std::cout << "plastic-update(plastic-branch) "
                  << (tangent ? "yes" : "no") << " " << s << " " << t_pl
                  << "\n";
      }
}
