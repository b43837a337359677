#include <ductile_contact/materials/plane_stress.h>

#include <cmath>
#include <limits>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    constexpr unsigned int d = material_dim, k = 2;

    /// Condenses the derivatives of @p r at P_33 = 0 (plane_stress()).
    void
    condense(MaterialResponse &r)
    {
      const double       A_kk = r.dP_dF[k][k][k][k];
      const Tensor<2, d> A_k  = r.dP_dF[k][k]; // A_k,cD
      Tensor<2, d>       col;                  // A_aB,k
      for (unsigned int a = 0; a < d; ++a)
        for (unsigned int B = 0; B < d; ++B)
          col[a][B] = r.dP_dF[a][B][k][k];

      const double dPk_ds = r.dP_ds[k][k], dPk_dalpha = r.dP_dalpha[k][k];
      r.dP_dF -= outer_product(col, A_k) / A_kk;
      r.dP_ds -= col * (dPk_ds / A_kk);
      r.dP_dalpha -= col * (dPk_dalpha / A_kk);

      const double dr_dk = r.dr_dF[k][k];
      r.dr_dF -= A_k * (dr_dk / A_kk);
      r.dr_ds -= dr_dk * dPk_ds / A_kk;
      r.dr_dalpha -= dr_dk * dPk_dalpha / A_kk;

      const double dpsi_dk = r.dpsi_plus_dF[k][k];
      r.dpsi_plus_dF -= A_k * (dpsi_dk / A_kk);
      r.dpsi_plus_ds -= dpsi_dk * dPk_ds / A_kk;
      r.dpsi_plus_dalpha -= dpsi_dk * dPk_dalpha / A_kk;
    }
  } // namespace



  MaterialResponse
  plane_stress(const std::function<MaterialResponse(const Tensor<2, d> &)> &law,
               const Tensor<2, d>                                          &F,
               const double first_guess)
  {
    Tensor<2, d> F3 = with_stretch(F, first_guess);
    for (unsigned int n = 0; n < 30; ++n)
      {
        MaterialResponse r    = law(F3);
        const double     A_kk = r.dP_dF[k][k][k][k];
        const double     step = -r.P[k][k] / A_kk;
        // Converged when the out-of-plane stretch moves by less than 1e-13
        // (its strain is then exact to round-off).
        if (std::abs(step) <= 1e-13 * F3[k][k])
          {
            condense(r);
            r.updated.stretch = F3[k][k];
            return r;
          }
        if (!(A_kk > 0.) || !(F3[k][k] + step > 0.))
          break;
        F3[k][k] += step;
      }
    MaterialResponse failed;
    const double     nan = std::numeric_limits<double>::quiet_NaN();
    failed.psi_elastic   = nan;
    for (unsigned int a = 0; a < d; ++a)
      for (unsigned int B = 0; B < d; ++B)
        failed.P[a][B] = nan;
    return failed;
  }
} // namespace DuctileContact
