// The semi-smooth Newton enforcement of ContactProblem: condensation of
// the dual multipliers from the slave rows (contact_problem.h).
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <Epetra_CrsMatrix.h>

#include <ductile_contact/assembly/scatter.h>
#include <ductile_contact/contact/contact_problem.h>

#include <algorithm>
#include <unordered_map>

namespace DuctileContact
{
  using namespace dealii;

  void
  ContactProblem::add_row(const MatrixRow                 &row,
                          const double                     weight,
                          const types::global_dof_index    dof,
                          const AffineConstraints<double> &constraints,
                          TrilinosWrappers::BlockSparseMatrix &tangent)
  {
    const auto add = [&](const types::global_dof_index target,
                         const double                  w) {
      for (unsigned int b = 0; b < row.columns.size(); ++b)
        {
          if (row.columns[b].empty())
            continue;
          std::vector<double> values = row.values[b];
          for (double &v : values)
            v *= w;
          tangent.block(0, b).add(target,
                                  values.size(),
                                  row.columns[b].data(),
                                  values.data(),
                                  true,
                                  false);
        }
    };
    if (!constraints.is_constrained(dof))
      add(dof, weight);
    else if (const auto *entries = constraints.get_constraint_entries(dof))
      for (const auto &[parent, w] : *entries)
        add(parent, weight * w);
  }



