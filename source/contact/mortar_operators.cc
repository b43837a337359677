#include <deal.II/base/quadrature_lib.h>

#include <ductile_contact/contact/contact_ad.h>
#include <ductile_contact/contact/mortar_operators.h>
#include <ductile_contact/contact/mortar_segments.h>

#include <cmath>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    template <typename Number>
    using Matrix9 = std::array<std::array<Number, 9>, 9>;

    /// Multiplier basis coefficients a_ik of the face x (class doc).
    template <typename Number>
    Matrix9<Number>
    basis_coefficients(const FaceCoordinates<Number> &x, const bool dual)
    {
      Matrix9<Number> a;
      for (unsigned int i = 0; i < 9; ++i)
        for (unsigned int k = 0; k < 9; ++k)
          a[i][k] = i == k ? 1. : 0.;
      if (!dual)
        return a;

      using std::sqrt;
      const QGauss<2>       gauss(4);
      Matrix9<Number>       mass;
      std::array<Number, 9> lumped;
      for (unsigned int i = 0; i < 9; ++i)
        {
          lumped[i] = 0.;
          for (unsigned int k = 0; k < 9; ++k)
            mass[i][k] = 0.;
        }
      std::array<double, 9> n, n_xi, n_eta;
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          Quad9::shape(gauss.point(q), n, &n_xi, &n_eta);
          std::array<Number, dim> t0, t1;
          for (unsigned int c = 0; c < dim; ++c)
            {
              t0[c] = 0.;
              t1[c] = 0.;
              for (unsigned int i = 0; i < 9; ++i)
                {
                  t0[c] += n_xi[i] * x[i][c];
                  t1[c] += n_eta[i] * x[i][c];
                }
            }
          const Number c0 = t0[1] * t1[2] - t0[2] * t1[1];
          const Number c1 = t0[2] * t1[0] - t0[0] * t1[2];
          const Number c2 = t0[0] * t1[1] - t0[1] * t1[0];
          const Number dA = sqrt(c0 * c0 + c1 * c1 + c2 * c2) * gauss.weight(q);
          for (unsigned int i = 0; i < 9; ++i)
            {
              const Number w = n[i] * dA;
              lumped[i] += w;
              for (unsigned int k = 0; k < 9; ++k)
                mass[i][k] += w * n[k];
            }
        }
      // a = diag(lumped) mass^-1 by Gauss-Jordan elimination on [mass |
      // diag(lumped)]^T (mass is symmetric positive definite: no pivoting).
      Matrix9<Number> rhs;
      for (unsigned int i = 0; i < 9; ++i)
        for (unsigned int k = 0; k < 9; ++k)
          rhs[i][k] = i == k ? lumped[i] : Number(0.);
      // Solve mass X = rhs; then a = X^T = X (mass symmetric, rhs diagonal:
      // a = L M^-1 and X = M^-1 L, so a = X^T).
      for (unsigned int p = 0; p < 9; ++p)
        {
          const Number pivot = mass[p][p];
          for (unsigned int k = 0; k < 9; ++k)
            {
              mass[p][k] /= pivot;
              rhs[p][k] /= pivot;
            }
          for (unsigned int r = 0; r < 9; ++r)
            if (r != p)
              {
                const Number factor = mass[r][p];
                for (unsigned int k = 0; k < 9; ++k)
                  {
                    mass[r][k] -= factor * mass[p][k];
                    rhs[r][k] -= factor * rhs[p][k];
                  }
              }
        }
      for (unsigned int i = 0; i < 9; ++i)
        for (unsigned int k = 0; k < 9; ++k)
          a[i][k] = rhs[k][i];
      return a;
    }

    /// D = a Dhat and M = a Mhat of the pair (class doc), D as @p weights
    /// says (with lumped weights only the row sums, from dhat_m = int N_m);
    /// false when the faces do not overlap.
    template <typename Number>
    bool
    integrate_pair(const FaceCoordinates<Number> &slave,
                   const FaceCoordinates<Number> &master,
                   const Matrix9<Number>         &a,
                   const SlaveWeights             weights,
                   Matrix9<Number>               &D,
                   Matrix9<Number>               &M)
    {
      const auto points = mortar_points(slave, master);
      if (points.empty())
        return false;
      const bool            lumped = weights == SlaveWeights::lumped;
      Matrix9<Number>       D_hat, M_hat;
      std::array<Number, 9> d_hat;
      for (unsigned int i = 0; i < 9; ++i)
        {
          d_hat[i] = 0.;
          for (unsigned int k = 0; k < 9; ++k)
            {
              D_hat[i][k] = 0.;
              M_hat[i][k] = 0.;
            }
        }
      std::array<Number, 9> ns, nm;
      for (const auto &q : points)
        {
          Quad9::shape_of(q.slave, ns);
          Quad9::shape_of(q.master, nm);
          for (unsigned int i = 0; i < 9; ++i)
            {
              const Number w = q.weight * ns[i];
              if (lumped)
                d_hat[i] += w;
              else
                for (unsigned int k = i; k < 9; ++k)
                  D_hat[i][k] += w * ns[k];
              for (unsigned int l = 0; l < 9; ++l)
                M_hat[i][l] += w * nm[l];
            }
        }
      for (unsigned int i = 0; i < 9; ++i)
        for (unsigned int k = 0; k < i; ++k)
          D_hat[i][k] = D_hat[k][i];
      for (unsigned int i = 0; i < 9; ++i)
        for (unsigned int k = 0; k < 9; ++k)
          {
            D[i][k] = 0.;
            M[i][k] = 0.;
            for (unsigned int m = 0; m < 9; ++m)
              {
                if (lumped && k == i)
                  D[i][k] += a[i][m] * d_hat[m];
                else if (!lumped)
                  D[i][k] += a[i][m] * D_hat[m][k];
                M[i][k] += a[i][m] * M_hat[m][k];
              }
          }
      return true;
    }
  } // namespace



  struct MortarFace::BasisDerivatives
  {
    Matrix9<ContactAD> a;
  };



  MortarFace::MortarFace(const Quad9       &slave,
                         const bool         dual,
                         const SlaveWeights weights)
      : slave(slave)
      , dual(dual)
      , weights(weights)
      , coefficients(basis_coefficients(coordinates_of(slave), dual))
  {
  }



  bool
  MortarFace::integrate(const Quad9       &master,
                        FacePairOperators &out,
                        const bool         derivatives) const
  {
    if (!derivatives)
      return integrate_pair(coordinates_of(slave),
                            coordinates_of(master),
                            coefficients,
                            weights,
                            out.D,
                            out.M);

    FaceCoordinates<ContactAD> s, m;
    for (unsigned int i = 0; i < 9; ++i)
      for (unsigned int c = 0; c < dim; ++c)
        {
          s[i][c] = ContactAD(face_pair_coordinates, 3 * i + c, slave.x[i][c]);
          m[i][c] =
            ContactAD(face_pair_coordinates, 27 + 3 * i + c, master.x[i][c]);
        }
    if (!basis_derivatives)
      {
        auto b            = std::make_shared<BasisDerivatives>();
        b->a              = basis_coefficients(s, dual);
        basis_derivatives = b;
      }
    Matrix9<ContactAD> D, M;
    if (!integrate_pair(s, m, basis_derivatives->a, weights, D, M))
      return false;
    for (unsigned int i = 0; i < 9; ++i)
      for (unsigned int k = 0; k < 9; ++k)
        {
          out.D[i][k] = D[i][k].val();
          out.M[i][k] = M[i][k].val();
          for (unsigned int a = 0; a < face_pair_coordinates; ++a)
            {
              out.dD[i][k][a] = D[i][k].fastAccessDx(a);
              out.dM[i][k][a] = M[i][k].fastAccessDx(a);
            }
        }
    return true;
  }
} // namespace DuctileContact
