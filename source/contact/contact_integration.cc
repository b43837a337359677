// ContactProblem: mortar integration of the face pairs into the nodal
// operators, the hanging slave nodes folded into their parents, the nodal
// contact law and the pair summaries.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/contact/contact_problem.h>
#include <ductile_contact/contact/mortar_operators.h>
#include <ductile_contact/contact/mortar_segments.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace DuctileContact
{
  using namespace dealii;



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
    // nodes fewer: its condensation starts after the gather.
    const auto near = search(pair, reach(pair));
    add_operators(
      pair, integrate_share(pair, close_face_pairs(pair, near), derivatives));

    // Aggregates.
    const bool lumped = pair.slave_weights() == SlaveWeights::lumped;
    for (unsigned int j = 0; j < n; ++j)
      {
        NodalAggregates &a = pair.aggregates[j];
        for (const auto &[k, d] : pair.D[j])
          {
            // A condensing enforcement: D lumped to node j (the force side
            // is, semi_smooth_newton.h), so that the contact forces do no
            // work on the weighted gap and slip.
            const unsigned int node = lumped ? j : k;
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
    if (pair.condenses() && pair.slave.has_hanging_nodes())
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
  ContactPair::carries_contact(const unsigned int j) const
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

} // namespace DuctileContact
