#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <ductile_contact/mesh/scene.h>

#include <cmath>

// A three-dimensional scene: MeshParameters::check() refuses it in the
// plane-strain build, which therefore has no builder for it.
#if DUCTILE_CONTACT_DIM == 3
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

      /// f(x): the radius at x over R.
      double
      taper(const double x) const
      {
        return 1. - imperfection * (1. - std::abs(2. * x / length - 1.));
      }

    private:
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
    const double                  R = parameters.radius, L = parameters.length;
    const TaperedCylinderManifold hull(L, parameters.imperfection);

    // Manifold ids: 0 on the hull faces and their edges (the tapered
    // surface), 1 on everything else (transfinite interpolation from the
    // hull into the cells; the end and symmetry faces stay plane).
    // (Faces, not boundary ids of lines: the lines inside the symmetry
    // planes carry the default boundary id 0 as well.)
    // The hull chart on id 0, transfinite interpolation on id 1.
    const auto attach_manifolds = [&hull](Triangulation<dim> &mesh) {
      mesh.set_manifold(0, hull);
      TransfiniteInterpolationManifold<dim> interior;
      interior.initialize(mesh);
      mesh.set_manifold(1, interior);
    };
    const auto set_manifold_ids = [](Triangulation<dim> &mesh) {
      mesh.set_all_manifold_ids(1);
      for (const auto &cell : mesh.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == 0)
            face->set_all_manifold_ids(0);
    };

    // The coarse cylinder (5 cells per cross-section, its 4 hull vertices
    // per section on the circle) along x in [-L/2, L/2], moved to [0, L]
    // and tapered to (1 - imperfection) R at mid-length. Boundary ids as
    // generated: 0 hull, 1 end x = 0, 2 end x = L.
    Triangulation<dim> coarse;
    GridGenerator::subdivided_cylinder(coarse,
                                       parameters.axial_subdivisions,
                                       R,
                                       0.5 * L);
    GridTools::transform(
      [&](const Point<dim> &p) {
        const double x = p[0] + 0.5 * L, f = hull.taper(x);
        return Point<dim>(x, f * p[1], f * p[2]);
      },
      coarse);
    set_manifold_ids(coarse);
    unsigned int refinements = parameters.refinements;

    if (parameters.model == RoundBarModel::octant)
      {
        // One refinement on the curved geometry puts every cell into one
        // octant; those of x >= L/2, y >= 0, z >= 0 become the coarse mesh.
        Triangulation<dim> refined;
        refined.copy_triangulation(coarse);
        attach_manifolds(refined);
        refined.refine_global(1);
        --refinements;

        Triangulation<dim> flat;
        GridGenerator::flatten_triangulation(refined, flat);
        const double                                       tolerance = 1e-9 * R;
        std::set<Triangulation<dim>::active_cell_iterator> outside;
        for (const auto &cell : flat.active_cell_iterators())
          {
            const Point<dim> c = cell->center();
            if (c[0] < 0.5 * L || c[1] < 0. || c[2] < 0.)
              outside.insert(cell);
          }
        coarse.clear();
        GridGenerator::create_triangulation_with_removed_cells(flat,
                                                               outside,
                                                               coarse);
        for (const auto &cell : coarse.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const Point<dim> c = face->center();
                if (std::abs(c[0] - 0.5 * L) < tolerance)
                  face->set_boundary_id(3);
                else if (std::abs(c[0] - L) < tolerance)
                  face->set_boundary_id(2);
                else if (std::abs(c[1]) < tolerance)
                  face->set_boundary_id(4);
                else if (std::abs(c[2]) < tolerance)
                  face->set_boundary_id(5);
                else
                  face->set_boundary_id(0);
              }
        set_manifold_ids(coarse);
      }

    for (const auto &cell : coarse.active_cell_iterators())
      cell->set_material_id(0);
    tria.copy_triangulation(coarse);
    attach_manifolds(tria);
    tria.refine_global(refinements);
  }
} // namespace DuctileContact
#endif
