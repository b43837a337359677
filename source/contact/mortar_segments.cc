#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>

#include <ductile_contact/contact/mortar_segments.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// Sub-quad (p, q) of a quad9: its four nodes, counter-clockwise in
    /// the parameter plane (so that its normal points outward).
    std::array<unsigned int, 4>
    sub_quad(const unsigned int p, const unsigned int q)
    {
      return {{p + 3 * q, p + 1 + 3 * q, p + 1 + 3 * (q + 1), p + 3 * (q + 1)}};
    }

    /// 2-D cross product of b - a and c - a.
    double
    orient(const Point<2> &a, const Point<2> &b, const Point<2> &c)
    {
      return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    }

    /// Collapsed (Duffy) Gauss rule on the triangle: barycentric
    /// coordinates of (centroid, a, b) and weights summing to 1. With n
    /// points per direction it integrates polynomials of degree 2 n - 2
    /// exactly; the integrands here (shape functions of the inverse
    /// bilinear face map) are smooth but not polynomial, so the error falls
    /// off exponentially with n.
    struct TrianglePoint
    {
      double l0, l1, l2, w;
    };
    std::vector<TrianglePoint>
    make_triangle_rule(const unsigned int n)
    {
      const QGauss<1>            gauss(n);
      std::vector<TrianglePoint> rule;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            // (u, v) in the unit square -> (1 - u, u (1 - v), u v)
            const double u = gauss.point(i)[0], v = gauss.point(j)[0];
            rule.push_back({1. - u,
                            u * (1. - v),
                            u * v,
                            2. * u * gauss.weight(i) * gauss.weight(j)});
          }
      return rule;
    }
    const std::vector<TrianglePoint> &
    triangle_rule()
    {
      static const std::vector<TrianglePoint> rule = make_triangle_rule(4);
      return rule;
    }

    Point<2>
    clamp(const Point<2> &p)
    {
      return {std::clamp(p[0], 0., 1.), std::clamp(p[1], 0., 1.)};
    }
  } // namespace



  double
  polygon_area(const std::vector<Point<2>> &polygon)
  {
    double a = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i)
      {
        const Point<2> &p = polygon[i];
        const Point<2> &q = polygon[(i + 1) % polygon.size()];
        a += p[0] * q[1] - p[1] * q[0];
      }
    return 0.5 * a;
  }



  std::vector<Point<2>>
  clip_polygon(const std::vector<Point<2>> &subject,
               const std::vector<Point<2>> &clipper)
  {
    std::vector<Point<2>> output = subject;
    for (std::size_t e = 0; e < clipper.size() && !output.empty(); ++e)
      {
        const Point<2>             &a     = clipper[e];
        const Point<2>             &b     = clipper[(e + 1) % clipper.size()];
        const std::vector<Point<2>> input = output;
        output.clear();
        for (std::size_t i = 0; i < input.size(); ++i)
          {
            const Point<2> &p    = input[i];
            const Point<2> &q    = input[(i + 1) % input.size()];
            const double    dp   = orient(a, b, p);
            const double    dq   = orient(a, b, q);
            const bool      p_in = dp >= 0.;
            const bool      q_in = dq >= 0.;
            if (p_in)
              output.push_back(p);
            if (p_in != q_in)
              {
                const double s = dp / (dp - dq);
                output.push_back(p + s * (q - p));
              }
          }
      }
    return output;
  }



  std::vector<MortarPoint>
  mortar_points(const Quad9 &slave, const Quad9 &master)
  {
    std::vector<MortarPoint> points;
    for (unsigned int sq = 0; sq < 4; ++sq)
      {
        const auto s_nodes = sub_quad(sq % 2, sq / 2);
        Point<dim> centre;
        for (const unsigned int i : s_nodes)
          centre += 0.25 * slave.x[i];
        Tensor<1, dim> n0 =
          cross_product_3d(slave.x[s_nodes[2]] - slave.x[s_nodes[0]],
                           slave.x[s_nodes[3]] - slave.x[s_nodes[1]]);
        n0 /= n0.norm();
        Tensor<1, dim> t1 = slave.x[s_nodes[1]] - slave.x[s_nodes[0]];
        t1 -= (t1 * n0) * n0;
        t1 /= t1.norm();
        const Tensor<1, dim> t2       = cross_product_3d(n0, t1);
        const auto           in_plane = [&](const Point<dim> &p) {
          const Tensor<1, dim> d = p - centre;
          return Point<2>(d * t1, d * t2);
        };

        std::vector<Point<2>> s_polygon;
        for (const unsigned int i : s_nodes)
          s_polygon.push_back(in_plane(slave.x[i]));
        const double s_area = polygon_area(s_polygon);
        if (!(s_area > 0.))
          continue; // degenerate (or inverted) slave sub-quad
        const Point<2> s_start(0.25 * (sq % 2) + 0.25, 0.25 * (sq / 2) + 0.25);

        for (unsigned int mq = 0; mq < 4; ++mq)
          {
            const auto     m_nodes = sub_quad(mq % 2, mq / 2);
            Tensor<1, dim> n_m =
              cross_product_3d(master.x[m_nodes[2]] - master.x[m_nodes[0]],
                               master.x[m_nodes[3]] - master.x[m_nodes[1]]);
            if (n_m * n0 >= 0.)
              continue; // the sub-quads do not face each other
            std::vector<Point<2>> m_polygon;
            for (const unsigned int i : m_nodes)
              m_polygon.push_back(in_plane(master.x[i]));
            // The master faces the other way: clockwise in this plane.
            std::reverse(m_polygon.begin(), m_polygon.end());
            if (!(polygon_area(m_polygon) > 0.))
              continue;
            const std::vector<Point<2>> overlap =
              clip_polygon(m_polygon, s_polygon);
            if (overlap.size() < 3)
              continue;
            const double area = polygon_area(overlap);
            if (!(area > 1e-12 * s_area))
              continue;

            Point<2> centroid;
            for (const Point<2> &p : overlap)
              centroid += p / static_cast<double>(overlap.size());
            const Point<2> m_start(0.25 * (mq % 2) + 0.25,
                                   0.25 * (mq / 2) + 0.25);
            for (std::size_t e = 0; e < overlap.size(); ++e)
              {
                const Point<2> &a = overlap[e];
                const Point<2> &b = overlap[(e + 1) % overlap.size()];
                const double    triangle_area = 0.5 * orient(centroid, a, b);
                if (!(triangle_area > 0.))
                  continue;
                for (const TrianglePoint &g : triangle_rule())
                  {
                    const Point<2>   q2 = g.l0 * centroid + g.l1 * a + g.l2 * b;
                    const Point<dim> q  = centre + q2[0] * t1 + q2[1] * t2;
                    Point<2>         xi_s, xi_m;
                    if (!slave.project_along(q, n0, s_start, xi_s) ||
                        !master.project_along(q, n0, m_start, xi_m))
                      continue;
                    points.push_back(
                      {clamp(xi_s), clamp(xi_m), g.w * triangle_area});
                  }
              }
          }
      }
    return points;
  }
} // namespace DuctileContact
