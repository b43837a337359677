// Unit test of the degraded small-strain linear elasticity (Elastic law =
// linear, doc/model.md section 2.1) with its three energy splits, no mesh:
//  1. positive_part(): X_+ has the positive eigenvalues of X on its
//     eigenvectors, X_+ : (X - X_+) = 0, and dX_+/dX against central
//     differences (including a plane-strain X with a zero eigenvalue);
//  2. closed forms at s = 0 for uniaxial strain in tension and compression
//     and for pure shear: psi^+, psi^- = psi - psi^+ and sigma_xx of each
//     split, printed at 5 digits; psi^+ + psi^- = psi and sigma^+ +
//     sigma^- = sigma of the unsplit law at any strain;
//  3. random F in 3-D and in plane strain (F_33 = 1), s = 0, 0.3, 0.9,
//     a_g = 2, 1, k = 1e-8, 1e-2, each split: dP/dF, dP/ds, dpsi^+/dF
//     against central differences, P = dPsi^e/dF and dPsi^e/ds = g_k'(s)
//     psi^+ by central differences of the energy;
//  4. an elastic body with Elastic law = linear through evaluate_material()
//     is this law without degradation (s ignored, psi^+ the whole energy).
#include <deal.II/base/tensor.h>

#include <ductile_contact/materials/body_material.h>
#include <ductile_contact/materials/degradation.h>
#include <ductile_contact/materials/linear_elasticity.h>

#include "tests.h"

