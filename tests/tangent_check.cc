// Newton/Check tangent (NewtonSolver::tangent_error) on a problem whose
// tangent is known exactly:
//
//   R(x) = A x + c x^3 - f   (x^3 entry by entry)
//
// on the displacement DoFs of a small mesh, A = 1e6 (1e-4 mass + stiffness)
// and c = 100, Newton from 0.95 x* to 1e-11 of |f|. With the exact tangent
// K = A + 3 c diag(x^2) the error reported for the last update of the solve
// must be small (below 1e-6); with K scaled by 1 + e it is e / (1 + e)
// along every update and for every difference step, so the check, which
// keeps the smallest error over the steps and orders it tries, must still
// report it (within 1 %). (Whether the check chooses longer steps where a
// short one would only measure round-off is shown on the coupled scenes:
// tests/block_on_plate, tests/contact_refined.)

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/solver/linear_solver.h>
#include <ductile_contact/solver/newton_solver.h>
#include <ductile_contact/solver/nonlinear_problem.h>

#include "tests.h"

#include <cmath>
#include <limits>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  constexpr double cubic = 1e2;
  /// Weight of the mass matrix in A: small, so that A is ill-conditioned.
  constexpr double mass = 1e-4;

  /// R(x) = A x + c x^3 - f with the tangent scaled by #tangent_scale.
  class CubicProblem : public NonlinearProblem
  {
  public:
    CubicProblem(const TrilinosWrappers::BlockSparsityPattern &pattern,
                 const Matrix                                 &A,
                 const Matrix                                 &A_abs,
                 const Vector                                 &f,
                 const double                                  tangent_scale)
        : A(A)
        , A_abs(A_abs)
        , f(f)
        , tangent_scale(tangent_scale)
    {
      K.reinit(pattern);
      rhs.reinit(f);
      r.reinit(f);
    }

    std::vector<std::string>
    block_names() const override
    {
      return {"u", "alpha", "s"};
    }
    bool
    block_solved(const unsigned int b) const override
    {
      return b == 0;
    }
    unsigned int
    n_nonempty_blocks() const override
    {
      return 1;
    }
    bool
    begin_iteration(const Vector &) override
    {
      return false;
    }
    ResidualEvaluation
    assemble_system(const Vector &x) override
    {
      const ResidualEvaluation e = assemble_residual(x);
      K.block(0, 0).copy_from(A.block(0, 0));
      for (const auto i : x.block(0).locally_owned_elements())
        K.block(0, 0).add(i, i, 3. * cubic * x.block(0)[i] * x.block(0)[i]);
      K.compress(VectorOperation::add);
      K *= tangent_scale;
      rhs = r;
      rhs *= -1.;
      return e;
    }
    ResidualEvaluation
    assemble_residual(const Vector &x) override
    {
      residual(x, r);
      // The size of the terms summed into each entry of R: |A| |x| +
      // c |x|^3 + |f|.
      Vector abs_x = x, terms(f);
      for (const auto i : x.block(0).locally_owned_elements())
        abs_x.block(0)[i] = std::abs(x.block(0)[i]);
      abs_x.compress(VectorOperation::insert);
      A_abs.vmult(terms, abs_x);
      for (const auto i : x.block(0).locally_owned_elements())
        terms.block(0)[i] +=
          cubic * std::pow(abs_x.block(0)[i], 3) + std::abs(f.block(0)[i]);
      terms.compress(VectorOperation::insert);

      ResidualEvaluation e;
      e.norms          = {r.block(0).l2_norm(), 0., 0.};
      e.relative_scale = {f.block(0).l2_norm(), 0., 0.};
      e.absolute_scale = {0., 0., 0.};
      e.round_off      = {std::numeric_limits<double>::epsilon() *
                            terms.block(0).l2_norm(),
                          0.,
                          0.};
      return e;
    }
    std::vector<double>
    modify_linear_system(const Vector &) override
    {
      return {r.block(0).l2_norm(), 0., 0.};
    }
    const Matrix &
    system_matrix() const override
    {
      return K;
    }
    const Vector &
    system_rhs() const override
    {
      return rhs;
    }
    void
    distribute(Vector &) const override
    {
    }
    void
    compared_product(const Vector &d, Vector &k_d) const override
    {
      K.vmult(k_d, d);
    }
    void
    compared_residual(const Vector &x, Vector &result) override
    {
      residual(x, result);
    }

  private:
    void
    residual(const Vector &x, Vector &result) const
    {
      A.vmult(result, x);
      for (const auto i : x.block(0).locally_owned_elements())
        result.block(0)[i] +=
          cubic * std::pow(x.block(0)[i], 3) - f.block(0)[i];
      result.compress(VectorOperation::insert);
    }

    const Matrix &A;
    const Matrix &A_abs;
    const Vector &f;
    const double  tangent_scale;
    Matrix        K;
    Vector        rhs, r;
  };



  /// A = 1e6 (1e-4 mass + stiffness) per displacement component, and the same
  /// assembled from the absolute values of the cell matrices.
  void
  assemble(const Discretisation                &d,
           TrilinosWrappers::BlockSparseMatrix &A,
           TrilinosWrappers::BlockSparseMatrix &A_abs)
  {
    hp::FEValues<dim>                    fe_values(d.mapping,
                                d.fe_collection,
                                d.quadrature,
                                update_values | update_gradients |
                                  update_JxW_values);
    FullMatrix<double>                   cell_matrix, cell_abs;
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : d.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          const FEValues<dim>      &fv = fe_values.get_present_fe_values();
          const FiniteElement<dim> &fe = cell->get_fe();
          const unsigned int        n  = fe.n_dofs_per_cell();
          cell_matrix.reinit(n, n);
          for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                if (fe.system_to_component_index(i).first ==
                    fe.system_to_component_index(j).first)
                  cell_matrix(i, j) +=
                    1e6 *
                    (mass * fv.shape_value(i, q) * fv.shape_value(j, q) +
                     fv.shape_grad(i, q) * fv.shape_grad(j, q)) *
                    fv.JxW(q);
          cell_abs = cell_matrix;
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              cell_abs(i, j) = std::abs(cell_matrix(i, j));
          dofs.resize(n);
          cell->get_dof_indices(dofs);
          d.hanging_node_constraints.distribute_local_to_global(cell_matrix,
                                                                dofs,
                                                                A);
          d.hanging_node_constraints.distribute_local_to_global(cell_abs,
                                                                dofs,
                                                                A_abs);
        }
    A.compress(VectorOperation::add);
    A_abs.compress(VectorOperation::add);
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out  = Testing::open_output();
  const MPI_Comm                   comm = MPI_COMM_WORLD;

  parallel::distributed::Triangulation<dim> tria(comm);
  GridGenerator::hyper_cube(tria);
  tria.refine_global(2);
  Discretisation d(tria, 2, {{0, BodyFields{false, false}}});
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
  TrilinosWrappers::BlockSparseMatrix A, A_abs;
  A.reinit(sp);
  A_abs.reinit(sp);
  assemble(d, A, A_abs);

  // f such that x* = 1 + 0.5 sin(0.37 i) solves R(x*) = 0.
  TrilinosWrappers::MPI::BlockVector x_star(d.owned_partitioning, comm),
    f(d.owned_partitioning, comm), x(d.owned_partitioning, comm);
  for (const auto i : d.owned_partitioning[0])
    x_star.block(0)[i] = 1. + 0.5 * std::sin(0.37 * i);
  x_star.compress(VectorOperation::insert);
  A.vmult(f, x_star);
  for (const auto i : d.owned_partitioning[0])
    f.block(0)[i] += cubic * std::pow(x_star.block(0)[i], 3);
  f.compress(VectorOperation::insert);

  ConditionalOStream screen(std::cout,
                            Utilities::MPI::this_mpi_process(comm) == 0);
  TimerOutput timer(comm, screen, TimerOutput::never, TimerOutput::wall_times);
  NewtonParameters newton_parameters;
  newton_parameters.relative_tolerance = 1e-11;
  newton_parameters.absolute_tolerance = 0.;
  newton_parameters.max_iterations     = 40;
  newton_parameters.check_tangent      = true;
  LinearSolverParameters linear_parameters;
  LinearSolver           linear_solver(linear_parameters, d);
  linear_solver.setup();
  NewtonSolver newton(newton_parameters, linear_solver, {screen, timer});

  // The tangent exact, and scaled by 1 + e: the check must find e / (1 + e).
  for (const double e : {0., 1e-3, -1e-2})
    {
      CubicProblem problem(sp, A, A_abs, f, 1. + e);
      // From 5 % below x*, where Newton takes its full steps.
      x = x_star;
      x *= 0.95;
      const NewtonReport report = newton.solve(problem, x);
      x -= x_star;
      const double error = x.l2_norm() / x_star.l2_norm();
      out << "tangent scaled by 1 + (" << e << "): converged to x*: "
          << Testing::yes_no(report.converged && error < 1e-9);
      if (e == 0.)
        out << ", tangent error of the last update < 1e-6: "
            << Testing::yes_no(report.tangent_error < 1e-6);
      else
        out << ", tangent error of the last update within 1 % of |e| / (1 + "
               "e): "
            << Testing::yes_no(
                 std::abs(report.tangent_error - std::abs(e) / (1. + e)) <
                 1e-2 * std::abs(e));
      out << std::endl;
      // Not compared: the numbers themselves.
      screen << "scale 1 + " << e << ": " << report.iterations
             << " Newton iterations, error " << error << ", tangent error "
             << report.tangent_error << std::endl;
    }
}
