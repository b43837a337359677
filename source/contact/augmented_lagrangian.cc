// AugmentedLagrangian: the enforcement by the nodal contact law on fixed
// multipliers with Uzawa updates (augmented_lagrangian.h).
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/assembly/scatter.h>
#include <ductile_contact/contact/augmented_lagrangian.h>
#include <ductile_contact/contact/contact_problem.h>

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace DuctileContact
{
  using namespace dealii;



  AugmentedLagrangian::AugmentedLagrangian(ContactProblem &problem)
      : problem(problem)
      , discretisation(problem.discretisation)
  {
  }



  bool
  AugmentedLagrangian::outer_update(ContactPair              &pair,
                                    const ContactPairSummary &summary) const
  {
    if (summary.max_penetration <= pair.tolerance)
      return true;
    for (unsigned int j = 0; j < pair.nodal.size(); ++j)
      pair.multiplier[j] = pair.nodal[j].pressure;
    return false;
  }



  void
  AugmentedLagrangian::apply_law(ContactPair &pair) const
  {
    for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
      if (pair.carries_contact(j))
        pair.nodal[j] = nodal_contact(pair.aggregates[j],
                                      pair.multiplier[j],
                                      pair.committed_traction[j],
                                      pair.law);
    problem.summarise(pair);
  }



  void
  AugmentedLagrangian::assemble(ContactPair                     &pair,
                                const AffineConstraints<double> &constraints,
                                const AssemblyTargets           &targets) const
  {
    apply_law(pair);
    FullMatrix<double>                   matrix;
    Vector<double>                       rhs, f_int;
    std::vector<types::global_dof_index> indices;
    const ContactSurface                &slave = pair.slave;
    const unsigned int                   ns    = slave.nodes.size();
    std::vector<bool>                    needed(ns);
    for (unsigned int j = 0; j < ns; ++j)
      needed[j] =
        pair.nodal[j].active &&
        discretisation.locally_owned_dofs.is_element(slave.nodes[j].dofs[0]);
    // d(aggregates)/dx: through D and M, then directly.
    std::vector<std::map<unsigned int, std::array<double, 10>>> gradients(ns);
    const bool tangent = targets.tangent != nullptr;
    if (tangent)
      {
        std::vector<Tensor<1, dim>> forces(ns);
        for (unsigned int j = 0; j < ns; ++j)
          forces[j] = pair.nodal[j].force_density;
        problem.linearise_operators(pair,
                                    needed,
                                    forces,
                                    true,
                                    ContactProblem::GradientShare::complete,
                                    constraints,
                                    targets,
                                    gradients);
      }

    for (unsigned int j = 0; j < ns; ++j)
      {
        if (!needed[j])
          continue;
        const NodalContactState &state = pair.nodal[j];
        auto                    &g     = gradients[j];
        if (tangent)
          ContactProblem::add_direct_gradients(pair, j, g);

        // Local system: rows D_jk f_j (slave k), -M_jl f_j (master l);
        // columns df_j/dx = (df_j/da) (da/dx).
        std::vector<unsigned int> slave_rows;
        for (const auto &[k, d] : pair.D[j])
          slave_rows.push_back(k);
        std::map<unsigned int, unsigned int> local;
        indices =
          ContactProblem::local_numbering(pair, j, slave_rows, g, local);
        const unsigned int size = indices.size();
        matrix.reinit(size, size);
        rhs.reinit(size);
        f_int.reinit(size);
        // df_j/dx per column
        std::vector<std::pair<unsigned int, Tensor<1, dim>>> df;
        for (const auto &[key, e] : g)
          {
            Tensor<1, dim> v;
            for (unsigned int r = 0; r < dim; ++r)
              for (unsigned int a = 0; a < 10; ++a)
                v[r] += state.jacobian[r][a] * e[a];
            df.emplace_back(local[key], v);
          }
        const auto add_row = [&](const unsigned int key, const double weight) {
          for (unsigned int r = 0; r < dim; ++r)
            {
              const unsigned int row = local[key + r];
              f_int[row] += weight * state.force_density[r];
              for (const auto &[column, v] : df)
                matrix(row, column) += weight * v[r];
            }
        };
        for (const auto &[k, d] : pair.D[j])
          add_row(3 * k, d);
        for (const auto &[l, m] : pair.M[j])
          add_row(3 * (ns + l), -m);
        for (unsigned int r = 0; r < size; ++r)
          rhs[r] = -f_int[r];
        scatter(matrix,
                rhs,
                f_int,
                indices,
                constraints,
                discretisation.hanging_node_constraints,
                targets);
      }
  }
} // namespace DuctileContact
