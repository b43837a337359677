// BernsteinElement, the Q2 Bernstein element of the alpha and s fields with
// `Finite elements/Internal field basis = Bernstein`:
//  1. prolongation is exact subdivision: a child's field equals its
//     parent's at sample points of every child (to 1e-12);
//  2. restriction takes each coefficient from the fine field's value at its
//     Greville point: a trilinear field comes back exactly, and coefficients
//     of a field in [0, 1] stay in [0, 1];
//  3. hanging-node constraints are exact subdivision of the coarse face: a
//     quadratic polynomial represented exactly on a mesh with a refined
//     cell is left unchanged by distribute() (to 1e-12). deal.II's
//     FE_Bernstein, whose constraints take values at the fine Greville
//     points, changes it by O(1): the line printed for it shows the defect
//     this element removes;
//  4. the field lies between the smallest and largest coefficient of its
//     cell at every point (the bound the phase-field and alpha bounds rely
//     on), for random coefficients.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_bernstein.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/discretisation/bernstein_element.h>

#include "tests.h"

#include <random>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  /// The field sum_j a_j phi_j at the unit point @p p.
  double
  field(const FiniteElement<dim> &fe,
        const Vector<double>     &a,
        const Point<dim>         &p)
  {
    double v = 0.;
    for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
      v += a[j] * fe.shape_value(j, p);
    return v;
  }

  /// Coefficients on the unit cell of the polynomial @p f of the space, by
  /// collocation at the Greville points.
  template <typename F>
  Vector<double>
  coefficients_of(const BernsteinElement &fe, const F &f)
  {
    const unsigned int n = fe.n_dofs_per_cell();
    FullMatrix<double> A(n, n);
    Vector<double>     b(n), a(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        const Point<dim> &g = fe.greville_points()[k];
        for (unsigned int j = 0; j < n; ++j)
          A(k, j) = fe.shape_value(j, g);
        b[k] = f(g);
      }
    A.gauss_jordan();
    A.vmult(a, b);
    return a;
  }

  double
  quadratic(const Point<dim> &x)
  {
    return 0.3 + x[0] * x[0] - 0.7 * x[0] * x[1] + 0.4 * x[1] * x[2] -
           x[2] * x[2] + 0.2 * x[0] * x[1] * x[2];
  }

  /// Largest change of a vector that holds the quadratic exactly (cell by
  /// cell, by collocation) under the hanging-node constraints of @p fe on
  /// two unit cells with the second refined once.
  double
  constraint_defect(const FiniteElement<dim> &fe, const BernsteinElement &ref)
  {
    Triangulation<dim> tria;
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {2, 1, 1},
                                              Point<dim>(),
                                              Point<dim>(2, 1, 1));
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->center()[0] > 1.)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();
    // An hp collection, as the application's: its hanging-node constraints
    // come from the subface interpolation matrices.
    DoFHandler<dim> dofs(tria);
    dofs.distribute_dofs(hp::FECollection<dim>(fe, FE_Nothing<dim>()));
    AffineConstraints<double> constraints;
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    constraints.close();

    Vector<double>                       u(dofs.n_dofs());
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      {
        const Point<dim>     x0 = cell->vertex(0);
        const double         h  = cell->vertex(7)[0] - x0[0];
        const Vector<double> a = coefficients_of(ref, [&](const Point<dim> &p) {
          return quadratic(x0 + h * p);
        });
        cell->get_dof_indices(indices);
        for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
          u[indices[j]] = a[j];
      }
    Vector<double> v = u;
    constraints.distribute(v);
    v -= u;
    return v.linfty_norm();
  }
} // namespace

int
main()
{
  std::ofstream                          out("output");
  const BernsteinElement                 fe(2);
  const unsigned int                     n = fe.n_dofs_per_cell();
  std::mt19937                           rng(7);
  std::uniform_real_distribution<double> unit(0., 1.);
  const QGauss<dim>                      samples(4);

  // 1. Prolongation.
  Vector<double> a(n), child(n);
  for (auto &v : a)
    v = unit(rng);
  double prolongation_error = 0.;
  for (unsigned int c = 0; c < GeometryInfo<dim>::max_children_per_cell; ++c)
    {
      fe.get_prolongation_matrix(c).vmult(child, a);
      for (const Point<dim> &xi : samples.get_points())
        prolongation_error = std::max(
          prolongation_error,
          std::abs(
            field(fe, child, xi) -
            field(fe, a, GeometryInfo<dim>::child_to_cell_coordinates(xi, c))));
    }
  out << "prolongation: child field = parent field to 1e-12: "
      << (prolongation_error < 1e-12 ? "yes" : "no") << std::endl;

  // 2. Restriction of a trilinear field and of a field in [0, 1].
  const auto trilinear = [](const Point<dim> &x) {
    return 0.2 + 0.3 * x[0] - 0.1 * x[1] * x[2] + 0.4 * x[0] * x[1] * x[2];
  };
  const auto restrict_field = [&](const auto &f) {
    // Children of the field f on the parent: coefficients by collocation.
    Vector<double> parent(n), tmp(n);
    for (unsigned int c = 0; c < GeometryInfo<dim>::max_children_per_cell; ++c)
      {
        const Vector<double> fine =
          coefficients_of(fe, [&](const Point<dim> &xi) {
            return f(GeometryInfo<dim>::child_to_cell_coordinates(xi, c));
          });
        fe.get_restriction_matrix(c).vmult(tmp, fine);
        for (unsigned int i = 0; i < n; ++i)
          if (tmp[i] != 0.)
            parent[i] = tmp[i];
      }
    return parent;
  };
  const Vector<double> exact    = coefficients_of(fe, trilinear);
  Vector<double>       restored = restrict_field(trilinear);
  restored -= exact;
  out << "restriction: trilinear field restored to 1e-12: "
      << (restored.linfty_norm() < 1e-12 ? "yes" : "no") << std::endl;
  const auto bump = [](const Point<dim> &x) {
    return std::exp(-20. * (x - Point<dim>(0.4, 0.5, 0.6)).norm_square());
  };
  const Vector<double> coarse = restrict_field(bump);
  out << "restriction of a field in (0, 1]: coefficients in [0, 1]: "
      << (*std::min_element(coarse.begin(), coarse.end()) >= 0. &&
              *std::max_element(coarse.begin(), coarse.end()) <= 1.
            ? "yes"
            : "no")
      << ", largest " << std::setprecision(5)
      << *std::max_element(coarse.begin(), coarse.end()) << std::endl;

  // 3. Hanging-node constraints.
  out << "hanging nodes, BernsteinElement: quadratic kept to 1e-12: "
      << (constraint_defect(fe, fe) < 1e-12 ? "yes" : "no") << std::endl;
  out << "hanging nodes, deal.II's FE_Bernstein: largest change "
      << std::setprecision(3) << constraint_defect(FE_Bernstein<dim>(2), fe)
      << std::endl;

  // 4. Convex hull.
  double below = 0., above = 0.;
  for (unsigned int trial = 0; trial < 20; ++trial)
    {
      for (auto &v : a)
        v = unit(rng);
      const double lo = *std::min_element(a.begin(), a.end());
      const double hi = *std::max_element(a.begin(), a.end());
      for (const Point<dim> &xi : QGauss<dim>(6).get_points())
        {
          const double v = field(fe, a, xi);
          below          = std::max(below, lo - v);
          above          = std::max(above, v - hi);
        }
    }
  out << "field within its coefficients' range: "
      << (below <= 1e-15 && above <= 1e-15 ? "yes" : "no") << std::endl;
}
