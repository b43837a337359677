// The inertia of a dynamic step (doc/model.md section 6.5): rows, tangent
// and the commit's kinetic quantities of one cell, from its scalar mass
// matrix m_ab = int rho N_a N_b dV over the displacement nodes.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <ductile_contact/assembly/cell_rows.h>
#include <ductile_contact/assembly/cell_scratch.h>
#include <ductile_contact/assembly/system_assembler.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// m_ab = int rho N_a N_b dV, a and b the nodes in the order of
    /// LocalDofs::u_by_component: M = N^T (rho JxW N) with the shape values
    /// N(q, a) gathered once (@p shapes and @p weighted are scratch).
    void
    cell_mass_matrix(const FEValues<dim> &fe_values,
                     const LocalDofs     &dofs,
                     const double         density,
                     FullMatrix<double>  &shapes,
                     FullMatrix<double>  &weighted,
                     FullMatrix<double>  &mass)
    {
      const std::vector<unsigned int> &nodes = dofs.u_by_component[0];
      const unsigned int               n     = nodes.size();
      const unsigned int               n_q   = fe_values.n_quadrature_points;
      shapes.reinit(n_q, n);
      weighted.reinit(n_q, n);
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const double w = density * fe_values.JxW(q);
          for (unsigned int a = 0; a < n; ++a)
            {
              shapes(q, a)   = fe_values.shape_value(nodes[a], q);
              weighted(q, a) = w * shapes(q, a);
            }
        }
      mass.reinit(n, n);
      shapes.Tmmult(mass, weighted);
    }

    /// sum_b m_ab x_b^c for node a and component c, x the local values.
    double
    mass_times(const FullMatrix<double> &mass,
               const Vector<double>     &x,
               const LocalDofs          &dofs,
               const unsigned int        a,
               const unsigned int        c)
    {
      const std::vector<unsigned int> &nodes = dofs.u_by_component[c];
      double                           sum   = 0.;
      for (unsigned int b = 0; b < nodes.size(); ++b)
        sum += mass(a, b) * x(nodes[b]);
      return sum;
    }
  } // namespace



  Quadrature<dim>
  redistributed_mass_rule(const std::vector<Point<dim>> &massless_nodes,
                          const unsigned int             n_gauss)
  {
    const auto on_face = [](const double xi) {
      return std::abs(xi) < 1e-12 || std::abs(xi - 1.) < 1e-12;
    };
    // Greedy: the direction whose faces hold most of the nodes not yet
    // covered, until all are.
    std::array<bool, dim>   midpoint{};
    std::vector<Point<dim>> left = massless_nodes;
    while (!left.empty())
      {
        std::array<unsigned int, dim> count{};
        for (const Point<dim> &p : left)
          for (unsigned int d = 0; d < dim; ++d)
            count[d] += (!midpoint[d] && on_face(p[d])) ? 1 : 0;
        const unsigned int d =
          std::max_element(count.begin(), count.end()) - count.begin();
        AssertThrow(count[d] > 0, ExcMessage("a massless node inside a cell"));
        midpoint[d] = true;
        left.erase(std::remove_if(left.begin(),
                                  left.end(),
                                  [&](const Point<dim> &p) {
                                    return on_face(p[d]);
                                  }),
                   left.end());
      }
    const auto rule = [&](const unsigned int d) {
      return midpoint[d] ? Quadrature<1>(QMidpoint<1>())
                         : Quadrature<1>(QGauss<1>(n_gauss));
    };
#if DUCTILE_CONTACT_DIM == 2
    return Quadrature<dim>(rule(0), rule(1));
#else
    return Quadrature<dim>(Quadrature<2>(rule(0), rule(1)), rule(2));
#endif
  }



  void
  SystemAssembler::inertia_terms(
    const DoFHandler<dim>::active_cell_iterator &cell,
    const BodyParameters                        &body,
    const LocalDofs                             &dofs,
    CellScratch                                 &scratch,
    CellCopy                                    &copy,
    const Pass                                  &pass) const
  {
    const InertiaTerms              &inertia = *pass.step->inertia;
    LocalRows                       &rows    = copy.cell;
    const std::vector<unsigned int> &nodes0  = dofs.u_by_component[0];

    // The cell's nodes on a contact surface (their x DoF is in the set).
    std::vector<Point<dim>> massless_nodes;
    if (inertia.massless && !inertia.massless->empty())
      {
        const FiniteElement<dim> &scalar = cell->get_fe().base_element(0);
        for (unsigned int a = 0; a < nodes0.size(); ++a)
          if (std::binary_search(inertia.massless->begin(),
                                 inertia.massless->end(),
                                 rows.indices[nodes0[a]]))
            massless_nodes.push_back(scalar.unit_support_point(a));
      }
    if (massless_nodes.empty())
      {
        scratch.mass_values.reinit(cell);
        cell_mass_matrix(scratch.mass_values.get_present_fe_values(),
                         dofs,
                         body.density,
                         scratch.mass_shapes,
                         scratch.mass_weighted,
                         scratch.mass);
      }
    else
      {
        AssertThrow(discretisation.degree == 2,
                    ExcMessage("the redistributed contact mass needs Q2"));
        FEValues<dim> fe_values(
          discretisation.mapping[0],
          cell->get_fe(),
          redistributed_mass_rule(massless_nodes, discretisation.degree + 1),
          update_values | update_JxW_values);
        fe_values.reinit(cell);
        cell_mass_matrix(fe_values,
                         dofs,
                         body.density,
                         scratch.mass_shapes,
                         scratch.mass_weighted,
                         scratch.mass);
      }

    const FullMatrix<double> &mass   = scratch.mass;
    const unsigned int        n      = mass.m();
    const unsigned int        n_dofs = cell->get_fe().n_dofs_per_cell();
    Vector<double> &u = scratch.inertia_u, &x = scratch.inertia_target,
                   &y = scratch.inertia_other;
    u.reinit(n_dofs);
    x.reinit(n_dofs);
    cell->get_dof_values(*pass.u, u);

    if (pass.targets)
      {
        // f_int += c M (u - u*): the inertial force of a_m = c (u - u*).
        cell->get_dof_values(*inertia.target, x);
        x.sadd(-1., 1., u);
        const double c = inertia.mass_factor;
        for (unsigned int comp = 0; comp < dim; ++comp)
          {
            const std::vector<unsigned int> &nodes = dofs.u_by_component[comp];
            for (unsigned int a = 0; a < n; ++a)
              {
                double magnitude = 0.;
                for (unsigned int b = 0; b < n; ++b)
                  magnitude += std::abs(mass(a, b) * x(nodes[b]));
                rows.f_int(nodes[a]) += c * mass_times(mass, x, dofs, a, comp);
                rows.magnitude(nodes[a]) += c * magnitude;
                if (pass.targets->tangent)
                  for (unsigned int b = 0; b < n; ++b)
                    rows.matrix(nodes[a], nodes[b]) += c * mass(a, b);
              }
          }
      }

    if (pass.updated_history && inertia.velocity)
      {
        // Kinetic energy and momentum of v_n+1; the inertial work
        // (u_n+1 - u_n) . M (a_m,n + a_m,n+1)/2 of the step.
        AssemblyReduction &sums = copy.sums;
        cell->get_dof_values(*inertia.velocity, x);
        y.reinit(n_dofs);
        cell->get_dof_values(*pass.step->old_solution, y);
        y.sadd(-1., 1., u); // u_n+1 - u_n
        cell->get_dof_values(*inertia.mean_acceleration, u);
        for (unsigned int comp = 0; comp < dim; ++comp)
          {
            const std::vector<unsigned int> &nodes = dofs.u_by_component[comp];
            for (unsigned int a = 0; a < n; ++a)
              {
                const double mv = mass_times(mass, x, dofs, a, comp);
                sums.kinetic_energy += 0.5 * x(nodes[a]) * mv;
                sums.momentum[comp] += mv;
                sums.inertial_work_increment +=
                  y(nodes[a]) * mass_times(mass, u, dofs, a, comp);
              }
          }
      }
  }
} // namespace DuctileContact
