// The committed contact state in and out of a checkpoint
// (ContactProblem::committed_state(), restore_committed_state()) and across
// a mesh change (keep_committed_state(), transfer_committed_state()).
#include <ductile_contact/contact/contact_problem.h>
#include <ductile_contact/core/input_error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    constexpr unsigned int slave_record  = 2 * dim + 1 + dim;
    constexpr unsigned int master_record = 2 * dim;

    /// Finds the nodes of @p surface by reference position, within
    /// @p tolerance [m].
    class NodeLocator
    {
    public:
      NodeLocator(const ContactSurface &surface, const double tolerance)
          : surface(surface)
          , tolerance(tolerance)
      {
        order.resize(surface.nodes.size());
        for (unsigned int n = 0; n < order.size(); ++n)
          order[n] = n;
        std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
          return surface.nodes[a].reference[0] < surface.nodes[b].reference[0];
        });
      }

      /// The node at @p x, or -1.
      int
      find(const Point<dim> &x) const
      {
        auto it = std::lower_bound(order.begin(),
                                   order.end(),
                                   x[0] - tolerance,
                                   [&](const unsigned n, const double v) {
                                     return surface.nodes[n].reference[0] < v;
                                   });
        for (; it != order.end() &&
               surface.nodes[*it].reference[0] <= x[0] + tolerance;
             ++it)
          if (surface.nodes[*it].reference.distance(x) <= tolerance)
            return static_cast<int>(*it);
        return -1;
      }

    private:
      const ContactSurface     &surface;
      const double              tolerance;
      std::vector<unsigned int> order;
    };

    Point<dim>
    point_at(const double *p)
    {
      Point<dim> x;
      for (unsigned int c = 0; c < dim; ++c)
        x[c] = p[c];
      return x;
    }

    /// Face shape function values at the parameter point of @p surface's
    /// face that contains the reference point @p x (the face whose
    /// parameters lie farthest inside [0, 1]^(dim-1)); false if no face
    /// does.
    bool
    locate_on_faces(const ContactSurface           &surface,
                    const Point<dim>               &x,
                    unsigned int                   &face,
                    std::array<double, face_nodes> &shape)
    {
      // Slack for points a curved boundary description moved off the old
      // faces' quadratic geometry.
      constexpr double slack = 1e-6;
      double           best  = -std::numeric_limits<double>::max();
      for (unsigned int f = 0; f < surface.faces.size(); ++f)
        {
          ContactFace q;
          for (unsigned int n = 0; n < face_nodes; ++n)
            q.x[n] = surface.nodes[surface.faces[f].nodes[n]].reference;
          // The diagonal (3-D) or chord (2-D).
          const double size = q.x[0].distance(q.x[face_nodes - 1]);
          if (x.distance(q.x[ContactFace::centre_node]) > size)
            continue;
          FaceParameter xi;
          if (!q.project_along(
                x, q.normal(ContactFace::centre()), ContactFace::centre(), xi))
            continue;
          double inside = std::numeric_limits<double>::max();
          for (unsigned int k = 0; k + 1 < dim; ++k)
            inside = std::min({inside, xi[k], 1. - xi[k]});
          if (inside > best && inside > -slack &&
              q.position(xi).distance(x) < 1e-3 * size)
            {
              best = inside;
              face = f;
              ContactFace::shape(xi, shape);
            }
        }
      return best > -std::numeric_limits<double>::max();
    }
  } // namespace



  std::vector<double>
  ContactProblem::committed_state() const
  {
    std::vector<double> state;
    for (const Pair &pair : data)
      {
        state.push_back(pair.slave.nodes.size());
        for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
          {
            for (unsigned int d = 0; d < dim; ++d)
              state.push_back(pair.slave.nodes[j].reference[d]);
            for (unsigned int d = 0; d < dim; ++d)
              state.push_back(pair.slave_committed[j][d]);
            state.push_back(pair.committed_multiplier[j]);
            for (unsigned int d = 0; d < dim; ++d)
              state.push_back(pair.committed_traction[j][d]);
          }
        state.push_back(pair.master.nodes.size());
        for (unsigned int l = 0; l < pair.master.nodes.size(); ++l)
          {
            for (unsigned int d = 0; d < dim; ++d)
              state.push_back(pair.master.nodes[l].reference[d]);
            for (unsigned int d = 0; d < dim; ++d)
              state.push_back(pair.master_committed[l][d]);
          }
        state.push_back(pair.dissipation);
      }
    return state;
  }



  void
  ContactProblem::restore_committed_state(const std::vector<double> &state)
  {
    const auto mismatch = [](const std::string &what) {
      return InputError("the checkpoint's contact state does not fit the "
                        "contact surfaces of this run (" +
                        what + ")");
    };
    std::size_t pos  = 0;
    const auto  take = [&](const std::size_t n) {
      if (pos + n > state.size())
        throw mismatch("the record ends early");
      const double *p = state.data() + pos;
      pos += n;
      return p;
    };
    for (Pair &pair : data)
      {
        // Positions are compared to a millionth of the smallest face.
        const double tolerance = 1e-6 * pair.face_size;
        const auto   n_slave   = static_cast<std::size_t>(*take(1));
        if (n_slave != pair.slave.nodes.size())
          throw mismatch(std::to_string(n_slave) + " slave nodes saved, " +
                         std::to_string(pair.slave.nodes.size()) + " here");
        const NodeLocator slaves(pair.slave, tolerance);
        for (std::size_t k = 0; k < n_slave; ++k)
          {
            const double *r = take(slave_record);
            const int     j = slaves.find(point_at(r));
            if (j < 0)
              throw mismatch("a slave node moved");
            pair.slave_committed[j]      = point_at(r + dim);
            pair.committed_multiplier[j] = r[2 * dim];
            for (unsigned int d = 0; d < dim; ++d)
              pair.committed_traction[j][d] = r[2 * dim + 1 + d];
          }
        const auto n_master = static_cast<std::size_t>(*take(1));
        if (n_master != pair.master.nodes.size())
          throw mismatch(std::to_string(n_master) + " master nodes saved, " +
                         std::to_string(pair.master.nodes.size()) + " here");
        const NodeLocator masters(pair.master, tolerance);
        for (std::size_t k = 0; k < n_master; ++k)
          {
            const double *r = take(master_record);
            const int     l = masters.find(point_at(r));
            if (l < 0)
              throw mismatch("a master node moved");
            pair.master_committed[l] = point_at(r + dim);
          }
        pair.dissipation      = *take(1);
        pair.step_dissipation = 0.;
        pair.multiplier       = pair.committed_multiplier;
      }
    if (pos != state.size())
      throw mismatch("records left over");
  }



  void
  ContactProblem::keep_committed_state()
  {
    kept = data;
  }



  void
  ContactProblem::transfer_committed_state(
    const TrilinosWrappers::MPI::BlockVector &accepted)
  {
    AssertDimension(kept.size(), data.size());
    for (Pair &pair : data)
      {
        const Pair &old = kept[pair.index];
        pair.slave.update(accepted, discretisation);
        pair.master.update(accepted, discretisation);
        for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
          pair.slave_committed[j] = pair.slave.nodes[j].current;
        for (unsigned int l = 0; l < pair.master.nodes.size(); ++l)
          pair.master_committed[l] = pair.master.nodes[l].current;

        const NodeLocator old_nodes(old.slave, 1e-6 * old.face_size);
        for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
          {
            const Point<dim> &x = pair.slave.nodes[j].reference;
            const int         k = old_nodes.find(x);
            if (k >= 0)
              {
                pair.committed_multiplier[j] = old.committed_multiplier[k];
                pair.committed_traction[j]   = old.committed_traction[k];
                continue;
              }
            unsigned int                   f = 0;
            std::array<double, face_nodes> N;
            if (!locate_on_faces(old.slave, x, f, N))
              throw std::logic_error("transfer_committed_state: a new slave "
                                     "node lies on no old slave face");
            pair.committed_multiplier[j] = 0.;
            pair.committed_traction[j]   = Tensor<1, dim>();
            for (unsigned int n = 0; n < face_nodes; ++n)
              {
                const unsigned int node = old.slave.faces[f].nodes[n];
                pair.committed_multiplier[j] +=
                  N[n] * old.committed_multiplier[node];
                pair.committed_traction[j] +=
                  N[n] * old.committed_traction[node];
              }
            // Quadratic shape functions dip below zero inside a face.
            pair.committed_multiplier[j] =
              std::max(0., pair.committed_multiplier[j]);
          }
        pair.multiplier       = pair.committed_multiplier;
        pair.dissipation      = old.dissipation;
        pair.step_dissipation = 0.;
      }
    kept.clear();
  }



  void
  ContactProblem::add_committed_forces(
    const TrilinosWrappers::MPI::BlockVector &u,
    TrilinosWrappers::MPI::BlockVector       &force)
  {
    for (Pair &pair : data)
      {
        // D, M and the normals on the geometry of u, with candidates of
        // their own: every master face within reach (the step's search
        // comes later and decides the sparsity pattern).
        pair.slave.update(u, discretisation);
        pair.master.update(u, discretisation);
        std::vector<std::vector<unsigned int>> step_candidates =
          std::move(pair.candidates);
        pair.candidates = search(pair, reach(pair));
        integrate(pair, false);
        pair.candidates = std::move(step_candidates);

        const auto &dofs    = discretisation.locally_owned_dofs;
        const auto &hanging = discretisation.hanging_node_constraints;
        for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
          {
            if (!pair.carries_contact(j) ||
                !dofs.is_element(pair.slave.nodes[j].dofs[0]))
              continue;
            const Tensor<1, dim> f =
              pair.committed_multiplier[j] * pair.aggregates[j].normal +
              pair.committed_traction[j];
            // As the assembly adds them: D_jk f_j on slave node k (D lumped
            // to node j by a condensing enforcement), -M_jl f_j on master
            // node l.
            std::map<unsigned int, double> slave_weights;
            if (pair.condenses())
              slave_weights[j] = pair.aggregates[j].area;
            else
              slave_weights = pair.D[j];
            Vector<double>                       values;
            std::vector<types::global_dof_index> indices;
            for (const auto &[k, d] : slave_weights)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  indices.push_back(pair.slave.nodes[k].dofs[c]);
                  values.grow_or_shrink(values.size() + 1);
                  values[values.size() - 1] = d * f[c];
                }
            for (const auto &[l, m] : pair.master_row(j))
              for (unsigned int c = 0; c < dim; ++c)
                {
                  indices.push_back(pair.master.nodes[l].dofs[c]);
                  values.grow_or_shrink(values.size() + 1);
                  values[values.size() - 1] = -m * f[c];
                }
            hanging.distribute_local_to_global(values, indices, force);
          }
      }
    force.compress(VectorOperation::add);
  }
} // namespace DuctileContact
