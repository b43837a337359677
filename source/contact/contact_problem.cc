#include <deal.II/base/bounding_box.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/rtree.h>

#include <ductile_contact/contact/contact_problem.h>
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
    summaries.assign(pairs.size(), ContactPairSummary());
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
        const double mu    = body->second->shear_modulus;
        const double kappa = body->second->bulk_modulus;
        const double E     = 9. * kappa * mu / (3. * kappa + mu);
        const double h     = pair.slave.smallest_face_size();
        pair.penalty       = prm.penalty_factor * E / h;
        pair.face_size     = h;
        pair.tolerance     = prm.penetration_tolerance * h;
        pair.search_radius = prm.search_radius > 0.
                               ? prm.search_radius
                               : std::max(pair.slave.largest_face_size(),
                                          pair.master.largest_face_size());
        pair.candidates.assign(pair.slave.faces.size(), {});
        pair.multiplier.assign(pair.slave.nodes.size(), 0.);
        pair.committed_multiplier = pair.multiplier;
      }
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
    IndexSet dofs(discretisation.dof_handler.n_dofs());
    for (const Pair &pair : data)
      for (const ContactSurface *surface : {&pair.slave, &pair.master})
        for (const auto &node : surface->nodes)
          for (const auto d : node.dofs)
            dofs.add_index(d);
    dofs.compress();
    return dofs;
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
          constraints.add_entries_local_to_global(indices, sp, false);
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

    // Segment-based D and M.
    std::array<double, 9> ns, nm;
    for (unsigned int f = 0; f < slave.faces.size(); ++f)
      for (const unsigned int c : pair.candidates[f])
        {
          const Quad9 master_face = master.current_face(c);
          for (const MortarPoint &q :
               mortar_points(slave_faces[f], master_face))
            {
              Quad9::shape(q.slave, ns);
              Quad9::shape(q.master, nm);
              for (unsigned int i = 0; i < 9; ++i)
                {
                  const unsigned int j  = slave.faces[f].nodes[i];
                  const double       wj = q.weight * ns[i];
                  for (unsigned int k = 0; k < 9; ++k)
                    pair.D[j][slave.faces[f].nodes[k]] += wj * ns[k];
                  for (unsigned int l = 0; l < 9; ++l)
                    pair.M[j][master.faces[c].nodes[l]] += wj * nm[l];
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
  }



  void
  ContactProblem::assemble(const TrilinosWrappers::MPI::BlockVector &u,
                           const AffineConstraints<double> &constraints,
                           const AssemblyTargets           &targets)
  {
    FullMatrix<double>                   matrix;
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
            const double       k    = pair.penalty / pair.area[j];
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
            scatter(matrix,
                    rhs,
                    f_int,
                    indices,
                    constraints,
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
      pair.committed_multiplier = pair.pressure;
  }
} // namespace DuctileContact
