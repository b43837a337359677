#include <ductile_contact/materials/linear_elasticity.h>

#include <algorithm>
#include <cmath>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    constexpr unsigned int d = material_dim;

    /// One side of a split: its energy, stress d psi/d eps and tangent.
    struct EnergyPart
    {
      double                psi = 0.;
      SymmetricTensor<2, d> sigma;
      Tensor<4, d>          C;
    };

    /// The two sides psi^+ and psi^- of the split, doc/model.md 2.3.
    struct SplitEnergy
    {
      EnergyPart plus, minus;
    };

    double
    positive(const double x)
    {
      return std::max(x, 0.);
    }

    double
    step(const double x)
    {
      return x > 0. ? 1. : 0.;
    }

    Tensor<4, d>
    I_x_I()
    {
      return Tensor<4, d>(
        outer_product(unit_symmetric_tensor<d>(), unit_symmetric_tensor<d>()));
    }

    /// psi = lambda/2 (tr eps)^2 + mu eps:eps, whole on one side.
    EnergyPart
    whole(const SymmetricTensor<2, d> &eps,
          const double                 mu,
          const double                 lambda,
          const bool                   with_tangent)
    {
      const double tr = trace(eps);
      EnergyPart   p;
      p.psi   = 0.5 * lambda * tr * tr + mu * (eps * eps);
      p.sigma = lambda * tr * unit_symmetric_tensor<d>() + 2. * mu * eps;
      if (with_tangent)
        p.C = lambda * I_x_I() + 2. * mu * Tensor<4, d>(identity_tensor<d>());
      return p;
    }

    /// The volumetric part kappa/2 <+-tr eps>^2 on one side.
    EnergyPart
    volumetric(const double tr,
               const double kappa,
               const bool   tension,
               const bool   with_tangent)
    {
      const double t = tension ? positive(tr) : tr - positive(tr);
      EnergyPart   p;
      p.psi   = 0.5 * kappa * t * t;
      p.sigma = kappa * t * unit_symmetric_tensor<d>();
      if (with_tangent)
        p.C = (tension ? step(tr) : 1. - step(tr)) * kappa * I_x_I();
      return p;
    }

    SplitEnergy
    volumetric_deviatoric(const SymmetricTensor<2, d> &eps,
                          const double                 mu,
                          const double                 kappa,
                          const bool                   with_tangent)
    {
      const double                tr  = trace(eps);
      const SymmetricTensor<2, d> dev = deviator(eps);
      SplitEnergy                 e;
      e.plus = volumetric(tr, kappa, true, with_tangent);
      e.plus.psi += mu * (dev * dev);
      e.plus.sigma += 2. * mu * dev;
      if (with_tangent)
        e.plus.C += 2. * mu * Tensor<4, d>(deviator_tensor<d>());
      e.minus = volumetric(tr, kappa, false, with_tangent);
      return e;
    }

    SplitEnergy
    spectral(const SymmetricTensor<2, d> &eps,
             const double                 mu,
             const double                 lambda,
             const bool                   with_tangent)
    {
      const double                tr = trace(eps);
      Tensor<4, d>                D_plus;
      const SymmetricTensor<2, d> eps_plus =
        positive_part(eps, with_tangent ? &D_plus : nullptr);
      const SymmetricTensor<2, d> eps_minus = eps - eps_plus;
      SplitEnergy                 e;
      e.plus  = volumetric(tr, lambda, true, with_tangent);
      e.minus = volumetric(tr, lambda, false, with_tangent);
      e.plus.psi += mu * (eps_plus * eps_plus);
      e.minus.psi += mu * (eps_minus * eps_minus);
      e.plus.sigma += 2. * mu * eps_plus;
      e.minus.sigma += 2. * mu * eps_minus;
      if (with_tangent)
        {
          e.plus.C += 2. * mu * D_plus;
          e.minus.C += 2. * mu * (Tensor<4, d>(identity_tensor<d>()) - D_plus);
        }
      return e;
    }
  } // namespace



  SymmetricTensor<2, d>
  positive_part(const SymmetricTensor<2, d> &X, Tensor<4, d> *derivative)
  {
    const auto eigen = eigenvectors(X);

    SymmetricTensor<2, d> X_plus;
    double                scale = 0.;
    for (const auto &[x, n] : eigen)
      {
        X_plus += positive(x) * symmetrize(outer_product(n, n));
        scale = std::max(scale, std::abs(x));
      }
    if (derivative == nullptr)
      return X_plus;

    // Daleckii-Krein: in the eigenbasis d(X_+)_ij = theta_ij dX_ij.
    *derivative = 0.;
    for (unsigned int i = 0; i < d; ++i)
      for (unsigned int j = 0; j < d; ++j)
        {
          const double xi = eigen[i].first, xj = eigen[j].first;
          double       theta;
          if (i != j && std::abs(xi - xj) > 1e-12 * scale)
            theta = (positive(xi) - positive(xj)) / (xi - xj);
          else
            theta = step(0.5 * (xi + xj));
          if (theta == 0.)
            continue;
          const Tensor<2, d> N = Tensor<2, d>(
            symmetrize(outer_product(eigen[i].second, eigen[j].second)));
          *derivative += theta * outer_product(N, N);
        }
    return X_plus;
  }



  MaterialResponse
  degraded_linear_elasticity(const Tensor<2, d>          &F,
                             const double                 s,
                             const double                 mu,
                             const double                 kappa,
                             const DegradationParameters &degradation,
                             const EnergySplit            split,
                             const bool                   with_tangent)
  {
    const SymmetricTensor<2, d> eps =
      symmetrize(F) - unit_symmetric_tensor<d>();
    const double lambda = kappa - 2. * mu / 3.;

    SplitEnergy e;
    switch (split)
      {
      case EnergySplit::none:
        e.plus = whole(eps, mu, lambda, with_tangent);
        break;
      case EnergySplit::volumetric_deviatoric:
        e = volumetric_deviatoric(eps, mu, kappa, with_tangent);
        break;
      case EnergySplit::spectral:
        e = spectral(eps, mu, lambda, with_tangent);
        break;
      }

    const double g  = degradation_value(s, degradation);
    const double dg = degradation_derivative(s, degradation);

    MaterialResponse r;
    r.J            = determinant(F);
    r.psi_elastic  = g * e.plus.psi + e.minus.psi;
    r.psi_plus     = e.plus.psi;
    r.tau          = g * e.plus.sigma + e.minus.sigma;
    r.P            = Tensor<2, d>(r.tau);
    r.dP_ds        = dg * Tensor<2, d>(e.plus.sigma);
    r.dpsi_plus_dF = Tensor<2, d>(e.plus.sigma);
    if (with_tangent)
      r.dP_dF = g * e.plus.C + e.minus.C;
    return r;
  }
} // namespace DuctileContact