#include <random>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  constexpr unsigned int d = material_dim;
  // mu, kappa of pfm-cracks' notched specimens in kN/mm^2 (lambda 121.15).
  const double mu = 80.77, kappa = 121.15 + 2. * 80.77 / 3.;

  const std::vector<std::pair<EnergySplit, std::string>> splits = {
    {EnergySplit::none, "none"},
    {EnergySplit::volumetric_deviatoric, "volumetric-deviatoric"},
    {EnergySplit::spectral, "spectral"}};


  /// Random F = I + H, |H_ij| <= 0.02: four in 3-D, four in plane strain
  /// (second: whether F is a plane-strain state).
  std::vector<std::pair<Tensor<2, d>, bool>>
  deformations()
  {
    std::mt19937                               gen(5);
    std::uniform_real_distribution<double>     h(-0.02, 0.02);
    std::vector<std::pair<Tensor<2, d>, bool>> result;
    for (const bool plane : {false, true})
      for (unsigned int n = 0; n < 4; ++n)
        {
          Tensor<2, d> F = unit_symmetric_tensor<d>();
          for (unsigned int i = 0; i < d; ++i)
            for (unsigned int j = 0; j < d; ++j)
              if (!plane || (i < 2 && j < 2))
                F[i][j] += h(gen);
          result.emplace_back(F, plane);
        }
    return result;
  }

  MaterialResponse
  law(const Tensor<2, d>          &F,
      const double                 s,
      const DegradationParameters &p,
      const EnergySplit            split,
      const bool                   with_tangent)
  {
    return degraded_linear_elasticity(F, s, mu, kappa, p, split, with_tangent);
  }

  void
  check_positive_part(std::ostream &out)
  {
    std::mt19937                           gen(3);
    std::uniform_real_distribution<double> r(-1., 1.);
    double worst_eigen = 0., worst_orthogonal = 0., worst_fd = 0.;
    for (unsigned int n = 0; n < 6; ++n)
      {
        SymmetricTensor<2, d> X;
        for (unsigned int i = 0; i < d; ++i)
          for (unsigned int j = i; j < d; ++j)
            X[i][j] = r(gen);
        if (n == 5) // plane strain: a zero eigenvalue along z
          X[0][2] = X[1][2] = X[2][2] = 0.;
        Tensor<4, d>                D;
        const SymmetricTensor<2, d> Xp = positive_part(X, &D);
        for (const auto &[x, v] : eigenvectors(X))
          worst_eigen =
            std::max(worst_eigen, (Xp * v - std::max(x, 0.) * v).norm());
        worst_orthogonal = std::max(worst_orthogonal, std::abs(Xp * (X - Xp)));
        // The plane-strain X sits on the kink of <.>_+ along z: there only
        // the in-plane derivatives exist.
        const unsigned int     m = (n == 5) ? 2 : d;
        Testing::RelativeError e;
        const double           h = 1e-7;
        for (unsigned int c = 0; c < m; ++c)
          for (unsigned int D_ = 0; D_ < m; ++D_)
            {
              SymmetricTensor<2, d> Xh = X;
              Xh[c][D_] += h; // moves X_cD and X_Dc together
              SymmetricTensor<2, d> Xm = X;
              Xm[c][D_] -= h;
              const SymmetricTensor<2, d> dXp =
                (positive_part(Xh) - positive_part(Xm)) / (2. * h);
              const double factor = (c == D_) ? 1. : 2.;
              for (unsigned int a = 0; a < d; ++a)
                for (unsigned int b = 0; b < d; ++b)
                  e.add(dXp[a][b], factor * D[a][b][c][D_]);
            }
        worst_fd = std::max(worst_fd, e.value());
      }
    out << "X_+ n_i = <x_i>_+ n_i (1e-13): "
        << Testing::yes_no(worst_eigen < 1e-13) << std::endl;
    out << "X_+ : (X - X_+) = 0 (1e-13): "
        << Testing::yes_no(worst_orthogonal < 1e-13) << std::endl;
    out << "dX_+/dX vs FD: max rel error < 1e-6: "
        << Testing::yes_no(worst_fd < 1e-6) << std::endl;
    std::cout << "positive_part: eigen " << worst_eigen << " orthogonal "
              << worst_orthogonal << " FD " << worst_fd << std::endl;
  }

  void
  check_closed_forms(std::ostream &out)
  {
    const DegradationParameters p{2., 0.};
    const double                e = 1.1e-3, lambda = kappa - 2. * mu / 3.;
    std::vector<std::pair<std::string, Tensor<2, d>>> states;
    for (const double sign : {1., -1.})
      {
        Tensor<2, d> F = unit_symmetric_tensor<d>();
        F[0][0] += sign * e;
        states.emplace_back(sign > 0 ? "uniaxial tension"
                                     : "uniaxial "
                                       "compression",
                            F);
      }
    Tensor<2, d> shear = unit_symmetric_tensor<d>();
    shear[0][1] = shear[1][0] = e;
    states.emplace_back("pure shear", shear);

    out << std::setprecision(5);
    double worst_sum = 0.;
    for (const auto &[name, F] : states)
      {
        const MaterialResponse whole = law(F, 0., p, EnergySplit::none, true);
        out << name << " (strain 1.1e-3), psi = " << whole.psi_elastic
            << std::endl;
        for (const auto &[split, split_name] : splits)
          {
            const MaterialResponse r      = law(F, 0., p, split, true);
            const MaterialResponse broken = law(F, 1., p, split, false);
            out << "  " << split_name << ": psi+ = " << r.psi_plus
                << ", psi- = " << broken.psi_elastic
                << ", broken sigma_xx = " << broken.P[0][0] << std::endl;
            worst_sum = std::max(
              {worst_sum,
               std::abs(r.psi_plus + broken.psi_elastic - whole.psi_elastic) /
                 whole.psi_elastic,
               (r.P - whole.P).norm() / whole.P.norm(),
               (r.dP_dF - whole.dP_dF).norm() / whole.dP_dF.norm()});
          }
      }
    // The closed forms: uniaxial tension of the spectral split is wholly
    // positive, pure shear half (psi = 2 mu e^2, psi^+ = mu e^2).
    const MaterialResponse t =
      law(states[0].second, 0., p, EnergySplit::spectral, false);
    const MaterialResponse c =
      law(states[1].second, 0., p, EnergySplit::spectral, false);
    const MaterialResponse sh =
      law(states[2].second, 0., p, EnergySplit::spectral, false);
    const bool closed =
      std::abs(t.psi_plus - (0.5 * lambda + mu) * e * e) < 1e-12 &&
      std::abs(c.psi_plus) < 1e-15 &&
      std::abs(sh.psi_plus - mu * e * e) < 1e-12 &&
      std::abs(sh.psi_elastic - 2. * mu * e * e) < 1e-12;
    out << "spectral: psi+ = (lambda/2 + mu) e^2, 0, mu e^2 in tension, "
           "compression, shear (1e-12): "
        << Testing::yes_no(closed) << std::endl;
    out << "at s = 0 every split is the unsplit law (psi, P, dP/dF; 1e-12): "
        << Testing::yes_no(worst_sum < 1e-12) << std::endl;
    out << std::setprecision(6);
  }

  void
  check_derivatives(std::ostream &out)
  {
    double worst_A = 0, worst_dP_ds = 0, worst_dpsi_plus = 0, worst_P = 0,
           worst_dpsi_ds = 0;
    for (const auto &[split, name] : splits)
      for (const DegradationParameters p :
           {DegradationParameters{2., 1e-8}, DegradationParameters{1., 1e-2}})
        for (const double s : {0., 0.3, 0.9})
          for (const auto &[F, plane] : deformations())
            {
              // In plane strain e_33 = 0 sits on the kink of <.>_+, so
              // only the in-plane derivatives (what a 2-D run uses) exist.
              const unsigned int     n = plane ? 2 : d;
              const double           h = 1e-8;
              const MaterialResponse r = law(F, s, p, split, true);
              Testing::RelativeError e_A, e_dpsi_plus, e_P, e_dP_ds;
              for (unsigned int c = 0; c < n; ++c)
                for (unsigned int D = 0; D < n; ++D)
                  {
                    Tensor<2, d> Fp = F, Fm = F;
                    Fp[c][D] += h;
                    Fm[c][D] -= h;
                    const MaterialResponse rp = law(Fp, s, p, split, false);
                    const MaterialResponse rm = law(Fm, s, p, split, false);
                    for (unsigned int a = 0; a < d; ++a)
                      for (unsigned int B = 0; B < d; ++B)
                        e_A.add((rp.P[a][B] - rm.P[a][B]) / (2 * h),
                                r.dP_dF[a][B][c][D]);
                    e_dpsi_plus.add((rp.psi_plus - rm.psi_plus) / (2 * h),
                                    r.dpsi_plus_dF[c][D]);
                    e_P.add((rp.psi_elastic - rm.psi_elastic) / (2 * h),
                            r.P[c][D]);
                  }
              const double           hs = 1e-6;
              const MaterialResponse sp = law(F, s + hs, p, split, false);
              const MaterialResponse sm = law(F, s - hs, p, split, false);
              for (unsigned int a = 0; a < d; ++a)
                for (unsigned int B = 0; B < d; ++B)
                  e_dP_ds.add((sp.P[a][B] - sm.P[a][B]) / (2 * hs),
                              r.dP_ds[a][B]);
              const double dpsi_ds = degradation_derivative(s, p) * r.psi_plus;
              worst_A              = std::max(worst_A, e_A.value());
              worst_dP_ds          = std::max(worst_dP_ds, e_dP_ds.value());
              worst_dpsi_plus = std::max(worst_dpsi_plus, e_dpsi_plus.value());
              worst_P         = std::max(worst_P, e_P.value());
              worst_dpsi_ds =
                std::max(worst_dpsi_ds,
                         std::abs((sp.psi_elastic - sm.psi_elastic) / (2 * hs) -
                                  dpsi_ds) /
                           std::max(std::abs(dpsi_ds), 1e-300));
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
    std::cout << "FD: A " << worst_A << " dP/ds " << worst_dP_ds << " dpsi+/dF "
              << worst_dpsi_plus << " P " << worst_P << " dPsi/ds "
              << worst_dpsi_ds << std::endl;
  }

  void
  check_body(std::ostream &out)
  {
    BodyParameters body;
    body.shear_modulus = mu;
    body.bulk_modulus  = kappa;
    body.elastic_law   = ElasticLaw::linear;
    body.crack.split   = EnergySplit::spectral;
    double worst       = 0.;
    for (const auto &[F, plane] : deformations())
      {
        (void)plane;
        const MaterialResponse r =
          evaluate_material(body, F, PlasticHistory(), 0., 0.5, 1., true);
        const MaterialResponse whole =
          law(F, 0., {2., 0.}, EnergySplit::none, true);
        worst = std::max(
          {worst,
           (r.P - whole.P).norm() / whole.P.norm(),
           (r.dP_dF - whole.dP_dF).norm() / whole.dP_dF.norm(),
           std::abs(r.psi_plus - whole.psi_elastic) / whole.psi_elastic});
      }
    out << "an elastic body without fracture: the whole law, psi+ = psi "
           "(1e-14): "
        << Testing::yes_no(worst < 1e-14) << std::endl;
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  check_positive_part(out);
  check_closed_forms(out);
  check_derivatives(out);
  check_body(out);
}
