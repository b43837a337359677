// The committed contact state in and out of a checkpoint
// (ContactProblem::committed_state(), restore_committed_state()).
#include <ductile_contact/contact/contact_problem.h>
#include <ductile_contact/core/input_error.h>

#include <algorithm>
#include <cmath>

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
      return Point<dim>(p[0], p[1], p[2]);
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
} // namespace DuctileContact
