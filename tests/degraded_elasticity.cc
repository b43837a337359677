// Unit test of the degraded neo-Hooke law of an elastic body that can crack,
// model.md (16)-(19) and (27), and of the degradation g_k(s), no mesh:
//  1. g_k, g_k', g_k'' against central differences, their values at s = 0
//     and s = 1 and beyond (g_k = k, no slope, for s > 1), the closed form
//     (1 - k)(1 - s)^2 + k for a_g = 2, and g_k' against the Sacado
//     derivative of degradation_value();
//  2. neo_hooke() splits exactly: its part (mu, kappa) = (0, kappa) is
//     kappa/2 (J - 1)^2 with tau = kappa (J^2 - J) I, and the parts
//     (0, kappa) + (mu, 0) give the full law (psi, tau, P, A);
//  3. diagonal F in tension and compression: tau, Psi^e, psi^+ against the
//     closed form (in compression only the deviatoric part degrades);
//     with Fracture/Energy split = none the whole law degrades in both;
//  4. F with J > 1 and J < 1 (both branches of g_vol), s = 0, 0.3, 0.9,
//     a_g = 2, 1, k = 1e-8, 1e-2: dP/dF, dP/ds, dpsi^+/dF against central
//     differences; P = dPsi^e/dF and dPsi^e/ds = g_k'(s) psi^+ by central
//     differences of the energy;
//  5. the same states through plastic_update() with a yield stress that is
//     never reached (C^p = I): P, dP/dF, dP/ds, tau, Psi^e, psi^+ agree to
//     1e-10.
#include <deal.II/base/tensor.h>
#include <deal.II/differentiation/ad.h>

#include <ductile_contact/materials/degradation.h>
#include <ductile_contact/materials/degraded_elasticity.h>
#include <ductile_contact/materials/neo_hooke.h>
#include <ductile_contact/materials/plasticity.h>

#include "tests.h"

