// The face of the plane-strain contact surfaces, Line3 (contact/line3.h), a
// 3-node quadratic curve with nodes at xi = 0, 1/2, 1:
//  - the shape functions are 1 at their own node and 0 at the others, sum
//    to 1 (their derivatives to 0) and shape_of() agrees with shape();
//  - position and tangent of a curved line3 (a rotated and shifted
//    parabola) against the closed forms, and its normal at the apex;
//  - the normal of straight segments is the tangent turned by -90 degrees,
//    and on the boundary of a square traversed counter-clockwise (the body
//    on the left of increasing xi) it points out of the square; reversing
//    the nodes reverses it;
//  - normal_derivatives() against central differences of normal();
//  - project_along() of a point along a direction onto a curved line3
//    finds the known intersection, and refuses a line parallel to a
//    straight segment;
//  - int N_i |x_xi| dxi over a straight segment of length L: L/6, 2L/3, L/6
//    (the diagonal of the dual-basis D_e), int N_i N_k |x_xi| dxi = M_e =
//    (L/30) [[4, 2, -1], [2, 16, 2], [-1, 2, 4]], and, with the middle node
//    at a fraction b of the chord, L (4 b - 1)/6, 2L/3, L (3 - 4 b)/6.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <ductile_contact/contact/line3.h>

#include "../tests.h"

