#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>

#include <ductile_contact/contact/contact_ad.h>
#include <ductile_contact/contact/mortar_segments.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    template <typename Number>
    using Vec = std::array<Number, dim>;
    template <typename Number>
    using Vec2 = std::array<Number, 2>;

    template <typename Number>
    Vec<Number>
    minus(const Vec<Number> &a, const Vec<Number> &b)
    {
      Vec<Number> d;
      for (unsigned int c = 0; c < dim; ++c)
        d[c] = a[c] - b[c];
      return d;
    }

    template <typename Number>
    Number
    dot(const Vec<Number> &a, const Vec<Number> &b)
    {
      Number d = a[0] * b[0];
      for (unsigned int c = 1; c < dim; ++c)
        d += a[c] * b[c];
      return d;
    }

#if DUCTILE_CONTACT_DIM == 3
    /// a x b.
    template <typename Number>
    Vec<Number>
    cross(const Vec<Number> &a, const Vec<Number> &b)
    {
      return {{a[1] * b[2] - a[2] * b[1],
               a[2] * b[0] - a[0] * b[2],
               a[0] * b[1] - a[1] * b[0]}};
    }
#else
    /// @p v turned by -90 degrees: the outward normal direction of a
    /// segment of a line3 that runs along @p v (Line3::normal()).
    template <typename Number>
    Vec<Number>
    turned(const Vec<Number> &v)
    {
      return {{v[1], -v[0]}};
    }
#endif

    template <typename Number>
    void
    normalise(Vec<Number> &a)
    {
      using std::sqrt;
      const Number length = sqrt(dot(a, a));
      for (auto &c : a)
        c /= length;
    }

#if DUCTILE_CONTACT_DIM == 3
    /// Sub-quad (p, q) of a quad9: its four nodes, counter-clockwise in
    /// the parameter plane (so that its normal points outward).
    std::array<unsigned int, 4>
    sub_quad(const unsigned int p, const unsigned int q)
    {
      return {{p + 3 * q, p + 1 + 3 * q, p + 1 + 3 * (q + 1), p + 3 * (q + 1)}};
    }
#endif

    /// 2-D cross product of b - a and c - a.
    template <typename Number>
    Number
    orient(const Vec2<Number> &a, const Vec2<Number> &b, const Vec2<Number> &c)
    {
      return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    }

    template <typename Number>
    Number
    area_of(const std::vector<Vec2<Number>> &polygon)
    {
      Number a = 0.;
      for (std::size_t i = 0; i < polygon.size(); ++i)
        {
          const Vec2<Number> &p = polygon[i];
          const Vec2<Number> &q = polygon[(i + 1) % polygon.size()];
          a += p[0] * q[1] - p[1] * q[0];
        }
      return 0.5 * a;
    }

    /**
     * Sutherland-Hodgman; inside/outside is decided on the values. A vertex
     * within @p tolerance (a distance) of a clipping line counts as on it:
     * it is kept and makes no intersection point, so coincident edges (the
     * flush sides of a patch test, a slave edge on a master edge) give
     * neither duplicate vertices nor intersections of nearly parallel
     * lines, whose position is well defined but whose derivative is not.
     */
    template <typename Number>
    std::vector<Vec2<Number>>
    clip(const std::vector<Vec2<Number>> &subject,
         const std::vector<Vec2<Number>> &clipper,
         const double                     tolerance)
    {
      std::vector<Vec2<Number>> output = subject, input;
      for (std::size_t e = 0; e < clipper.size() && !output.empty(); ++e)
        {
          const Vec2<Number> &a = clipper[e];
          const Vec2<Number> &b = clipper[(e + 1) % clipper.size()];
          const double        length =
            std::hypot(value_of(b[0] - a[0]), value_of(b[1] - a[1]));
          const double eps = tolerance * length;
          // The last edge's output is this edge's input (swapped: an AD
          // vertex is 110 numbers).
          input.swap(output);
          output.clear();
          for (std::size_t i = 0; i < input.size(); ++i)
            {
              const Vec2<Number> &p    = input[i];
              const Vec2<Number> &q    = input[(i + 1) % input.size()];
              const Number        dp   = orient(a, b, p);
              const Number        dq   = orient(a, b, q);
              const bool          p_in = value_of(dp) >= -eps;
              const bool          q_in = value_of(dq) >= -eps;
              if (p_in)
                output.push_back(p);
              // A crossing from strictly inside to strictly outside (or
              // back): a new vertex.
              if (p_in != q_in && std::abs(value_of(p_in ? dp : dq)) > eps)
                {
                  const Number s = dp / (dp - dq);
                  output.push_back(
                    {{p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])}});
                }
            }
        }
      return output;
    }

