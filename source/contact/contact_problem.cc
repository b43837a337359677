#include <deal.II/base/bounding_box.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/rtree.h>

#include <ductile_contact/assembly/scatter.h>
#include <ductile_contact/contact/contact_problem.h>
#include <ductile_contact/contact/contact_writer.h>
#include <ductile_contact/contact/mortar_operators.h>
#include <ductile_contact/contact/mortar_segments.h>
#include <ductile_contact/core/input_error.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <set>
#include <sstream>
#include <unordered_set>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    BoundingBox<dim>
    face_box(const ContactSurface &surface, const unsigned int f, double r)
    {
      std::vector<Point<dim>> points;
      for (const unsigned int n : surface.faces[f].nodes)
        points.push_back(surface.nodes[n].current);
      BoundingBox<dim> box(points);
      box.extend(r);
      return box;
    }
  } // namespace



  ContactProblem::ContactProblem(
    const std::deque<ContactPairParameters>                    &pairs,
    const Discretisation                                       &discretisation,
    const std::map<types::material_id, const BodyParameters *> &bodies)
      : pairs(pairs)
      , discretisation(discretisation)
      , bodies(bodies)
  {
  }



  void
  ContactProblem::setup()
  {
    data.assign(pairs.size(), Pair());
    surface = IndexSet(discretisation.dof_handler.n_dofs());
    summaries.assign(pairs.size(), ContactPairSummary());
    if (output_records.size() != pairs.size()) // kept over mesh changes
      output_records.assign(pairs.size(), {});
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const ContactPairParameters &prm  = pairs[p];
        Pair                        &pair = data[p];
        pair.slave.gather(discretisation, prm.slave_boundary_id);
        pair.master.gather(discretisation, prm.master_boundary_id);
        const std::string s = prm.subsection() + "/";
        check_input(!pair.slave.faces.empty(),
                    s + "Slave boundary id",
                    std::to_string(prm.slave_boundary_id),
                    "the id of a boundary of the mesh (no face has it)");
        check_input(!pair.master.faces.empty(),
                    s + "Master boundary id",
                    std::to_string(prm.master_boundary_id),
                    "the id of a boundary of the mesh (no face has it)");

        // eps_N = factor E / h, E the smaller Young's modulus of the two
        // bodies (the interface is as stiff as the softer one).
        const auto youngs_modulus = [&](const ContactSurface &side) {
          const auto body = bodies.find(side.faces[0].material_id);
          Assert(body != bodies.end(), ExcInternalError());
          const double mu    = body->second->shear_modulus;
          const double kappa = body->second->bulk_modulus;
          return 9. * kappa * mu / (3. * kappa + mu);
        };
        const double E =
          std::min(youngs_modulus(pair.slave), youngs_modulus(pair.master));
        const double h = pair.slave.smallest_face_size();
        pair.index     = p;
        pair.dual      = prm.multiplier_basis == MultiplierBasis::dual;
        pair.semi_smooth =
          prm.enforcement == ContactEnforcement::semi_smooth_newton;
        pair.law.penalty            = prm.penalty_factor * E / h;
        pair.law.friction           = prm.friction_coefficient;
        pair.law.tangential_penalty = prm.tangential_penalty_factor * E / h;
        // Active also when just touching (a gap at round-off level): then
        // the tangent holds the contact stiffness of a closed interface, so
        // that bodies which only touch at the start are not free.
        pair.law.activation_threshold = 1e-12 * pair.law.penalty * h;
        pair.face_size                = h;
        pair.tolerance                = prm.penetration_tolerance * h;
        pair.given_radius             = prm.search_radius;
        pair.candidates.assign(pair.slave.faces.size(), {});
        for (const ContactSurface *side : {&pair.slave, &pair.master})
          for (const auto &node : side->nodes)
            for (const auto d : node.dofs)
              surface.add_index(d);
        pair.multiplier.assign(pair.slave.nodes.size(), 0.);
        for (const auto &node : pair.slave.nodes)
          pair.slave_committed.push_back(node.reference);
        for (const auto &node : pair.master.nodes)
          pair.master_committed.push_back(node.reference);
        pair.committed_traction.assign(pair.slave.nodes.size(),
                                       Tensor<1, dim>());
        pair.committed_multiplier = pair.multiplier;
      }
    surface.compress();
    for (const Pair &pair : data)
      if (pair.semi_smooth)
        check_condensable(pair);
    bulk_rows_here = slave_rows_complete_here();
  }



  bool
  ContactProblem::slave_rows_complete_here() const
  {
    // The DoFs of the slave nodes this rank condenses.
    std::unordered_set<types::global_dof_index> rows;
    for (const Pair &pair : data)
      if (pair.semi_smooth)
        for (const auto &node : pair.slave.nodes)
          if (discretisation.locally_owned_dofs.is_element(node.dofs[0]))
            rows.insert(node.dofs.begin(), node.dofs.end());
    bool here = true;
    for_each_cell_row([](const auto &cell) { return cell->is_ghost(); },
                      [&](const types::global_dof_index row, const auto &) {
                        here = here && rows.count(row) == 0;
                      });
    return Utilities::MPI::min(here ? 1 : 0,
                               discretisation.dof_handler.get_communicator()) ==
           1;
  }



  void
  ContactProblem::check_condensable(const Pair &pair) const
  {
    // The condensation replaces the rows of the slave nodes: those that
    // have rows (no hanging node) take over the hanging ones, which must
    // hang on slave nodes; and they must be rows of this pair only.
    const std::string entry  = pairs[pair.index].subsection() + "/Enforcement";
    bool              orphan = false;
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
    for (const Pair &other : data)
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



  bool
  ContactProblem::begin_step(const TrilinosWrappers::MPI::BlockVector &u)
  {
    bool changed = false;
    for (Pair &pair : data)
      {
        pair.slave.update(u, discretisation);
        pair.master.update(u, discretisation);
        pair.multiplier = pair.committed_multiplier;
        if (!pair.missed.empty())
          pair.widen *= 2.;
        pair.missed.clear();
        pair.search_radius = search_radius(pair);

        std::vector<std::vector<unsigned int>> candidates =
          search(pair, pair.search_radius);
        if (candidates != pair.candidates)
          {
            changed         = true;
            pair.candidates = std::move(candidates);
          }
      }
    return changed;
  }



  std::vector<std::vector<unsigned int>>
  ContactProblem::search(const Pair &pair, const double radius)
  {
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes;
    for (unsigned int m = 0; m < pair.master.faces.size(); ++m)
      boxes.emplace_back(face_box(pair.master, m, 0.), m);
    const auto tree = pack_rtree(boxes);

    std::vector<std::vector<unsigned int>> candidates(pair.slave.faces.size());
    for (unsigned int s = 0; s < pair.slave.faces.size(); ++s)
      {
        std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
        tree.query(boost::geometry::index::intersects(
                     face_box(pair.slave, s, radius)),
                   std::back_inserter(hits));
        for (const auto &hit : hits)
          candidates[s].push_back(hit.second);
        std::sort(candidates[s].begin(), candidates[s].end());
      }
    return candidates;
  }



  double
  ContactProblem::search_radius(const Pair &pair)
  {
    if (pair.given_radius > 0.)
      return pair.widen * pair.given_radius;
    const auto largest_motion = [](const ContactSurface          &surface,
                                   const std::vector<Point<dim>> &committed) {
      double motion = 0.;
      for (unsigned int n = 0; n < surface.nodes.size(); ++n)
        motion =
          std::max(motion, surface.nodes[n].current.distance(committed[n]));
      return motion;
    };
    const double motion = largest_motion(pair.slave, pair.slave_committed) +
                          largest_motion(pair.master, pair.master_committed);
    return pair.widen *
           (reach(pair) + std::max(0.25 * pair.face_size, 2. * motion));
  }



  std::string
  ContactProblem::missed_pair(
    const Pair                                   &pair,
    const std::vector<std::vector<unsigned int>> &near)
  {
    for (unsigned int f = 0; f < pair.slave.faces.size(); ++f)
      {
        const auto &candidates = pair.candidates[f];
        for (const unsigned int c : near[f])
          if (!std::binary_search(candidates.begin(), candidates.end(), c) &&
              faces_may_overlap(pair.slave_faces[f],
                                pair.master.current_face(c)))
            {
              std::ostringstream s;
              s << "contact pair " << pair.index + 1 << ": the master face at ("
                << pair.master.current_face(c).position(ContactFace::centre())
                << ") m came within reach of the slave face at ("
                << pair.slave_faces[f].position(ContactFace::centre())
                << ") m but is not among the candidates of the step "
                   "(search radius "
                << pair.search_radius
                << " m); the step is redone with the radius doubled";
              return s.str();
            }
      }
    return "";
  }



  std::string
  ContactProblem::fault() const
  {
    for (const Pair &pair : data)
      if (!pair.missed.empty())
        return pair.missed;
    return "";
  }



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
    // Semi-smooth Newton: node j takes over its hanging nodes' couplings.
    if (pair.semi_smooth)
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
        // Semi-smooth Newton: the master rows take the bulk rows of the
        // slave nodes (condense()).
        const auto columns =
          pair.semi_smooth
            ? slave_row_columns(pair)
            : std::vector<std::vector<types::global_dof_index>>();
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
            if (owned && pair.semi_smooth && !m.empty())
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



  std::vector<std::pair<unsigned int, unsigned int>>
  ContactProblem::close_face_pairs(
    const Pair                                   &pair,
    const std::vector<std::vector<unsigned int>> &near)
  {
    std::vector<std::pair<unsigned int, unsigned int>> close;
    for (unsigned int f = 0; f < pair.slave.faces.size(); ++f)
      {
        // Both lists are sorted.
        std::vector<unsigned int> both;
        std::set_intersection(near[f].begin(),
                              near[f].end(),
                              pair.candidates[f].begin(),
                              pair.candidates[f].end(),
                              std::back_inserter(both));
        for (const unsigned int c : both)
          close.emplace_back(f, c);
      }
    return close;
  }



  std::vector<double>
  ContactProblem::integrate_share(
    Pair                                              &pair,
    std::vector<std::pair<unsigned int, unsigned int>> close,
    const bool                                         derivatives) const
  {
    // With derivatives the clipping alone first (every rank): a pair that
    // does not overlap costs little in double, but as much as one that
    // does with derivatives, and the shares should hold equal work.
    if (derivatives)
      close.erase(std::remove_if(close.begin(),
                                 close.end(),
                                 [&](const auto &fc) {
                                   return !faces_may_overlap(
                                     pair.slave_faces[fc.first],
                                     pair.master.current_face(fc.second));
                                 }),
                  close.end());
    const auto [begin, end] =
      share(close.size(), discretisation.dof_handler.get_communicator());
    const SlaveWeights  weights = pair.slave_weights();
    std::vector<double> records;
    pair.linearised_here = derivatives;
    pair.linearised_pairs.clear();
    const auto                  local = std::make_unique<FacePairOperators>();
    std::unique_ptr<MortarFace> face;
    unsigned int                face_index = numbers::invalid_unsigned_int;
    for (std::size_t q = begin; q < end; ++q)
      {
        const auto [f, c] = close[q];
        if (f != face_index)
          {
            face       = std::make_unique<MortarFace>(pair.slave_faces[f],
                                                pair.dual,
                                                weights);
            face_index = f;
          }
        const std::size_t stored = pair.linearised_pairs.size();
        if (derivatives && pair.linearised_operators.size() <= stored)
          pair.linearised_operators.resize(stored + 1);
        FacePairOperators &operators =
          derivatives ? pair.linearised_operators[stored] : *local;
        if (!face->integrate(pair.master.current_face(c),
                             operators,
                             derivatives))
          continue;
        if (derivatives) // the position of the record, made global later
          pair.linearised_pairs.push_back(records.size());
        records.push_back(f);
        records.push_back(c);
        for (unsigned int i = 0; i < face_nodes; ++i)
          for (unsigned int k = 0; k < face_nodes; ++k)
            if (weights == SlaveWeights::full || k == i)
              records.push_back(operators.D[i][k]);
        for (unsigned int i = 0; i < face_nodes; ++i)
          for (unsigned int k = 0; k < face_nodes; ++k)
            records.push_back(operators.M[i][k]);
      }
    return records;
  }



  void
  ContactProblem::add_operators(Pair                      &pair,
                                const std::vector<double> &mine) const
  {
    const MPI_Comm         comm = discretisation.dof_handler.get_communicator();
    constexpr unsigned int n_full = face_nodes * face_nodes;
    const unsigned int     n_d =
      pair.slave_weights() == SlaveWeights::full ? n_full : face_nodes;
    const std::size_t record = 2 + n_d + n_full;
    const auto        all    = Utilities::MPI::all_gather(comm, mine);
    std::size_t       before = 0;
    for (unsigned int r = 0; r < Utilities::MPI::this_mpi_process(comm); ++r)
      before += all[r].size() / record;
    for (std::size_t &k : pair.linearised_pairs)
      k = before + k / record;
    const ContactSurface &slave = pair.slave, &master = pair.master;
    for (const auto &data : all)
      for (std::size_t p = 0; p < data.size(); p += record)
        {
          const unsigned int f = data[p], c = data[p + 1];
          pair.overlaps.emplace_back(f, c);
          const double *D = &data[p + 2], *M = D + n_d;
          for (unsigned int i = 0; i < face_nodes; ++i)
            {
              const unsigned int j = slave.faces[f].nodes[i];
              for (unsigned int k = 0; k < face_nodes; ++k)
                {
                  if (n_d == n_full)
                    pair.D[j][slave.faces[f].nodes[k]] += D[face_nodes * i + k];
                  else if (k == i)
                    pair.D[j][j] += D[i];
                  pair.M[j][master.faces[c].nodes[k]] += M[face_nodes * i + k];
                }
            }
        }
  }



  void
  ContactProblem::integrate(Pair &pair, const bool derivatives)
  {
    const ContactSurface &slave = pair.slave, &master = pair.master;
    const unsigned int    n = slave.nodes.size();
    pair.D.assign(n, {});
    pair.M.assign(n, {});
    pair.aggregates.assign(n, NodalAggregates());
    pair.normal_length.assign(n, 0.);
    pair.nodal.assign(n, NodalContactState());
    pair.overlaps.clear();

    // Averaged nodal normals of the slave surface.
    pair.slave_faces.resize(slave.faces.size());
    std::vector<Tensor<1, dim>> normal_sum(n);
    for (unsigned int f = 0; f < slave.faces.size(); ++f)
      {
        pair.slave_faces[f] = slave.current_face(f);
        for (unsigned int i = 0; i < face_nodes; ++i)
          normal_sum[slave.faces[f].nodes[i]] +=
            pair.slave_faces[f].normal(ContactFace::node_parameter(i));
      }
    for (unsigned int j = 0; j < n; ++j)
      {
        pair.normal_length[j]     = normal_sum[j].norm();
        pair.aggregates[j].normal = normal_sum[j] / pair.normal_length[j];
      }

    // Segment-based D and M of every overlapping face pair: each rank
    // integrates an equal share, and all gather the operators (in their
    // order). Nothing is gained by giving the rank that owns the slave
    // nodes fewer: its condensation (condense()) starts after the gather.
    const auto near = search(pair, reach(pair));
    add_operators(
      pair, integrate_share(pair, close_face_pairs(pair, near), derivatives));

    // Aggregates.
    for (unsigned int j = 0; j < n; ++j)
      {
        NodalAggregates &a = pair.aggregates[j];
        for (const auto &[k, d] : pair.D[j])
          {
            // Semi-smooth Newton: D lumped to node j (the force side is,
            // contact_problem.h), so that the contact forces do no work
            // on the weighted gap and slip.
            const unsigned int node = pair.semi_smooth ? j : k;
            a.area += d;
            a.G -= d * slave.nodes[node].current;
            a.H += d * (slave.nodes[node].current - pair.slave_committed[node]);
          }
        for (const auto &[l, m] : pair.M[j])
          {
            a.G += m * master.nodes[l].current;
            a.H -= m * (master.nodes[l].current - pair.master_committed[l]);
          }
      }
    pair.folded_M.clear();
    if (pair.semi_smooth && pair.slave.has_hanging_nodes())
      fold_hanging_nodes(pair);
    // Kept until the next step: a missed pair widens its search.
    if (pair.missed.empty())
      pair.missed = missed_pair(pair, near);
  }



  void
  ContactProblem::fold_hanging_nodes(Pair &pair) const
  {
    const ContactSurface &slave = pair.slave;
    pair.folded_M               = pair.M;
    for (unsigned int h = 0; h < slave.nodes.size(); ++h)
      {
        if (slave.nodes[h].parents.empty())
          continue;
        NodalAggregates &a = pair.aggregates[h];
        for (const auto &[p, w] : slave.nodes[h].parents)
          {
            NodalAggregates &b = pair.aggregates[p];
            b.area += w * a.area;
            b.G += w * a.G;
            b.H += w * a.H;
            for (const auto &[l, m] : pair.M[h])
              pair.folded_M[p][l] += w * m;
          }
        a.area = 0.;
        a.G    = Tensor<1, dim>();
        a.H    = Tensor<1, dim>();
        pair.folded_M[h].clear();
      }
  }



  bool
  ContactProblem::Pair::carries_contact(const unsigned int j) const
  {
    // A node that only touches the overlap at its rim (or not at all)
    // carries no contact.
    // (The area is a length in 2-D.)
    if constexpr (dim == 3)
      return aggregates[j].area > 1e-10 * face_size * face_size;
    else
      return aggregates[j].area > 1e-10 * face_size;
  }



  void
  ContactProblem::apply_law(Pair &pair)
  {
    for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
      if (pair.carries_contact(j))
        pair.nodal[j] = nodal_contact(pair.aggregates[j],
                                      pair.multiplier[j],
                                      pair.committed_traction[j],
                                      pair.law);
    summarise(pair);
  }



  void
  ContactProblem::summarise(Pair &pair)
  {
    ContactPairSummary &summary = summaries[pair.index];
    summary                     = ContactPairSummary();
    summary.min_pressure        = std::numeric_limits<double>::max();
    pair.step_dissipation       = 0.;
    for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
      {
        if (!pair.carries_contact(j))
          continue;
        const NodalAggregates   &a     = pair.aggregates[j];
        const NodalContactState &state = pair.nodal[j];
        summary.max_penetration =
          std::max(summary.max_penetration, -state.gap / a.area);
        if (state.pressure > 0.)
          {
            summary.force += state.pressure * a.area * a.normal;
            summary.area += a.area;
            ++summary.active_nodes;
            summary.max_pressure =
              std::max(summary.max_pressure, state.pressure);
            summary.min_pressure =
              std::min(summary.min_pressure, state.pressure);
          }
        if (state.pressure > 0.)
          summary.max_slip = std::max(summary.max_slip, state.slip.norm());
        if (state.friction_state == 1)
          ++summary.sticking_nodes;
        if (state.friction_state == 2)
          ++summary.slipping_nodes;
        summary.friction_force += a.area * state.traction;
        pair.step_dissipation += state.dissipation;
      }
    if (summary.active_nodes == 0)
      summary.min_pressure = 0.;
    summary.dissipation = pair.dissipation + pair.step_dissipation;
  }



  void
  ContactProblem::assemble(const TrilinosWrappers::MPI::BlockVector &u,
                           const AffineConstraints<double> &constraints,
                           const AssemblyTargets           &targets)
  {
    AffineConstraints<double> all_constraints;
    extend_constraints(constraints, all_constraints);
    bool semi_smooth = false, penalty = false;
    for (Pair &pair : data)
      {
        pair.slave.update(u, discretisation);
        pair.master.update(u, discretisation);
        integrate(pair, targets.tangent != nullptr && pair.semi_smooth);
        semi_smooth = semi_smooth || pair.semi_smooth;
        if (!pair.semi_smooth)
          {
            penalty = true;
            apply_law(pair);
            assemble_penalty(pair, all_constraints, targets);
          }
      }
    // Without semi-smooth Newton the one compress of the assembly (the
    // bulk assembly leaves its terms to it: needs_compressed_bulk()). Each
    // compress costs ~8 ms per tangent on prm/two_bodies.prm, with or
    // without new entries.
    if (!semi_smooth)
      {
        compress(targets);
        return;
      }
    if (penalty)
      compress(targets);
    // The condensation reads the complete bulk rows of the slave nodes:
    // compressed, or complete where they are (slave_rows_complete_here()).
    for (Pair &pair : data)
      if (pair.semi_smooth)
        condense(pair, all_constraints, targets);
    compress(targets);
  }



  bool
  ContactProblem::augment()
  {
    bool done = true;
    for (unsigned int p = 0; p < data.size(); ++p)
      if (!data[p].semi_smooth &&
          summaries[p].max_penetration > data[p].tolerance)
        {
          done = false;
          for (unsigned int j = 0; j < data[p].nodal.size(); ++j)
            data[p].multiplier[j] = data[p].nodal[j].pressure;
        }
    return done;
  }



  void
  ContactProblem::commit()
  {
    for (Pair &pair : data)
      {
        for (unsigned int j = 0; j < pair.nodal.size(); ++j)
          {
            pair.committed_multiplier[j] = pair.nodal[j].pressure;
            pair.committed_traction[j]   = pair.nodal[j].traction;
          }
        pair.dissipation += pair.step_dissipation;
        pair.step_dissipation = 0.;
        for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
          pair.slave_committed[j] = pair.slave.nodes[j].current;
        for (unsigned int l = 0; l < pair.master.nodes.size(); ++l)
          pair.master_committed[l] = pair.master.nodes[l].current;
      }
  }



  void
  ContactProblem::write_output(const std::string &directory,
                               const OutputFormat format,
                               const unsigned int step,
                               const double       time)
  {
    for (unsigned int p = 0; p < data.size(); ++p)
      {
        const Pair      &pair = data[p];
        ContactNodalData nodal;
        nodal.surface = &pair.slave;
        for (unsigned int j = 0; j < pair.nodal.size(); ++j)
          {
            const NodalAggregates &a = pair.aggregates[j];
            nodal.pressure.push_back(pair.nodal[j].pressure);
            nodal.normal.push_back(a.normal);
            nodal.active.push_back(pair.nodal[j].active);
            nodal.slip.push_back(pair.nodal[j].slip);
            nodal.traction.push_back(pair.nodal[j].traction);
            nodal.friction_state.push_back(pair.nodal[j].friction_state);
            nodal.gap.push_back(a.area > 0. ? pair.nodal[j].gap / a.area : 0.);
          }
        // Before the first assembly (step 0) nothing is computed yet.
        const std::size_t n = pair.slave.nodes.size();
        nodal.pressure.resize(n, 0.);
        nodal.normal.resize(n);
        nodal.slip.resize(n);
        nodal.traction.resize(n);
        nodal.active.resize(n, false);
        nodal.friction_state.resize(n, 0);
        nodal.gap.resize(n, 0.);
        write_contact_surface(nodal,
                              directory,
                              "contact" + std::to_string(pairs[p].number),
                              step,
                              time,
                              format,
                              discretisation.dof_handler.get_communicator(),
                              output_records[p]);
      }
  }


  void
  ContactProblem::add_columns(Statistics &statistics) const
  {
    const char *xyz[] = {"x", "y", "z"};
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const ContactPairSummary &c = summaries[p];
        const std::string name = "contact" + std::to_string(pairs[p].number);
        for (unsigned int d = 0; d < dim; ++d)
          statistics.add(name + "_force_" + xyz[d], c.force[d]);
        statistics.add(name + "_area", c.area);
        statistics.add(name + "_active_nodes", c.active_nodes);
        statistics.add(name + "_max_penetration", c.max_penetration);
        statistics.add(name + "_max_pressure", c.max_pressure);
        statistics.add(name + "_min_pressure", c.min_pressure);
        for (unsigned int d = 0; d < dim; ++d)
          statistics.add(name + "_friction_" + xyz[d], c.friction_force[d]);
        statistics.add(name + "_sticking_nodes", c.sticking_nodes);
        statistics.add(name + "_slipping_nodes", c.slipping_nodes);
        statistics.add(name + "_max_slip", c.max_slip);
        statistics.add(name + "_dissipation", c.dissipation);
      }
  }
} // namespace DuctileContact
