#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/assembly/scatter.h>
#include <ductile_contact/contact/contact_problem.h>
#include <ductile_contact/contact/mortar_operators.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

// The tangent of the mortar contact rows (doc/contact.md): the
// linearisation of D, M and the weighted gaps by automatic
// differentiation, the direct gradients of the nodal law, and the rows of
// the augmented-Lagrangian (penalty) enforcement.
namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    using Gradients =
      std::vector<std::map<unsigned int, std::array<double, 10>>>;

    /// The slave nodes each rank needs, their union and the complete forces
    /// on them (a force is summed from the ranks that own its node or, at
    /// a hanging node, its parents).
    struct SharedNeeds
    {
      std::vector<std::vector<unsigned int>> of_rank;
      std::vector<bool>                      any;
      std::vector<Tensor<1, dim>>            forces;
    };

    SharedNeeds
    share_needs(const std::vector<bool>           &needed,
                const std::vector<Tensor<1, dim>> &forces,
                const MPI_Comm                     comm)
    {
      const unsigned int        ns = needed.size();
      std::vector<unsigned int> mine;
      std::vector<double>       sums(dim * ns, 0.);
      for (unsigned int j = 0; j < ns; ++j)
        if (needed[j])
          {
            mine.push_back(j);
            for (unsigned int c = 0; c < dim; ++c)
              sums[dim * j + c] = forces[j][c];
          }
      SharedNeeds shared;
      shared.of_rank = Utilities::MPI::all_gather(comm, mine);
      Utilities::MPI::sum(sums, comm, sums);
      shared.any.assign(ns, false);
      shared.forces.resize(ns);
      for (const auto &list : shared.of_rank)
        for (const unsigned int j : list)
          shared.any[j] = true;
      for (unsigned int j = 0; j < ns; ++j)
        for (unsigned int c = 0; c < dim; ++c)
          shared.forces[j][c] = sums[dim * j + c];
      return shared;
    }

    /// Sends the partial gradients of the nodes other ranks need to them,
    /// drops those this rank does not need (@p needed) and adds what the
    /// others computed for its own.
    void
    exchange_gradients(const SharedNeeds       &shared,
                       const std::vector<bool> &needed,
                       const MPI_Comm           comm,
                       Gradients               &gradients)
    {
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      // Per node: j, the number of entries, then per entry its key and
      // the ten derivatives.
      std::map<unsigned int, std::vector<double>> outgoing;
      for (unsigned int q = 0; q < shared.of_rank.size(); ++q)
        if (q != rank)
          for (const unsigned int j : shared.of_rank[q])
            if (!gradients[j].empty())
              {
                auto &data = outgoing[q];
                data.push_back(j);
                data.push_back(gradients[j].size());
                for (const auto &[key, e] : gradients[j])
                  {
                    data.push_back(key);
                    data.insert(data.end(), e.begin(), e.end());
                  }
              }
      const auto incoming = Utilities::MPI::some_to_some(comm, outgoing);
      for (unsigned int j = 0; j < needed.size(); ++j)
        if (!needed[j])
          gradients[j].clear();
      for (const auto &[q, data] : incoming)
        for (std::size_t i = 0; i < data.size();)
          {
            auto             &g = gradients[static_cast<unsigned int>(data[i])];
            const std::size_t n = static_cast<std::size_t>(data[i + 1]);
            i += 2;
            for (std::size_t e = 0; e < n; ++e, i += 11)
              {
                auto &target = g[static_cast<unsigned int>(data[i])];
                for (unsigned int a = 0; a < 10; ++a)
                  target[a] += data[i + 1 + a];
              }
          }
    }
  } // namespace



  std::pair<std::size_t, std::size_t>
  ContactProblem::face_pair_share(const Pair              &pair,
                                  const std::vector<bool> &any,
                                  const MPI_Comm           comm)
  {
    std::vector<std::size_t> touching;
    for (std::size_t i = 0; i < pair.overlaps.size(); ++i)
      {
        const auto &nodes = pair.slave.faces[pair.overlaps[i].first].nodes;
        if (std::any_of(nodes.begin(), nodes.end(), [&](const unsigned int j) {
              return any[j];
            }))
          touching.push_back(i);
      }
    const auto [begin, end] = share(touching.size(), comm);
    if (begin == end)
      return {0, 0};
    return {touching[begin], touching[end - 1] + 1};
  }



  std::pair<std::size_t, std::size_t>
  ContactProblem::share(const std::size_t n_items, const MPI_Comm comm)
  {
    const std::size_t rank    = Utilities::MPI::this_mpi_process(comm);
    const std::size_t n_ranks = Utilities::MPI::n_mpi_processes(comm);
    return {n_items * rank / n_ranks, n_items * (rank + 1) / n_ranks};
  }



  std::vector<bool>
  ContactProblem::linearise_operators(
    const Pair                        &pair,
    const std::vector<bool>           &needed,
    const std::vector<Tensor<1, dim>> &forces,
    const bool                         slave_rows,
    const GradientShare                kept,
    const AffineConstraints<double>   &constraints,
    const AssemblyTargets             &targets,
    Gradients                         &gradients) const
  {
    Assert(!pair.linearised_here || kept == GradientShare::partial,
           ExcInternalError());
    const MPI_Comm comm = discretisation.dof_handler.get_communicator();
    const bool     one  = Utilities::MPI::n_mpi_processes(comm) == 1;
    // Every rank integrates a share of the face pairs that any rank needs,
    // whichever rank owns their nodes.
    SharedNeeds shared;
    if (!one)
      shared = share_needs(needed, forces, comm);
    const std::vector<bool>           &any = one ? needed : shared.any;
    const std::vector<Tensor<1, dim>> &all = one ? forces : shared.forces;
    if (pair.linearised_here)
      for (std::size_t k = 0; k < pair.linearised_pairs.size(); ++k)
        add_face_pair_terms(pair,
                            pair.linearised_pairs[k],
                            pair.linearised_operators[k],
                            any,
                            all,
                            slave_rows,
                            constraints,
                            targets,
                            gradients);
    else
      integrate_face_pairs(pair,
                           any,
                           all,
                           slave_rows,
                           one ? std::make_pair(std::size_t(0),
                                                pair.overlaps.size())
                               : face_pair_share(pair, any, comm),
                           constraints,
                           targets,
                           gradients);
    if (one || kept == GradientShare::partial)
      return any;
    exchange_gradients(shared, needed, comm, gradients);
    return needed;
  }



  void
  ContactProblem::integrate_face_pairs(
    const Pair                                                  &pair,
    const std::vector<bool>                                     &needed,
    const std::vector<Tensor<1, dim>>                           &forces,
    const bool                                                   slave_rows,
    const std::pair<std::size_t, std::size_t>                   &range,
    const AffineConstraints<double>                             &constraints,
    const AssemblyTargets                                       &targets,
    std::vector<std::map<unsigned int, std::array<double, 10>>> &gradients)
    const
  {
    const auto operators = std::make_unique<FacePairOperators>();
    std::unique_ptr<MortarFace> face;
    unsigned int                face_index = numbers::invalid_unsigned_int;
    for (std::size_t i = range.first; i < range.second; ++i)
      {
        const auto [f, c]   = pair.overlaps[i];
        const auto &s_nodes = pair.slave.faces[f].nodes;
        if (std::none_of(s_nodes.begin(),
                         s_nodes.end(),
                         [&](const unsigned int j) { return needed[j]; }))
          continue;
        if (f != face_index)
          {
            face       = std::make_unique<MortarFace>(pair.slave_faces[f],
                                                pair.dual,
                                                pair.slave_weights());
            face_index = f;
          }
        face->integrate(pair.master.current_face(c), *operators, true);
        add_face_pair_terms(pair,
                            i,
                            *operators,
                            needed,
                            forces,
                            slave_rows,
                            constraints,
                            targets,
                            gradients);
      }
  }



  void
  ContactProblem::add_face_pair_terms(
    const Pair                                                  &pair,
    const std::size_t                                            overlap,
    const FacePairOperators                                     &operators,
    const std::vector<bool>                                     &needed,
    const std::vector<Tensor<1, dim>>                           &forces,
    const bool                                                   slave_rows,
    const AffineConstraints<double>                             &constraints,
    const AssemblyTargets                                       &targets,
    std::vector<std::map<unsigned int, std::array<double, 10>>> &gradients)
    const
  {
    const ContactSurface  &slave = pair.slave, &master = pair.master;
    const unsigned int     ns            = slave.nodes.size();
    constexpr unsigned int n_coordinates = face_pair_coordinates;
    const auto [f, c]                    = pair.overlaps[overlap];
    const auto &s_nodes                  = slave.faces[f].nodes;
    const auto &m_nodes                  = master.faces[c].nodes;
    if (std::none_of(s_nodes.begin(), s_nodes.end(), [&](const unsigned int j) {
          return needed[j];
        }))
      return;
    const bool         lumped = pair.slave_weights() == SlaveWeights::lumped;
    FullMatrix<double> matrix(n_coordinates, n_coordinates);
    Vector<double>     rhs(n_coordinates), f_int(n_coordinates);
    std::vector<types::global_dof_index>    indices(n_coordinates);
    std::array<unsigned int, n_coordinates> keys;
    for (unsigned int a = 0; a < n_coordinates; ++a)
      {
        // AD direction a: slave (dim i + c), then master coordinates; the
        // keys number node coordinates with stride 3 in either build.
        keys[a] =
          a < face_coordinates
            ? 3 * s_nodes[a / dim] + a % dim
            : 3 * (ns + m_nodes[(a - face_coordinates) / dim]) + a % dim;
        indices[a] = coordinate_dof(pair, keys[a]);
      }
    matrix = 0.;
    for (unsigned int i = 0; i < face_nodes; ++i)
      {
        const unsigned int j = s_nodes[i];
        if (!needed[j])
          continue;
        const Tensor<1, dim> &force = forces[j];
        auto                 &g     = gradients[j];
        for (unsigned int a = 0; a < n_coordinates; ++a)
          {
            std::array<double, 10> &e = g[keys[a]];
            for (unsigned int k = 0; k < face_nodes; ++k)
              {
                if (lumped && k != i)
                  continue; // lumped: D_ii holds the row sum
                const double       d    = operators.dD[i][k][a];
                const unsigned int node = lumped ? j : s_nodes[k];
                e[0] += d;
                for (unsigned int r = 0; r < dim; ++r)
                  {
                    e[1 + r] -= d * slave.nodes[node].current[r];
                    e[4 + r] += d * (slave.nodes[node].current[r] -
                                     pair.slave_committed[node][r]);
                    if (slave_rows)
                      matrix(dim * k + r, a) += d * force[r];
                  }
              }
            for (unsigned int l = 0; l < face_nodes; ++l)
              {
                const double       m    = operators.dM[i][l][a];
                const unsigned int node = m_nodes[l];
                for (unsigned int r = 0; r < dim; ++r)
                  {
                    e[1 + r] += m * master.nodes[node].current[r];
                    e[4 + r] -= m * (master.nodes[node].current[r] -
                                     pair.master_committed[node][r]);
                    matrix(face_coordinates + dim * l + r, a) -= m * force[r];
                  }
              }
          }
      }
    rhs = 0.;
    scatter(matrix,
            rhs,
            f_int,
            indices,
            constraints,
            discretisation.hanging_node_constraints,
            targets);
  }



  void
  ContactProblem::add_direct_gradients(
    const Pair                                     &pair,
    const unsigned int                              j,
    std::map<unsigned int, std::array<double, 10>> &g,
    const bool                                      normal)
  {
    const ContactSurface &slave = pair.slave;
    const unsigned int    ns    = slave.nodes.size();
    // D and M fixed (D lumped to node j by a condensing enforcement) ...
    const bool lumped = pair.slave_weights() == SlaveWeights::lumped;
    for (const auto &[k, d] : pair.D[j])
      for (unsigned int r = 0; r < dim; ++r)
        {
          auto &e = g[3 * (lumped ? j : k) + r];
          e[1 + r] -= d;
          e[4 + r] += d;
        }
    for (const auto &[l, m] : pair.M[j])
      for (unsigned int r = 0; r < dim; ++r)
        {
          auto &e = g[3 * (ns + l) + r];
          e[1 + r] += m;
          e[4 + r] -= m;
        }
    if (!normal)
      return;
    // ... and the normal n_j = sum_f n_f / |sum_f n_f|:
    // dn_j = (I - n_j n_j) / |sum_f n_f| sum_f dn_f.
    const Tensor<1, dim> &n = pair.aggregates[j].normal;
    const Tensor<2, dim>  P =
      (unit_symmetric_tensor<dim>() - outer_product(n, n)) /
      pair.normal_length[j];
    for (const unsigned int f : slave.node_faces[j])
      {
        const auto &nodes = slave.faces[f].nodes;
        const auto i = std::find(nodes.begin(), nodes.end(), j) - nodes.begin();
        const auto dn = pair.slave_faces[f].normal_derivatives(
          ContactFace::node_parameter(i));
        for (unsigned int r = 0; r < face_nodes; ++r)
          {
            const Tensor<2, dim> dn_j = P * dn[r];
            for (unsigned int m = 0; m < dim; ++m)
              {
                auto &e = g[3 * nodes[r] + m];
                for (unsigned int c = 0; c < dim; ++c)
                  e[7 + c] += dn_j[c][m];
              }
          }
      }
  }
} // namespace DuctileContact