#if DUCTILE_CONTACT_DIM == 3
    /// A point of a triangle rule: barycentric coordinates of the
    /// triangle's corners (apex, a, b) and the weight, the weights summing
    /// to 1.
    struct TrianglePoint
    {
      double l0, l1, l2, w;
    };

    /**
     * The symmetric 16-point rule of Dunavant (1985) on the triangle, exact
     * for polynomials of degree 8 with positive weights: the centroid and
     * orbits of 3, 3, 3 and 6 points. Degree 8 integrates the product of
     * two quad9 shape functions exactly where the face maps are affine
     * (flat parallelogram faces, e.g. two_bodies), so that the overlap can
     * be cut into the fewest triangles (a fan from one vertex: 2 for a
     * quadrilateral). It replaced the 12-point degree-6 rule on a
     * fan from the centroid (4 triangles for a quadrilateral, 48 points
     * against 32 now); against 12 x 12-point collapsed Gauss rules on three
     * face pairs (a two_bodies-like pair and two distorted curved ones)
     * the operators move by 3e-15, 2.4e-6, 1.2e-5 (relative) instead of
     * 3.9e-7, 3.6e-6, 1.0e-4, with a third fewer points. (The curved
     * pairs' integrands have kinks where back-projected points are clamped
     * to the face: the two references, on either fan, differ by 7.8e-7
     * and 3.2e-5 themselves.)
     */
    std::vector<TrianglePoint>
    make_triangle_rule()
    {
      std::vector<TrianglePoint> rule;
      rule.push_back({1. / 3., 1. / 3., 1. / 3., 0.144315607677787});
      const auto orbit3 = [&](const double a, const double w) {
        const double b = 1. - 2. * a;
        rule.push_back({b, a, a, w});
        rule.push_back({a, b, a, w});
        rule.push_back({a, a, b, w});
      };
      orbit3(0.459292588292723, 0.095091634267285);
      orbit3(0.170569307751760, 0.103217370534718);
      orbit3(0.050547228317031, 0.032458497623198);
      const double a = 0.008394777409958, b = 0.263112829634638, c = 1. - a - b,
                   w = 0.027230314174435;
      for (const auto &p : {std::array<double, 3>{{a, b, c}},
                            std::array<double, 3>{{a, c, b}},
                            std::array<double, 3>{{b, a, c}},
                            std::array<double, 3>{{b, c, a}},
                            std::array<double, 3>{{c, a, b}},
                            std::array<double, 3>{{c, b, a}}})
        rule.push_back({p[0], p[1], p[2], w});
      return rule;
    }
    const std::vector<TrianglePoint> &
    triangle_rule()
    {
      static const std::vector<TrianglePoint> rule = make_triangle_rule();
      return rule;
    }
