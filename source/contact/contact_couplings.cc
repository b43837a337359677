// ContactProblem: the DoFs of the contact surfaces, the constraints they
// extend, and the matrix couplings of slave and master nodes.
#include <ductile_contact/contact/contact_problem.h>

#include <set>

namespace DuctileContact
{
  using namespace dealii;



  IndexSet
  ContactProblem::surface_dofs() const
  {
    return surface;
  }



  void
  ContactProblem::extend_constraints(
    const AffineConstraints<double> &constraints,
    AffineConstraints<double>       &extended) const
  {
    // Lines of the surface DoFs this rank owns: dof, inhomogeneity, number
    // of entries, (column, weight) pairs.
    std::vector<double> mine;
    for (const auto dof : surface)
      if (discretisation.locally_owned_dofs.is_element(dof) &&
          constraints.is_constrained(dof))
        {
          const auto *entries = constraints.get_constraint_entries(dof);
          mine.push_back(dof);
          mine.push_back(constraints.get_inhomogeneity(dof));
          mine.push_back(entries ? entries->size() : 0);
          if (entries)
            for (const auto &[column, weight] : *entries)
              {
                mine.push_back(column);
                mine.push_back(weight);
              }
        }
    const auto all =
      Utilities::MPI::all_gather(discretisation.dof_handler.get_communicator(),
                                 mine);

    IndexSet lines = discretisation.locally_relevant_dofs;
    lines.add_indices(surface);
    extended.clear();
    extended.reinit(lines);
    extended.merge(constraints,
                   AffineConstraints<double>::no_conflicts_allowed,
                   true);
    for (const auto &records : all)
      for (std::size_t r = 0; r < records.size();)
        {
          const auto   dof = static_cast<types::global_dof_index>(records[r]);
          const double inhomogeneity = records[r + 1];
          const unsigned int n = static_cast<unsigned int>(records[r + 2]);
          if (!extended.is_constrained(dof))
            {
              extended.add_line(dof);
              for (unsigned int e = 0; e < n; ++e)
                extended.add_entry(dof,
                                   static_cast<types::global_dof_index>(
                                     records[r + 3 + 2 * e]),
                                   records[r + 4 + 2 * e]);
              extended.set_inhomogeneity(dof, inhomogeneity);
            }
          r += 3 + 2 * n;
        }
    extended.close();
  }



  std::vector<types::global_dof_index>
  ContactProblem::local_numbering(
    const Pair                                           &pair,
    const unsigned int                                    j,
    const std::vector<unsigned int>                      &slave_rows,
    const std::map<unsigned int, std::array<double, 10>> &g,
    std::map<unsigned int, unsigned int>                 &local)
  {
    const unsigned int ns = pair.slave.nodes.size();
    local.clear();
    for (const unsigned int k : slave_rows)
      for (unsigned int r = 0; r < dim; ++r)
        local.emplace(3 * k + r, 0);
    for (const auto &[l, m] : pair.master_row(j))
      for (unsigned int r = 0; r < dim; ++r)
        local.emplace(3 * (ns + l) + r, 0);
    for (const auto &entry : g)
      local.emplace(entry.first, 0);
    std::vector<types::global_dof_index> indices;
    for (auto &[key, position] : local)
      {
        position = indices.size();
        indices.push_back(coordinate_dof(pair, key));
      }
    return indices;
  }



  types::global_dof_index
  ContactProblem::coordinate_dof(const Pair &pair, const unsigned int key)
  {
    const unsigned int node = key / 3, ns = pair.slave.nodes.size();
    return node < ns ? pair.slave.nodes[node].dofs[key % 3]
                     : pair.master.nodes[node - ns].dofs[key % 3];
  }



  void
  ContactProblem::coupled_nodes(const Pair                &pair,
                                const unsigned int         j,
                                std::vector<unsigned int> &slave_nodes,
                                std::vector<unsigned int> &master_nodes) const
  {
    std::set<unsigned int> s, m;
    const auto             add_faces_of = [&](const unsigned int node) {
      for (const unsigned int f : pair.slave.node_faces[node])
        {
          s.insert(pair.slave.faces[f].nodes.begin(),
                   pair.slave.faces[f].nodes.end());
          for (const unsigned int c : pair.candidates[f])
            m.insert(pair.master.faces[c].nodes.begin(),
                     pair.master.faces[c].nodes.end());
        }
    };
    add_faces_of(j);
    // A condensing enforcement: node j takes over its hanging nodes'
    // couplings.
    if (pair.condenses())
      for (const auto &[h, w] : pair.slave.children[j])
        add_faces_of(h);
    slave_nodes.assign(s.begin(), s.end());
    master_nodes.assign(m.begin(), m.end());
  }



  void
  ContactProblem::add_couplings(
    TrilinosWrappers::BlockSparsityPattern &sp,
    const AffineConstraints<double>        &constraints) const
  {
    AffineConstraints<double> all_constraints;
    extend_constraints(constraints, all_constraints);
    std::vector<unsigned int>            s, m;
    std::vector<types::global_dof_index> indices;
    std::vector<types::global_dof_index> master_rows;
    for (const Pair &pair : data)
      {
        // The columns the master rows take besides the contact couplings
        // (semi-smooth Newton: the bulk rows of the slave nodes).
        const auto columns = pair.enforcement->master_row_columns(pair);
        // Every rank declares the couplings of every slave node: it may
        // integrate any face pair (linearise_operators()).
        for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
          {
            const bool owned = discretisation.locally_owned_dofs.is_element(
              pair.slave.nodes[j].dofs[0]);
            coupled_nodes(pair, j, s, m);
            indices.clear();
            for (const unsigned int k : s)
              indices.insert(indices.end(),
                             pair.slave.nodes[k].dofs.begin(),
                             pair.slave.nodes[k].dofs.end());
            master_rows.clear();
            for (const unsigned int l : m)
              master_rows.insert(master_rows.end(),
                                 pair.master.nodes[l].dofs.begin(),
                                 pair.master.nodes[l].dofs.end());
            indices.insert(indices.end(),
                           master_rows.begin(),
                           master_rows.end());
            all_constraints.add_entries_local_to_global(indices, sp, false);
            if (owned && !columns.empty() && !m.empty())
              all_constraints.add_entries_local_to_global(master_rows,
                                                          columns[j],
                                                          sp,
                                                          false);
          }
      }
  }



  void
  ContactProblem::for_each_cell_row(const CellFilter &take,
                                    const RowVisitor &visit) const
  {
    const auto &hanging = discretisation.hanging_node_constraints;
    std::vector<types::global_dof_index> cell_dofs;
    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      {
        if (!take(cell))
          continue;
        cell_dofs.resize(cell->get_fe().n_dofs_per_cell());
        cell->get_dof_indices(cell_dofs);
        for (const auto dof : cell_dofs)
          if (const auto *parents = hanging.get_constraint_entries(dof))
            for (const auto &parent : *parents)
              visit(parent.first, cell_dofs);
          else
            visit(dof, cell_dofs);
      }
  }

} // namespace DuctileContact
