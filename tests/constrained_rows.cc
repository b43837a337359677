// DisplacementPreconditioner with `Constrained rows = eliminate` is exact
// where its two approximations are: a Q2 vector Laplacian plus mass on a
// cube of 3x3x3 cells (1029 DoFs: ML's hierarchy is one level with a direct
// coarse solve, so its V-cycle is an exact inverse), in which the rows of the
// top face's nodes are rotated into a frame of their own (a tilted normal
// n, different per node, and two tangents) and the first 1 or 3 of them
// (alternating) replaced by a tie of the node to the node below it, c q_k .
// (u_node - u_below) = 0, as semi-smooth Newton writes its complementarity
// rows; the other rotated rows keep the Laplacian's. The constrained
// components' own block is then diagonal in the frame, so the elimination
// with W = diag(C_cc)^-1 is exact too, and GMRES must converge in one
// iteration (at most two, for round-off) to the known solution. A wrong
// rotation, split or Schur complement would make it iterate. Kept rows (the
// AMG on the block as it is, also exact here) and the number of eliminated
// components are checked as well. Identical on 1 and 2 MPI ranks (on 2, the
// rows are split in halves and the constrained nodes' columns cross them).
#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ductile_contact/solver/displacement_preconditioner.h>

#include "tests.h"

#include <cmath>
#include <map>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  constexpr unsigned int d = 3;
  using Dofs               = std::array<types::global_dof_index, d>;

  /// The DoFs of every support point, by position.
  std::map<std::array<double, d>, Dofs>
  nodes_by_point(const DoFHandler<d> &dh)
  {
    std::map<std::array<double, d>, Dofs> nodes;
    const MappingQ<d>                     mapping(1);
    std::vector<Point<d>>                 points(dh.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dh, points);
    std::vector<types::global_dof_index> dofs(dh.get_fe().n_dofs_per_cell());
    for (const auto &cell : dh.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const Point<d>             &x = points[dofs[i]];
            const std::array<double, d> key{{std::round(6 * x[0]),
                                             std::round(6 * x[1]),
                                             std::round(6 * x[2])}};
            nodes[key][dh.get_fe().system_to_component_index(i).first] =
              dofs[i];
          }
      }
    return nodes;
  }

  /// Vector Laplacian plus mass, the rows of @p owned.
  void
  assemble(const DoFHandler<d>            &dh,
           const IndexSet                 &owned,
           TrilinosWrappers::SparseMatrix &A)
  {
    const QGauss<d>                      quadrature(3);
    FEValues<d>                          fe_values(dh.get_fe(),
                          quadrature,
                          update_values | update_gradients | update_JxW_values);
    const unsigned int                   n = dh.get_fe().n_dofs_per_cell();
    FullMatrix<double>                   local(n, n);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : dh.active_cell_iterators())
      {
        fe_values.reinit(cell);
        local = 0;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              if (dh.get_fe().system_to_component_index(i).first ==
                  dh.get_fe().system_to_component_index(j).first)
                local(i, j) +=
                  (fe_values.shape_grad(i, q) * fe_values.shape_grad(j, q) +
                   fe_values.shape_value(i, q) * fe_values.shape_value(j, q)) *
                  fe_values.JxW(q);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          if (owned.is_element(dofs[i]))
            for (unsigned int j = 0; j < n; ++j)
              A.add(dofs[i], dofs[j], local(i, j));
      }
    A.compress(VectorOperation::add);
  }

  /// The frame of top node @p m: a tilted normal, then tangents.
  std::vector<double>
  frame(const unsigned int m)
  {
    Tensor<1, d> n({0.3 * std::sin(m + 1.), -0.2 * std::cos(m), 1.});
    n /= n.norm();
    Tensor<1, d> t({1., 0., 0.});
    t -= (t * n) * n;
    t /= t.norm();
    const Tensor<1, d>  s = cross_product_3d(n, t);
    std::vector<double> q;
    for (const auto &v : {n, t, s})
      for (unsigned int c = 0; c < d; ++c)
        q.push_back(v[c]);
    return q;
  }

  /**
   * Replaces the rows of @p node (owned) by Q^T rho: rho_k the tie
   * c q_k . (u_node - u_below) for k < n_constrained, else q_k^T times the
   * node's rows.
   */
  void
  constrain(const ConstrainedNode          &node,
            const Dofs                     &below,
            TrilinosWrappers::SparseMatrix &A)
  {
    const auto                                              &q = node.frame;
    std::array<std::map<types::global_dof_index, double>, d> rows, rotated;
    for (unsigned int c = 0; c < d; ++c)
      for (auto e = A.begin(node.dofs[c]); e != A.end(node.dofs[c]); ++e)
        rows[c][e->column()] = e->value();
    const double tie = rows[0][node.dofs[0]];
    for (unsigned int k = 0; k < d; ++k)
      if (k < node.n_constrained)
        for (unsigned int c = 0; c < d; ++c)
          {
            rotated[k][node.dofs[c]] += tie * q[k * d + c];
            rotated[k][below[c]] -= tie * q[k * d + c];
          }
      else
        for (unsigned int c = 0; c < d; ++c)
          for (const auto &[column, value] : rows[c])
            rotated[k][column] += q[k * d + c] * value;
    for (unsigned int c = 0; c < d; ++c)
      {
        std::map<types::global_dof_index, double> row;
        for (const auto &entry : rows[c])
          row[entry.first] = 0.;
        for (unsigned int k = 0; k < d; ++k)
          for (const auto &[column, value] : rotated[k])
            row[column] += q[k * d + c] * value;
        for (const auto &[column, value] : row)
          A.set(node.dofs[c], column, value);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out  = Testing::open_output();
  const MPI_Comm                   comm = MPI_COMM_WORLD;

  Triangulation<d> tria;
  GridGenerator::subdivided_hyper_cube(tria, 3);
  DoFHandler<d> dh(tria);
  dh.distribute_dofs(FESystem<d>(FE_Q<d>(2), d));
  const types::global_dof_index n_dofs = dh.n_dofs();
  const unsigned int            rank   = Utilities::MPI::this_mpi_process(comm);
  const unsigned int            ranks  = Utilities::MPI::n_mpi_processes(comm);
  IndexSet                      owned(n_dofs);
  owned.add_range(rank * n_dofs / ranks, (rank + 1) * n_dofs / ranks);

  DynamicSparsityPattern dsp(n_dofs);
  DoFTools::make_sparsity_pattern(dh, dsp);
  TrilinosWrappers::SparseMatrix A;
  A.reinit(owned, owned, dsp, comm);
  assemble(dh, owned, A);

  // The top face's nodes (z = 1), each tied to the node below (z = 5/6).
  const auto       nodes = nodes_by_point(dh);
  ConstrainedNodes constrained;
  unsigned int     expected = 0;
  for (const auto &[key, dofs] : nodes)
    if (key[2] == 6.)
      {
        ConstrainedNode node;
        node.dofs.assign(dofs.begin(), dofs.end());
        node.frame         = frame(constrained.size());
        node.n_constrained = constrained.size() % 2 == 0 ? 1 : d;
        expected += node.n_constrained;
        if (owned.is_element(dofs[0]))
          constrain(node, nodes.at({{key[0], key[1], 5.}}), A);
        constrained.push_back(node);
      }
  A.compress(VectorOperation::insert);

  TrilinosWrappers::MPI::Vector exact(owned, comm), b(owned, comm),
    x(owned, comm);
  for (const auto i : owned)
    exact(i) = std::sin(0.37 * i) + 0.1 * std::cos(1.3 * i);
  exact.compress(VectorOperation::insert);
  A.vmult(b, exact);

  LinearSolverParameters parameters;
  for (const ConstrainedRows rows :
       {ConstrainedRows::eliminate, ConstrainedRows::keep})
    {
      parameters.constrained_rows = rows;
      DisplacementPreconditioner preconditioner;
      preconditioner.initialize(A, &constrained, parameters, 2, nullptr);
      SolverControl control(100, 1e-10 * b.l2_norm());
      SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
        control,
        SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(100, true));
      x = 0;
      gmres.solve(A, x, b, preconditioner);
      x -= exact;
      const double error = x.l2_norm() / exact.l2_norm();
      out << name_of(constrained_rows_names(), rows)
          << ": eliminated components " << preconditioner.n_eliminated()
          << " (top-face nodes " << constrained.size()
          << ", constrained components " << expected
          << "), error < 1e-8: " << Testing::yes_no(error < 1e-8)
          << ", GMRES iterations <= 2: "
          << Testing::yes_no(control.last_step() <= 2) << "\n";
      std::cout << "iterations " << control.last_step() << ", error " << error
                << std::endl;
    }
}