#endif

    template <typename Number>
    ContactFace
    values_of(const FaceCoordinates<Number> &x)
    {
      ContactFace face;
      for (unsigned int i = 0; i < face_nodes; ++i)
        for (unsigned int c = 0; c < dim; ++c)
          face.x[i][c] = value_of(x[i][c]);
      return face;
    }

    /**
     * The parameter point where the line q + t d meets the face x: Newton
     * on the values (ContactFace::project_along), then one Newton
     * correction in Number, which carries the derivatives dxi = -J^-1 dr
     * (implicit function theorem, J = [x_xi, x_eta, -d] in 3-D, [x_xi, -d]
     * in 2-D, at the solution). The point is clamped to the face. With
     * derivatives, x[i][c] is the independent variable @p first + dim i + c.
     */
    template <typename Number>
    bool
    project(const FaceCoordinates<Number> &x,
            const unsigned int             first,
            const ContactFace             &face,
            const Vec<Number>             &q,
            const Vec<Number>             &d,
            const FaceParameter           &start,
            std::array<Number, dim - 1>   &xi)
    {
      Point<dim>     q0;
      Tensor<1, dim> d0;
      for (unsigned int c = 0; c < dim; ++c)
        {
          q0[c] = value_of(q[c]);
          d0[c] = value_of(d[c]);
        }
      FaceParameter xi0;
      if (!face.project_along(q0, d0, start, xi0))
        return false;
      const double   t  = (face.position(xi0) - q0) * d0 / d0.norm_square();
      const auto     tg = face.tangents(xi0);
      Tensor<2, dim> jac;
      for (unsigned int c = 0; c < dim; ++c)
        {
          for (unsigned int k = 0; k + 1 < dim; ++k)
            jac[c][k] = tg[k][c];
          jac[c][dim - 1] = -d0[c];
        }
      const Tensor<2, dim>           inverse = invert(jac);
      std::array<double, face_nodes> n;
      ContactFace::shape(xi0, n);
      Vec<Number> r;
      for (unsigned int c = 0; c < dim; ++c)
        {
          r[c] = -q[c] - t * d[c];
          if constexpr (std::is_same_v<Number, ContactAD>)
            {
              // x[i][c] is the independent variable first + dim i + c
              // (mortar_points()): its terms touch one derivative each.
              for (unsigned int i = 0; i < face_nodes; ++i)
                {
                  Assert(x[i][c].fastAccessDx(first + dim * i + c) == 1.,
                         ExcInternalError());
                  r[c].val() += n[i] * x[i][c].val();
                  r[c].fastAccessDx(first + dim * i + c) += n[i];
                }
            }
          else
            for (unsigned int i = 0; i < face_nodes; ++i)
              r[c] += n[i] * x[i][c];
        }
      for (unsigned int k = 0; k + 1 < dim; ++k)
        {
          xi[k] = xi0[k];
          for (unsigned int c = 0; c < dim; ++c)
            xi[k] -= inverse[k][c] * r[c];
          if (value_of(xi[k]) < 0.)
            xi[k] = 0.;
          else if (value_of(xi[k]) > 1.)
            xi[k] = 1.;
        }
      return true;
    }
  } // namespace