#include <cmath>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  /// Rotation of @p v by @p angle.
  Tensor<1, dim>
  rotated(const double angle, const Tensor<1, dim> &v)
  {
    Tensor<1, dim> r;
    r[0] = std::cos(angle) * v[0] - std::sin(angle) * v[1];
    r[1] = std::sin(angle) * v[0] + std::cos(angle) * v[1];
    return r;
  }

  /// The vector (@p x, @p y).
  Tensor<1, dim>
  vec(const double x, const double y)
  {
    Tensor<1, dim> v;
    v[0] = x;
    v[1] = y;
    return v;
  }

  /// The parabola X(xi) = c + Q (u, k u^2), u = 2 xi - 1, Q the rotation
  /// by parabola_angle, and its tangent X_xi = Q (2, 4 k u): a line3
  /// represents it exactly.
  const double         parabola_angle = 0.3, parabola_k = 0.4;
  const Tensor<1, dim> parabola_centre = vec(1.5, -0.7);

  Point<dim>
  parabola(const double xi)
  {
    const double u = 2. * xi - 1.;
    return Point<dim>(parabola_centre +
                      rotated(parabola_angle, vec(u, parabola_k * u * u)));
  }

  Tensor<1, dim>
  parabola_tangent(const double xi)
  {
    const double u = 2. * xi - 1.;
    return rotated(parabola_angle, vec(2., 4. * parabola_k * u));
  }

  Line3
  parabola_line3()
  {
    Line3 l;
    for (unsigned int i = 0; i < 3; ++i)
      l.x[i] = parabola(Line3::node_parameter(i)[0]);
    return l;
  }

  /// The straight segment from @p a to @p b, its middle node at the
  /// fraction @p b_mid of the chord.
  Line3
  segment(const Point<dim> &a, const Point<dim> &b, const double b_mid = 0.5)
  {
    Line3 l;
    l.x[0] = a;
    l.x[1] = a + b_mid * (b - a);
    l.x[2] = b;
    return l;
  }

  /// A curved line3 of no particular shape: x(xi) = A + B xi + C xi^2 with
  /// A = x_0, B = -3 x_0 + 4 x_1 - x_2, C = 2 x_0 - 4 x_1 + 2 x_2.
  Line3
  general_line3()
  {
    Line3 l;
    l.x[0] = Point<dim>(0., 0.);
    l.x[1] = Point<dim>(0.9, 0.35);
    l.x[2] = Point<dim>(2., 0.1);
    return l;
  }

  Point<dim>
  general_position(const double xi)
  {
    const Line3          l = general_line3();
    const Tensor<1, dim> A = l.x[0];
    const Tensor<1, dim> B = -3. * l.x[0] + 4. * l.x[1] - l.x[2];
    const Tensor<1, dim> C = 2. * l.x[0] - 4. * l.x[1] + 2. * l.x[2];
    return Point<dim>(A + xi * B + xi * xi * C);
  }

  void
  check_shape_functions(std::ostream &out)
  {
    bool kronecker = true;
    for (unsigned int j = 0; j < 3; ++j)
      {
        std::array<double, 3> v;
        Line3::shape(Line3::node_parameter(j), v);
        for (unsigned int i = 0; i < 3; ++i)
          kronecker = kronecker && std::abs(v[i] - (i == j)) < 1e-14;
      }
    bool unity = true, same = true;
    for (const double t : {0., 0.17, 0.5, 0.62, 0.93, 1.})
      {
        std::array<double, 3> v, d, w;
        Line3::shape(Point<1>(t), v, &d);
        Line3::shape_of(std::array<double, 1>{{t}}, w);
        unity = unity && std::abs(v[0] + v[1] + v[2] - 1.) < 1e-14 &&
                std::abs(d[0] + d[1] + d[2]) < 1e-14;
        for (unsigned int i = 0; i < 3; ++i)
          same = same && std::abs(v[i] - w[i]) < 1e-14;
      }
    out << "shape functions: N_i(node j) = delta_ij: "
        << Testing::yes_no(kronecker)
        << ", sum N_i = 1 and sum N_i' = 0: " << Testing::yes_no(unity)
        << ", shape_of() = shape(): " << Testing::yes_no(same) << std::endl;
    out << "node parameters, centre and vertices: "
        << Testing::yes_no(Line3::node_parameter(0)[0] == 0. &&
                           Line3::node_parameter(1)[0] == 0.5 &&
                           Line3::node_parameter(2)[0] == 1. &&
                           Line3::centre() ==
                             Line3::node_parameter(Line3::centre_node) &&
                           Line3::vertices[0] == 0 && Line3::vertices[1] == 2)
        << std::endl;
  }

  void
  check_curved(std::ostream &out)
  {
    const Line3 l     = parabola_line3();
    double      worst = 0.;
    for (const double t : {0., 0.13, 0.3, 0.5, 0.77, 1.})
      {
        const Point<1> xi(t);
        worst = std::max(worst, l.position(xi).distance(parabola(t)));
        worst = std::max(worst,
                         (l.tangents(xi)[0] - parabola_tangent(t)).norm() /
                           parabola_tangent(t).norm());
      }
    std::cout << "parabola: position/tangent error " << worst << std::endl;
    const Point<dim>     x = l.position(Point<1>(0.3));
    const Tensor<1, dim> t = l.tangents(Point<1>(0.3))[0];
    out << "curved line3 (parabola): position and tangent = closed form "
           "(1e-14): "
        << Testing::yes_no(worst < 1e-14) << "; x(0.3) = (" << x[0] << ", "
        << x[1] << "), |x_xi(0.3)| = " << t.norm() << std::endl;
    // at the apex u = 0 the tangent is Q (2, 0): n = Q (0, -1)
    out << "curved line3: normal at the apex = Q (0, -1): "
        << Testing::yes_no(
             (l.normal(Line3::centre()) - rotated(parabola_angle, vec(0., -1.)))
               .norm() < 1e-14)
        << std::endl;
  }

  void
  check_straight_normals(std::ostream &out)
  {
    // along +x: the body lies on the left (y > 0), so n = (0, -1)
    out << "segment (0, 0)-(2, 0): normal (0, -1): "
        << Testing::yes_no((segment(Point<dim>(0., 0.), Point<dim>(2., 0.))
                              .normal(Point<1>(0.3)) -
                            vec(0., -1.))
                             .norm() < 1e-14)
        << std::endl;
    // along (cos phi, sin phi), the middle node off centre: n = (sin phi,
    // -cos phi) everywhere
    {
      const double phi   = 2.2;
      const Line3  l     = segment(Point<dim>(0.4, -0.3),
                              Point<dim>(0.4 + 1.7 * std::cos(phi),
                                         -0.3 + 1.7 * std::sin(phi)),
                              0.4);
      double       worst = 0.;
      for (const double t : {0., 0.25, 0.5, 0.9, 1.})
        worst = std::max(
          worst,
          (l.normal(Point<1>(t)) - vec(std::sin(phi), -std::cos(phi))).norm());
      out << "segment at 2.2 rad, middle node at 0.4 of the chord: normal "
             "(sin, -cos) (1e-14): "
          << Testing::yes_no(worst < 1e-14) << std::endl;
    }
    // The unit square counter-clockwise: every normal points out.
    const std::array<Point<dim>, 4> corner{{Point<dim>(0., 0.),
                                            Point<dim>(1., 0.),
                                            Point<dim>(1., 1.),
                                            Point<dim>(0., 1.)}};
    const Point<dim>                centre(0.5, 0.5);
    bool                            outward = true, inward = true;
    for (unsigned int s = 0; s < 4; ++s)
      {
        const Line3 l = segment(corner[s], corner[(s + 1) % 4]);
        // the outward normal of the side: from the centre to its middle
        const Tensor<1, dim> expected = 2. * (l.x[1] - centre);
        outward =
          outward && (l.normal(Line3::centre()) - expected).norm() < 1e-14;
        const Line3 reversed = segment(corner[(s + 1) % 4], corner[s]);
        inward               = inward &&
                 (reversed.normal(Line3::centre()) + expected).norm() < 1e-14;
      }
    out << "unit square counter-clockwise: the four normals point out: "
        << Testing::yes_no(outward)
        << ", clockwise (nodes reversed): they point in: "
        << Testing::yes_no(inward) << std::endl;
  }

  void
  check_normal_derivatives(std::ostream &out)
  {
    const double h     = 1e-6;
    double       worst = 0.;
    for (const Line3 &l : {general_line3(), parabola_line3()})
      for (const double t : {0., 0.3, 0.5, 0.85, 1.})
        {
          const Point<1> xi(t);
          const auto     dn    = l.normal_derivatives(xi);
          double         scale = 0., error = 0.;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int m = 0; m < dim; ++m)
              {
                Line3 p = l, n = l;
                p.x[i][m] += h;
                n.x[i][m] -= h;
                const Tensor<1, dim> fd =
                  (p.normal(xi) - n.normal(xi)) / (2 * h);
                for (unsigned int r = 0; r < dim; ++r)
                  {
                    scale = std::max(scale, std::abs(dn[i][r][m]));
                    error = std::max(error, std::abs(dn[i][r][m] - fd[r]));
                  }
              }
          worst = std::max(worst, error / scale);
        }
    std::cout << "normal derivatives: max relative error " << worst
              << std::endl;
    out << "normal derivatives match central differences of normal() "
           "(1e-6): "
        << Testing::yes_no(worst < 1e-6) << std::endl;
  }

  void
  check_projection(std::ostream &out)
  {
    // The line through p along d meets the curve at xi = 0.37 (t = 0.6).
    const Line3          l       = general_line3();
    const double         xi_star = 0.37, t_star = 0.6;
    const Tensor<1, dim> d     = vec(0.2, -1.);
    const Point<dim>     p     = general_position(xi_star) - t_star * d;
    double               worst = 0.;
    bool                 found = true;
    for (const double start : {0., 0.5, 1.})
      {
        Point<1> xi;
        found = found && l.project_along(p, d, Point<1>(start), xi);
        worst = std::max(worst, std::abs(xi[0] - xi_star));
      }
    std::cout << "projection: parameter error " << worst << std::endl;
    out << "project_along onto a curved line3 from xi = 0, 0.5, 1: xi = 0.37 "
           "(1e-12): "
        << Testing::yes_no(found && worst < 1e-12) << std::endl;
    Point<1> xi;
    out << "project_along parallel to a straight segment: refused: "
        << Testing::yes_no(!segment(Point<dim>(0., 0.), Point<dim>(2., 0.))
                              .project_along(Point<dim>(1., 1.),
                                             vec(1., 0.),
                                             Line3::centre(),
                                             xi))
        << std::endl;
  }

  using Matrix3 = std::array<std::array<double, 3>, 3>;

  /// D_i = int N_i |x_xi| dxi and M_ik = int N_i N_k |x_xi| dxi over @p l
  /// (4-point Gauss rule: exact for these polynomials).
  void
  shape_integrals(const Line3 &l, std::array<double, 3> &D, Matrix3 &M)
  {
    const QGauss<1> rule(4);
    D = {};
    M = {};
    for (unsigned int q = 0; q < rule.size(); ++q)
      {
        std::array<double, 3> v;
        Line3::shape(rule.point(q), v);
        const double dA = l.tangents(rule.point(q))[0].norm() * rule.weight(q);
        for (unsigned int i = 0; i < 3; ++i)
          {
            D[i] += v[i] * dA;
            for (unsigned int k = 0; k < 3; ++k)
              M[i][k] += v[i] * v[k] * dA;
          }
      }
  }

  void
  check_integrals(std::ostream &out)
  {
    const double          L = 2.5, angle = 0.7;
    const Point<dim>      a(0.3, -0.2);
    const Point<dim>      b = a + L * rotated(angle, vec(1., 0.));
    std::array<double, 3> D;
    Matrix3               M;
    shape_integrals(segment(a, b), D, M);
    const std::array<double, 3> D_e{{L / 6., 2. * L / 3., L / 6.}};
    const double M_e[3][3] = {{4., 2., -1.}, {2., 16., 2.}, {-1., 2., 4.}};
    bool         ok_D = true, ok_M = true;
    for (unsigned int i = 0; i < 3; ++i)
      {
        ok_D = ok_D && std::abs(D[i] - D_e[i]) < 1e-14 * L;
        for (unsigned int k = 0; k < 3; ++k)
          ok_M = ok_M && std::abs(M[i][k] - L / 30. * M_e[i][k]) < 1e-14 * L;
      }
    out << "straight segment of length L = 2.5: int N_i dA = (" << D[0] << ", "
        << D[1] << ", " << D[2]
        << "); = (L/6, 2L/3, L/6) (1e-14 L): " << Testing::yes_no(ok_D)
        << ", int N_i N_k dA = M_e (1e-14 L): " << Testing::yes_no(ok_M)
        << std::endl;
    const double b_mid = 0.4;
    shape_integrals(segment(a, b, b_mid), D, M);
    const std::array<double, 3> D_b{
      {L * (4. * b_mid - 1.) / 6., 2. * L / 3., L * (3. - 4. * b_mid) / 6.}};
    bool ok_b = true;
    for (unsigned int i = 0; i < 3; ++i)
      ok_b = ok_b && std::abs(D[i] - D_b[i]) < 1e-14 * L;
    out << "middle node at b = 0.4 of the chord: int N_i dA = (" << D[0] << ", "
        << D[1] << ", " << D[2]
        << "); = (L (4b - 1)/6, 2L/3, L (3 - 4b)/6) (1e-14 L): "
        << Testing::yes_no(ok_b) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();
  out << std::setprecision(5);
  check_shape_functions(out);
  check_curved(out);
  check_straight_normals(out);
  check_normal_derivatives(out);
  check_projection(out);
  check_integrals(out);
}
