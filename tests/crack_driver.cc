// Material-point check of the crack drivers (crack_driving_energy(),
// no mesh):
//  1. the elastic driver is psi^+ of (27) with its derivatives;
//  2. the elastic-plus-plastic-work driver psi_D = zeta <psi^+ +
//     W_p(alpha) - w_c> (zeta = 2.5): its derivatives with respect to F,
//     alpha and s equal fourth-order central differences of the whole
//     chain (plastic_update then crack_driving_energy, the yield switch
//     frozen as in Newton) to 1e-7 in plastic and elastic states with
//     damage and a prior plastic history, w_c chosen so that the bracket
//     is open at some samples and closed at others; where it is closed
//     psi_D and its derivatives are 0;
//  3. W_p(alpha) = int_0^alpha yhat: its derivative is yhat (central
//     differences) and W_p(0) = 0; in uniaxial rate-independent flow the
//     work of the flow stress, int yhat d alpha, equals W_p (trapezoidal
//     sum over 2000 increments, 1e-6).
#include <deal.II/base/tensor.h>

#include <ductile_contact/materials/crack_driver.h>
#include <ductile_contact/materials/plasticity.h>

#include "tests.h"

#include <random>

using namespace dealii;
using namespace DuctileContact;

int
main()
{
  std::ofstream out("output");
  out << std::setprecision(6);
  const PlasticityParameters p = Testing::unit_plasticity();

  std::mt19937                           gen(11);
  std::uniform_real_distribution<double> d(-1., 1.);
  // psi^+ ~ 1e-3 and W_p(alpha ~ 0.01) ~ 5e-5 in these units: w_c in
  // between opens the bracket at some samples only.
  const double w_c = 4e-4;
  // zeta != 1, so that a missing factor shows.
  const PlasticWorkDriver work_driver{w_c, 2.5};
  double                  worst = 0., elastic_error = 0., closed_value = 0.;
  unsigned int            open_samples = 0, closed_samples = 0, plastic = 0;
  for (unsigned int sample = 0; sample < 60; ++sample)
    {
      const auto history       = Testing::random_plastic_history(gen, d, 0.01);
      const Tensor<2, dim> &Fp = history.first;
      const PlasticHistory &h  = history.second;
      // The last 20 samples stay near the plastic deformation of the
      // history (F = (I + A) F^p, small A): mostly below yield.
      const bool     near_yield = sample >= 40;
      Tensor<2, dim> F =
        Testing::perturbed_identity(gen, d, near_yield ? 0.001 : 0.03);
      if (near_yield)
        F = F * Fp;
      const double           alpha = h.alpha + 0.002 * (1.2 + d(gen));
      const double           s = 0.3, dt = 0.1;
      const MaterialResponse m = plastic_update(F, h, alpha, s, dt, p, true);
      plastic += m.yielding;

      // 1. The elastic driver.
      const DrivingEnergy e = crack_driving_energy(
        m, alpha, CrackDriverType::elastic, work_driver, p);
      elastic_error = std::max({elastic_error,
                                std::abs(e.value - m.psi_plus),
                                (e.d_dF - m.dpsi_plus_dF).norm(),
                                std::abs(e.d_dalpha - m.dpsi_plus_dalpha),
                                std::abs(e.d_ds - m.dpsi_plus_ds)});

      // 2. The plastic work driver against central differences.
      const DrivingEnergy D = crack_driving_energy(
        m, alpha, CrackDriverType::elastic_plastic, work_driver, p);
      const auto value_at = [&](const Tensor<2, dim> &dF,
                                const double          dalpha,
                                const double          ds,
                                const double          t) {
        const MaterialResponse r = plastic_update(F + t * dF,
                                                  h,
                                                  alpha + t * dalpha,
                                                  s + t * ds,
                                                  dt,
                                                  p,
                                                  false,
                                                  m.yielding);
        return crack_driving_energy(r,
                                    alpha + t * dalpha,
                                    CrackDriverType::elastic_plastic,
                                    work_driver,
                                    p)
          .value;
      };
      const auto derivative =
        [&](const Tensor<2, dim> &dF, const double dalpha, const double ds) {
          return Testing::derivative_4th_order(
            [&](const double t) { return value_at(dF, dalpha, ds, t); }, 1e-5);
        };
      if (D.value > 1e-4 * w_c)
        {
          ++open_samples;
          worst = std::max(worst,
                           Testing::point_gradient_error(
                             derivative, D.d_dF, D.d_dalpha, D.d_ds));
        }
      else if (m.psi_plus + plastic_work_density(alpha, p) < w_c)
        {
          ++closed_samples;
          closed_value = std::max({closed_value,
                                   std::abs(D.value),
                                   D.d_dF.norm(),
                                   std::abs(D.d_dalpha),
                                   std::abs(D.d_ds)});
        }
    }
  out << "elastic driver = psi^+ with its derivatives: "
      << Testing::yes_no(elastic_error == 0.) << std::endl;
  out << "plastic samples: " << (plastic >= 10 ? "at least 10" : "too few")
      << std::endl;
  out << "elastic samples: " << (60 - plastic >= 10 ? "at least 10" : "too few")
      << std::endl;
  out << "samples with the bracket open: "
      << (open_samples >= 10 ? "at least 10" : "too few") << std::endl;
  out << "samples with the bracket closed: "
      << (closed_samples >= 10 ? "at least 10" : "too few") << std::endl;
  out << "plastic work driver: derivatives equal central differences "
         "(1e-7): "
      << Testing::yes_no(worst < 1e-7) << std::endl;
  out << "closed bracket: psi_D and its derivatives are 0: "
      << Testing::yes_no(closed_value == 0.) << std::endl;
  std::cout << plastic << " plastic, " << open_samples << " open, "
            << closed_samples << " closed; worst " << worst << std::endl;

  // 3. W_p.
  double slope_error = 0.;
  for (const double a : {0., 0.01, 0.05, 0.2})
    {
      const double ea = 1e-6;
      const double fd =
        (plastic_work_density(a + ea, p) - plastic_work_density(a - ea, p)) /
        (2. * ea);
      slope_error = std::max(slope_error,
                             std::abs(fd - hardening_stress(a, p)) /
                               hardening_stress(a, p));
    }
  out << "dW_p/dalpha = yhat (1e-8): " << Testing::yes_no(slope_error < 1e-8)
      << std::endl;
  out << "W_p(0) = 0: " << Testing::yes_no(plastic_work_density(0., p) == 0.)
      << std::endl;
  const unsigned int n_increments = 2000;
  const double       alpha_end    = 0.2;
  double             work         = 0.;
  for (unsigned int i = 0; i < n_increments; ++i)
    {
      const double a0 = alpha_end * i / n_increments,
                   a1 = alpha_end * (i + 1) / n_increments;
      work +=
        0.5 * (hardening_stress(a0, p) + hardening_stress(a1, p)) * (a1 - a0);
    }
  out << "work of the flow stress = W_p (1e-6): "
      << Testing::yes_no(std::abs(work - plastic_work_density(alpha_end, p)) <
                         1e-6 * work)
      << std::endl;
}
