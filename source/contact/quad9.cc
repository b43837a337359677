#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <ductile_contact/contact/quad9.h>

#include <cmath>

// Empty in the plane-strain build (quad9.h).
#if DUCTILE_CONTACT_DIM == 3
namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// Quadratic Lagrange polynomials on [0, 1] with nodes 0, 1/2, 1.
    void
    lagrange(const double t, double l[3], double dl[3])
    {
      l[0]  = 2. * (t - 0.5) * (t - 1.);
      l[1]  = 4. * t * (1. - t);
      l[2]  = 2. * t * (t - 0.5);
      dl[0] = 4. * t - 3.;
      dl[1] = 4. - 8. * t;
      dl[2] = 4. * t - 1.;
    }
  } // namespace



  void
  Quad9::shape(const Point<2>        &xi,
               std::array<double, 9> &values,
               std::array<double, 9> *d_xi,
               std::array<double, 9> *d_eta)
  {
    double la[3], dla[3], lb[3], dlb[3];
    lagrange(xi[0], la, dla);
    lagrange(xi[1], lb, dlb);
    for (unsigned int b = 0; b < 3; ++b)
      for (unsigned int a = 0; a < 3; ++a)
        {
          values[a + 3 * b] = la[a] * lb[b];
          if (d_xi)
            (*d_xi)[a + 3 * b] = dla[a] * lb[b];
          if (d_eta)
            (*d_eta)[a + 3 * b] = la[a] * dlb[b];
        }
  }



  Point<dim>
  Quad9::position(const Point<2> &xi) const
  {
    std::array<double, 9> n;
    shape(xi, n);
    Point<dim> p;
    for (unsigned int i = 0; i < 9; ++i)
      p += n[i] * x[i];
    return p;
  }



  std::array<Tensor<1, dim>, 2>
  Quad9::tangents(const Point<2> &xi) const
  {
    std::array<double, 9>         n, dxi, deta;
    std::array<Tensor<1, dim>, 2> t;
    shape(xi, n, &dxi, &deta);
    for (unsigned int i = 0; i < 9; ++i)
      {
        t[0] += dxi[i] * x[i];
        t[1] += deta[i] * x[i];
      }
    return t;
  }



  Tensor<1, dim>
  Quad9::normal(const Point<2> &xi) const
  {
    const auto           t = tangents(xi);
    const Tensor<1, dim> n = cross_product_3d(t[0], t[1]);
    return n / n.norm();
  }



  std::array<Tensor<2, dim>, 9>
  Quad9::normal_derivatives(const Point<2> &xi) const
  {
    // n = c / |c|, c = x_xi x x_eta: dn = (I - n n) dc / |c| with dc =
    // dN_i/dxi (dx_i x x_eta) + dN_i/deta (x_xi x dx_i).
    std::array<double, 9> n, dxi, deta;
    shape(xi, n, &dxi, &deta);
    const auto           t      = tangents(xi);
    const Tensor<1, dim> c      = cross_product_3d(t[0], t[1]);
    const double         length = c.norm();
    const Tensor<1, dim> normal = c / length;
    const Tensor<2, dim> P =
      (unit_symmetric_tensor<dim>() - outer_product(normal, normal)) / length;
    std::array<Tensor<2, dim>, 9> derivatives;
    for (unsigned int i = 0; i < 9; ++i)
      for (unsigned int m = 0; m < dim; ++m)
        {
          Tensor<1, dim> e;
          e[m]                    = 1.;
          const Tensor<1, dim> dc = dxi[i] * cross_product_3d(e, t[1]) +
                                    deta[i] * cross_product_3d(t[0], e);
          const Tensor<1, dim> dn = P * dc;
          for (unsigned int r = 0; r < dim; ++r)
            derivatives[i][r][m] = dn[r];
        }
    return derivatives;
  }



  bool
  Quad9::project_along(const Point<dim>     &p,
                       const Tensor<1, dim> &d,
                       const Point<2>       &start,
                       Point<2>             &xi) const
  {
    // Solve x(xi, eta) - p - t d = 0 for (xi, eta, t).
    xi                   = start;
    const double size    = (x[8] - x[0]).norm() + (x[8] - x[4]).norm();
    double       t_along = 0.;
    for (unsigned int it = 0; it < 20; ++it)
      {
        const Tensor<1, dim> r  = position(xi) - p - t_along * d;
        const auto           tg = tangents(xi);
        Tensor<2, dim>       jac;
        for (unsigned int c = 0; c < dim; ++c)
          {
            jac[c][0] = tg[0][c];
            jac[c][1] = tg[1][c];
            jac[c][2] = -d[c];
          }
        const double det = determinant(jac);
        if (std::abs(det) < 1e-14 * size * size * d.norm())
          return false;
        const Tensor<1, dim> step = invert(jac) * r;
        xi[0] -= step[0];
        xi[1] -= step[1];
        t_along -= step[2];
        if (std::abs(step[0]) + std::abs(step[1]) < 1e-13)
          return true;
      }
    return false;
  }
} // namespace DuctileContact
#endif
