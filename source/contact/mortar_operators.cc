#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>

#include <ductile_contact/contact/contact_ad.h>
#include <ductile_contact/contact/mortar_operators.h>
#include <ductile_contact/contact/mortar_segments.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    template <typename Number>
    using MatrixF = std::array<std::array<Number, face_nodes>, face_nodes>;

    /// Multiplier basis coefficients a_ik of the face x (class doc).
    template <typename Number>
    MatrixF<Number>
    basis_coefficients(const FaceCoordinates<Number> &x, const bool dual)
    {
      MatrixF<Number> a;
      for (unsigned int i = 0; i < face_nodes; ++i)
        for (unsigned int k = 0; k < face_nodes; ++k)
          a[i][k] = i == k ? 1. : 0.;
      if (!dual)
        return a;

      using std::sqrt;
      const QGauss<dim - 1>          gauss(4);
      MatrixF<Number>                mass;
      std::array<Number, face_nodes> lumped;
      for (unsigned int i = 0; i < face_nodes; ++i)
        {
          lumped[i] = 0.;
          for (unsigned int k = 0; k < face_nodes; ++k)
            mass[i][k] = 0.;
        }
#if DUCTILE_CONTACT_DIM == 3
      std::array<double, face_nodes> n, n_xi, n_eta;
#else
      std::array<double, face_nodes> n, n_xi;
#endif
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
#if DUCTILE_CONTACT_DIM == 3
          ContactFace::shape(gauss.point(q), n, &n_xi, &n_eta);
          std::array<Number, dim> t0, t1;
          for (unsigned int c = 0; c < dim; ++c)
            {
              t0[c] = 0.;
              t1[c] = 0.;
              for (unsigned int i = 0; i < face_nodes; ++i)
                {
                  t0[c] += n_xi[i] * x[i][c];
                  t1[c] += n_eta[i] * x[i][c];
                }
            }
          const Number c0 = t0[1] * t1[2] - t0[2] * t1[1];
          const Number c1 = t0[2] * t1[0] - t0[0] * t1[2];
          const Number c2 = t0[0] * t1[1] - t0[1] * t1[0];
          const Number dA = sqrt(c0 * c0 + c1 * c1 + c2 * c2) * gauss.weight(q);
#else
          ContactFace::shape(gauss.point(q), n, &n_xi);
          std::array<Number, dim> t0;
          for (unsigned int c = 0; c < dim; ++c)
            {
              t0[c] = 0.;
              for (unsigned int i = 0; i < face_nodes; ++i)
                t0[c] += n_xi[i] * x[i][c];
            }
          const Number dA =
            sqrt(t0[0] * t0[0] + t0[1] * t0[1]) * gauss.weight(q);
#endif
          for (unsigned int i = 0; i < face_nodes; ++i)
            {
              const Number w = n[i] * dA;
              lumped[i] += w;
              for (unsigned int k = 0; k < face_nodes; ++k)
                mass[i][k] += w * n[k];
            }
        }
      // a = diag(lumped) mass^-1 by Gauss-Jordan elimination on [mass |
      // diag(lumped)]^T (mass is symmetric positive definite: no pivoting).
      MatrixF<Number> rhs;
      for (unsigned int i = 0; i < face_nodes; ++i)
        for (unsigned int k = 0; k < face_nodes; ++k)
          rhs[i][k] = i == k ? lumped[i] : Number(0.);
      // Solve mass X = rhs; then a = X^T = X (mass symmetric, rhs diagonal:
      // a = L M^-1 and X = M^-1 L, so a = X^T).
      for (unsigned int p = 0; p < face_nodes; ++p)
        {
          const Number pivot = mass[p][p];
          for (unsigned int k = 0; k < face_nodes; ++k)
            {
              mass[p][k] /= pivot;
              rhs[p][k] /= pivot;
            }
          for (unsigned int r = 0; r < face_nodes; ++r)
            if (r != p)
              {
                const Number factor = mass[r][p];
                for (unsigned int k = 0; k < face_nodes; ++k)
                  {
                    mass[r][k] -= factor * mass[p][k];
                    rhs[r][k] -= factor * rhs[p][k];
                  }
              }
        }
      for (unsigned int i = 0; i < face_nodes; ++i)
        for (unsigned int k = 0; k < face_nodes; ++k)
          a[i][k] = rhs[k][i];
      return a;
    }

    /// The face's shape functions at @p xi. In ContactAD by the chain rule,
    /// N_i(xi) + dN_i/dxi_k dxi_k, from their values and gradients at the
    /// value of @p xi: two vector updates each instead of the products of
    /// Quad9::shape_of() in ContactAD (~3 times the work).
    template <typename Number>
    void
    shape_values(const std::array<Number, dim - 1> &xi,
                 std::array<Number, face_nodes>    &n)
    {
      if constexpr (std::is_same_v<Number, ContactAD>)
        {
#if DUCTILE_CONTACT_DIM == 3
          std::array<double, face_nodes> v, v_xi, v_eta;
          Quad9::shape(Point<2>(xi[0].val(), xi[1].val()), v, &v_xi, &v_eta);
          const double *d0 = &xi[0].fastAccessDx(0);
          const double *d1 = &xi[1].fastAccessDx(0);
          for (unsigned int i = 0; i < face_nodes; ++i)
            {
              n[i]      = v[i];
              double *d = &n[i].fastAccessDx(0);
              for (unsigned int a = 0; a < face_pair_coordinates; ++a)
                d[a] = v_xi[i] * d0[a] + v_eta[i] * d1[a];
            }
#else
          std::array<double, face_nodes> v, v_xi;
          ContactFace::shape(FaceParameter(xi[0].val()), v, &v_xi);
          const double *d0 = &xi[0].fastAccessDx(0);
          for (unsigned int i = 0; i < face_nodes; ++i)
            {
              n[i]      = v[i];
              double *d = &n[i].fastAccessDx(0);
              for (unsigned int a = 0; a < face_pair_coordinates; ++a)
                d[a] = v_xi[i] * d0[a];
            }
#endif
        }
      else
        ContactFace::shape_of(xi, n);
    }

    /// D = a Dhat and M = a Mhat (class doc), D as @p lumped says (then
    /// only its diagonal, a dhat).
    template <typename Number>
    void
    apply_basis(const MatrixF<Number>                &a,
                const bool                            lumped,
                const std::array<Number, face_nodes> &d_hat,
                const MatrixF<Number>                &D_hat,
                const MatrixF<Number>                &M_hat,
                MatrixF<Number>                      &D,
                MatrixF<Number>                      &M)
    {
      for (unsigned int i = 0; i < face_nodes; ++i)
        for (unsigned int k = 0; k < face_nodes; ++k)
          {
            D[i][k] = 0.;
            M[i][k] = 0.;
            for (unsigned int m = 0; m < face_nodes; ++m)
              {
                if (lumped && k == i)
                  D[i][k] += a[i][m] * d_hat[m];
                else if (!lumped)
                  D[i][k] += a[i][m] * D_hat[m][k];
                M[i][k] += a[i][m] * M_hat[m][k];
              }
          }
    }

    /**
     * dhat_i = sum_q W_qi and Mhat_il = sum_q W_qi N_l(m_q), W_qi = w_q
     * N_i(s_q), over the points of a pair, in ContactAD, with the sums of
     * the derivatives as matrix products: a point's terms depend on the 54
     * coordinates only through its weight w_q and its parameter points s_q
     * and m_q, so
     *   dMhat_il = sum_q N_l(m_q) dW_qi + W_qi dN_ql,
     *   dW_qi    = N_i(s_q) dw_q + w_q grad N_i(s_q) . ds_q,
     *   dN_ql    = grad N_l(m_q) . dm_q,
     * i.e. N^T [dW] + W^T [dN] with [dW], [dN] of size points x (9 x 54),
     * formed for a block of points at a time (BLAS). The same sums as the
     * point-by-point products in ContactAD (integrate_pair()), which
     * cost the same arithmetic at a fraction of the speed (each product
     * loads and stores 54 derivatives).
     */
    void
    sum_lumped_derivatives(const std::vector<MortarPointOf<ContactAD>> &points,
                           std::array<ContactAD, face_nodes>           &d_hat,
                           MatrixF<ContactAD>                          &M_hat)
    {
      constexpr unsigned int n = face_pair_coordinates, width = face_nodes * n;
      constexpr unsigned int block = 64;
      // Kept from pair to pair (thread_local: the tangent integrates the
      // pairs of one rank one after the other; no zero fill per pair).
      thread_local FullMatrix<double> W(block, face_nodes),
        N(block, face_nodes), dW(block, width), dN(block, width),
        M_values(face_nodes, face_nodes), N_dW(face_nodes, width),
        W_dN(face_nodes, width);
#if DUCTILE_CONTACT_DIM == 3
      std::array<double, face_nodes> ns, ns_xi, ns_eta, nm, nm_xi, nm_eta;
#else
      std::array<double, face_nodes> ns, ns_xi, nm, nm_xi;
#endif
      std::array<double, face_nodes> d_values{};
      std::array<double, width>      d_sum{};
      for (std::size_t first = 0; first < points.size(); first += block)
        {
          const unsigned int size =
            std::min<std::size_t>(block, points.size() - first);
          if (size < block)
            {
              // The rows past the last point add nothing.
              W  = 0.;
              N  = 0.;
              dW = 0.;
              dN = 0.;
            }
          for (unsigned int r = 0; r < size; ++r)
            {
              const MortarPointOf<ContactAD> &q = points[first + r];
#if DUCTILE_CONTACT_DIM == 3
              Quad9::shape(Point<2>(q.slave[0].val(), q.slave[1].val()),
                           ns,
                           &ns_xi,
                           &ns_eta);
              Quad9::shape(Point<2>(q.master[0].val(), q.master[1].val()),
                           nm,
                           &nm_xi,
                           &nm_eta);
              const double *ds1 = &q.slave[1].fastAccessDx(0);
              const double *dm1 = &q.master[1].fastAccessDx(0);
#else
              ContactFace::shape(FaceParameter(q.slave[0].val()), ns, &ns_xi);
              ContactFace::shape(FaceParameter(q.master[0].val()), nm, &nm_xi);
#endif
              const double  w   = q.weight.val();
              const double *dw  = &q.weight.fastAccessDx(0);
              const double *ds0 = &q.slave[0].fastAccessDx(0);
              const double *dm0 = &q.master[0].fastAccessDx(0);
              for (unsigned int i = 0; i < face_nodes; ++i)
                {
                  W(r, i)           = w * ns[i];
                  N(r, i)           = nm[i];
                  const double c_w  = ns[i];
                  const double c_s0 = w * ns_xi[i];
                  const double c_m0 = nm_xi[i];
                  double      *dW_i = &dW(r, i * n);
                  double      *dN_i = &dN(r, i * n);
#if DUCTILE_CONTACT_DIM == 3
                  const double c_s1 = w * ns_eta[i];
                  const double c_m1 = nm_eta[i];
                  for (unsigned int a = 0; a < n; ++a)
                    {
                      dW_i[a] = c_w * dw[a] + c_s0 * ds0[a] + c_s1 * ds1[a];
                      dN_i[a] = c_m0 * dm0[a] + c_m1 * dm1[a];
                    }
#else
                  for (unsigned int a = 0; a < n; ++a)
                    {
                      dW_i[a] = c_w * dw[a] + c_s0 * ds0[a];
                      dN_i[a] = c_m0 * dm0[a];
                    }
#endif
                  d_values[i] += W(r, i);
                  for (unsigned int a = 0; a < n; ++a)
                    d_sum[i * n + a] += dW_i[a];
                }
            }
          const bool adding = first > 0;
          W.Tmmult(M_values, N, adding);
          N.Tmmult(N_dW, dW, adding);
          W.Tmmult(W_dN, dN, adding);
        }
      for (unsigned int i = 0; i < face_nodes; ++i)
        {
          d_hat[i] = d_values[i];
          for (unsigned int a = 0; a < n; ++a)
            d_hat[i].fastAccessDx(a) = d_sum[i * n + a];
          for (unsigned int l = 0; l < face_nodes; ++l)
            {
              M_hat[i][l] = M_values(i, l);
              for (unsigned int a = 0; a < n; ++a)
                M_hat[i][l].fastAccessDx(a) =
                  N_dW(l, i * n + a) + W_dN(i, l * n + a);
            }
        }
    }

    /// D = a Dhat and M = a Mhat of the pair (class doc), D as @p weights
    /// says (with lumped weights only the row sums, from dhat_m = int N_m);
    /// false when the faces do not overlap.
    template <typename Number>
    bool
    integrate_pair(const FaceCoordinates<Number> &slave,
                   const FaceCoordinates<Number> &master,
                   const MatrixF<Number>         &a,
                   const SlaveWeights             weights,
                   MatrixF<Number>               &D,
                   MatrixF<Number>               &M)
    {
      const auto points = mortar_points(slave, master);
      if (points.empty())
        return false;
      const bool                     lumped = weights == SlaveWeights::lumped;
      MatrixF<Number>                D_hat, M_hat;
      std::array<Number, face_nodes> d_hat;
      if constexpr (std::is_same_v<Number, ContactAD>)
        if (lumped)
          {
            sum_lumped_derivatives(points, d_hat, M_hat);
            apply_basis(a, lumped, d_hat, D_hat, M_hat, D, M);
            return true;
          }
      for (unsigned int i = 0; i < face_nodes; ++i)
        {
          d_hat[i] = 0.;
          for (unsigned int k = 0; k < face_nodes; ++k)
            {
              D_hat[i][k] = 0.;
              M_hat[i][k] = 0.;
            }
        }
      std::array<Number, face_nodes> ns, nm;
      for (const auto &q : points)
        {
          shape_values(q.slave, ns);
          shape_values(q.master, nm);
          for (unsigned int i = 0; i < face_nodes; ++i)
            {
              const Number w = q.weight * ns[i];
              if (lumped)
                d_hat[i] += w;
              else
                for (unsigned int k = i; k < face_nodes; ++k)
                  D_hat[i][k] += w * ns[k];
              for (unsigned int l = 0; l < face_nodes; ++l)
                M_hat[i][l] += w * nm[l];
            }
        }
      for (unsigned int i = 0; i < face_nodes; ++i)
        for (unsigned int k = 0; k < i; ++k)
          D_hat[i][k] = D_hat[k][i];
      apply_basis(a, lumped, d_hat, D_hat, M_hat, D, M);
      return true;
    }
  } // namespace



  struct MortarFace::BasisDerivatives
  {
    MatrixF<ContactAD> a;
  };



  MortarFace::MortarFace(const ContactFace &slave,
                         const bool         dual,
                         const SlaveWeights weights)
      : slave(slave)
      , dual(dual)
      , weights(weights)
      , coefficients(basis_coefficients(coordinates_of(slave), dual))
  {
  }



  bool
  MortarFace::integrate(const ContactFace &master,
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
    for (unsigned int i = 0; i < face_nodes; ++i)
      for (unsigned int c = 0; c < dim; ++c)
        {
          s[i][c] =
            ContactAD(face_pair_coordinates, dim * i + c, slave.x[i][c]);
          m[i][c] = ContactAD(face_pair_coordinates,
                              face_coordinates + dim * i + c,
                              master.x[i][c]);
        }
    if (!basis_derivatives)
      {
        auto b            = std::make_shared<BasisDerivatives>();
        b->a              = basis_coefficients(s, dual);
        basis_derivatives = b;
      }
    MatrixF<ContactAD> D, M;
    if (!integrate_pair(s, m, basis_derivatives->a, weights, D, M))
      return false;
    for (unsigned int i = 0; i < face_nodes; ++i)
      for (unsigned int k = 0; k < face_nodes; ++k)
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
