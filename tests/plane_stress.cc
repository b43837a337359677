// Unit test of the plane-stress material point (Out-of-plane state = plane
// stress, doc/model.md section 2.2), through evaluate_material() of a body
// with plane_stress set, no mesh:
//  1. closed forms of linear elasticity: for eps = diag(e, 0) the stress is
//     E/(1 - nu^2) e (plane strain: (lambda + 2 mu) e), eps_33 = -lambda/
//     (lambda + 2 mu) e, printed at 5 digits;
//  2. P_33 = 0 to 1e-12 mu for neo-Hooke, the degraded laws (both
//     splits of neo-Hooke, the spectral split of the linear law) and the
//     plastic update at yield;
//  3. the condensed derivatives against central differences of the whole
//     plane-stress response (F_33 solved again at each perturbed state):
//     in-plane dP/dF, dP/ds, dpsi^+/dF and dpsi^+/ds for the cracking
//     laws; dP/dF, dP/dalpha, dr/dF and dr/dalpha for the plastic update
//     (its yield branch frozen, as the assembly's tangent is);
//  4. P = dPsi^e/dF in the plane (P_33 = 0, so the out-of-plane stretch
//     does no work) by central differences of the energy, elastic laws.
#include <deal.II/base/tensor.h>

#include <ductile_contact/materials/body_material.h>

#include "tests.h"