#if DUCTILE_CONTACT_DIM == 3
  namespace
  {
    /// One overlap of a slave and a master sub-quad, in the auxiliary
    /// plane of the slave sub-quad (mortar_points()).
    template <typename Number>
    struct SubQuadOverlap
    {
      unsigned int              slave_quad, master_quad;
      Vec<Number>               centre, n0, t1, t2;
      std::vector<Vec2<Number>> polygon; ///< counter-clockwise
    };

    /**
     * Calls @p visit for every pair of a slave and a master sub-quad that
     * face each other and overlap in the slave sub-quad's plane (the
     * clipping of mortar_points()), until it returns false.
     */
    template <typename Number, typename Visitor>
    void
    for_each_overlap(const FaceCoordinates<Number> &slave,
                     const FaceCoordinates<Number> &master,
                     const Visitor                 &visit)
    {
      // Which sub-quads overlap is decided on the values: with derivatives
      // it is found in plain numbers first, so that the AD work below goes
      // to those pairs only (on two_bodies 6 of the 16).
      std::array<bool, 16> overlaps;
      overlaps.fill(true);
      if constexpr (!std::is_same_v<Number, double>)
        {
          overlaps.fill(false);
          for_each_overlap(coordinates_of(values_of(slave)),
                           coordinates_of(values_of(master)),
                           [&](const SubQuadOverlap<double> &o) {
                             overlaps[4 * o.slave_quad + o.master_quad] = true;
                             return true;
                           });
        }
      SubQuadOverlap<Number> o;
      for (unsigned int sq = 0; sq < 4; ++sq)
        {
          if (std::none_of(overlaps.begin() + 4 * sq,
                           overlaps.begin() + 4 * sq + 4,
                           [](const bool b) { return b; }))
            continue;
          const auto s_nodes = sub_quad(sq % 2, sq / 2);
          o.slave_quad       = sq;
          o.centre           = Vec<Number>{};
          for (const unsigned int i : s_nodes)
            for (unsigned int c = 0; c < dim; ++c)
              o.centre[c] += 0.25 * slave[i][c];
          o.n0 = cross(minus(slave[s_nodes[2]], slave[s_nodes[0]]),
                       minus(slave[s_nodes[3]], slave[s_nodes[1]]));
          normalise(o.n0);
          o.t1               = minus(slave[s_nodes[1]], slave[s_nodes[0]]);
          const Number t1_n0 = dot(o.t1, o.n0);
          for (unsigned int c = 0; c < dim; ++c)
            o.t1[c] -= t1_n0 * o.n0[c];
          normalise(o.t1);
          o.t2                = cross(o.n0, o.t1);
          const auto in_plane = [&](const Vec<Number> &p) {
            const Vec<Number> d = minus(p, o.centre);
            return Vec2<Number>{{dot(d, o.t1), dot(d, o.t2)}};
          };

          std::vector<Vec2<Number>> s_polygon;
          for (const unsigned int i : s_nodes)
            s_polygon.push_back(in_plane(slave[i]));
          const double s_area = value_of(area_of(s_polygon));
          if (!(s_area > 0.))
            continue; // degenerate (or inverted) slave sub-quad

          for (unsigned int mq = 0; mq < 4; ++mq)
            {
              if (!overlaps[4 * sq + mq])
                continue;
              const auto        m_nodes = sub_quad(mq % 2, mq / 2);
              const Vec<Number> n_m =
                cross(minus(master[m_nodes[2]], master[m_nodes[0]]),
                      minus(master[m_nodes[3]], master[m_nodes[1]]));
              if (value_of(dot(n_m, o.n0)) >= 0.)
                continue; // the sub-quads do not face each other
              std::vector<Vec2<Number>> m_polygon;
              for (const unsigned int i : m_nodes)
                m_polygon.push_back(in_plane(master[i]));
              // The master faces the other way: clockwise in this plane.
              std::reverse(m_polygon.begin(), m_polygon.end());
              if (!(value_of(area_of(m_polygon)) > 0.))
                continue;
              o.polygon = clip(m_polygon, s_polygon, 1e-10 * std::sqrt(s_area));
              if (o.polygon.size() < 3 ||
                  !(value_of(area_of(o.polygon)) > 1e-12 * s_area))
                continue;
              o.master_quad = mq;
              if (!visit(o))
                return;
            }
        }
    }
  } // namespace



  template <typename Number>
  std::vector<MortarPointOf<Number>>
  mortar_points(const FaceCoordinates<Number> &slave,
                const FaceCoordinates<Number> &master)
  {
    const ContactFace slave_face  = values_of(slave),
                      master_face = values_of(master);
    std::vector<MortarPointOf<Number>> points;
    for_each_overlap(slave, master, [&](const SubQuadOverlap<Number> &o) {
      const unsigned int sq = o.slave_quad, mq = o.master_quad;
      const Point<2> s_start(0.25 * (sq % 2) + 0.25, 0.25 * (sq / 2) + 0.25);
      const Point<2> m_start(0.25 * (mq % 2) + 0.25, 0.25 * (mq / 2) + 0.25);
      const std::vector<Vec2<Number>> &overlap = o.polygon;
      // A fan from the first vertex (the polygon is convex).
      const Vec2<Number> &apex = overlap[0];
      for (std::size_t e = 1; e + 1 < overlap.size(); ++e)
        {
          const Vec2<Number> &a             = overlap[e];
          const Vec2<Number> &b             = overlap[e + 1];
          const Number        triangle_area = 0.5 * orient(apex, a, b);
          if (!(value_of(triangle_area) > 0.))
            continue;
          // The triangle's corners in space: then each point is a
          // combination of three vectors with plain coefficients.
          std::array<Vec<Number>, 3> corner;
          for (unsigned int v = 0; v < 3; ++v)
            {
              const Vec2<Number> &p = v == 0 ? apex : v == 1 ? a : b;
              for (unsigned int c = 0; c < dim; ++c)
                corner[v][c] = o.centre[c] + p[0] * o.t1[c] + p[1] * o.t2[c];
            }
          for (const TrianglePoint &g : triangle_rule())
            {
              Vec<Number> q;
              for (unsigned int c = 0; c < dim; ++c)
                q[c] = g.l0 * corner[0][c] + g.l1 * corner[1][c] +
                       g.l2 * corner[2][c];
              MortarPointOf<Number> point;
              if (!project(
                    slave, 0, slave_face, q, o.n0, s_start, point.slave) ||
                  !project(master,
                           face_coordinates,
                           master_face,
                           q,
                           o.n0,
                           m_start,
                           point.master))
                continue;
              point.weight = g.w * triangle_area;
              points.push_back(point);
            }
        }
      return true;
    });
    return points;
  }
