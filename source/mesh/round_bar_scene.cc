#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <ductile_contact/mesh/scene.h>

#include <cmath>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /**
     * The hull of the tapered bar, r = f(x) R with
     * f(x) = 1 - e (1 - |x - L/2| / (L/2)), as a chart manifold with
     * coordinates (x, theta, rho = r / f(x)): new hull points are averaged
     * in these coordinates, so they lie on the tapered surface exactly, at
     * every refinement level. Used for the hull faces and edges only (the
     * chart is singular on the axis).
     */
    class TaperedCylinderManifold : public ChartManifold<dim, dim, dim>
    {
    public:
      TaperedCylinderManifold(const double length, const double imperfection)
          : ChartManifold<dim, dim, dim>(Tensor<1, dim>({0., 2. * M_PI, 0.}))
          , length(length)
          , imperfection(imperfection)
      {
      }

      std::unique_ptr<Manifold<dim, dim>>
      clone() const override
      {
        return std::make_unique<TaperedCylinderManifold>(length, imperfection);
      }

      Point<dim>
      pull_back(const Point<dim> &p) const override
      {
        const double theta = std::atan2(p[2], p[1]);
        return Point<dim>(p[0],
                          theta < 0. ? theta + 2. * M_PI : theta,
                          std::hypot(p[1], p[2]) / taper(p[0]));
      }

      Point<dim>
      push_forward(const Point<dim> &chart) const override
      {
        const double r = taper(chart[0]) * chart[2];
        return Point<dim>(chart[0],
                          r * std::cos(chart[1]),
                          r * std::sin(chart[1]));
      }

      DerivativeForm<1, dim, dim>
      push_forward_gradient(const Point<dim> &chart) const override
      {
        const double f = taper(chart[0]), df = taper_slope(chart[0]);
        const double c = std::cos(chart[1]), s = std::sin(chart[1]);
        const double rho = chart[2];
        DerivativeForm<1, dim, dim> d;
        d[0][0] = 1.;
        d[1][0] = df * rho * c;
        d[1][1] = -f * rho * s;
        d[1][2] = f * c;
        d[2][0] = df * rho * s;
        d[2][1] = f * rho * c;
        d[2][2] = f * s;
        return d;
      }

    private:
      double
      taper(const double x) const
      {
        return 1. - imperfection * (1. - std::abs(2. * x / length - 1.));
      }

      double
      taper_slope(const double x) const
      {
        return imperfection * 2. / length * (x > 0.5 * length ? 1. : -1.);
      }

      const double length, imperfection;
    };
  } // namespace



  void
  create_round_bar_scene(const MeshParameters::RoundBar &parameters,
                         Triangulation<dim>             &tria)
  {
    const double R = parameters.radius, L = parameters.length;

    // The coarse cylinder (5 cells per cross-section, its 4 hull vertices
    // per section on the circle) along x in [-L/2, L/2], moved to [0, L]
    // and tapered to (1 - imperfection) R at mid-length.
    Triangulation<dim> coarse;
    GridGenerator::subdivided_cylinder(coarse,
                                       parameters.axial_subdivisions,
                                       R,
                                       0.5 * L);
    GridTools::transform(
      [&](const Point<dim> &p) {
        const double f =
          1. - parameters.imperfection * (1. - std::abs(p[0]) / (0.5 * L));
        return Point<dim>(p[0] + 0.5 * L, f * p[1], f * p[2]);
      },
      coarse);

    // Manifold ids: 0 on the hull faces and their edges (the tapered
    // surface), 1 on everything else (transfinite interpolation from the
    // hull into the cells; the end faces stay plane). Boundary ids as
    // generated: 0 hull, 1 end x = 0, 2 end x = L.
    coarse.set_all_manifold_ids(1);
    coarse.set_all_manifold_ids_on_boundary(0, 0);
    for (const auto &cell : coarse.active_cell_iterators())
      cell->set_material_id(0);

    tria.copy_triangulation(coarse);
    tria.set_manifold(0, TaperedCylinderManifold(L, parameters.imperfection));
    TransfiniteInterpolationManifold<dim> interior;
    interior.initialize(tria);
    tria.set_manifold(1, interior);
    tria.refine_global(parameters.refinements);
  }
} // namespace DuctileContact