#include <random>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  constexpr unsigned int d = material_dim;


  BodyParameters
  elastic_body(const ElasticLaw law, const bool fracture, EnergySplit split)
  {
    BodyParameters b;
    b.shear_modulus = 1.;
    b.bulk_modulus  = 2.5;
    b.elastic_law   = law;
    b.fracture      = fracture;
    b.crack.split   = split;
    b.plane_stress  = true;
    return b;
  }

  BodyParameters
  plastic_body()
  {
    BodyParameters             b  = elastic_body(ElasticLaw::neo_hooke,
                                    true,
                                    EnergySplit::volumetric_deviatoric);
    const PlasticityParameters p  = Testing::unit_plasticity();
    b.plasticity                  = true;
    b.plastic.initial_yield       = p.initial_yield;
    b.plastic.saturation_yield    = p.saturation_yield;
    b.plastic.saturation_exponent = p.saturation_exponent;
    b.plastic.viscosity           = p.viscosity;
    return b;
  }

  /// In-plane F = I + H, |H_ab| <= amplitude (F_33 = 1).
  std::vector<Tensor<2, d>>
  deformations(const double amplitude)
  {
    std::mt19937                           gen(7);
    std::uniform_real_distribution<double> h(-amplitude, amplitude);
    std::vector<Tensor<2, d>>              result;
    for (unsigned int n = 0; n < 4; ++n)
      {
        Tensor<2, d> F = unit_symmetric_tensor<d>();
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int b = 0; b < 2; ++b)
            F[a][b] += h(gen);
        result.push_back(F);
      }
    return result;
  }

  struct State
  {
    double              alpha = 0., s = 0.;
    std::optional<bool> frozen;
  };

  MaterialResponse
  response(const BodyParameters &b, const Tensor<2, d> &F, const State &x)
  {
    return evaluate_material(
      b, F, PlasticHistory(), x.alpha, x.s, 1., true, x.frozen);
  }

  void
  check_closed_form(std::ostream &out)
  {
    BodyParameters b =
      elastic_body(ElasticLaw::linear, false, EnergySplit::none);
    const double e = 1.3e-3, mu = 1., lambda = 2.5 - 2. / 3.;
    Tensor<2, d> F = unit_symmetric_tensor<d>();
    F[0][0] += e;
    const MaterialResponse stress = response(b, F, {});
    b.plane_stress                = false;
    const MaterialResponse strain = response(b, F, {});
    const double           E  = mu * (3. * lambda + 2. * mu) / (lambda + mu);
    const double           nu = lambda / (2. * (lambda + mu));
    out << std::setprecision(5)
        << "eps = diag(1.3e-3, 0): plane stress P_xx = " << stress.P[0][0]
        << " (E/(1 - nu^2) e = " << E / (1. - nu * nu) * e << "), plane strain "
        << strain.P[0][0] << " ((lambda + 2 mu) e = " << (lambda + 2. * mu) * e
        << ")" << std::endl
        << std::setprecision(6);
    const bool closed =
      std::abs(stress.P[0][0] - E / (1. - nu * nu) * e) < 1e-14 &&
      std::abs(strain.P[0][0] - (lambda + 2. * mu) * e) < 1e-14 &&
      std::abs(stress.P[1][1] - nu * E / (1. - nu * nu) * e) < 1e-14 &&
      std::abs(stress.dP_dF[0][0][0][0] - E / (1. - nu * nu)) < 1e-13;
    out << "closed forms of P_xx, P_yy and dP_xx/dF_xx (1e-13): "
        << Testing::yes_no(closed) << std::endl;
  }

  /// Worst FD errors of the condensed derivatives of @p b at @p x.
  void
  check_derivatives(std::ostream         &out,
                    const std::string    &name,
                    const BodyParameters &b,
                    const State          &x,
                    const double          amplitude)
  {
    double worst_P33 = 0., worst_A = 0., worst_field = 0., worst_psi = 0.,
           worst_energy   = 0.;
    const bool   plastic  = b.plasticity;
    unsigned int yielding = 0;
    for (const Tensor<2, d> &F : deformations(amplitude))
      {
        State y = x;
        if (plastic) // freeze the branch of the unperturbed state
          y.frozen = response(b, F, x).trial_yielding;
        yielding += y.frozen.value_or(false);
        const MaterialResponse r = response(b, F, y);
        // The stretch's strain error: |P_33| over the modulus.
        worst_P33 = std::max(worst_P33, std::abs(r.P[2][2]) / b.shear_modulus);

        const double           h = 1e-7;
        Testing::RelativeError e_A, e_psi, e_energy;
        for (unsigned int c = 0; c < 2; ++c)
          for (unsigned int D = 0; D < 2; ++D)
            {
              Tensor<2, d> Fp = F, Fm = F;
              Fp[c][D] += h;
              Fm[c][D] -= h;
              const MaterialResponse rp = response(b, Fp, y),
                                     rm = response(b, Fm, y);
              for (unsigned int a = 0; a < 2; ++a)
                for (unsigned int B = 0; B < 2; ++B)
                  e_A.add((rp.P[a][B] - rm.P[a][B]) / (2 * h),
                          r.dP_dF[a][B][c][D]);
              if (plastic)
                e_psi.add((rp.r - rm.r) / (2 * h), r.dr_dF[c][D]);
              else
                {
                  e_psi.add((rp.psi_plus - rm.psi_plus) / (2 * h),
                            r.dpsi_plus_dF[c][D]);
                  e_energy.add((rp.psi_elastic - rm.psi_elastic) / (2 * h),
                               r.P[c][D]);
                }
            }
        // The field derivative: alpha for the plastic update, s otherwise.
        Testing::RelativeError e_field;
        State                  yp = y, ym = y;
        const double           hf = 1e-7;
        (plastic ? yp.alpha : yp.s) += hf;
        (plastic ? ym.alpha : ym.s) -= hf;
        const MaterialResponse fp = response(b, F, yp), fm = response(b, F, ym);
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int B = 0; B < 2; ++B)
            e_field.add((fp.P[a][B] - fm.P[a][B]) / (2 * hf),
                        plastic ? r.dP_dalpha[a][B] : r.dP_ds[a][B]);
        if (plastic)
          e_field.add((fp.r - fm.r) / (2 * hf), r.dr_dalpha);
        else
          e_field.add((fp.psi_plus - fm.psi_plus) / (2 * hf), r.dpsi_plus_ds);
        worst_A      = std::max(worst_A, e_A.value());
        worst_field  = std::max(worst_field, e_field.value());
        worst_psi    = std::max(worst_psi, e_psi.value());
        worst_energy = std::max(worst_energy, e_energy.value());
      }
    const std::string field = plastic ? "alpha" : "s";
    if (plastic)
      out << name << ": yielding at " << yielding << " of 4 states"
          << std::endl;
    out << name
        << ": P_33 = 0 (1e-12 mu): " << Testing::yes_no(worst_P33 < 1e-12)
        << ", dP/dF, dP/d" << field << ", "
        << (plastic ? "dr/dF, dr/dalpha" : "dpsi+/dF, dpsi+/ds")
        << (plastic ? "" : ", P = dPsi/dF") << " vs FD (1e-6): "
        << Testing::yes_no(worst_A < 1e-6 && worst_field < 1e-6 &&
                           worst_psi < 1e-6 && worst_energy < 1e-6)
        << std::endl;
    std::cout << name << ": P33 " << worst_P33 << " A " << worst_A << " field "
              << worst_field << " psi/r " << worst_psi << " energy "
              << worst_energy << std::endl;
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  check_closed_form(out);
  check_derivatives(out,
                    "neo-Hooke, volumetric-deviatoric split, s = 0.4",
                    elastic_body(ElasticLaw::neo_hooke,
                                 true,
                                 EnergySplit::volumetric_deviatoric),
                    {0., 0.4, {}},
                    0.2);
  check_derivatives(out,
                    "neo-Hooke, no split, s = 0.4",
                    elastic_body(ElasticLaw::neo_hooke,
                                 true,
                                 EnergySplit::none),
                    {0., 0.4, {}},
                    0.2);
  check_derivatives(out,
                    "linear, spectral split, s = 0.4",
                    elastic_body(ElasticLaw::linear,
                                 true,
                                 EnergySplit::spectral),
                    {0., 0.4, {}},
                    0.02);
  check_derivatives(out,
                    "plastic update at yield, alpha = 0.01, s = 0.2",
                    plastic_body(),
                    {0.01, 0.2, {}},
                    0.02);
}
