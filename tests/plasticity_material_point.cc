// Material-point driver of the visco-plastic finite-strain J2 update
// (model.md section 3), no mesh:
//  1. the tangents dP/dF, dP/dalpha, dP/ds, dr/dF, dr/dalpha, dr/ds and
//     those of the crack driver psi^+ (dF, dalpha, ds) equal central finite
//     differences (relative 1e-6) in plastic and in elastic states (alpha
//     != alpha_n in both, as during Newton's iterations) with damage s =
//     0.3 and a prior plastic history;
//     the same with the tension/compression switch of the split (17)
//     blended over |J - 1| < delta = 0.05 (Volumetric switch width), with
//     samples inside the blend; in both, P is the derivative of the
//     elastic energy Psi^e(F, (C^p_{n+1})^{-1}) (central differences);
//     the same with Plasticity/Loading condition = bound, where in addition
//     the backward Euler local plastic dissipation of every sample, w_BE -
//     Delta Psi^p_loc + r Delta alpha (doc/model.md section 3.2), is at
//     least eta_p Delta alpha^2/dt (to 1e-12 y_0 |Delta alpha|), also with
//     a degraded plastic energy, which softens in alpha (the discrete
//     gradient of the flow resistance);
//  2. det (C^p)^{-1} = 1 to round-off after plastic steps;
//  3. uniaxial stress (lateral stretch from tau_yy = 0, alpha from the
//     local hardening equation r = 0 by Newton with dr/dalpha) with a
//     nearly rate-independent viscosity: the axial Kirchhoff stress follows
//     the independent small-strain rate-independent solution
//     sigma = yhat(eps - sigma/E) within 1 % up to 2 % strain, and the
//     overstress vanishes linearly with eta_p;
//  4. unloading from a plastic state is elastic: no yielding, C^p (to
//     round-off) and alpha unchanged, stress drops with Young's modulus;
//  5. the hold of a non-yielding point (model.md section 3.1, choice 3)
//     in simple shear, with the force r_n = 0.3 y_0 that the rest of the
//     field held the point with at the last accepted step: with F
//     unchanged the accepted state is a fixed point (r = r_n at alpha_n,
//     C^p unchanged), so the pull does not move alpha again in every step
//     (it did while the hold was c (alpha - alpha_n) alone: the paper
//     scene's force depended on the number of load steps); the pull
//     lowers the shear at which the point yields; at that switch the two
//     branches of r agree to second order in alpha - alpha_n (the
//     difference shrinks 4x when alpha - alpha_n halves).
#include <deal.II/base/tensor.h>

#include <ductile_contact/materials/plasticity.h>

#include "tests.h"

