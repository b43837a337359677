// SemiSmoothNewton: the enforcement that condenses the dual multipliers
// from the slave rows (semi_smooth_newton.h).
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/assembly/scatter.h>
#include <ductile_contact/contact/contact_problem.h>
#include <ductile_contact/contact/semi_smooth_newton.h>
#include <ductile_contact/core/input_error.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <deque>
#include <map>
#include <set>
#include <unordered_map>

namespace DuctileContact
{
  using namespace dealii;

  SemiSmoothNewton::SemiSmoothNewton(ContactProblem &problem)
      : problem(problem)
      , discretisation(problem.discretisation)
  {
  }



  void
  SemiSmoothNewton::check(const ContactPair &pair) const
  {
    // The condensation replaces the rows of the slave nodes: those that
    // have rows (no hanging node) take over the hanging ones, which must
    // hang on slave nodes; and they must be rows of this pair only.
    const std::string entry =
      problem.pairs[pair.index].subsection() + "/Enforcement";
    bool orphan = false;
    for (const auto &node : pair.slave.nodes)
      for (const auto &parent : node.parents)
        orphan = orphan || parent.first == numbers::invalid_unsigned_int;
    check_input(!orphan,
                entry,
                "semi-smooth Newton",
                "augmented Lagrangian where a hanging node of the slave "
                "surface is constrained to nodes off it (a refined cell next "
                "to a coarse one whose face is not in the slave surface)");
    std::set<types::global_dof_index> others;
    for (const ContactPair &other : problem.data)
      if (&other != &pair)
        for (const ContactSurface *side : {&other.slave, &other.master})
          for (const auto &node : side->nodes)
            others.insert(node.dofs[0]);
    for (const auto &node : pair.slave.nodes)
      check_input(others.count(node.dofs[0]) == 0,
                  entry,
                  "semi-smooth Newton",
                  "augmented Lagrangian where the slave surface shares nodes "
                  "with another contact pair (the condensation replaces the "
                  "slave rows of one pair)");
  }



