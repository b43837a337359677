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

    /// This rank's contiguous share [first, second) of the face pairs
    /// @p overlaps whose slave face has a node in @p any (contiguous: the
    /// pairs of one slave face share its MortarFace), sized so that every
    /// rank's integration plus its @p rows_after rows of later work (a
    /// row counted as row_cost face pairs) come out even.
    std::pair<std::size_t, std::size_t>
    face_pair_share(
      const std::vector<std::pair<unsigned int, unsigned int>> &overlaps,
      const ContactSurface                                     &slave,
      const std::vector<bool>                                  &any,
      const unsigned int                                        rows_after,
      const MPI_Comm                                            comm)
    {
      constexpr double         row_cost = 0.1;
      std::vector<std::size_t> touching;
      for (std::size_t i = 0; i < overlaps.size(); ++i)
        {
          const auto &nodes = slave.faces[overlaps[i].first].nodes;
          if (std::any_of(nodes.begin(),
                          nodes.end(),
                          [&](const unsigned int j) { return any[j]; }))
            touching.push_back(i);
        }
      // Per rank: the pairs it takes = an even share of all the work less
      // its own rows, the shares then scaled to the pairs there are.
      const std::vector<unsigned int> rows =
        Utilities::MPI::all_gather(comm, rows_after);
      const std::size_t n_ranks = rows.size();
      double            total   = touching.size();
      for (const unsigned int r : rows)
        total += row_cost * r;
      std::vector<double> wanted(n_ranks);
      double              sum = 0.;
      for (std::size_t r = 0; r < n_ranks; ++r)
        sum += wanted[r] = std::max(0., total / n_ranks - row_cost * rows[r]);
      const std::size_t rank   = Utilities::MPI::this_mpi_process(comm);
      double            before = 0.;
      for (std::size_t r = 0; r < rank; ++r)
        before += wanted[r];
      const auto bound = [&](const double w) {
        return static_cast<std::size_t>(
          std::lround(sum > 0. ? touching.size() * w / sum : 0.));
      };
      const std::size_t begin = bound(before);
      const std::size_t end   = bound(before + wanted[rank]);
      if (begin >= end)
        return {0, 0};
      return {touching[begin], touching[end - 1] + 1};
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



  std::vector<bool>
  ContactProblem::linearise_operators(
    const Pair                        &pair,
    const std::vector<bool>           &needed,
    const std::vector<Tensor<1, dim>> &forces,
    const bool                         slave_rows,
    const unsigned int                 rows_after,
    const GradientShare                share,
    const AffineConstraints<double>   &constraints,
    const AssemblyTargets             &targets,
    Gradients                         &gradients) const
  {
    const MPI_Comm comm = discretisation.dof_handler.get_communicator();
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      {
        integrate_face_pairs(pair,
                             needed,
                             forces,
                             slave_rows,
                             {0, pair.overlaps.size()},
                             constraints,
                             targets,
                             gradients);
        return needed;
      }
    // Every rank integrates a share of the face pairs that any rank needs,
    // whichever rank owns their nodes.
    const SharedNeeds shared = share_needs(needed, forces, comm);
    integrate_face_pairs(
      pair,
      shared.any,
      shared.forces,
      slave_rows,
      face_pair_share(pair.overlaps, pair.slave, shared.any, rows_after, comm),
      constraints,
      targets,
      gradients);
    if (share == GradientShare::partial)
      return shared.any;
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
    const ContactSurface  &slave = pair.slave, &master = pair.master;
    const unsigned int     ns            = slave.nodes.size();
    constexpr unsigned int n_coordinates = face_pair_coordinates;
    const auto             operators = std::make_unique<FacePairOperators>();
    std::unique_ptr<MortarFace> face;
    unsigned int                face_index = numbers::invalid_unsigned_int;
    FullMatrix<double>          matrix(n_coordinates, n_coordinates);
    Vector<double>              rhs(n_coordinates), f_int(n_coordinates);
    std::vector<types::global_dof_index>    indices(n_coordinates);
    std::array<unsigned int, n_coordinates> keys;
    for (std::size_t i = range.first; i < range.second; ++i)
      {
        const auto [f, c]   = pair.overlaps[i];
        const auto &s_nodes = slave.faces[f].nodes;
        const auto &m_nodes = master.faces[c].nodes;
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
        face->integrate(master.current_face(c), *operators, true);
        for (unsigned int a = 0; a < n_coordinates; ++a)
          {
            keys[a]    = a < 27 ? 3 * s_nodes[a / 3] + a % 3
                                : 3 * (ns + m_nodes[(a - 27) / 3]) + a % 3;
            indices[a] = coordinate_dof(pair, keys[a]);
          }
        matrix = 0.;
        for (unsigned int i = 0; i < 9; ++i)
          {
            const unsigned int j = s_nodes[i];
            if (!needed[j])
              continue;
            const Tensor<1, dim> &force = forces[j];
            auto                 &g     = gradients[j];
            for (unsigned int a = 0; a < n_coordinates; ++a)
              {
                std::array<double, 10> &e = g[keys[a]];
                for (unsigned int k = 0; k < 9; ++k)
                  {
                    if (pair.semi_smooth && k != i)
                      continue; // lumped: D_ii holds the row sum
                    const double       d    = operators->dD[i][k][a];
                    const unsigned int node = pair.semi_smooth ? j : s_nodes[k];
                    e[0] += d;
                    for (unsigned int r = 0; r < dim; ++r)
                      {
                        e[1 + r] -= d * slave.nodes[node].current[r];
                        e[4 + r] += d * (slave.nodes[node].current[r] -
                                         pair.slave_committed[node][r]);
                        if (slave_rows)
                          matrix(3 * k + r, a) += d * force[r];
                      }
                  }
                for (unsigned int l = 0; l < 9; ++l)
                  {
                    const double       m    = operators->dM[i][l][a];
                    const unsigned int node = m_nodes[l];
                    for (unsigned int r = 0; r < dim; ++r)
                      {
                        e[1 + r] += m * master.nodes[node].current[r];
                        e[4 + r] -= m * (master.nodes[node].current[r] -
                                         pair.master_committed[node][r]);
                        matrix(27 + 3 * l + r, a) -= m * force[r];
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
    // D and M fixed (D lumped to node j for semi-smooth Newton) ...
    for (const auto &[k, d] : pair.D[j])
      for (unsigned int r = 0; r < dim; ++r)
        {
          auto &e = g[3 * (pair.semi_smooth ? j : k) + r];
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
        const auto dn =
          pair.slave_faces[f].normal_derivatives(Quad9::node_parameter(i));
        for (unsigned int r = 0; r < 9; ++r)
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

  void
  ContactProblem::assemble_penalty(Pair                            &pair,
                                   const AffineConstraints<double> &constraints,
                                   const AssemblyTargets           &targets)
  {
    FullMatrix<double>                   matrix;
    Vector<double>                       rhs, f_int;
    std::vector<types::global_dof_index> indices;
    const ContactSurface                &slave = pair.slave;
    const unsigned int                   ns    = slave.nodes.size();
    std::vector<bool>                    needed(ns);
    for (unsigned int j = 0; j < ns; ++j)
      needed[j] =
        pair.nodal[j].active &&
        discretisation.locally_owned_dofs.is_element(slave.nodes[j].dofs[0]);
    // d(aggregates)/dx: through D and M, then directly.
    std::vector<std::map<unsigned int, std::array<double, 10>>> gradients(ns);
    const bool tangent = targets.tangent != nullptr;
    if (tangent)
      {
        std::vector<Tensor<1, dim>> forces(ns);
        for (unsigned int j = 0; j < ns; ++j)
          forces[j] = pair.nodal[j].force_density;
        linearise_operators(pair,
                            needed,
                            forces,
                            true,
                            0,
                            GradientShare::complete,
                            constraints,
                            targets,
                            gradients);
      }

    for (unsigned int j = 0; j < ns; ++j)
      {
        if (!needed[j])
          continue;
        const NodalContactState &state = pair.nodal[j];
        auto                    &g     = gradients[j];
        if (tangent)
          add_direct_gradients(pair, j, g);

        // Local system: rows D_jk f_j (slave k), -M_jl f_j (master l);
        // columns df_j/dx = (df_j/da) (da/dx).
        std::vector<unsigned int> slave_rows;
        for (const auto &[k, d] : pair.D[j])
          slave_rows.push_back(k);
        std::map<unsigned int, unsigned int> local;
        indices = local_numbering(pair, j, slave_rows, g, local);
        const unsigned int size = indices.size();
        matrix.reinit(size, size);
        rhs.reinit(size);
        f_int.reinit(size);
        // df_j/dx per column
        std::vector<std::pair<unsigned int, Tensor<1, dim>>> df;
        for (const auto &[key, e] : g)
          {
            Tensor<1, dim> v;
            for (unsigned int r = 0; r < dim; ++r)
              for (unsigned int a = 0; a < 10; ++a)
                v[r] += state.jacobian[r][a] * e[a];
            df.emplace_back(local[key], v);
          }
        const auto add_row = [&](const unsigned int key, const double weight) {
          for (unsigned int r = 0; r < dim; ++r)
            {
              const unsigned int row = local[key + r];
              f_int[row] += weight * state.force_density[r];
              for (const auto &[column, v] : df)
                matrix(row, column) += weight * v[r];
            }
        };
        for (const auto &[k, d] : pair.D[j])
          add_row(3 * k, d);
        for (const auto &[l, m] : pair.M[j])
          add_row(3 * (ns + l), -m);
        for (unsigned int r = 0; r < size; ++r)
          rhs[r] = -f_int[r];
        scatter(matrix,
                rhs,
                f_int,
                indices,
                constraints,
                discretisation.hanging_node_constraints,
                targets);
      }
  }
} // namespace DuctileContact
