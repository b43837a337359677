// LinearSolver on the coupled [u | alpha | s] block system. Two
// disconnected bodies (a Q2 cube 4x4x4 carrying alpha and s, one corner
// cell refined so hanging nodes constrain all fields; a bar of 80 cells with
// u only, so many cells that on 2 ranks one of them owns no alpha or s DoF),
// a non-symmetric test tangent: u-u vector Laplacian + mass, alpha-alpha and
// s-s mass + Laplacian, and first-order couplings c phi_i d_k phi_j between
// every pair of fields with different coefficients each way. For a known
// x_exact, b = K x_exact; each solver must return x_exact to 1e-6 relative:
//  - direct with KLU and MUMPS on the monolithic copy of the nine blocks,
//    MUMPS with each ordering (PT-Scotch's in MUMPS's parallel analysis,
//    which must run on all ranks on 2),
//    also after the values change (the copied pattern is reused) and after
//    setup() (the pattern is rebuilt); MUMPS with the factors of the last
//    matrix through GMRES after a small change of the couplings (2 to 20
//    iterations) and after a large one (giving up within 10 of the ~55
//    iterations left, then factorising again); MUMPS with single-precision
//    factors (through flexible GMRES: the rounded triangular solves are not one
//    fixed linear map, and plain GMRES reported a residual ~1e3 below the
//    true one), and with a tolerance GMRES cannot reach, where it must
//    factorise again in double precision;
//  - gmres-amg (and cg-amg, which is GMRES for coupled systems) with the
//    block lower-triangular preconditioner, s by AMG and by a direct
//    factorisation, within an iteration bound; with the symmetric
//    Gauss-Seidel smoother, and with GMRES restarted every 10 iterations;
//  - the same with whole blocks frozen (their rows hold only a diagonal
//    entry, as in a staggered iteration): s frozen, and u frozen;
//  - a layout with s but no alpha (an empty block between two others);
//  - u only (the displacement solver path), the matrix scaled by 1e9 like a
//    stiffness in Pa: the stopping test must be on the true residual (with
//    left-preconditioned GMRES it was on the AMG-preconditioned one, ~1e9
//    smaller, and the solve stopped far too early).
// Identical on 1 and 2 MPI ranks (also run on 3 by hand).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/solver/linear_solver.h>

#include "tests.h"

