#include <ductile_contact/contact/line3.h>

// Empty in the 3-D build (see line3.h).
#if DUCTILE_CONTACT_DIM == 2
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>

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

    /// R v = (v_y, -v_x): @p v turned by -90 degrees.
    Tensor<1, dim>
    turned(const Tensor<1, dim> &v)
    {
      Tensor<1, dim> r;
      r[0] = v[1];
      r[1] = -v[0];
      return r;
    }
  } // namespace



  void
  Line3::shape(const Point<1>        &xi,
               std::array<double, 3> &values,
               std::array<double, 3> *d_xi)
  {
    double l[3], dl[3];
    lagrange(xi[0], l, dl);
    for (unsigned int a = 0; a < 3; ++a)
      {
        values[a] = l[a];
        if (d_xi)
          (*d_xi)[a] = dl[a];
      }
  }



  Point<dim>
  Line3::position(const Point<1> &xi) const
  {
    std::array<double, 3> n;
    shape(xi, n);
    Point<dim> p;
    for (unsigned int i = 0; i < 3; ++i)
      p += n[i] * x[i];
    return p;
  }



  std::array<Tensor<1, dim>, 1>
  Line3::tangents(const Point<1> &xi) const
  {
    std::array<double, 3>         n, dxi;
    std::array<Tensor<1, dim>, 1> t;
    shape(xi, n, &dxi);
    for (unsigned int i = 0; i < 3; ++i)
      t[0] += dxi[i] * x[i];
    return t;
  }



  Tensor<1, dim>
  Line3::normal(const Point<1> &xi) const
  {
    const Tensor<1, dim> n = turned(tangents(xi)[0]);
    return n / n.norm();
  }



  std::array<Tensor<2, dim>, 3>
  Line3::normal_derivatives(const Point<1> &xi) const
  {
    // n = c / |c|, c = R x_xi: dn = (I - n n) dc / |c| with dc = dN_i/dxi
    // R dx_i.
    std::array<double, 3> n, dxi;
    shape(xi, n, &dxi);
    const Tensor<1, dim> c      = turned(tangents(xi)[0]);
    const double         length = c.norm();
    const Tensor<1, dim> normal = c / length;
    const Tensor<2, dim> P =
      (unit_symmetric_tensor<dim>() - outer_product(normal, normal)) / length;
    std::array<Tensor<2, dim>, 3> derivatives;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int m = 0; m < dim; ++m)
        {
          Tensor<1, dim> e;
          e[m]                    = 1.;
          const Tensor<1, dim> dc = dxi[i] * turned(e);
          const Tensor<1, dim> dn = P * dc;
          for (unsigned int r = 0; r < dim; ++r)
            derivatives[i][r][m] = dn[r];
        }
    return derivatives;
  }



  bool
  Line3::project_along(const Point<dim>     &p,
                       const Tensor<1, dim> &d,
                       const Point<1>       &start,
                       Point<1>             &xi) const
  {
    // Solve x(xi) - p - t d = 0 for (xi, t). det [x_xi | -d] ~ |x_xi| |d|
    // sin(angle), with |x_xi| of the order of the curve's length (Quad9's
    // size^2 becomes size here).
    xi                   = start;
    const double size    = (x[2] - x[0]).norm() + (x[2] - x[1]).norm();
    double       t_along = 0.;
    for (unsigned int it = 0; it < 20; ++it)
      {
        const Tensor<1, dim> r  = position(xi) - p - t_along * d;
        const auto           tg = tangents(xi);
        Tensor<2, dim>       jac;
        for (unsigned int c = 0; c < dim; ++c)
          {
            jac[c][0] = tg[0][c];
            jac[c][1] = -d[c];
          }
        const double det = determinant(jac);
        if (std::abs(det) < 1e-14 * size * d.norm())
          return false;
        const Tensor<1, dim> step = invert(jac) * r;
        xi[0] -= step[0];
        t_along -= step[1];
        if (std::abs(step[0]) < 1e-13)
          return true;
      }
    return false;
  }
} // namespace DuctileContact
#endif
