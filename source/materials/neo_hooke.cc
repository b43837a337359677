#include <deal.II/physics/elasticity/standard_tensors.h>

#include <ductile_contact/materials/neo_hooke.h>

namespace DuctileContact
{
  using namespace dealii;
  using StandardTensors = Physics::Elasticity::StandardTensors<material_dim>;

  namespace
  {
    struct Kinematics
    {
      double                           J;
      SymmetricTensor<2, material_dim> b_bar;
    };

    Kinematics
    kinematics(const Tensor<2, material_dim> &F)
    {
      Kinematics k;
      k.J     = determinant(F);
      k.b_bar = std::pow(k.J, -2. / 3.) * symmetrize(F * transpose(F));
      return k;
    }
  } // namespace



  namespace
  {
    SymmetricTensor<4, material_dim>
    spatial_tangent(const Kinematics &k, const double mu, const double kappa)
    {
      const double                            J       = k.J;
      const SymmetricTensor<2, material_dim> &I       = StandardTensors::I;
      const SymmetricTensor<2, material_dim>  tau_iso = mu * deviator(k.b_bar);

      const SymmetricTensor<4, material_dim> c_vol =
        kappa * (2. * J * J - J) * StandardTensors::IxI -
        2. * kappa * (J * J - J) * StandardTensors::S;
      const SymmetricTensor<4, material_dim> c_iso =
        (2. / 3.) * mu * trace(k.b_bar) * StandardTensors::dev_P -
        (2. / 3.) * (outer_product(tau_iso, I) + outer_product(I, tau_iso));
      return c_vol + c_iso;
    }
  } // namespace



  Tensor<4, material_dim>
  first_elasticity_tensor(const Tensor<2, material_dim>          &F_inv,
                          const SymmetricTensor<4, material_dim> &c,
                          const SymmetricTensor<2, material_dim> &tau)
  {
    // tmp_abcD = sum_d (c_abcd + delta_ac tau_bd) F^{-1}_Dd
    double tmp[material_dim][material_dim][material_dim][material_dim];
    for (unsigned int a = 0; a < material_dim; ++a)
      for (unsigned int b = 0; b < material_dim; ++b)
        for (unsigned int cc = 0; cc < material_dim; ++cc)
          for (unsigned int D = 0; D < material_dim; ++D)
            {
              double sum = 0;
              for (unsigned int d = 0; d < material_dim; ++d)
                sum +=
                  (c[a][b][cc][d] + (a == cc ? tau[b][d] : 0.)) * F_inv[D][d];
              tmp[a][b][cc][D] = sum;
            }
    Tensor<4, material_dim> A;
    for (unsigned int a = 0; a < material_dim; ++a)
      for (unsigned int B = 0; B < material_dim; ++B)
        for (unsigned int cc = 0; cc < material_dim; ++cc)
          for (unsigned int D = 0; D < material_dim; ++D)
            {
              double sum = 0;
              for (unsigned int b = 0; b < material_dim; ++b)
                sum += F_inv[B][b] * tmp[a][b][cc][D];
              A[a][B][cc][D] = sum;
            }
    return A;
  }



  MaterialResponse
  neo_hooke(const Tensor<2, material_dim> &F,
            const double                   mu,
            const double                   kappa,
            const bool                     with_tangent)
  {
    const Kinematics k = kinematics(F);
    MaterialResponse r;
    r.J = k.J;
    r.psi_elastic =
      0.5 * kappa * (k.J - 1.) * (k.J - 1.) + 0.5 * mu * (trace(k.b_bar) - 3.);
    r.tau =
      kappa * (k.J * k.J - k.J) * StandardTensors::I + mu * deviator(k.b_bar);
    const Tensor<2, material_dim> F_inv = invert(F);
    r.P = Tensor<2, material_dim>(r.tau) * transpose(F_inv);
    if (with_tangent)
      r.dP_dF =
        first_elasticity_tensor(F_inv, spatial_tangent(k, mu, kappa), r.tau);
    return r;
  }
} // namespace DuctileContact