#include <cmath>
#include <sstream>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  /// 0 = u, 1 = alpha, 2 = s for a vector component.
  unsigned int
  field(const unsigned int component)
  {
    return component < dim ? 0 : component - dim + 1;
  }

  /**
   * The test tangent with the given constraints. @p coupling_scale scales
   * the off-diagonal blocks (to change the values between solves).
   */
  void
  assemble(const Discretisation                &d,
           const AffineConstraints<double>     &constraints,
           const double                         coupling_scale,
           TrilinosWrappers::BlockSparseMatrix &K)
  {
    // coupling[a][b]: coefficient of the (a, b) block; different each way,
    // so K is not symmetric.
    const double coupling[3][3] = {{0., 3., 3.}, {2., 0., 3.}, {-2., -1., 0.}};
    K                           = 0;
    hp::FEValues<dim>                    fe_values(d.mapping,
                                d.fe_collection,
                                d.quadrature,
                                update_values | update_gradients |
                                  update_JxW_values);
    FullMatrix<double>                   cell_matrix;
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
              {
                const unsigned int ci = fe.system_to_component_index(i).first;
                for (unsigned int j = 0; j < n; ++j)
                  {
                    const unsigned int cj =
                      fe.system_to_component_index(j).first;
                    const unsigned int fi = field(ci), fj = field(cj);
                    double             value = 0;
                    if (fi == fj)
                      {
                        if (ci == cj)
                          value = fv.shape_value(i, q) * fv.shape_value(j, q) +
                                  fv.shape_grad(i, q) * fv.shape_grad(j, q);
                      }
                    else
                      {
                        // A derivative in the direction of the u component
                        // involved, else in x.
                        const unsigned int k =
                          (fi == 0 ? ci : (fj == 0 ? cj : 0));
                        value = coupling_scale * coupling[fi][fj] *
                                fv.shape_value(i, q) * fv.shape_grad(j, q)[k];
                      }
                    cell_matrix(i, j) += value * fv.JxW(q);
                  }
              }
          dofs.resize(n);
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(cell_matrix, dofs, K);
        }
    K.compress(VectorOperation::add);
  }

  /// The hanging-node constraints plus every DoF of the given blocks fixed.
  AffineConstraints<double>
  frozen_constraints(const Discretisation            &d,
                     const std::vector<unsigned int> &blocks)
  {
    AffineConstraints<double> c;
    c.reinit(d.locally_relevant_dofs);
    types::global_dof_index offset = 0;
    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      {
        if (std::find(blocks.begin(), blocks.end(), b) != blocks.end())
          for (const auto i : d.relevant_partitioning[b])
            c.add_line(offset + i);
        offset += d.dofs_per_block[b];
      }
    c.merge(d.hanging_node_constraints,
            AffineConstraints<double>::MergeConflictBehavior::left_object_wins);
    c.close();
    return c;
  }

  /**
   * Builds the layout with @p fields on body 0 (body 1: u only) and runs
   * the solvers on it, the test tangent scaled by @p scale; @p full adds
   * KLU, the change of values, setup() and the frozen blocks.
   */
  void
  test_layout(const parallel::distributed::Triangulation<dim> &tria,
              const BodyFields                                &fields,
              const bool                                       full,
              std::ostream                                    &out,
              const double                                     scale = 1.)
  {
    const MPI_Comm comm = tria.get_communicator();
    Discretisation d(tria, 2, {{0, fields}, {1, BodyFields{false, false}}});
    d.setup();
    out << "DoFs u, alpha, s: " << d.dofs_per_block[0] << ", "
        << d.dofs_per_block[1] << ", " << d.dofs_per_block[2] << std::endl;
    const unsigned int n_hanging =
      Utilities::MPI::sum(static_cast<unsigned int>(
                            d.hanging_node_constraints.n_constraints()),
                          comm);
    out << "hanging nodes: " << Testing::yes_no(n_hanging > 0) << std::endl;
    // Not compared: whether some rank owns no alpha and s DoFs (the AMG and
    // the direct solvers must cope with empty local parts).
    std::cout << "rank " << Utilities::MPI::this_mpi_process(comm)
              << " owns alpha, s DoFs: " << d.owned_partitioning[1].n_elements()
              << ", " << d.owned_partitioning[2].n_elements() << std::endl;

    // Pattern as in NewtonSolver::setup().
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

    TrilinosWrappers::MPI::BlockVector x_exact(d.owned_partitioning, comm),
      x(d.owned_partitioning, comm), b(d.owned_partitioning, comm);
    // A known solution: a smooth function of the global DoF index.
    {
      types::global_dof_index offset = 0;
      for (unsigned int block = 0; block < Block::n_blocks; ++block)
        {
          for (const auto i : d.owned_partitioning[block])
            x_exact.block(block)[i] = 1. + std::sin(0.37 * (offset + i));
          offset += d.dofs_per_block[block];
        }
      x_exact.compress(VectorOperation::insert);
    }

    LinearSolverParameters parameters;
    parameters.relative_tolerance = 1e-10;
    // Every direct solve factorises; the reuse of factors is checked apart.
    parameters.reuse_iterations = 0;
    LinearSolver solver(parameters, d);
    solver.setup();

    // Solves K x = K x_exact; prints whether x = x_exact to 1e-6 and, for
    // the iterative solvers, whether the iteration count is within a bound.
    const auto check = [&](const std::string &name, const unsigned int bound) {
      K.vmult(b, x_exact);
      x                      = 0;
      const unsigned int its = solver.solve(K, x, b);
      x -= x_exact;
      const double error = x.l2_norm() / x_exact.l2_norm();
      out << "  " << name
          << ": error < 1e-6: " << Testing::yes_no(error < 1e-6);
      if (bound > 0)
        out << ", iterations <= " << bound << ": "
            << Testing::yes_no(its <= bound);
      out << std::endl;
      // Not compared: the iteration count and the error.
      std::cout << name << ": " << its << " iterations, relative error "
                << error << std::endl;
    };

    // Every solver on the current K (KLU, slow in 3-D, only when asked);
    // cg-amg is GMRES with the same preconditioner for coupled systems.
    const unsigned int bound   = 30;
    const auto         run_all = [&](const std::string &label, const bool klu) {
      parameters.type = LinearSolverType::direct;
      for (const std::string direct : {"Amesos_Klu", "Amesos_Mumps", "mumps"})
        if (klu || direct != "Amesos_Klu")
          {
            parameters.direct_solver = from_name(direct_solver_names(), direct);
            check(label + "direct " + direct, 0);
          }
      // MUMPS's other orderings (the first layout only); PT-Scotch's in
      // its parallel analysis, which must run on all ranks when there are
      // several.
      if (label.empty())
        {
          parameters.direct_solver = DirectSolver::mumps;
          for (const std::string o : {"pt-scotch", "amd", "pord"})
            {
              parameters.ordering = from_name(direct_ordering_names(), o);
              check("direct mumps, " + o + " ordering", 0);
              if (o == "pt-scotch")
                {
                  std::ostringstream summary;
                  solver.print_summary(summary);
                  const bool parallel =
                    summary.str().find("(1 on all ranks)") != std::string::npos;
                  out << "    analysis on all ranks where there are several: "
                      << Testing::yes_no(
                           parallel ==
                           (Utilities::MPI::n_mpi_processes(comm) > 1))
                      << std::endl;
                }
            }
          parameters.ordering = DirectOrdering::metis;
        }
      // Single-precision factors through flexible GMRES; on the whole
      // layouts also with a tolerance GMRES cannot reach (below double
      // round-off): then double-precision factors.
      parameters.direct_solver = DirectSolver::mumps;
      parameters.precision     = FactorPrecision::single_precision;
      check(label + "direct mumps, single-precision factors", 0);
      if (label.empty())
        {
          const unsigned int fallbacks = solver.fallback_factorisations();
          parameters.relative_tolerance = 1e-20;
          check("direct mumps, single-precision factors, tolerance 1e-20", 0);
          out << "    factorised again in double precision: "
              << Testing::yes_no(solver.fallback_factorisations() ==
                                 fallbacks + 1)
              << std::endl;
          parameters.relative_tolerance = 1e-10;
        }
      parameters.precision = FactorPrecision::double_precision;
      const bool has_s     = d.dofs_per_block[Block::phase_field] > 0;
      // The u-only test tangent is symmetric: LDL^T of its upper triangle.
      if (!has_s && d.dofs_per_block[Block::hardening] == 0)
        {
          parameters.direct_solver = DirectSolver::mumps;
          parameters.factorisation = Factorisation::ldlt;
          check(label + "direct mumps ldlt (symmetric K)", 0);
          parameters.factorisation = Factorisation::lu;
        }
      for (const std::string type : {"gmres-amg", "cg-amg"})
        for (const std::string s : {"amg", "direct"})
          if ((type == "gmres-amg" || (s == "amg" && (full || !has_s))) &&
              (has_s || s == "amg"))
            {
              parameters.type = from_name(linear_solver_type_names(), type);
              parameters.phase_field_preconditioner =
                from_name(phase_field_preconditioner_names(), s);
              check(label + type + (has_s ? ", s by " + s : ""), bound);
            }
      // The other AMG smoother, and a GMRES restart shorter than the
      // iterations (the answer only).
      parameters.type = LinearSolverType::gmres_amg;
      parameters.phase_field_preconditioner = PhaseFieldPreconditioner::amg;
      parameters.smoother = AmgSmoother::symmetric_gauss_seidel;
      check(label + "gmres-amg, symmetric Gauss-Seidel smoother", bound);
      parameters.smoother      = AmgSmoother::chebyshev;
      parameters.gmres_restart = 10;
      check(label + "gmres-amg, GMRES restart 10", 0);
      parameters.gmres_restart = 100;
    };

    assemble(d, d.hanging_node_constraints, 1., K);
    K *= scale;
    run_all("", full);
    if (!full)
      return;

    // New values, same pattern: the monolithic copy must follow the values.
    assemble(d, d.hanging_node_constraints, 2., K);
    parameters.type             = LinearSolverType::direct;
    parameters.direct_solver    = DirectSolver::mumps;
    parameters.reuse_iterations = 60;
    check("direct after a change of values", 0);
    // A small change: GMRES with the factors of the last matrix.
    assemble(d, d.hanging_node_constraints, 2.1, K);
    {
      K.vmult(b, x_exact);
      x                      = 0;
      const unsigned int its = solver.solve(K, x, b);
      x -= x_exact;
      out << "  direct reusing the last factors: error < 1e-6: "
          << Testing::yes_no(x.l2_norm() / x_exact.l2_norm() < 1e-6)
          << ", GMRES with old factors (2 to 20 iterations): "
          << Testing::yes_no(its >= 2 && its <= 20) << std::endl;
      std::cout << "reuse: " << its << " iterations" << std::endl;
    }
    // The same matrix again, and said so (a chord step): the solver skips
    // its copy of the values and the check of the factors' pattern.
    {
      K.vmult(b, x_exact);
      x = 0;
      solver.solve(K, x, b, {}, true);
      x -= x_exact;
      out << "  direct on the matrix of the last solve: error < 1e-6: "
          << Testing::yes_no(x.l2_norm() / x_exact.l2_norm() < 1e-6)
          << std::endl;
    }
    // A large change: the factors of the last matrix cannot bring GMRES to
    // the tolerance within the ~55 iterations left; it must give up within
    // 10 (ProjectedGmresControl) and factorise again.
    assemble(d, d.hanging_node_constraints, 8., K);
    {
      K.vmult(b, x_exact);
      x = 0;
      solver.solve(K, x, b);
      x -= x_exact;
      const auto [failed, spent] = solver.failed_reuse_counts();
      out << "  direct after a large change: error < 1e-6: "
          << Testing::yes_no(x.l2_norm() / x_exact.l2_norm() < 1e-6)
          << ", GMRES with old factors gave up within 10 iterations: "
          << Testing::yes_no(failed == 1 && spent <= 10) << std::endl;
      std::cout << "large change: " << failed << " failed reuse, " << spent
                << " solves, error " << x.l2_norm() / x_exact.l2_norm()
                << std::endl;
    }
    assemble(d, d.hanging_node_constraints, 2.1, K);
    parameters.reuse_iterations = 0;
    solver.setup();
    check("direct after setup()", 0);

    // A SolveAccuracy with weights of very different sizes per block (as
    // Newton's tolerances of u, alpha and s are): a solve may stop once the
    // weighted residual is below `enough`, here 1e-4 of the weighted
    // right-hand side. GMRES on the factors of an earlier matrix (a few
    // tenths gained per iteration, so the stop is decided by the norm it
    // measures) must meet that bound with fewer iterations than to the
    // relative tolerance (1e-10) on the same factors; GMRES-AMG meets it
    // too.
    {
      const std::vector<double> weights{1., 1e3, 1e6};
      const auto                weighted = [&](const auto &v) {
        double sum = 0.;
        for (unsigned int block = 0; block < Block::n_blocks; ++block)
          sum += Utilities::fixed_power<2>(weights[block] *
                                           v.block(block).l2_norm());
        return std::sqrt(sum);
      };
      parameters.type             = LinearSolverType::direct;
      parameters.direct_solver    = DirectSolver::mumps;
      parameters.reuse_iterations = 60;
      solver.setup();
      assemble(d, d.hanging_node_constraints, 2., K);
      K.vmult(b, x_exact);
      x = 0;
      solver.solve(K, x, b); // factorises
      assemble(d, d.hanging_node_constraints, 2.1, K);
      K.vmult(b, x_exact);
      const SolveAccuracy accuracy{weights, 1e-4 * weighted(b)};
      const auto          meets = [&](const unsigned int its) {
        TrilinosWrappers::MPI::BlockVector r = b, k_x = b;
        K.vmult(k_x, x);
        r -= k_x;
        const double ratio = weighted(r) / accuracy.enough;
        std::cout << "accuracy: " << its << " iterations, weighted residual "
                  << ratio << " of enough" << std::endl;
        return ratio <= 1.;
      };
      x                               = 0;
      const unsigned int its_relative = solver.solve(K, x, b);
      x                               = 0;
      const unsigned int its          = solver.solve(K, x, b, accuracy);
      out << "  GMRES on old factors to a weighted accuracy: met: "
          << Testing::yes_no(meets(its))
          << ", fewer iterations than to the relative tolerance: "
          << Testing::yes_no(its < its_relative) << std::endl;
      std::cout << "relative tolerance: " << its_relative << " iterations"
                << std::endl;
      parameters.type             = LinearSolverType::gmres_amg;
      parameters.reuse_iterations = 0;
      x                           = 0;
      const unsigned int its_amg  = solver.solve(K, x, b, accuracy);
      out << "  gmres-amg to a weighted accuracy: met: "
          << Testing::yes_no(meets(its_amg)) << std::endl;
    }

    // Whole blocks frozen: rows with a diagonal entry only.
    assemble(d, frozen_constraints(d, {Block::phase_field}), 1., K);
    run_all("s frozen: ", false);
    assemble(d, frozen_constraints(d, {Block::displacement}), 1., K);
    run_all("u frozen: ", false);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  // Body 0: [0,1]^3, 4x4x4 cells; body 1: a bar [1.5,5.5]x[0,0.05]^2 of 80
  // cells (cheap for the direct solvers).
  parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
  {
    Triangulation<dim> cube, box, both;
    GridGenerator::subdivided_hyper_rectangle(cube,
                                              {4, 4, 4},
                                              Point<dim>(0, 0, 0),
                                              Point<dim>(1, 1, 1));
    GridGenerator::subdivided_hyper_rectangle(box,
                                              {80, 1, 1},
                                              Point<dim>(1.5, 0, 0),
                                              Point<dim>(5.5, 0.05, 0.05));
    for (const auto &cell : box.active_cell_iterators())
      cell->set_material_id(1);
    GridGenerator::merge_triangulations(cube, box, both);
    tria.copy_triangulation(both);
  }
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned() && cell->center().norm() < 0.25)
      cell->set_refine_flag();
  tria.execute_coarsening_and_refinement();

  out << "alpha and s on body 0:" << std::endl;
  test_layout(tria, BodyFields{true, true}, true, out);
  out << "s on body 0, no alpha (an empty middle block):" << std::endl;
  test_layout(tria, BodyFields{false, true}, false, out);
  out << "u only, tangent scaled by 1e9:" << std::endl;
  test_layout(tria, BodyFields{false, false}, false, out, 1e9);
}