#else
  namespace
  {
    /// One overlap of a slave and a master sub-segment, along the
    /// auxiliary line of the slave sub-segment (mortar_points()).
    template <typename Number>
    struct SubSegmentOverlap
    {
      unsigned int slave_segment, master_segment;
      Vec<Number>  centre, n0, t1;
      /// The overlap is centre + [lo, hi] t1.
      Number lo, hi;
    };

    /**
     * The plane-strain counterpart of the 3-D clipping: both line3 faces
     * are split into their two straight sub-segments; for each slave
     * sub-segment an auxiliary line through its centre, along its chord t1
     * with normal n0 = t1 turned by -90 degrees (outward); the ends of
     * every master sub-segment that faces it are projected onto the line
     * and the two intervals intersected. Calls @p visit for every
     * overlap until it returns false.
     */
    template <typename Number, typename Visitor>
    void
    for_each_overlap(const FaceCoordinates<Number> &slave,
                     const FaceCoordinates<Number> &master,
                     const Visitor                 &visit)
    {
      // Decided on the values first, as in 3-D.
      std::array<bool, 4> overlaps;
      overlaps.fill(true);
      if constexpr (!std::is_same_v<Number, double>)
        {
          overlaps.fill(false);
          for_each_overlap(coordinates_of(values_of(slave)),
                           coordinates_of(values_of(master)),
                           [&](const SubSegmentOverlap<double> &o) {
                             overlaps[2 * o.slave_segment + o.master_segment] =
                               true;
                             return true;
                           });
        }
      SubSegmentOverlap<Number> o;
      for (unsigned int ss = 0; ss < 2; ++ss)
        {
          if (!overlaps[2 * ss] && !overlaps[2 * ss + 1])
            continue;
          const Vec<Number> &a = slave[ss], &b = slave[ss + 1];
          o.slave_segment = ss;
          for (unsigned int c = 0; c < dim; ++c)
            o.centre[c] = 0.5 * a[c] + 0.5 * b[c];
          o.t1                  = minus(b, a);
          const double s_length = std::sqrt(value_of(dot(o.t1, o.t1)));
          if (!(s_length > 0.))
            continue; // degenerate slave sub-segment
          normalise(o.t1);
          o.n0              = turned(o.t1);
          const Number s_lo = dot(minus(a, o.centre), o.t1);
          const Number s_hi = dot(minus(b, o.centre), o.t1);
          // A master end within eps of a slave end counts as on it (the
          // flush ends of a patch test), as a vertex on a clipping line in
          // 3-D.
          const double eps = 1e-10 * s_length;
          for (unsigned int ms = 0; ms < 2; ++ms)
            {
              if (!overlaps[2 * ss + ms])
                continue;
              const Vec<Number> &p = master[ms], &q = master[ms + 1];
              if (value_of(dot(turned(minus(q, p)), o.n0)) >= 0.)
                continue; // the sub-segments do not face each other
              // The master runs the other way along t1.
              const Number m_lo = dot(minus(q, o.centre), o.t1);
              const Number m_hi = dot(minus(p, o.centre), o.t1);
              o.lo = value_of(m_lo) >= value_of(s_lo) - eps ? m_lo : s_lo;
              o.hi = value_of(m_hi) <= value_of(s_hi) + eps ? m_hi : s_hi;
              if (!(value_of(o.hi) - value_of(o.lo) > 1e-12 * s_length))
                continue;
              o.master_segment = ms;
              if (!visit(o))
                return;
            }
        }
    }
  } // namespace



  template <typename Number>
  std::vector<MortarPointOf<Number>>
  mortar_points(const FaceCoordinates<Number> &slave,
                const FaceCoordinates<Number> &master)
  {
    // Five Gauss points per overlap: exact for the product of two line3
    // shape functions (degree 4) where the faces are straight, with margin
    // for curved ones.
    static const QGauss<1> gauss(5);
    const ContactFace      slave_face = values_of(slave),
                      master_face     = values_of(master);
    std::vector<MortarPointOf<Number>> points;
    for_each_overlap(slave, master, [&](const SubSegmentOverlap<Number> &o) {
      const FaceParameter s_start(0.25 + 0.5 * o.slave_segment);
      const FaceParameter m_start(0.25 + 0.5 * o.master_segment);
      const Number        length = o.hi - o.lo;
      for (unsigned int g = 0; g < gauss.size(); ++g)
        {
          const Number along = o.lo + gauss.point(g)[0] * length;
          Vec<Number>  q;
          for (unsigned int c = 0; c < dim; ++c)
            q[c] = o.centre[c] + along * o.t1[c];
          MortarPointOf<Number> point;
          if (!project(slave, 0, slave_face, q, o.n0, s_start, point.slave) ||
              !project(master,
                       face_coordinates,
                       master_face,
                       q,
                       o.n0,
                       m_start,
                       point.master))
            continue;
          point.weight = gauss.weight(g) * length;
          points.push_back(point);
        }
      return true;
    });
    return points;
  }