  void
  SemiSmoothNewton::add_row(const MatrixRow                     &row,
                            const double                         weight,
                            const types::global_dof_index        dof,
                            const AffineConstraints<double>     &constraints,
                            TrilinosWrappers::BlockSparseMatrix &tangent)
  {
    const auto add = [&](const types::global_dof_index target, const double w) {
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



  /**
   * Sums of weighted tangent rows, one per target row of the displacement
   * block, added to the matrix once each: a master row takes M_jl / A_j K_j
   * from every slave node j whose multiplier support meets its shape function's
   * (tens on prm/two_bodies.prm, each row ~375 entries), and one addition of
   * their union costs a fraction of the matrix's per-entry searches.
   */
  class SemiSmoothNewton::RowSums
  {
  public:
    /// Keeps @p row (a copy) and returns its key.
    std::size_t
    keep(const MatrixRow &row)
    {
      rows.push_back(row);
      return rows.size() - 1;
    }

    /// Adds @p weight times the kept row @p key to the sum of the row of
    /// @p dof, through @p constraints as add_row().
    void
    add(const std::size_t                key,
        const double                     weight,
        const types::global_dof_index    dof,
        const AffineConstraints<double> &constraints)
    {
      if (!constraints.is_constrained(dof))
        terms[dof].emplace_back(key, weight);
      else if (const auto *entries = constraints.get_constraint_entries(dof))
        for (const auto &[parent, w] : *entries)
          terms[parent].emplace_back(key, weight * w);
    }

    /// Adds every sum to its row of @p tangent.
    void
    flush(TrilinosWrappers::BlockSparseMatrix &tangent) const
    {
      std::vector<double>                  sum;
      std::vector<bool>                    touched;
      std::vector<types::global_dof_index> columns;
      std::vector<double>                  values;
      for (unsigned int b = 0; b < tangent.n_block_cols(); ++b)
        {
          sum.assign(tangent.block(0, b).n(), 0.);
          touched.assign(sum.size(), false);
          for (const auto &[target, parts] : terms)
            {
              // Rows of the first block (displacements): the global row is
              // the block's row.
              Assert(target < tangent.block(0, 0).m(), ExcInternalError());
              columns.clear();
              for (const auto &[key, weight] : parts)
                {
                  const MatrixRow &row = rows[key];
                  for (std::size_t e = 0; e < row.columns[b].size(); ++e)
                    {
                      const auto c = row.columns[b][e];
                      if (!touched[c])
                        {
                          touched[c] = true;
                          columns.push_back(c);
                        }
                      sum[c] += weight * row.values[b][e];
                    }
                }
              if (columns.empty())
                continue;
              std::sort(columns.begin(), columns.end());
              values.resize(columns.size());
              for (std::size_t e = 0; e < columns.size(); ++e)
                {
                  values[e]           = sum[columns[e]];
                  sum[columns[e]]     = 0.;
                  touched[columns[e]] = false;
                }
              tangent.block(0, b).add(target,
                                      columns.size(),
                                      columns.data(),
                                      values.data(),
                                      true,
                                      true);
            }
        }
    }

  private:
    std::deque<MatrixRow> rows;
    std::map<types::global_dof_index,
             std::vector<std::pair<std::size_t, double>>>
      terms;
  };



  std::vector<std::vector<types::global_dof_index>>
  SemiSmoothNewton::master_row_columns(const ContactPair &pair) const
  {
    std::unordered_map<types::global_dof_index, unsigned int> node_of;
    for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
      if (discretisation.locally_owned_dofs.is_element(
            pair.slave.nodes[j].dofs[0]))
        node_of[pair.slave.nodes[j].dofs[0]] = j;
    std::vector<std::vector<types::global_dof_index>> columns(
      pair.slave.nodes.size());
    // The cells that write into the row of node j.
    problem.for_each_cell_row(
      [](const auto &cell) { return !cell->is_artificial(); },
      [&](const types::global_dof_index               row,
          const std::vector<types::global_dof_index> &cell_dofs) {
        if (const auto it = node_of.find(row); it != node_of.end())
          columns[it->second].insert(columns[it->second].end(),
                                     cell_dofs.begin(),
                                     cell_dofs.end());
      });
    for (auto &c : columns)
      {
        std::sort(c.begin(), c.end());
        c.erase(std::unique(c.begin(), c.end()), c.end());
      }
    return columns;
  }



  void
  SemiSmoothNewton::condensed_states(
    ContactPair                     &pair,
    const AffineConstraints<double> &constraints,
    const AssemblyTargets           &targets,
    CondensedNodes                  &nodes) const
  {
    const ContactSurface &slave = pair.slave;
    const unsigned int    ns    = slave.nodes.size();
    const auto           &R     = *targets.residual;
    nodes.owned.assign(ns, false);
    nodes.free.assign(ns, {});
    nodes.law.assign(ns, NodalComplementarity());

    // f_j = -R_j / A_j on the owned nodes (components fixed by a Dirichlet
    // condition carry none), summed over the ranks so that every rank has
    // the states for the summary.
    std::vector<double> f(dim * ns, 0.);
    for (unsigned int j = 0; j < ns; ++j)
      {
        const auto &dofs = slave.nodes[j].dofs;
        if (!pair.carries_contact(j))
          continue;
        nodes.owned[j] = discretisation.locally_owned_dofs.is_element(dofs[0]);
        // @p constraints know every contact-surface DoF (extend_constraints()).
        for (unsigned int c = 0; c < dim; ++c)
          {
            // No hanging node here: check() refused them.
            Assert(constraints.get_constraint_entries(dofs[c]) == nullptr ||
                     constraints.get_constraint_entries(dofs[c])->empty(),
                   ExcInternalError());
            nodes.free[j][c] = !constraints.is_constrained(dofs[c]);
            if (nodes.owned[j] && nodes.free[j][c])
              f[dim * j + c] = -R(dofs[c]) / pair.aggregates[j].area;
          }
      }
    Utilities::MPI::sum(f, discretisation.dof_handler.get_communicator(), f);

    for (unsigned int j = 0; j < ns; ++j)
      {
        if (!pair.carries_contact(j))
          continue;
        Tensor<1, dim> fj;
        for (unsigned int c = 0; c < dim; ++c)
          fj[c] = f[dim * j + c];
        const NodalComplementarity &law = nodes.law[j] =
          nodal_complementarity(pair.aggregates[j], fj, pair.law);
        NodalContactState &state = pair.nodal[j];
        state.gap                = law.gap;
        state.pressure           = law.pressure;
        state.active             = law.active;
        state.traction           = law.traction;
        state.slip               = law.slip;
        state.friction_state     = law.friction_state;
        state.dissipation        = law.dissipation;
        state.force_density      = fj;
      }
    problem.summarise(pair);
  }



  void
  SemiSmoothNewton::record_constrained_rows(ContactPair          &pair,
                                            const CondensedNodes &nodes)
  {
    pair.constrained_rows.clear();
    for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
      {
        const NodalComplementarity &law  = nodes.law[j];
        const auto                 &free = nodes.free[j];
        if (!pair.carries_contact(j) || !law.active ||
            !pair.slave.nodes[j].parents.empty() ||
            std::find(free.begin(), free.end(), false) != free.end())
          continue;
        Tensor<1, dim> n = pair.aggregates[j].normal;
        if (n.norm() == 0.)
          continue;
        n /= n.norm();
        // The frame: n, then the coordinate axes least aligned with it,
        // orthonormalised (Gram-Schmidt).
        std::array<unsigned int, dim> axes;
        for (unsigned int c = 0; c < dim; ++c)
          axes[c] = c;
        std::sort(axes.begin(), axes.end(), [&](const auto a, const auto b) {
          return std::abs(n[a]) < std::abs(n[b]);
        });
        std::array<Tensor<1, dim>, dim> q;
        q[0] = n;
        for (unsigned int k = 1; k < dim; ++k)
          {
            q[k][axes[k - 1]] = 1.;
            for (unsigned int i = 0; i < k; ++i)
              q[k] -= (q[k] * q[i]) * q[i];
            q[k] /= q[k].norm();
          }
        ConstrainedNode node;
        node.dofs.assign(pair.slave.nodes[j].dofs.begin(),
                         pair.slave.nodes[j].dofs.end());
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int c = 0; c < dim; ++c)
            node.frame.push_back(q[k][c]);
        // Stick: C_T = -c_T A s holds no traction either.
        node.n_constrained = law.friction_state == 1 ? dim : 1;
        pair.constrained_rows.push_back(std::move(node));
      }
  }



  SemiSmoothNewton::Matrix3
  SemiSmoothNewton::CondensedNodes::row_weights(const unsigned int j,
                                                const double       area) const
  {
    // S = dC/df P / A; a row fixed by a Dirichlet condition stays as it is.
    Matrix3 S;
    for (unsigned int r = 0; r < dim; ++r)
      for (unsigned int c = 0; c < dim; ++c)
        S[r][c] = !free[j][r]  ? (r == c ? 1. : 0.)
                  : free[j][c] ? law[j].jacobian[r][10 + c] / area
                               : 0.;
    return S;
  }



  void
  SemiSmoothNewton::add_condensed_vectors(
    const ContactPair               &pair,
    const unsigned int               j,
    const CondensedNodes            &nodes,
    const AffineConstraints<double> &constraints,
    const AssemblyTargets           &targets) const
  {
    const double            A    = pair.aggregates[j].area;
    const auto             &dofs = pair.slave.nodes[j].dofs;
    const auto             &C    = nodes.law[j].value;
    const Tensor<1, dim>   &f    = pair.nodal[j].force_density;
    const Matrix3           S    = nodes.row_weights(j, A);
    std::array<double, dim> R{}, rhs{};
    for (unsigned int c = 0; c < dim; ++c)
      if (nodes.free[j][c])
        {
          R[c]   = (*targets.residual)(dofs[c]);
          rhs[c] = targets.newton_rhs ? (*targets.newton_rhs)(dofs[c]) : 0.;
        }
    const auto add = [](TrilinosWrappers::MPI::BlockVector *v,
                        const types::global_dof_index       dof,
                        const double                        value) {
      if (v)
        v->add(std::vector<types::global_dof_index>{dof},
               std::vector<double>{value});
    };
    // Slave rows: R_j -> -C_j; the right-hand side C + S (rhs_j + R_j)
    // (rhs_j holds -R_j and the prescribed values of the iterate).
    for (unsigned int r = 0; r < dim; ++r)
      {
        if (!nodes.free[j][r])
          continue;
        double rhs_new = C[r];
        for (unsigned int c = 0; c < dim; ++c)
          rhs_new += S[r][c] * (rhs[c] + R[c]);
        add(targets.residual, dofs[r], -C[r] - R[r]);
        add(targets.newton_rhs, dofs[r], rhs_new - rhs[r]);
        add(targets.internal_force, dofs[r], A * f[r]);
      }
    // Master rows: -M_jl f_j, right-hand side M_jl / A rhs_j, through the
    // constraints (all rows of the node at once: one call per vector).
    const auto                          &row = pair.master_row(j);
    std::vector<types::global_dof_index> master_dofs;
    Vector<double> force(dim * row.size()), right(dim * row.size());
    for (const auto &[l, m] : row)
      for (unsigned int r = 0; r < dim; ++r)
        {
          force[master_dofs.size()] = -m * f[r];
          right[master_dofs.size()] = m / A * rhs[r];
          master_dofs.push_back(pair.master.nodes[l].dofs[r]);
        }
    if (targets.residual)
      constraints.distribute_local_to_global(force,
                                             master_dofs,
                                             *targets.residual);
    if (targets.newton_rhs)
      constraints.distribute_local_to_global(right,
                                             master_dofs,
                                             *targets.newton_rhs);
    if (targets.internal_force)
      discretisation.hanging_node_constraints.distribute_local_to_global(
        force, master_dofs, *targets.internal_force);
  }



  void
  SemiSmoothNewton::combine_rows(const ContactPair               &pair,
                                 const unsigned int               j,
                                 const CondensedNodes            &nodes,
                                 const AffineConstraints<double> &constraints,
                                 TrilinosWrappers::BlockSparseMatrix &tangent,
                                 RowSums &master_rows) const
  {
    const double  A    = pair.aggregates[j].area;
    const auto   &dofs = pair.slave.nodes[j].dofs;
    const Matrix3 S    = nodes.row_weights(j, A);
    // All three rows are read before any of them changes.
    const unsigned int         n_blocks = tangent.n_block_cols();
    std::array<MatrixRow, dim> rows;
    for (unsigned int c = 0; c < dim; ++c)
      {
        rows[c].columns.assign(n_blocks, {});
        rows[c].values.assign(n_blocks, {});
        if (!nodes.free[j][c])
          continue;
        for (unsigned int b = 0; b < n_blocks; ++b)
          {
            if (tangent.block(0, b).n() == 0)
              continue;
            // The row as Epetra stores it (deal.II's row iterator looks up
            // every entry again).
            const Epetra_CrsMatrix &epetra =
              tangent.block(0, b).trilinos_matrix();
            int     n = 0;
            double *values;
            int    *local_columns;
            epetra.ExtractMyRowView(epetra.LRID(
                                      static_cast<long long>(dofs[c])),
                                    n,
                                    values,
                                    local_columns);
            for (int e = 0; e < n; ++e)
              if (values[e] != 0.)
                {
                  rows[c].columns[b].push_back(
                    epetra.ColMap().GID64(local_columns[e]));
                  rows[c].values[b].push_back(values[e]);
                }
          }
      }
    // Slave rows S K_j, master rows + M_jl / A K_j.
    for (unsigned int c = 0; c < dim; ++c)
      {
        if (!nodes.free[j][c])
          continue;
        for (unsigned int r = 0; r < dim; ++r)
          if (nodes.free[j][r] && S[r][c] != (r == c ? 1. : 0.))
            add_row(rows[c],
                    S[r][c] - (r == c ? 1. : 0.),
                    dofs[r],
                    constraints,
                    tangent);
        const std::size_t key = master_rows.keep(rows[c]);
        for (const auto &[l, m] : pair.master_row(j))
          master_rows.add(key,
                          m / A,
                          pair.master.nodes[l].dofs[c],
                          constraints);
      }
  }



  void
  SemiSmoothNewton::add_aggregate_terms(
    const ContactPair                              &pair,
    const unsigned int                              j,
    const CondensedNodes                           &nodes,
    std::map<unsigned int, std::array<double, 10>> &g,
    const bool                                      direct,
    const AffineConstraints<double>                &constraints,
    const AssemblyTargets                          &targets) const
  {
    // Slave rows -(dC/da - dC/df f / A e_A) da, master rows M_jl / A f dA
    // (da/dx in g: through dD and dM already, here the direct part).
    const unsigned int    ns = pair.slave.nodes.size();
    const double          A  = pair.aggregates[j].area;
    const auto           &J  = nodes.law[j].jacobian;
    const Tensor<1, dim> &f  = pair.nodal[j].force_density;
    if (direct)
      ContactProblem::add_direct_gradients(pair, j, g);
    std::array<std::array<double, 10>, dim> Js;
    for (unsigned int r = 0; r < dim; ++r)
      {
        double Cf_f = 0.;
        for (unsigned int c = 0; c < dim; ++c)
          Cf_f += J[r][10 + c] * f[c];
        for (unsigned int a = 0; a < 10; ++a)
          Js[r][a] = nodes.free[j][r] ? J[r][a] - (a == 0 ? Cf_f / A : 0.) : 0.;
      }
    // The block: rows of node j, then of its master nodes; a column per
    // key of g.
    const auto                          &master_row = pair.master_row(j);
    std::vector<unsigned int>            row_keys;
    std::vector<types::global_dof_index> rows, columns;
    for (unsigned int r = 0; r < dim; ++r)
      row_keys.push_back(3 * j + r);
    for (const auto &lm : master_row)
      for (unsigned int r = 0; r < dim; ++r)
        row_keys.push_back(3 * (ns + lm.first) + r);
    for (const unsigned int key : row_keys)
      rows.push_back(ContactProblem::coordinate_dof(pair, key));
    for (const auto &entry : g)
      columns.push_back(ContactProblem::coordinate_dof(pair, entry.first));
    FullMatrix<double> block(rows.size(), columns.size());
    unsigned int       column = 0;
    for (const auto &[key, e] : g)
      {
        for (unsigned int r = 0; r < dim; ++r)
          {
            double v = 0.;
            for (unsigned int a = 0; a < 10; ++a)
              v += Js[r][a] * e[a];
            block(r, column) -= v;
          }
        unsigned int row = dim;
        for (const auto &[l, m] : master_row)
          for (unsigned int r = 0; r < dim; ++r)
            block(row++, column) += m / A * f[r] * e[0];
        ++column;
      }
    const auto constrained = [&](const types::global_dof_index dof) {
      return constraints.is_constrained(dof);
    };
    if (std::none_of(rows.begin(), rows.end(), constrained) &&
        std::none_of(columns.begin(), columns.end(), constrained))
      {
        scatter_matrix_block(
          block, rows, columns, constraints, *targets.tangent);
        return;
      }
    // Through the square local system of scatter(), which applies the
    // constraints (and their inhomogeneities to the right-hand side).
    std::map<unsigned int, unsigned int>       local;
    const std::vector<types::global_dof_index> indices =
      ContactProblem::local_numbering(pair, j, {j}, g, local);
    FullMatrix<double> matrix(indices.size(), indices.size());
    Vector<double>     zero(indices.size());
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        unsigned int c = 0;
        for (const auto &entry : g)
          matrix(local[row_keys[r]], local[entry.first]) += block(r, c++);
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



  void
  SemiSmoothNewton::assemble(ContactPair                     &pair,
                             const AffineConstraints<double> &constraints,
                             const AssemblyTargets           &targets) const
  {
    Assert(targets.residual != nullptr, ExcInternalError());
    CondensedNodes nodes;
    condensed_states(pair, constraints, targets, nodes);
    if (targets.tangent)
      record_constrained_rows(pair, nodes);
    const unsigned int ns = pair.slave.nodes.size();
    // The tractions whose dM terms this rank adds: those of its nodes and,
    // at a hanging node, the share its parents here interpolate.
    std::vector<bool>           needed = nodes.owned;
    std::vector<Tensor<1, dim>> forces(ns);
    for (unsigned int j = 0; j < ns; ++j)
      if (nodes.owned[j])
        forces[j] = pair.nodal[j].force_density;
    for (unsigned int h = 0; h < ns; ++h)
      for (const auto &[p, w] : pair.slave.nodes[h].parents)
        {
          // Output: a hanging node shows its parents' interpolation.
          pair.nodal[h].pressure += w * pair.nodal[p].pressure;
          pair.nodal[h].gap += w * pair.nodal[p].gap;
          if (nodes.owned[p])
            {
              needed[h] = true;
              forces[h] += w * pair.nodal[p].force_density;
            }
        }
    std::vector<std::map<unsigned int, std::array<double, 10>>> gradients(ns);
    // The nodes whose gradients this rank has a share of.
    std::vector<bool> held;
    if (targets.tangent)
      {
        held =
          problem.linearise_operators(pair,
                                      needed,
                                      forces,
                                      false,
                                      ContactProblem::GradientShare::partial,
                                      constraints,
                                      targets,
                                      gradients);
        fold_hanging_gradients(pair, nodes.owned, gradients);
      }
    // The bulk rows of node j are read (combine_rows()) before its
    // aggregate terms go into them.
    RowSums master_rows;
    for (unsigned int j = 0; j < ns; ++j)
      {
        if (!nodes.owned[j])
          continue;
        add_condensed_vectors(pair, j, nodes, constraints, targets);
        if (targets.tangent)
          combine_rows(
            pair, j, nodes, constraints, *targets.tangent, master_rows);
      }
    if (!targets.tangent)
      return;
    master_rows.flush(*targets.tangent);
    // Each rank adds the terms of its share of the gradients (rows owned
    // elsewhere are sent at the compress); the owner adds the direct ones.
    for (unsigned int j = 0; j < ns; ++j)
      if (pair.carries_contact(j) &&
          (nodes.owned[j] || (held[j] && !gradients[j].empty())))
        add_aggregate_terms(
          pair, j, nodes, gradients[j], nodes.owned[j], constraints, targets);
  }



  void
  SemiSmoothNewton::fold_hanging_gradients(
    const ContactPair                                           &pair,
    const std::vector<bool>                                     &owned,
    std::vector<std::map<unsigned int, std::array<double, 10>>> &gradients)
  {
    for (unsigned int h = 0; h < pair.slave.nodes.size(); ++h)
      {
        const auto &parents = pair.slave.nodes[h].parents;
        if (parents.empty())
          continue;
        // Area, G and H of h through D and M (this rank's share, to every
        // parent) and through the positions (once: to the parents owned
        // here); its normal is not folded.
        std::map<unsigned int, std::array<double, 10>> direct;
        if (std::any_of(parents.begin(), parents.end(), [&](const auto &p) {
              return owned[p.first];
            }))
          ContactProblem::add_direct_gradients(pair, h, direct, false);
        for (const auto &[p, w] : parents)
          for (const auto *g : {&gradients[h], &direct})
            if (g == &gradients[h] || owned[p])
              for (const auto &[key, e] : *g)
                {
                  auto &target = gradients[p][key];
                  for (unsigned int a = 0; a < 7; ++a)
                    target[a] += w * e[a];
                }
      }
  }
} // namespace DuctileContact