  std::vector<std::vector<types::global_dof_index>>
  ContactProblem::slave_row_columns(const Pair &pair) const
  {
    std::unordered_map<types::global_dof_index, unsigned int> node_of;
    for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
      if (discretisation.locally_owned_dofs.is_element(
            pair.slave.nodes[j].dofs[0]))
        node_of[pair.slave.nodes[j].dofs[0]] = j;
    std::vector<std::vector<types::global_dof_index>> columns(
      pair.slave.nodes.size());
    std::vector<types::global_dof_index> cell_dofs;
    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        cell_dofs.resize(cell->get_fe().n_dofs_per_cell());
        cell->get_dof_indices(cell_dofs);
        for (const auto dof : cell_dofs)
          if (const auto it = node_of.find(dof); it != node_of.end())
            columns[it->second].insert(columns[it->second].end(),
                                       cell_dofs.begin(),
                                       cell_dofs.end());
      }
    for (auto &c : columns)
      {
        std::sort(c.begin(), c.end());
        c.erase(std::unique(c.begin(), c.end()), c.end());
      }
    return columns;
  }



  void
  ContactProblem::condense(Pair                            &pair,
                           const AffineConstraints<double> &constraints,
                           const AssemblyTargets           &targets)
  {
    Assert(targets.residual != nullptr, ExcInternalError());
    const MPI_Comm comm = discretisation.dof_handler.get_communicator();
    const ContactSurface &slave = pair.slave;
    const unsigned int    ns    = slave.nodes.size();
    const auto           &R     = *targets.residual;

    // The condensed multipliers f_j = -R_j / A_j of the owned nodes
    // (components fixed by a Dirichlet condition carry none), summed over
    // the ranks so that every rank has the states for the summary.
    std::vector<bool>                 owned(ns, false);
    std::vector<std::array<bool, dim>> free(ns);
    std::vector<double>               f(dim * ns, 0.);
    for (unsigned int j = 0; j < ns; ++j)
      {
        const auto &dofs = slave.nodes[j].dofs;
        owned[j] = pair.carries_contact(j) &&
                   discretisation.locally_owned_dofs.is_element(dofs[0]);
        if (!owned[j])
          continue;
        for (unsigned int c = 0; c < dim; ++c)
          {
            const auto *entries = constraints.get_constraint_entries(dofs[c]);
            AssertThrow(
              entries == nullptr || entries->empty(),
              ExcMessage(
                pairs[pair.index].subsection() +
                ": a slave node is a hanging node, which the "
                "semi-smooth Newton enforcement does not support; refine "
                "the slave surface uniformly or set Enforcement = "
                "augmented Lagrangian"));
            free[j][c] = !constraints.is_constrained(dofs[c]);
            if (free[j][c])
              f[dim * j + c] = -R(dofs[c]) / pair.aggregates[j].area;
          }
      }
    Utilities::MPI::sum(f, comm, f);

    std::vector<NodalComplementarity> law(ns);
    for (unsigned int j = 0; j < ns; ++j)
      {
        if (!pair.carries_contact(j))
          continue;
        Tensor<1, dim> fj;
        for (unsigned int c = 0; c < dim; ++c)
          fj[c] = f[dim * j + c];
        law[j]                   = nodal_complementarity(pair.aggregates[j], fj, pair.law);
        NodalContactState &state = pair.nodal[j];
        state.gap                = law[j].gap;
        state.pressure           = law[j].pressure;
        state.active             = law[j].active;
        state.traction           = law[j].traction;
        state.slip               = law[j].slip;
        state.friction_state     = law[j].friction_state;
        state.dissipation        = law[j].dissipation;
        state.force_density      = fj;
      }
    summarise(pair);

    const bool tangent = targets.tangent != nullptr;
    std::vector<std::map<unsigned int, std::array<double, 10>>> gradients(ns);
    if (tangent)
      linearise_operators(pair, owned, false, constraints, targets, gradients);

    // Master rows through the constraints: vector entries first.
    const auto add_vector = [&](TrilinosWrappers::MPI::BlockVector *v,
                                const AffineConstraints<double>    &c,
                                const types::global_dof_index       dof,
                                const double                        value) {
      if (v == nullptr)
        return;
      const std::vector<types::global_dof_index> index{dof};
      Vector<double>                             x(1);
      x[0] = value;
      c.distribute_local_to_global(x, index, *v);
    };

    std::array<MatrixRow, dim> rows;
    FullMatrix<double> matrix;
    Vector<double>     zero;
    std::vector<types::global_dof_index> indices;
    for (unsigned int j = 0; j < ns; ++j)
      {
        if (!owned[j])
          continue;
        const double          A    = pair.aggregates[j].area;
        const auto           &dofs = slave.nodes[j].dofs;
        const auto           &J    = law[j].jacobian;
        const Tensor<1, dim> &fj   = pair.nodal[j].force_density;
        // S = dC/df P / A: the slave rows become S K_j (free rows only).
        FullMatrix<double> S(dim, dim);
        for (unsigned int r = 0; r < dim; ++r)
          for (unsigned int c = 0; c < dim; ++c)
            S(r, c) = !free[j][r] ? (r == c ? 1. : 0.) :
                      free[j][c]  ? J[r][10 + c] / A :
                                    0.;
        std::array<double, dim> Rj{}, rhs_j{};
        for (unsigned int c = 0; c < dim; ++c)
          if (free[j][c])
            {
              Rj[c]    = R(dofs[c]);
              rhs_j[c] = targets.newton_rhs ? (*targets.newton_rhs)(dofs[c]) : 0.;
            }
        for (unsigned int r = 0; r < dim; ++r)
          {
            if (!free[j][r])
              continue;
            double rhs_new = law[j].value[r];
            for (unsigned int c = 0; c < dim; ++c)
              rhs_new += S(r, c) * (rhs_j[c] + Rj[c]);
            targets.residual->add(std::vector<types::global_dof_index>{dofs[r]},
                                  std::vector<double>{-law[j].value[r] - Rj[r]});
            if (targets.newton_rhs)
              targets.newton_rhs->add(
                std::vector<types::global_dof_index>{dofs[r]},
                std::vector<double>{rhs_new - rhs_j[r]});
            if (targets.internal_force)
              targets.internal_force->add(
                std::vector<types::global_dof_index>{dofs[r]},
                std::vector<double>{A * fj[r]});
          }
        for (const auto &[l, m] : pair.M[j])
          for (unsigned int r = 0; r < dim; ++r)
            {
              const auto dof = pair.master.nodes[l].dofs[r];
              add_vector(targets.residual, constraints, dof, -m * fj[r]);
              add_vector(targets.newton_rhs, constraints, dof, m / A * rhs_j[r]);
              add_vector(targets.internal_force,
                         discretisation.hanging_node_constraints,
                         dof,
                         -m * fj[r]);
            }
        if (!tangent)
          continue;

        // Row combinations of the bulk tangent: all three rows are read
        // before any of them changes.
        const unsigned int n_blocks = targets.tangent->n_block_cols();
        for (unsigned int c = 0; c < dim; ++c)
          {
            rows[c].columns.assign(n_blocks, {});
            rows[c].values.assign(n_blocks, {});
            if (!free[j][c])
              continue;
            for (unsigned int b = 0; b < n_blocks; ++b)
              {
                const auto &block = targets.tangent->block(0, b);
                if (block.n() == 0)
                  continue;
                // The row as Epetra stores it (deal.II's row iterator looks
                // up every entry again).
                const Epetra_CrsMatrix &epetra = block.trilinos_matrix();
                const int row = epetra.LRID(static_cast<long long>(dofs[c]));
                int       n   = 0;
                double   *values;
                int      *local_columns;
                epetra.ExtractMyRowView(row, n, values, local_columns);
                for (int e = 0; e < n; ++e)
                  if (values[e] != 0.)
                    {
                      rows[c].columns[b].push_back(
                        epetra.ColMap().GID64(local_columns[e]));
                      rows[c].values[b].push_back(values[e]);
                    }
              }
          }
        for (unsigned int c = 0; c < dim; ++c)
          {
            if (!free[j][c])
              continue;
            for (unsigned int r = 0; r < dim; ++r)
              if (free[j][r])
                {
                  const double w = S(r, c) - (r == c ? 1. : 0.);
                  if (w != 0.)
                    add_row(rows[c], w, dofs[r], constraints, *targets.tangent);
                }
            for (const auto &[l, m] : pair.M[j])
              add_row(rows[c], m / A, pair.master.nodes[l].dofs[c], constraints,
                      *targets.tangent);
          }

        // Terms of d(aggregates): slave rows -(dC/da - dC/df f / A e_A) da,
        // master rows M_jl / A f dA.
        auto &g = gradients[j];
        add_direct_gradients(pair, j, g);
        std::map<unsigned int, unsigned int> local;
        for (unsigned int r = 0; r < dim; ++r)
          local.emplace(3 * j + r, 0);
        for (const auto &[l, m] : pair.M[j])
          for (unsigned int r = 0; r < dim; ++r)
            local.emplace(3 * (ns + l) + r, 0);
        for (const auto &entry : g)
          local.emplace(entry.first, 0);
        indices.clear();
        for (auto &[key, position] : local)
          {
            position = indices.size();
            indices.push_back(coordinate_dof(pair, key));
          }
        const unsigned int size = indices.size();
        matrix.reinit(size, size);
        zero.reinit(size);
        std::array<std::array<double, 10>, dim> Js;
        for (unsigned int r = 0; r < dim; ++r)
          {
            double Cf_f = 0.;
            for (unsigned int c = 0; c < dim; ++c)
              Cf_f += J[r][10 + c] * fj[c];
            for (unsigned int a = 0; a < 10; ++a)
              Js[r][a] = free[j][r] ? J[r][a] - (a == 0 ? Cf_f / A : 0.) : 0.;
          }
        for (const auto &[key, e] : g)
          {
            const unsigned int column = local[key];
            for (unsigned int r = 0; r < dim; ++r)
              {
                double v = 0.;
                for (unsigned int a = 0; a < 10; ++a)
                  v += Js[r][a] * e[a];
                matrix(local[3 * j + r], column) -= v;
              }
            for (const auto &[l, m] : pair.M[j])
              for (unsigned int r = 0; r < dim; ++r)
                matrix(local[3 * (ns + l) + r], column) += m / A * fj[r] * e[0];
          }
        AssemblyTargets matrix_only = targets;
        matrix_only.residual        = nullptr;
        matrix_only.internal_force  = nullptr;
        scatter(matrix,
                zero,
                zero,
                indices,
                constraints,
                discretisation.hanging_node_constraints,
                matrix_only);
      }
  }
} // namespace DuctileContact