#endif



  FaceCoordinates<double>
  coordinates_of(const ContactFace &face)
  {
    FaceCoordinates<double> x;
    for (unsigned int i = 0; i < face_nodes; ++i)
      for (unsigned int c = 0; c < dim; ++c)
        x[i][c] = face.x[i][c];
    return x;
  }



  bool
  faces_may_overlap(const ContactFace &slave, const ContactFace &master)
  {
    bool found = false;
    for_each_overlap(coordinates_of(slave),
                     coordinates_of(master),
                     [&](const auto &) {
                       found = true;
                       return false;
                     });
    return found;
  }



  std::vector<MortarPoint>
  mortar_points(const ContactFace &slave, const ContactFace &master)
  {
    std::vector<MortarPoint> points;
    for (const auto &p :
         mortar_points(coordinates_of(slave), coordinates_of(master)))
      {
        MortarPoint point;
        for (unsigned int k = 0; k + 1 < dim; ++k)
          {
            point.slave[k]  = p.slave[k];
            point.master[k] = p.master[k];
          }
        point.weight = p.weight;
        points.push_back(point);
      }
    return points;
  }



  double
  polygon_area(const std::vector<Point<2>> &polygon)
  {
    std::vector<Vec2<double>> p;
    for (const auto &v : polygon)
      p.push_back({{v[0], v[1]}});
    return area_of(p);
  }



  std::vector<Point<2>>
  clip_polygon(const std::vector<Point<2>> &subject,
               const std::vector<Point<2>> &clipper)
  {
    std::vector<Vec2<double>> s, c;
    for (const auto &v : subject)
      s.push_back({{v[0], v[1]}});
    for (const auto &v : clipper)
      c.push_back({{v[0], v[1]}});
    std::vector<Point<2>> result;
    for (const auto &v : clip(s, c, 0.))
      result.emplace_back(v[0], v[1]);
    return result;
  }



  template std::vector<MortarPointOf<double>>
  mortar_points(const FaceCoordinates<double> &,
                const FaceCoordinates<double> &);
  template std::vector<MortarPointOf<ContactAD>>
  mortar_points(const FaceCoordinates<ContactAD> &,
                const FaceCoordinates<ContactAD> &);
} // namespace DuctileContact