#include <array>
#include <random>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  const double mu = 1.0, kappa = 2.5;


  /// Three random F with J = 1.2 and three with J = 0.8.
  std::vector<Tensor<2, dim>>
  deformations()
  {
    std::mt19937                           gen(11);
    std::uniform_real_distribution<double> d(-0.3, 0.3);
    std::vector<Tensor<2, dim>>            result;
    for (const double J : {1.2, 0.8})
      for (unsigned int n = 0; n < 3;)
        {
          Tensor<2, dim> F = unit_symmetric_tensor<dim>();
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              F[i][j] += d(gen);
          const double det = determinant(F);
          if (det < 0.3)
            continue;
          result.push_back(std::cbrt(J / det) * F);
          ++n;
        }
    return result;
  }

  std::vector<DegradationParameters>
  degradations()
  {
    std::vector<DegradationParameters> result;
    for (const double a : {2., 1.})
      for (const double k : {1e-8, 1e-2})
        result.push_back({a, k});
    return result;
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  out << std::setprecision(6);

  // 1. The degradation function.
  {
    double fd_error = 0, end_error = 0, quadratic_error = 0, ad_error = 0;
    for (const double a : {0., 1., 2., 3.})
      for (const double k : {1e-8, 1e-2})
        {
          const DegradationParameters p{a, k};
          end_error =
            std::max({end_error,
                      std::abs(degradation_value(0., p) - 1.),
                      std::abs(degradation_value(1., p) - k),
                      std::abs(degradation_derivative(0., p) + a * (1. - k)),
                      std::abs(degradation_derivative(1., p))});
          // Beyond s = 1: g_k = k, no slope (the continuation of the
          // degradation.h).
          for (const double s : {1. + 1e-9, 1.01, 1.05, 1.3})
            end_error = std::max(
              {end_error,
               std::abs(degradation_value(s, p) - k),
               std::abs(degradation_derivative(s, p)),
               std::abs(degradation_second_derivative(s, p)),
               std::abs(degradation_value(Sacado::Fad::DFad<double>(1, 0, s), p)
                          .dx(0))});
          // Samples inside [0, 1], and at 1 from the left (g'' jumps there).
          for (unsigned int i = 0; i <= 10; ++i)
            {
              const double s = i < 10 ? 0.1 * i : 1. - 1e-4, h = 1e-5;
              const double dg_fd =
                (degradation_value(s + h, p) - degradation_value(s - h, p)) /
                (2 * h);
              const double ddg_fd = (degradation_derivative(s + h, p) -
                                     degradation_derivative(s - h, p)) /
                                    (2 * h);
              fd_error = std::max(
                {fd_error,
                 std::abs(dg_fd - degradation_derivative(s, p)),
                 std::abs(ddg_fd - degradation_second_derivative(s, p))});

              const Sacado::Fad::DFad<double> s_ad(1, 0, s);
              ad_error = std::max(ad_error,
                                  std::abs(degradation_value(s_ad, p).dx(0) -
                                           degradation_derivative(s, p)));
              if (a == 2.)
                quadratic_error =
                  std::max({quadratic_error,
                            std::abs(degradation_value(s, p) -
                                     ((1. - k) * (1. - s) * (1. - s) + k)),
                            std::abs(degradation_derivative(s, p) +
                                     2. * (1. - k) * (1. - s)),
                            std::abs(degradation_second_derivative(s, p) -
                                     2. * (1. - k))});
            }
        }
    out << "g_k(0) = 1, g_k(1) = k, g_k'(0) = -a (1 - k), g_k'(1) = 0, "
           "g_k = k without slope for s > 1 (1e-14): "
        << Testing::yes_no(end_error < 1e-14) << std::endl;
    out << "g_k' and g_k'' vs FD: max error < 1e-8: "
        << Testing::yes_no(fd_error < 1e-8) << std::endl;
    out << "a = 2: g_k = (1 - k)(1 - s)^2 + k with its derivatives (1e-14): "
        << Testing::yes_no(quadratic_error < 1e-14) << std::endl;
    out << "g_k' equals the Sacado derivative of g_k (1e-14): "
        << Testing::yes_no(ad_error < 1e-14) << std::endl;
    std::cout << "degradation: end " << end_error << " fd " << fd_error
              << " quadratic " << quadratic_error << " ad " << ad_error
              << std::endl;
  }

  // 2. The volumetric/deviatoric split of neo_hooke().
  {
    double volumetric_error = 0, sum_error = 0;
    for (const Tensor<2, dim> &F : deformations())
      {
        const MaterialResponse        vol  = neo_hooke(F, 0., kappa, true);
        const MaterialResponse        dev  = neo_hooke(F, mu, 0., true);
        const MaterialResponse        full = neo_hooke(F, mu, kappa, true);
        const double                  J    = determinant(F);
        const SymmetricTensor<2, dim> tau_vol =
          kappa * (J * J - J) * unit_symmetric_tensor<dim>();
        const double psi_vol = 0.5 * kappa * (J - 1.) * (J - 1.);
        volumetric_error =
          std::max({volumetric_error,
                    std::abs(vol.psi_elastic - psi_vol) / kappa,
                    (vol.tau - tau_vol).norm() / kappa});
        sum_error = std::max(
          {sum_error,
           std::abs(vol.psi_elastic + dev.psi_elastic - full.psi_elastic) /
             full.psi_elastic,
           (vol.tau + dev.tau - full.tau).norm() / full.tau.norm(),
           (vol.P + dev.P - full.P).norm() / full.P.norm(),
           (vol.dP_dF + dev.dP_dF - full.dP_dF).norm() / full.dP_dF.norm()});
      }
    out << "neo_hooke(F, 0, kappa) is kappa/2 (J - 1)^2, tau = kappa (J^2 - J)"
           " I (1e-13): "
        << Testing::yes_no(volumetric_error < 1e-13) << std::endl;
    out << "neo_hooke(F, 0, kappa) + neo_hooke(F, mu, 0) = neo_hooke(F, mu, "
           "kappa) (1e-13): "
        << Testing::yes_no(sum_error < 1e-13) << std::endl;
    std::cout << "split: volumetric " << volumetric_error << " sum "
              << sum_error << std::endl;
  }

  // 3. Closed form for diagonal F, s = 0.3, a_g = 2: g_k = 0.49.
  {
    const DegradationParameters p;
    const double                s = 0.3, g = degradation_value(s, p);
    bool                        exact = true;
    for (const auto &l : {std::array<double, 3>{{1.3, 1.0, 0.95}},
                          std::array<double, 3>{{1.1, 0.9, 0.8}}})
      {
        Tensor<2, dim> F;
        for (unsigned int i = 0; i < dim; ++i)
          F[i][i] = l[i];
        const double J = l[0] * l[1] * l[2];
        const double tr =
          (l[0] * l[0] + l[1] * l[1] + l[2] * l[2]) * std::pow(J, -2. / 3.);
        const double           g_vol = (J > 1.) ? g : 1.;
        const MaterialResponse r =
          degraded_neo_hooke(F, s, mu, kappa, p, false);
        out << (J > 1. ? "tension" : "compression") << ", J = " << J << ":";
        for (unsigned int i = 0; i < dim; ++i)
          {
            const double tau =
              g_vol * kappa * (J * J - J) +
              g * mu * (l[i] * l[i] * std::pow(J, -2. / 3.) - tr / 3.);
            exact = exact && std::abs(r.tau[i][i] - tau) < 1e-12;
            out << " tau_" << i << i << "/mu = " << r.tau[i][i] / mu;
          }
        const double psi_vol  = 0.5 * kappa * (J - 1.) * (J - 1.);
        const double psi_dev  = 0.5 * mu * (tr - 3.);
        const double psi      = g_vol * psi_vol + g * psi_dev;
        const double psi_plus = (J > 1. ? psi_vol : 0.) + psi_dev;
        exact = exact && std::abs(r.psi_elastic - psi) < 1e-12 &&
                std::abs(r.psi_plus - psi_plus) < 1e-12 &&
                std::abs(r.J - J) < 1e-14;
        out << " psi/mu = " << r.psi_elastic / mu
            << " psi+/mu = " << r.psi_plus / mu << std::endl;
      }
    out << "tau, Psi^e, psi^+ equal the closed form (1e-12): "
        << Testing::yes_no(exact) << std::endl;

    // Energy split = none: the whole law degrades at every J, and psi^+ is
    // the whole undegraded energy.
    bool no_split = true;
    for (const auto &l : {std::array<double, 3>{{1.3, 1.0, 0.95}},
                          std::array<double, 3>{{1.1, 0.9, 0.8}}})
      {
        Tensor<2, dim> F;
        for (unsigned int i = 0; i < dim; ++i)
          F[i][i] = l[i];
        const MaterialResponse full = neo_hooke(F, mu, kappa, true);
        const MaterialResponse r =
          degraded_neo_hooke(F, s, mu, kappa, p, true, false);
        no_split =
          no_split && (r.tau - g * full.tau).norm() < 1e-12 &&
          (r.P - g * full.P).norm() < 1e-12 &&
          (r.dP_dF - g * full.dP_dF).norm() < 1e-12 &&
          (r.dP_ds - degradation_derivative(s, p) * full.P).norm() < 1e-12 &&
          std::abs(r.psi_elastic - g * full.psi_elastic) < 1e-12 &&
          std::abs(r.psi_plus - full.psi_elastic) < 1e-12;
      }
    out << "without the split, in tension and compression: tau, P, dP/dF = "
           "g_k times the undegraded law, dP/ds = g_k' P, psi^+ = Psi "
           "(1e-12): "
        << Testing::yes_no(no_split) << std::endl;
  }

  // 4. Derivatives against central differences; 5. against plastic_update().
  {
    const std::vector<Tensor<2, dim>> Fs        = deformations();
    unsigned int                      n_tension = 0, n_compression = 0;
    for (const Tensor<2, dim> &F : Fs)
      ++(determinant(F) > 1. ? n_tension : n_compression);
    out << "states with J > 1: " << n_tension
        << ", with J < 1: " << n_compression << std::endl;

    double worst_A = 0, worst_dP_ds = 0, worst_dpsi_plus = 0, worst_P = 0,
           worst_dpsi_ds = 0, worst_plastic = 0;
    bool never_yields = true;
    for (const DegradationParameters &p : degradations())
      for (const double s : {0., 0.3, 0.9})
        for (const Tensor<2, dim> &F : Fs)
          {
            const double           h = 1e-6;
            const MaterialResponse r =
              degraded_neo_hooke(F, s, mu, kappa, p, true);

            Testing::RelativeError e_A, e_dpsi_plus, e_P, e_dP_ds;
            for (unsigned int c = 0; c < dim; ++c)
              for (unsigned int D = 0; D < dim; ++D)
                {
                  Tensor<2, dim> Fp = F, Fm = F;
                  Fp[c][D] += h;
                  Fm[c][D] -= h;
                  const MaterialResponse rp =
                    degraded_neo_hooke(Fp, s, mu, kappa, p, false);
                  const MaterialResponse rm =
                    degraded_neo_hooke(Fm, s, mu, kappa, p, false);
                  for (unsigned int a = 0; a < dim; ++a)
                    for (unsigned int B = 0; B < dim; ++B)
                      e_A.add((rp.P[a][B] - rm.P[a][B]) / (2 * h),
                              r.dP_dF[a][B][c][D]);
                  e_dpsi_plus.add((rp.psi_plus - rm.psi_plus) / (2 * h),
                                  r.dpsi_plus_dF[c][D]);
                  e_P.add((rp.psi_elastic - rm.psi_elastic) / (2 * h),
                          r.P[c][D]);
                }
            const MaterialResponse sp =
              degraded_neo_hooke(F, s + h, mu, kappa, p, false);
            const MaterialResponse sm =
              degraded_neo_hooke(F, s - h, mu, kappa, p, false);
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int B = 0; B < dim; ++B)
                e_dP_ds.add((sp.P[a][B] - sm.P[a][B]) / (2 * h), r.dP_ds[a][B]);
            const double dpsi_ds = degradation_derivative(s, p) * r.psi_plus;
            worst_A              = std::max(worst_A, e_A.value());
            worst_dP_ds          = std::max(worst_dP_ds, e_dP_ds.value());
            worst_dpsi_plus = std::max(worst_dpsi_plus, e_dpsi_plus.value());
            worst_P         = std::max(worst_P, e_P.value());
            worst_dpsi_ds =
              std::max(worst_dpsi_ds,
                       std::abs((sp.psi_elastic - sm.psi_elastic) / (2 * h) -
                                dpsi_ds) /
                         std::abs(dpsi_ds));

            // 5. The plastic update with a yield stress never reached.
            PlasticityParameters q = Testing::unit_plasticity();
            q.shear_modulus        = mu;
            q.bulk_modulus         = kappa;
            q.initial_yield        = 1e30;
            q.saturation_yield     = 1e30;
            q.degradation_a        = p.a;
            q.residual_stiffness   = p.residual_stiffness;
            const MaterialResponse pr =
              plastic_update(F, PlasticHistory(), 0., s, 1., q, true);
            never_yields = never_yields && !pr.yielding;
            Testing::RelativeError e_plastic;
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int B = 0; B < dim; ++B)
                {
                  e_plastic.add(r.P[a][B], pr.P[a][B]);
                  e_plastic.add(r.tau[a][B], pr.tau[a][B]);
                }
            Testing::RelativeError e_plastic_A, e_plastic_dP_ds,
              e_plastic_energy;
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int B = 0; B < dim; ++B)
                {
                  e_plastic_dP_ds.add(r.dP_ds[a][B], pr.dP_ds[a][B]);
                  for (unsigned int c = 0; c < dim; ++c)
                    for (unsigned int D = 0; D < dim; ++D)
                      e_plastic_A.add(r.dP_dF[a][B][c][D],
                                      pr.dP_dF[a][B][c][D]);
                }
            e_plastic_energy.add(r.psi_elastic, pr.psi_elastic);
            e_plastic_energy.add(r.psi_plus, pr.psi_plus);
            worst_plastic = std::max({worst_plastic,
                                      e_plastic.value(),
                                      e_plastic_A.value(),
                                      e_plastic_dP_ds.value(),
                                      e_plastic_energy.value()});
          }
    out << "dP/dF vs FD: max rel error < 1e-6: "
        << Testing::yes_no(worst_A < 1e-6) << std::endl;
    out << "dP/ds vs FD: max rel error < 1e-6: "
        << Testing::yes_no(worst_dP_ds < 1e-6) << std::endl;
    out << "dpsi+/dF vs FD: max rel error < 1e-6: "
        << Testing::yes_no(worst_dpsi_plus < 1e-6) << std::endl;
    out << "P = dPsi^e/dF by FD: max rel error < 1e-6: "
        << Testing::yes_no(worst_P < 1e-6) << std::endl;
    out << "dPsi^e/ds = g_k'(s) psi+ by FD: max rel error < 1e-6: "
        << Testing::yes_no(worst_dpsi_ds < 1e-6) << std::endl;
    out << "plastic_update with infinite yield stress never yields: "
        << Testing::yes_no(never_yields) << std::endl;
    out << "plastic_update agrees (P, tau, dP/dF, dP/ds, Psi^e, psi+): max "
           "rel error < 1e-10: "
        << Testing::yes_no(worst_plastic < 1e-10) << std::endl;
    std::cout << "FD: A " << worst_A << " dP/ds " << worst_dP_ds << " dpsi+/dF "
              << worst_dpsi_plus << " P " << worst_P << " dPsi/ds "
              << worst_dpsi_ds << "; plastic_update " << worst_plastic
              << std::endl;
  }
}