#include <limits>
#include <random>
#include <tuple>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  /// Small-strain rate-independent reference: sigma = yhat(eps - sigma/E).
  double
  reference_stress(const double eps, const PlasticityParameters &p)
  {
    const double mu = p.shear_modulus, kappa = p.bulk_modulus;
    const double E = 9. * kappa * mu / (3. * kappa + mu);
    if (E * eps <= p.initial_yield)
      return E * eps;
    double lo = p.initial_yield, hi = E * eps;
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double mid                                     = 0.5 * (lo + hi);
        (hardening_stress(eps - mid / E, p) > mid ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  out << std::setprecision(6);
  PlasticityParameters p = Testing::unit_plasticity();

  // 1. and 2.: tangents and incompressibility in random plastic states,
  // with the sharp and the blended switch of (17), and with the loading
  // condition 'bound' (no pointwise switch of the local equation). With the
  // bound, the backward Euler local dissipation of the step, w_BE -
  // Delta Psi^p_loc + r Delta alpha with w_BE = Psi^e(F, C^p_n) - Psi^e(F,
  // C^p), is eta_p Delta alpha^2/dt plus two non-negative terms (the
  // relaxation of the stress along the flow, and yhat Delta alpha - Delta
  // W_p, W_p convex) at every alpha, above or below alpha_n.
  // The last case degrades the plastic energy above a work density inside
  // the samples' range (w_c = 2e-5, rounded over y_0/100 = 5e-5), where
  // Psi^p_loc is not convex in alpha and the bound's flow resistance is
  // the discrete gradient.
  for (const auto &[delta, loading, degraded] :
       {std::tuple(0., LoadingCondition::pointwise_switch, false),
        std::tuple(0.05, LoadingCondition::pointwise_switch, false),
        std::tuple(0., LoadingCondition::bound, false),
        std::tuple(0., LoadingCondition::bound, true)})
    {
      p.volumetric_switch_width      = delta;
      p.loading_condition            = loading;
      p.degrade_plastic_energy       = degraded;
      p.critical_work_density        = degraded ? 2e-5 : 0.;
      const bool   bound             = loading == LoadingCondition::bound;
      double       worst_dissipation = std::numeric_limits<double>::max();
      std::mt19937 gen(7);
      std::uniform_real_distribution<double> d(-1., 1.);
      double       worst = 0, worst_driver = 0, det_error = 0, energy_error = 0;
      unsigned int plastic = 0, elastic = 0, blended = 0;
      for (unsigned int sample = 0; sample < 60; ++sample)
        {
          // The last 20 samples stay near the plastic deformation of the
          // history (F = (I + A) F^p, small A): mostly below yield.
          const bool   near_yield = sample >= 40;
          const double amplitude  = near_yield ? 0.001 : 0.03;
          const auto   history = Testing::random_plastic_history(gen, d, 0.01);
          const Tensor<2, dim> &Fp = history.first;
          const PlasticHistory &h  = history.second;
          Tensor<2, dim> F = Testing::perturbed_identity(gen, d, amplitude);
          if (near_yield)
            F = F * Fp;
          // With the bound alpha also falls below alpha_n (the local
          // equation is the same on both sides).
          const double alpha =
            h.alpha + 0.002 * (bound ? 1.5 * d(gen) : 1.2 + d(gen));
          // Nearly broken where the plastic energy is degraded: the stress
          // relaxation along the flow, ~ g(s) mu dalpha^2, no longer covers
          // the softening of Psi^p_loc, ~ (1 - g) yhat^2/w_r dalpha^2.
          const double           s = degraded ? 0.9 : 0.3, dt = 0.1;
          const MaterialResponse r =
            plastic_update(F, h, alpha, s, dt, p, true);
          {
            const double dalpha = alpha - h.alpha;
            const double work   = elastic_energy(F, h.Cp_inv, s, p) -
                                elastic_energy(F, r.updated.Cp_inv, s, p);
            const double local = work -
                                 (plastic_energy_density(alpha, s, p) -
                                  plastic_energy_density(h.alpha, s, p)) +
                                 r.r * dalpha -
                                 p.viscosity * dalpha * dalpha / dt;
            // Relative to the work of the flow resistance, y_0 |dalpha|.
            worst_dissipation =
              std::min(worst_dissipation,
                       local / (p.initial_yield * std::abs(dalpha)));
          }
          // With the bound: above and below alpha_n.
          ++((bound ? alpha > h.alpha : r.yielding) ? plastic : elastic);
          if (r.yielding && std::abs(r.J - 1.) < delta)
            ++blended;
          det_error =
            std::max(det_error, std::abs(determinant(r.updated.Cp_inv) - 1.));

          const double eps  = 1e-6;
          double       diff = 0, norm = 0, e_diff = 0, e_norm = 0;
          const auto   add = [&](const double fd, const double exact) {
            diff += (fd - exact) * (fd - exact);
            norm += exact * exact;
          };
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int D = 0; D < dim; ++D)
              {
                Tensor<2, dim> Fp1 = F, Fm1 = F;
                Fp1[c][D] += eps;
                Fm1[c][D] -= eps;
                const auto rp = plastic_update(Fp1, h, alpha, s, dt, p, false);
                const auto rm = plastic_update(Fm1, h, alpha, s, dt, p, false);
                for (unsigned int a = 0; a < dim; ++a)
                  for (unsigned int B = 0; B < dim; ++B)
                    add((rp.P[a][B] - rm.P[a][B]) / (2 * eps),
                        r.dP_dF[a][B][c][D]);
                add((rp.r - rm.r) / (2 * eps), r.dr_dF[c][D]);
                const double dpsi =
                  (elastic_energy(Fp1, r.updated.Cp_inv, s, p) -
                   elastic_energy(Fm1, r.updated.Cp_inv, s, p)) /
                  (2 * eps);
                e_diff += (dpsi - r.P[c][D]) * (dpsi - r.P[c][D]);
                e_norm += r.P[c][D] * r.P[c][D];
              }
          const double ea = 1e-7;
          const auto   ap = plastic_update(F, h, alpha + ea, s, dt, p, false);
          const auto   am = plastic_update(F, h, alpha - ea, s, dt, p, false);
          const auto   sp = plastic_update(F, h, alpha, s + eps, dt, p, false);
          const auto   sm = plastic_update(F, h, alpha, s - eps, dt, p, false);
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int B = 0; B < dim; ++B)
              {
                add((ap.P[a][B] - am.P[a][B]) / (2 * ea), r.dP_dalpha[a][B]);
                add((sp.P[a][B] - sm.P[a][B]) / (2 * eps), r.dP_ds[a][B]);
              }
          add((ap.r - am.r) / (2 * ea), r.dr_dalpha);
          add((sp.r - sm.r) / (2 * eps), r.dr_ds);

          // The crack driver's derivatives, measured on their own (they are
          // small next to those of P). psi^+ ~ mu (tr bbar - 3) loses
          // ~eps_machine mu to cancellation, and at points below yield it
          // varies on the strain scale eps / mu of the regularised flow
          // direction (plastic_update()): fourth-order central differences
          // (h = 1e-5) keep both errors below 1e-7 where second-order ones
          // reach 1e-6.
          // d/dx psi^+(x + t direction) at t = 0, from t = +-h, +-2h.
          const auto derivative = [&](const Tensor<2, dim> &dF,
                                      const double          dalpha,
                                      const double          ds) {
            const auto at = [&](const double t) {
              return plastic_update(F + t * dF,
                                    h,
                                    alpha + t * dalpha,
                                    s + t * ds,
                                    dt,
                                    p,
                                    false,
                                    r.yielding)
                .psi_plus;
            };
            return Testing::derivative_4th_order(at, 1e-5);
          };
          worst = std::max(worst, std::sqrt(diff / norm));
          worst_driver =
            std::max(worst_driver,
                     Testing::point_gradient_error(derivative,
                                                   r.dpsi_plus_dF,
                                                   r.dpsi_plus_dalpha,
                                                   r.dpsi_plus_ds));
          energy_error = std::max(energy_error, std::sqrt(e_diff / e_norm));
        }
      out << (delta == 0. ? "sharp switch of (17)" : "blended switch of (17)")
          << (bound ? ", loading condition bound" : "")
          << (degraded ? ", degraded plastic energy" : "") << std::endl;
      if (bound)
        out << "backward Euler local dissipation >= eta_p dalpha^2/dt "
               "(1e-12 y_0 |dalpha|): "
            << Testing::yes_no(worst_dissipation > -1e-12) << std::endl;
      out << (bound ? "samples above alpha_n: " : "plastic samples: ")
          << (plastic >= 10 ? "at least 10" : "too few") << std::endl;
      out << (bound ? "samples below alpha_n: " : "elastic samples: ")
          << (elastic >= 10 ? "at least 10" : "too few") << std::endl;
      if (delta > 0.)
        out << "samples inside the blend: "
            << (blended >= 3 ? "at least 3" : "too few") << std::endl;
      out << "P = dPsi^e/dF (1e-6): " << Testing::yes_no(energy_error < 1e-6)
          << std::endl;
      out << "tangents equal central differences (1e-6): "
          << Testing::yes_no(worst < 1e-6) << std::endl;
      out << "crack driver psi^+: tangents equal central differences (1e-6): "
          << Testing::yes_no(worst_driver < 1e-6) << std::endl;
      out << "det (C^p)^-1 = 1 to round-off (1e-14): "
          << Testing::yes_no(det_error < 1e-14) << std::endl;
      std::cout << "delta " << delta << ": " << plastic << " plastic, "
                << elastic << " elastic, " << blended
                << " blended samples; worst tangent error " << worst
                << ", of psi^+ " << worst_driver << ", energy error "
                << energy_error << ", det error " << det_error
                << ", local dissipation less the viscous part / (y_0 "
                   "|dalpha|) down to "
                << worst_dissipation << std::endl;
    }
  p.loading_condition      = LoadingCondition::pointwise_switch;
  p.degrade_plastic_energy = false;
  p.critical_work_density  = 0.;
  // The blended volumetric energy stays convex in J at every damage: the
  // pressure dPsi/dJ of a pure dilation rises strictly across the blend
  // (at s = 1 a blend of the weight of (17) has a negative slope there).
  {
    p.volumetric_switch_width = 0.05;
    bool rising               = true;
    for (const double s : {0., 0.5, 0.9, 1.})
      {
        double previous = -1e300;
        for (int i = -200; i <= 200; ++i)
          {
            const double         J = 1. + 0.1 * i / 200.;
            const Tensor<2, dim> F =
              std::cbrt(J) * Tensor<2, dim>(unit_symmetric_tensor<dim>());
            const MaterialResponse r =
              plastic_update(F, PlasticHistory(), 0., s, 0.1, p, false);
            const double pressure = r.tau[0][0] / J;
            rising                = rising && pressure > previous;
            previous              = pressure;
          }
      }
    out << "blended volumetric energy convex in J (s = 0, 0.5, 0.9, 1): "
        << Testing::yes_no(rising) << std::endl;
  }
  p.volumetric_switch_width = 0.;

  // 3. Uniaxial stress, nearly rate independent, against the small-strain
  // reference; overstress against eta_p.
  {
    const double E = 9. * p.bulk_modulus * p.shear_modulus /
                     (3. * p.bulk_modulus + p.shear_modulus);
    double overstress[2] = {0, 0};
    bool   close         = true;
    for (const unsigned int k : {0u, 1u})
      {
        PlasticityParameters q = p;
        q.viscosity            = (k == 0) ? 1e-5 : 1e-6;
        PlasticHistory h;
        const double   dt = 0.01; // 100 steps to 2 % stretch
        for (unsigned int n = 1; n <= 100; ++n)
          {
            const double           lambda = 1. + 0.0002 * n;
            const MaterialResponse r =
              Testing::uniaxial_plastic_step(lambda, h, dt, q);
            h                  = r.updated;
            const double eps   = std::log(lambda);
            const double sigma = r.tau[0][0];
            if (k == 1 && n % 25 == 0)
              {
                const double ref = reference_stress(eps, q);
                close            = close && std::abs(sigma - ref) < 0.01 * ref;
                out << "  strain " << std::setprecision(3) << eps
                    << ": sigma / y0 = " << sigma / q.initial_yield
                    << std::setprecision(6) << std::endl;
              }
            if (n == 100)
              overstress[k] =
                std::sqrt(1.5) * std::sqrt(deviator(r.tau) * deviator(r.tau)) -
                hardening_stress(h.alpha, q);
          }
      }
    out << "uniaxial stress follows the rate-independent reference (1 %): "
        << Testing::yes_no(close) << std::endl;
    out << "overstress shrinks with eta_p (ratio 10 +- 1): "
        << Testing::yes_no(std::abs(overstress[0] / overstress[1] - 10.) < 1.)
        << std::endl;
    std::cout << "overstress " << overstress[0] << " " << overstress[1] << " E "
              << E << std::endl;
  }

  // 4. Elastic unloading.
  {
    PlasticHistory   h;
    MaterialResponse r;
    for (unsigned int n = 1; n <= 50; ++n)
      {
        r = Testing::uniaxial_plastic_step(1. + 0.0002 * n, h, 0.01, p);
        h = r.updated;
      }
    const MaterialResponse u =
      Testing::uniaxial_plastic_step(1. + 0.0002 * 49, h, 0.01, p);
    const double E = 9. * p.bulk_modulus * p.shear_modulus /
                     (3. * p.bulk_modulus + p.shear_modulus);
    const double slope = (r.tau[0][0] - u.tau[0][0]) / 0.0002;
    std::cout << "unloading: yielding " << u.yielding << " dalpha "
              << u.updated.alpha - h.alpha << " dCp "
              << (u.updated.Cp_inv - h.Cp_inv).norm() << " slope / E "
              << slope / E << std::endl;
    // The flow formula is evaluated at every point (with alpha = alpha_n
    // it is zero, C^p moves by the round-off of its determinant rescaling).
    const bool elastic = !u.yielding && u.updated.alpha == h.alpha &&
                         (u.updated.Cp_inv - h.Cp_inv).norm() < 1e-14 &&
                         std::abs(slope - E) < 0.01 * E;
    out << "unloading is elastic with slope E (1 %): "
        << Testing::yes_no(elastic) << std::endl;
  }

  // 5. The hold of a non-yielding point.
  {
    const auto shear = [](const double gamma) {
      Tensor<2, dim> F = unit_symmetric_tensor<dim>();
      F[0][1]          = gamma;
      return F;
    };
    const double   dt = 0.01, pull = 0.3 * p.initial_yield;
    PlasticHistory free_point, pulled;
    pulled.r = pull;
    // The shear at which the trial test switches, by bisection.
    const auto onset = [&](const PlasticHistory &h) {
      double lo = 0., hi = 0.1;
      for (unsigned int i = 0; i < 100; ++i)
        {
          const double mid = 0.5 * (lo + hi);
          (plastic_update(shear(mid), h, h.alpha, 0., dt, p, false).yielding
             ? hi
             : lo)         = mid;
        }
      return 0.5 * (lo + hi);
    };
    const double gamma_free = onset(free_point), gamma_pulled = onset(pulled);

    const MaterialResponse held =
      plastic_update(shear(0.5 * gamma_pulled), pulled, 0., 0., dt, p, false);
    out << "a held point with F unchanged stays: r = r_n, C^p unchanged: "
        << Testing::yes_no(!held.yielding && held.r == pull &&
                           (held.updated.Cp_inv - pulled.Cp_inv).norm() < 1e-14)
        << std::endl;
    std::cout << "onset of yield in shear: " << gamma_free << " free, "
              << gamma_pulled << " pulled" << std::endl;
    out << "the pull lowers the yield onset (ratio below 0.8): "
        << Testing::yes_no(gamma_pulled < 0.8 * gamma_free) << std::endl;

    const auto branch_gap = [&](const double d_alpha) {
      const auto r = [&](const bool yielding) {
        return plastic_update(shear(gamma_pulled),
                              pulled,
                              d_alpha,
                              0.,
                              dt,
                              p,
                              true,
                              yielding)
          .r;
      };
      return std::abs(r(true) - r(false));
    };
    const double d_alpha = 1e-3;
    const double ratio   = branch_gap(d_alpha) / branch_gap(0.5 * d_alpha);
    const double slope =
      plastic_update(shear(gamma_pulled), pulled, 0., 0., dt, p, true, false)
        .dr_dalpha;
    std::cout << "branch gap at the switch: " << branch_gap(d_alpha)
              << " against slope x dalpha " << slope * d_alpha << ", ratio "
              << ratio << std::endl;
    out << "both branches of r agree to second order at the switch: "
        << Testing::yes_no(std::abs(ratio - 4.) < 0.2 &&
                           branch_gap(d_alpha) < 0.05 * slope * d_alpha)
        << std::endl;
  }
}
