// FieldBound::identify_active_set on a linearised bound problem whose
// operator has no maximum principle: the s-s block is the crack
// functional's cell terms (mass 1/(2l) + l Laplacian + l^3/2 bi-Laplacian,
// Q2, l = 2h, so the fourth-order term dominates), s = s_n = 0, and the
// right-hand side b = int f v with f changing sign over the cube. The
// quadratic program min 1/2 d.K d - b.d subject to d >= 0 has KKT
// conditions (free rows: d >= 0, K d = b; held rows: d = 0, multiplier
// (K d - b)_i >= 0). Checks:
//  - the first set of update_active_set() (the DoFs whose Newton step on
//    their own row, b_i / K_ii, ends below 0) does NOT meet them (the test
//    would not see a broken refinement otherwise), and differs from the refined
//    set;
//  - the refined set does, in fewer sweeps than the limit and more than one;
//  - with the refined set the constrained step is >= 0 everywhere.
// Identical on 1 and 2 MPI ranks (the data are functions of position).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <ductile_contact/coupled/field_bound.h>
#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/phase_field/c0ip.h>

#include "tests.h"

#include <cmath>
#include <limits>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  constexpr unsigned int max_sweeps = 20;

  /// Smallest d_i over the free rows and smallest multiplier over the held
  /// rows of the step d with the rows of @p held replaced by d_i = 0.
  std::pair<double, double>
  kkt(const TrilinosWrappers::SparseMatrix &K,
      const TrilinosWrappers::MPI::Vector  &b,
      const IndexSet                       &held)
  {
    TrilinosWrappers::SparseMatrix K_A;
    K_A.copy_from(K);
    TrilinosWrappers::MPI::Vector rhs = b, d = b, r = b;
    for (const auto i : held)
      {
        K_A.clear_row(i, K.diag_element(i));
        rhs[i] = 0.;
      }
    rhs.compress(VectorOperation::insert);
    SolverControl                  control(1, 0.);
    TrilinosWrappers::SolverDirect direct(control);
    direct.solve(K_A, d, rhs);
    K.vmult(r, d);
    r -= b;
    double min_free = std::numeric_limits<double>::max();
    double min_held = std::numeric_limits<double>::max();
    for (const auto i : b.locally_owned_elements())
      if (held.is_element(i))
        min_held = std::min<double>(min_held, r[i]);
      else
        min_free = std::min<double>(min_free, d[i]);
    const MPI_Comm comm = b.get_mpi_communicator();
    return {Utilities::MPI::min(min_free, comm),
            Utilities::MPI::min(min_held, comm)};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out  = Testing::open_output();
  const MPI_Comm                   comm = MPI_COMM_WORLD;

  parallel::distributed::Triangulation<dim> tria(comm);
  GridGenerator::subdivided_hyper_cube(tria, 6);
  Discretisation d(tria, 2, {{0, BodyFields{false, true}}});
  d.setup();

  TrilinosWrappers::BlockSparsityPattern sp(d.owned_partitioning,
                                            d.owned_partitioning,
                                            d.relevant_partitioning,
                                            comm);
  DoFTools::make_sparsity_pattern(d.dof_handler,
                                  sp,
                                  d.hanging_node_constraints,
                                  false,
                                  Utilities::MPI::this_mpi_process(comm));
  sp.compress();
  TrilinosWrappers::BlockSparseMatrix K;
  K.reinit(sp);
  TrilinosWrappers::MPI::BlockVector b(d.owned_partitioning, comm),
    zero(d.owned_partitioning, comm), residual(d.owned_partitioning, comm);

  // K_ss and b_s = int f v; f > 0 pulls s up, f < 0 down.
  const double     l = 2. / 6.;
  C0IPCoefficients c;
  c.mass        = 1. / (2. * l);
  c.gradient    = l;
  c.bilaplacian = l * l * l / 2.;
  hp::FEValues<dim>                    hp_fe_values(d.mapping,
                                 d.fe_collection,
                                 d.quadrature,
                                 update_values | update_gradients |
                                   update_hessians | update_quadrature_points |
                                   update_JxW_values);
  FullMatrix<double>                   cell_matrix;
  Vector<double>                       cell_rhs;
  std::vector<types::global_dof_index> dofs;
  for (const auto &cell : d.dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        hp_fe_values.reinit(cell);
        const FEValues<dim> &fv = hp_fe_values.get_present_fe_values();
        const unsigned int   n  = cell->get_fe().n_dofs_per_cell();
        cell_matrix.reinit(n, n);
        cell_rhs.reinit(n);
        add_c0ip_cell_terms(fv, d.phase_field, c, cell_matrix);
        for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
          {
            const Point<dim> &x = fv.quadrature_point(q);
            const double      f =
              std::sin(2. * M_PI * x[0]) * std::cos(M_PI * x[1]) + 0.3 * x[2];
            for (unsigned int i = 0; i < n; ++i)
              cell_rhs(i) += f * fv[d.phase_field].value(i, q) * fv.JxW(q);
          }
        dofs.resize(n);
        cell->get_dof_indices(dofs);
        d.hanging_node_constraints.distribute_local_to_global(
          cell_matrix, cell_rhs, dofs, K, b);
      }
  K.compress(VectorOperation::add);
  b.compress(VectorOperation::add);
  residual = b;
  residual *= -1.;

  AffineConstraints<double> constraints;
  constraints.reinit(d.locally_relevant_dofs);
  constraints.close();

  // The first set, then the refined one; s = s_n = 0 (u = old = zero).
  FieldBound bound(d, Block::phase_field, 1.);
  bound.record_diagonal(K);
  const auto n_first =
    bound.update_active_set(zero, zero, residual, constraints);
  const auto &K_ss = K.block(Block::phase_field, Block::phase_field);
  const auto &b_s  = b.block(Block::phase_field);

  // The first set by hand: at s = s_n the rule R_i + K_ii (s_n,i - s_i) > 0
  // holds the DoFs whose Newton step on their row alone, b_i / K_ii, ends
  // below 0.
  IndexSet first(d.dofs_per_block[Block::phase_field]);
  for (const auto i : d.owned_partitioning[Block::phase_field])
    if (b_s[i] < 0.)
      first.add_index(i);
  first.compress();
  const auto n_first_by_hand = Utilities::MPI::sum(first.n_elements(), comm);
  const auto [first_free, first_held] = kkt(K_ss, b_s, first);

  DirectSolve        direct(comm, DirectSolveSettings::exact_lu());
  const unsigned int sweeps = bound.identify_active_set(
    K, b, zero, zero, constraints, direct, max_sweeps);
  const auto n_final = bound.active_size();
  // The refined set: held DoFs are those whose rows identify_active_set
  // replaced; recover them through remove_active_rows on a vector of ones.
  TrilinosWrappers::MPI::BlockVector ones(d.owned_partitioning, comm);
  ones = 1.;
  bound.remove_active_rows(ones);
  IndexSet final_set(d.dofs_per_block[Block::phase_field]);
  for (const auto i : d.owned_partitioning[Block::phase_field])
    if (ones.block(Block::phase_field)[i] == 0.)
      final_set.add_index(i);
  final_set.compress();
  const auto [final_free, final_held] = kkt(K_ss, b_s, final_set);

  // Scale of the step and of the multipliers, for the tolerances.
  const double scale = b_s.linfty_norm();
  out << "s DoFs: " << d.dofs_per_block[Block::phase_field] << std::endl
      << "first set = DoFs whose step on their own row ends below 0: "
      << Testing::yes_no(n_first == n_first_by_hand) << std::endl
      << "first set violates the KKT conditions: "
      << Testing::yes_no(first_free < -1e-8 * scale ||
                         first_held < -1e-8 * scale)
      << std::endl
      << "refined set differs from the first: "
      << Testing::yes_no(n_final != n_first) << std::endl
      << "sweeps: more than one, below the limit: "
      << Testing::yes_no(sweeps > 1 && sweeps < max_sweeps) << std::endl
      << "refined set meets the KKT conditions (step >= 0 on the free rows, "
         "multipliers >= 0 on the held rows, 1e-8): "
      << Testing::yes_no(final_free > -1e-8 * scale &&
                         final_held > -1e-8 * scale)
      << std::endl;
  std::cout << "first set " << n_first << ", refined " << n_final << " in "
            << sweeps << " sweeps; first: min free step " << first_free
            << ", min multiplier " << first_held << "; refined: " << final_free
            << ", " << final_held << std::endl;
}
