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

  void
  ContactProblem::linearise_operators(
    const Pair                                                  &pair,
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
    const auto             operators = std::make_unique<FacePairOperators>();
    std::unique_ptr<MortarFace> face;
    unsigned int                face_index = numbers::invalid_unsigned_int;
    FullMatrix<double>          matrix(n_coordinates, n_coordinates);
    Vector<double>              rhs(n_coordinates), f_int(n_coordinates);
    std::vector<types::global_dof_index>    indices(n_coordinates);
    std::array<unsigned int, n_coordinates> keys;
    for (const auto &[f, c] : pair.overlaps)
      {
        const auto &s_nodes = slave.faces[f].nodes;
        const auto &m_nodes = master.faces[c].nodes;
        if (std::none_of(s_nodes.begin(),
                         s_nodes.end(),
                         [&](const unsigned int j) { return needed[j]; }))
          continue;
        if (f != face_index)
          {
            face = std::make_unique<MortarFace>(pair.slave_faces[f], pair.dual);
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
        linearise_operators(
          pair, needed, forces, true, constraints, targets, gradients);
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
