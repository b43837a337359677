#include <deal.II/base/bounding_box.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/rtree.h>

#include <ductile_contact/contact/contact_problem.h>
#include <ductile_contact/contact/contact_writer.h>
#include <ductile_contact/contact/mortar_segments.h>
#include <ductile_contact/core/input_error.h>
#include <ductile_contact/solver/scatter.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /**
     * Coefficients a_ik of the dual (biorthogonal) basis Phi_i = sum_k a_ik
     * N_k of a quad9 face (Wohlmuth 2000): int Phi_i N_k dA = delta_ik int
     * N_k dA over the face, i.e. A = D_e M_e^-1 with the face's mass matrix
     * M_e and D_e = diag(int N_i dA) (positive for quad9, so no basis
     * transformation is needed). sum_i Phi_i = 1, so uniform pressures
     * are still represented exactly.
     */
    FullMatrix<double>
    dual_basis(const Quad9 &face)
    {
      const QGauss<2>       gauss(4);
      FullMatrix<double>    mass(9, 9), coefficients(9, 9);
      Vector<double>        lumped(9);
      std::array<double, 9> n;
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const auto   t = face.tangents(gauss.point(q));
          const double dA =
            cross_product_3d(t[0], t[1]).norm() * gauss.weight(q);
          Quad9::shape(gauss.point(q), n);
          for (unsigned int i = 0; i < 9; ++i)
            {
              lumped[i] += n[i] * dA;
              for (unsigned int k = 0; k < 9; ++k)
                mass(i, k) += n[i] * n[k] * dA;
            }
        }
      mass.gauss_jordan();
      for (unsigned int i = 0; i < 9; ++i)
        for (unsigned int k = 0; k < 9; ++k)
          coefficients(i, k) = lumped[i] * mass(i, k);
      return coefficients;
    }



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

        // eps_N = factor E / h for the slave body.
        const auto body = bodies.find(pair.slave.faces[0].material_id);
        Assert(body != bodies.end(), ExcInternalError());
        const double mu         = body->second->shear_modulus;
        const double kappa      = body->second->bulk_modulus;
        const double E          = 9. * kappa * mu / (3. * kappa + mu);
        const double h          = pair.slave.smallest_face_size();
        pair.penalty            = prm.penalty_factor * E / h;
        pair.friction           = prm.friction_coefficient;
        pair.tangential_penalty = prm.tangential_penalty_factor * E / h;
        pair.face_size          = h;
        pair.tolerance          = prm.penetration_tolerance * h;
        pair.search_radius      = prm.search_radius > 0.
                                    ? prm.search_radius
                                    : std::max(pair.slave.largest_face_size(),
                                          pair.master.largest_face_size());
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

        std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes;
        for (unsigned int m = 0; m < pair.master.faces.size(); ++m)
          boxes.emplace_back(face_box(pair.master, m, 0.), m);
        const auto tree = pack_rtree(boxes);

        std::vector<std::vector<unsigned int>> candidates(
          pair.slave.faces.size());
        for (unsigned int s = 0; s < pair.slave.faces.size(); ++s)
          {
            std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
            tree.query(boost::geometry::index::intersects(
                         face_box(pair.slave, s, pair.search_radius)),
                       std::back_inserter(hits));
            for (const auto &hit : hits)
              candidates[s].push_back(hit.second);
            std::sort(candidates[s].begin(), candidates[s].end());
          }
        if (candidates != pair.candidates)
          {
            changed         = true;
            pair.candidates = std::move(candidates);
          }
      }
    return changed;
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



  void
  ContactProblem::coupled_nodes(const Pair                &pair,
                                const unsigned int         j,
                                std::vector<unsigned int> &slave_nodes,
                                std::vector<unsigned int> &master_nodes) const
  {
    std::set<unsigned int> s, m;
    for (const unsigned int f : pair.slave.node_faces[j])
      {
        s.insert(pair.slave.faces[f].nodes.begin(),
                 pair.slave.faces[f].nodes.end());
        for (const unsigned int c : pair.candidates[f])
          m.insert(pair.master.faces[c].nodes.begin(),
                   pair.master.faces[c].nodes.end());
      }
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
    for (const Pair &pair : data)
      for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
        {
          if (!discretisation.locally_owned_dofs.is_element(
                pair.slave.nodes[j].dofs[0]))
            continue;
          coupled_nodes(pair, j, s, m);
          indices.clear();
          for (const unsigned int k : s)
            indices.insert(indices.end(),
                           pair.slave.nodes[k].dofs.begin(),
                           pair.slave.nodes[k].dofs.end());
          for (const unsigned int l : m)
            indices.insert(indices.end(),
                           pair.master.nodes[l].dofs.begin(),
                           pair.master.nodes[l].dofs.end());
          all_constraints.add_entries_local_to_global(indices, sp, false);
        }
  }



  void
  ContactProblem::integrate(Pair &pair)
  {
    const ContactSurface &slave = pair.slave, &master = pair.master;
    const unsigned int    n = slave.nodes.size();
    pair.D.assign(n, {});
    pair.M.assign(n, {});
    pair.normal.assign(n, Tensor<1, dim>());
    pair.area.assign(n, 0.);
    pair.gap.assign(n, 0.);
    pair.pressure.assign(n, 0.);
    pair.active.assign(n, false);

    // Averaged nodal normals of the slave surface.
    std::vector<Quad9> slave_faces(slave.faces.size());
    for (unsigned int f = 0; f < slave.faces.size(); ++f)
      {
        slave_faces[f] = slave.current_face(f);
        for (unsigned int i = 0; i < 9; ++i)
          pair.normal[slave.faces[f].nodes[i]] +=
            slave_faces[f].normal(Quad9::node_parameter(i));
      }
    for (auto &normal : pair.normal)
      normal /= normal.norm();

    // Segment-based D and M with the multiplier basis Phi of each face.
    const bool dual = pairs[&pair - data.data()].multiplier_basis == "dual";
    std::array<double, 9> ns, nm, phi;
    FullMatrix<double>    dual_coefficients;
    for (unsigned int f = 0; f < slave.faces.size(); ++f)
      {
        if (pair.candidates[f].empty())
          continue;
        if (dual)
          dual_coefficients = dual_basis(slave_faces[f]);
        // Exact check first: only candidates whose current box comes within
        // half a slave face of this face's box can overlap it (an open gap
        // wider than that is not in contact in any case).
        const auto slave_box =
          face_box(slave, f, 0.5 * pair.face_size).get_boundary_points();
        for (const unsigned int c : pair.candidates[f])
          {
            const auto master_box =
              face_box(master, c, 0.).get_boundary_points();
            bool apart = false;
            for (unsigned int d = 0; d < dim; ++d)
              apart = apart || slave_box.first[d] > master_box.second[d] ||
                      master_box.first[d] > slave_box.second[d];
            if (apart)
              continue;
            const Quad9                    master_face = master.current_face(c);
            const std::vector<MortarPoint> points =
              mortar_points(slave_faces[f], master_face);
            if (points.empty())
              continue;
            // This pair's D and M, added to the nodal rows once.
            std::array<std::array<double, 9>, 9> D_pair{}, M_pair{};
            for (const MortarPoint &q : points)
              {
                Quad9::shape(q.slave, ns);
                Quad9::shape(q.master, nm);
                for (unsigned int i = 0; i < 9; ++i)
                  {
                    phi[i] = dual ? 0. : ns[i];
                    if (dual)
                      for (unsigned int k = 0; k < 9; ++k)
                        phi[i] += dual_coefficients(i, k) * ns[k];
                  }
                for (unsigned int i = 0; i < 9; ++i)
                  {
                    const double wj = q.weight * phi[i];
                    for (unsigned int k = 0; k < 9; ++k)
                      {
                        D_pair[i][k] += wj * ns[k];
                        M_pair[i][k] += wj * nm[k];
                      }
                  }
              }
            for (unsigned int i = 0; i < 9; ++i)
              {
                const unsigned int j = slave.faces[f].nodes[i];
                for (unsigned int k = 0; k < 9; ++k)
                  {
                    pair.D[j][slave.faces[f].nodes[k]] += D_pair[i][k];
                    pair.M[j][master.faces[c].nodes[k]] += M_pair[i][k];
                  }
              }
          }
      }

    // Weighted gaps and multipliers.
    ContactPairSummary &summary = summaries[&pair - data.data()];
    summary                     = ContactPairSummary();
    summary.min_pressure        = std::numeric_limits<double>::max();
    for (unsigned int j = 0; j < n; ++j)
      {
        double         A = 0;
        Tensor<1, dim> x;
        for (const auto &[k, d] : pair.D[j])
          {
            A += d;
            x -= d * slave.nodes[k].current;
          }
        for (const auto &[l, m] : pair.M[j])
          x += m * master.nodes[l].current;
        pair.area[j] = A;
        // A node that only touches the overlap at its rim (or not at all)
        // carries no contact.
        if (!(A > 1e-10 * pair.face_size * pair.face_size))
          continue;
        pair.gap[j] = pair.normal[j] * x;
        const double trial =
          pair.multiplier[j] - pair.penalty * pair.gap[j] / A;
        pair.pressure[j] = std::max(0., trial);
        // Active also when just touching (a gap at round-off level): then
        // the tangent holds the contact stiffness of a closed interface, so
        // that bodies which only touch at the start are not free.
        pair.active[j] = trial > -1e-12 * pair.penalty * pair.face_size;
        summary.max_penetration =
          std::max(summary.max_penetration, -pair.gap[j] / A);
        if (pair.pressure[j] > 0.)
          {
            summary.force += pair.pressure[j] * A * pair.normal[j];
            summary.area += A;
            ++summary.active_nodes;
            summary.max_pressure =
              std::max(summary.max_pressure, pair.pressure[j]);
            summary.min_pressure =
              std::min(summary.min_pressure, pair.pressure[j]);
          }
      }
    if (summary.active_nodes == 0)
      summary.min_pressure = 0.;

    // Coulomb friction (48) at the nodes that carry pressure.
    pair.traction.assign(n, Tensor<1, dim>());
    pair.trial_traction.assign(n, Tensor<1, dim>());
    pair.friction_state.assign(n, 0);
    pair.step_dissipation = 0.;
    if (pair.friction > 0.)
      for (unsigned int j = 0; j < n; ++j)
        {
          if (!(pair.pressure[j] > 0.))
            continue;
          const double         A = pair.area[j];
          const Tensor<2, dim> T =
            unit_symmetric_tensor<dim>() -
            outer_product(pair.normal[j], pair.normal[j]);
          Tensor<1, dim> du;
          for (const auto &[k, d] : pair.D[j])
            du += d * (slave.nodes[k].current - pair.slave_committed[k]);
          for (const auto &[l, m] : pair.M[j])
            du -= m * (master.nodes[l].current - pair.master_committed[l]);
          // Slip increment of the slave relative to the master [m].
          const Tensor<1, dim> slip = T * du / A;
          // Accepted traction, rotated into the current tangent plane.
          Tensor<1, dim> old = T * pair.committed_traction[j];
          if (old.norm() > 0.)
            old *= pair.committed_traction[j].norm() / old.norm();
          const Tensor<1, dim> trial = old + pair.tangential_penalty * slip;
          const double         limit = pair.friction * pair.pressure[j];
          pair.trial_traction[j]     = trial;
          if (trial.norm() <= limit)
            {
              pair.traction[j]       = trial;
              pair.friction_state[j] = 1;
              ++summary.sticking_nodes;
            }
          else
            {
              pair.traction[j]       = limit / trial.norm() * trial;
              pair.friction_state[j] = 2;
              ++summary.slipping_nodes;
            }
          // (47): the traction times the slip that is not elastic.
          pair.step_dissipation +=
            A * pair.traction[j] *
            (slip - (pair.traction[j] - old) / pair.tangential_penalty);
          summary.friction_force += A * pair.traction[j];
        }
    summary.dissipation = pair.dissipation + pair.step_dissipation;
  }



  void
  ContactProblem::assemble(const TrilinosWrappers::MPI::BlockVector &u,
                           const AffineConstraints<double> &constraints,
                           const AssemblyTargets           &targets)
  {
    AffineConstraints<double> all_constraints;
    extend_constraints(constraints, all_constraints);
    FullMatrix<double>                   matrix, b, dt;
    Vector<double>                       rhs, f_int;
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  a;
    for (Pair &pair : data)
      {
        pair.slave.update(u, discretisation);
        pair.master.update(u, discretisation);
        integrate(pair);

        for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
          {
            if (!pair.active[j] ||
                !discretisation.locally_owned_dofs.is_element(
                  pair.slave.nodes[j].dofs[0]))
              continue;
            // a_j = dg_j/dx with D, M and n_j fixed.
            const Tensor<1, dim> &n = pair.normal[j];
            indices.clear();
            a.clear();
            for (const auto &[k, d] : pair.D[j])
              for (unsigned int c = 0; c < dim; ++c)
                {
                  indices.push_back(pair.slave.nodes[k].dofs[c]);
                  a.push_back(-d * n[c]);
                }
            for (const auto &[l, m] : pair.M[j])
              for (unsigned int c = 0; c < dim; ++c)
                {
                  indices.push_back(pair.master.nodes[l].dofs[c]);
                  a.push_back(m * n[c]);
                }
            const unsigned int size = indices.size();
            const double       A    = pair.area[j];
            const double       k    = pair.penalty / A;
            matrix.reinit(size, size);
            rhs.reinit(size);
            f_int.reinit(size);
            for (unsigned int r = 0; r < size; ++r)
              {
                rhs[r]   = pair.pressure[j] * a[r];
                f_int[r] = -pair.pressure[j] * a[r];
                for (unsigned int c = 0; c < size; ++c)
                  matrix(r, c) = k * a[r] * a[c];
              }
            if (pair.friction_state[j] > 0)
              {
                // Friction: R += A_j b_j^T t_j with b_j = ds_j/dx (D, M,
                // n_j fixed); dt/dx = eps_T b (stick) or mu (t/|t|) dlambda
                // /dx + mu lambda eps_T / |t_trial| (I - t t/|t|^2) b
                // (slip, not symmetric).
                const Tensor<2, dim> T =
                  unit_symmetric_tensor<dim>() - outer_product(n, n);
                b.reinit(dim, size);
                unsigned int col = 0;
                for (const auto &[k_node, d] : pair.D[j])
                  for (unsigned int c = 0; c < dim; ++c, ++col)
                    for (unsigned int i = 0; i < dim; ++i)
                      b(i, col) = T[i][c] * d / A;
                for (const auto &[l_node, m] : pair.M[j])
                  for (unsigned int c = 0; c < dim; ++c, ++col)
                    for (unsigned int i = 0; i < dim; ++i)
                      b(i, col) = -T[i][c] * m / A;
                dt.reinit(dim, size);
                const Tensor<1, dim> &t = pair.traction[j];
                if (pair.friction_state[j] == 1)
                  for (unsigned int i = 0; i < dim; ++i)
                    for (unsigned int c = 0; c < size; ++c)
                      dt(i, c) = pair.tangential_penalty * b(i, c);
                else
                  {
                    const Tensor<1, dim> &trial = pair.trial_traction[j];
                    const Tensor<1, dim>  dir   = trial / trial.norm();
                    const double scale = pair.friction * pair.pressure[j] *
                                         pair.tangential_penalty / trial.norm();
                    for (unsigned int i = 0; i < dim; ++i)
                      for (unsigned int c = 0; c < size; ++c)
                        {
                          double v = -pair.friction * dir[i] * k * a[c];
                          for (unsigned int m = 0; m < dim; ++m)
                            v += scale *
                                 ((i == m ? 1. : 0.) - dir[i] * dir[m]) *
                                 b(m, c);
                          dt(i, c) = v;
                        }
                  }
                for (unsigned int r = 0; r < size; ++r)
                  {
                    double force = 0;
                    for (unsigned int i = 0; i < dim; ++i)
                      force += A * b(i, r) * t[i];
                    rhs[r] -= force;
                    f_int[r] += force;
                    for (unsigned int c = 0; c < size; ++c)
                      for (unsigned int i = 0; i < dim; ++i)
                        matrix(r, c) += A * b(i, r) * dt(i, c);
                  }
              }
            scatter(matrix,
                    rhs,
                    f_int,
                    indices,
                    all_constraints,
                    discretisation.hanging_node_constraints,
                    targets);
          }
      }
    if (targets.tangent)
      targets.tangent->compress(VectorOperation::add);
    for (auto *v :
         {targets.newton_rhs, targets.residual, targets.internal_force})
      if (v)
        v->compress(VectorOperation::add);
  }



  bool
  ContactProblem::augment()
  {
    bool done = true;
    for (unsigned int p = 0; p < data.size(); ++p)
      if (summaries[p].max_penetration > data[p].tolerance)
        {
          done               = false;
          data[p].multiplier = data[p].pressure;
        }
    return done;
  }



  void
  ContactProblem::commit()
  {
    for (Pair &pair : data)
      {
        pair.committed_multiplier = pair.pressure;
        pair.committed_traction   = pair.traction;
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
                               const unsigned int step,
                               const double       time)
  {
    if (Utilities::MPI::this_mpi_process(
          discretisation.dof_handler.get_communicator()) != 0)
      return;
    for (unsigned int p = 0; p < data.size(); ++p)
      {
        const Pair      &pair = data[p];
        ContactNodalData nodal;
        nodal.surface  = &pair.slave;
        nodal.pressure = pair.pressure;
        nodal.normal   = pair.normal;
        nodal.active   = pair.active;
        nodal.gap.resize(pair.gap.size());
        for (unsigned int j = 0; j < pair.gap.size(); ++j)
          nodal.gap[j] = pair.area[j] > 0. ? pair.gap[j] / pair.area[j] : 0.;
        // Before the first assembly (step 0) nothing is computed yet.
        const std::size_t n = pair.slave.nodes.size();
        nodal.pressure.resize(n, 0.);
        nodal.normal.resize(n);
        nodal.active.resize(n, false);
        nodal.gap.resize(n, 0.);
        write_contact_surface(nodal,
                              directory,
                              "contact" + std::to_string(pairs[p].number),
                              step,
                              time,
                              output_records[p]);
      }
  }
} // namespace DuctileContact
