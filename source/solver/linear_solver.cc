#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/exceptions.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_solver.h>

#include <ductile_contact/discretisation/bernstein_element.h>
#include <ductile_contact/solver/block_preconditioner.h>
#include <ductile_contact/solver/linear_solver.h>

#include <Epetra_CrsGraph.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// The Epetra map of the indices @p owned of one block (block-local
    /// numbers), on which the near-null-space vectors of its AMG live.
    Epetra_Map
    block_map(const IndexSet &owned, const MPI_Comm comm)
    {
      std::vector<int> ids;
      for (const auto i : owned)
        ids.push_back(static_cast<int>(i));
      return Epetra_Map(
        -1, static_cast<int>(ids.size()), ids.data(), 0, Epetra_MpiComm(comm));
    }
  } // namespace



  LinearSolver::LinearSolver(const LinearSolverParameters &parameters,
                             const Discretisation         &discretisation)
      : parameters(parameters)
      , discretisation(discretisation)
  {
  }



  void
  LinearSolver::setup()
  {
    // deal.II 9.4 has no DoFTools::extract_rigid_body_modes: build them from
    // the support points. Modes at a DoF of component c and point x: the
    // translations e_r, and a rotation in each coordinate plane (i, j),
    // u_i = -x_j, u_j = x_i: (-y, x) in 2-D; (-y, x, 0), (-z, 0, x),
    // (0, -z, y) in 3-D.
    constexpr unsigned int n_modes = dim * (dim + 1) / 2;
    const IndexSet        &owned =
      discretisation.owned_partitioning[Block::displacement];
    const Epetra_Map map =
      block_map(owned, discretisation.dof_handler.get_communicator());
    rigid_body_modes = std::make_unique<Epetra_MultiVector>(map, n_modes);

    std::vector<types::global_dof_index> dof_indices;
    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const FiniteElement<dim> &fe = cell->get_fe();
          dof_indices.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              // The displacement block starts at 0, so global = block index.
              if (c >= dim || !owned.is_element(dof_indices[i]))
                continue;
              const Point<dim> x =
                discretisation.mapping[0].transform_unit_to_real_cell(
                  cell, fe.unit_support_point(i));
              const int row = map.LID(static_cast<int>(dof_indices[i]));
              double    mode[n_modes] = {};
              mode[c]                 = 1.;
              unsigned int r          = dim;
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = a + 1; b < dim; ++b, ++r)
                  mode[r] = c == a ? -x[b] : c == b ? x[a] : 0.;
              for (unsigned int k = 0; k < n_modes; ++k)
                (*rigid_body_modes)[k][row] = mode[k];
            }
        }

    make_phase_field_modes();

    // The DoFs changed: the monolithic copy is rebuilt on the next solve,
    // and so is the direct solver's analysis.
    monolithic.reset();
    mumps.reset();
    fallback.reset();
    reuse_iterations_left = 0;
    reuses_to_skip        = 0;
    skipped_reuses        = 0;
    failed_reuses         = 0;
    failed_reuse_solves   = 0;
    last_reuse_iterations = 0;
  }



  void
  LinearSolver::make_phase_field_modes()
  {
    phase_field_modes.reset();
    if (discretisation.dofs_per_block[Block::phase_field] == 0)
      return;
    const IndexSet &owned =
      discretisation.owned_partitioning[Block::phase_field];
    const types::global_dof_index offset =
      discretisation.dofs_per_block[Block::displacement] +
      discretisation.dofs_per_block[Block::hardening];
    const Epetra_Map map =
      block_map(owned, discretisation.dof_handler.get_communicator());
    phase_field_modes = std::make_unique<Epetra_MultiVector>(map, 1 + dim);

    std::vector<types::global_dof_index> dof_indices;
    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const FiniteElement<dim> &fe = cell->get_fe();
          dof_indices.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              if (fe.system_to_component_index(i).first !=
                    Component::phase_field ||
                  !owned.is_element(dof_indices[i] - offset))
                continue;
              // The point whose coordinates are the DoF's coefficient of
              // the linear functions: the support point, or for the
              // Bernstein basis (no support points) its Greville point.
              const auto                base = fe.system_to_base_index(i);
              const FiniteElement<dim> &base_fe =
                fe.base_element(base.first.first);
              const auto *bernstein =
                dynamic_cast<const BernsteinElement *>(&base_fe);
              const Point<dim> unit =
                bernstein ? bernstein->greville_points()[base.second]
                          : base_fe.unit_support_point(base.second);
              const Point<dim> x =
                discretisation.mapping[0].transform_unit_to_real_cell(cell,
                                                                      unit);
              const int row =
                map.LID(static_cast<int>(dof_indices[i] - offset));
              (*phase_field_modes)[0][row] = 1.;
              for (unsigned int d = 0; d < dim; ++d)
                (*phase_field_modes)[1 + d][row] = x[d];
            }
        }
  }



  unsigned int
  LinearSolver::solve(const TrilinosWrappers::BlockSparseMatrix &K,
                      TrilinosWrappers::MPI::BlockVector        &x,
                      const TrilinosWrappers::MPI::BlockVector  &b,
                      const SolveAccuracy                       &accuracy,
                      const bool                                 same_matrix)
  {
    Assert(accuracy.block_weights.empty() ||
             accuracy.block_weights.size() == b.n_blocks(),
           ExcDimensionMismatch(accuracy.block_weights.size(), b.n_blocks()));
    for (unsigned int i = 0; i < accuracy.block_weights.size(); ++i)
      Assert(b.block(i).size() == 0 || accuracy.block_weights[i] > 0.,
             ExcMessage("every block with DoFs needs a positive weight"));
    if (discretisation.dofs_per_block[Block::hardening] == 0 &&
        discretisation.dofs_per_block[Block::phase_field] == 0)
      return solve_displacement(K, x, b, accuracy, same_matrix);
    if (parameters.type == LinearSolverType::direct)
      return solve_coupled_direct(K, x, b, accuracy, same_matrix);
    // cg-amg too: the coupled tangent is not symmetric (documented with the
    // parameter).
    return solve_coupled_iterative(K, x, b, accuracy);
  }



  double
  LinearSolver::plain_tolerance(const double         rhs_norm,
                                const SolveAccuracy &accuracy) const
  {
    double tolerance = parameters.relative_tolerance * rhs_norm;
    if (!accuracy.block_weights.empty())
      tolerance = std::max(tolerance,
                           accuracy.enough /
                             *std::max_element(accuracy.block_weights.begin(),
                                               accuracy.block_weights.end()));
    return tolerance;
  }



  void
  LinearSolver::initialize_amg(const TrilinosWrappers::SparseMatrix &A,
                               TrilinosWrappers::PreconditionAMG    &amg,
                               const double              aggregation_threshold,
                               const Epetra_MultiVector *modes) const
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = (discretisation.degree > 1);
    data.smoother_sweeps       = parameters.smoother_sweeps;
    data.aggregation_threshold = aggregation_threshold;
    data.smoother_type =
      name_of(amg_smoother_names(), parameters.smoother).c_str();
    if (!modes)
      {
        amg.initialize(A, data);
        return;
      }
    Teuchos::ParameterList              ml_list;
    std::unique_ptr<Epetra_MultiVector> unused_modes;
    data.set_parameters(ml_list, unused_modes, A);
    ml_list.set("null space: type", "pre-computed");
    ml_list.set("null space: dimension", modes->NumVectors());
    ml_list.set("null space: vectors", modes->Values());
    amg.initialize(A, ml_list);
  }



  unsigned int
  LinearSolver::solve_displacement(const TrilinosWrappers::BlockSparseMatrix &K,
                                   TrilinosWrappers::MPI::BlockVector        &x,
                                   const TrilinosWrappers::MPI::BlockVector  &b,
                                   const SolveAccuracy &accuracy,
                                   const bool           same_matrix)
  {
    const auto &A  = K.block(Block::displacement, Block::displacement);
    auto       &xu = x.block(Block::displacement);
    const auto &bu = b.block(Block::displacement);

    // One block, one weight: the weighted bound is a plain one.
    if (parameters.type == LinearSolverType::direct)
      return solve_direct(A,
                          xu,
                          bu,
                          nullptr,
                          accuracy.block_weights.empty()
                            ? 0.
                            : accuracy.enough /
                                accuracy.block_weights[Block::displacement],
                          same_matrix);

    TrilinosWrappers::PreconditionAMG amg;
    initialize_amg(A,
                   amg,
                   parameters.aggregation_threshold,
                   rigid_body_modes.get());

    SolverControl control(parameters.max_iterations,
                          plain_tolerance(bu.l2_norm(), accuracy));
    if (parameters.type == LinearSolverType::cg_amg)
      {
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        cg.solve(A, xu, bu, amg);
      }
    else
      {
        // Right preconditioning, so that the stopping test is on the true
        // residual ||b - A x|| (left preconditioning tests ||P^-1 (b - A x)||,
        // which the AMG scales by ~1/E: the solve stopped far too early and
        // Newton converged linearly).
        SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
          control,
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
            parameters.gmres_restart, true));
        gmres.solve(A, xu, bu, amg);
      }
    return control.last_step();
  }



  void
  LinearSolver::print_summary(std::ostream &out) const
  {
    if (!mumps)
      return;
    const MumpsSolver::Statistics &s = mumps->statistics();
    out << "MUMPS (" << name_of(factorisation_names(), parameters.factorisation)
        << ", " << name_of(direct_ordering_names(), parameters.ordering)
        << " ordering, "
        << name_of(factor_precision_names(), parameters.precision)
        << " precision): " << s.analyses << " analyses " << s.analysis_time
        << " s, " << s.factorisations << " factorisations " << s.factor_time
        << " s, " << s.solves << " solves " << s.solve_time << " s ("
        << (s.solves > 0 ? s.bytes_sent / s.solves : 0.)
        << " bytes of solution sent per solve by this rank); "
        << s.factor_entries << " entries in the last factors; " << failed_reuses
        << " GMRES runs on old factors missed the tolerance ("
        << failed_reuse_solves << " solves)";
    if (fallback)
      out << "; " << fallback->statistics().factorisations
          << " double-precision factorisations where the single-precision "
             "factors did not converge";
    out << std::endl;
  }



  unsigned int
  LinearSolver::fallback_factorisations() const
  {
    return fallback ? fallback->statistics().factorisations : 0;
  }



  std::pair<unsigned int, unsigned int>
  LinearSolver::failed_reuse_counts() const
  {
    return {failed_reuses, failed_reuse_solves};
  }



  unsigned int
  LinearSolver::solve_direct(const TrilinosWrappers::SparseMatrix &A,
                             TrilinosWrappers::MPI::Vector        &x,
                             const TrilinosWrappers::MPI::Vector  &b,
                             const TrilinosWrappers::MPI::Vector  *weights,
                             const double                          enough,
                             const bool                            same_matrix)
  {
    if (parameters.direct_solver == DirectSolver::mumps)
      {
        if (!mumps || !mumps->made_for(parameters.factorisation,
                                       parameters.ordering,
                                       parameters.precision))
          mumps = std::make_unique<MumpsSolver>(
            discretisation.dof_handler.get_communicator(),
            parameters.factorisation,
            parameters.ordering,
            parameters.precision);
        // Old factors serve until GMRES has made `Factorisation reuse`
        // iterations with them in all, or fails within those left. When
        // the factors of the previous matrix fail, the next 1, 2, 4, ...
        // solves factorise at once. Old factors are not tried when fewer
        // iterations are left than the last solve with them needed (most
        // such tries ran out of budget). Counts, not times: the same run
        // takes the same path.
        if (reuse_iterations_left > 0 &&
            reuse_iterations_left >= last_reuse_iterations &&
            skipped_reuses >= reuses_to_skip &&
            (same_matrix ? mumps->has_factors()
                         : mumps->has_factors_for(A.trilinos_matrix())))
          {
            const bool fresh =
              reuse_iterations_left == parameters.reuse_iterations;
            const unsigned int solves_before = mumps->statistics().solves;
            const unsigned int n             = solve_with_old_factors(
              A, x, b, weights, enough, reuse_iterations_left, true);
            if (n == 0)
              {
                ++failed_reuses;
                failed_reuse_solves +=
                  mumps->statistics().solves - solves_before;
              }
            if (n > 0)
              {
                reuse_iterations_left -= std::min(n, reuse_iterations_left);
                reuses_to_skip        = 0;
                last_reuse_iterations = n;
                return n;
              }
            // The matrix changes too fast for reuse now: back off. Older
            // factors may just be old.
            if (fresh)
              {
                reuses_to_skip = std::max(1u, 2 * reuses_to_skip);
                skipped_reuses = 0;
              }
          }
        else
          ++skipped_reuses;
        mumps->factorize(A.trilinos_matrix());
        reuse_iterations_left = parameters.reuse_iterations;
        if (mumps->exact())
          {
            mumps->solve(x.trilinos_vector(), b.trilinos_vector());
            return 1;
          }
        // Single-precision factors of this matrix: GMRES to the tolerance,
        // within the reuse budget (one restart cycle if reuse is off).
        const unsigned int n =
          solve_with_old_factors(A,
                                 x,
                                 b,
                                 weights,
                                 enough,
                                 std::max(parameters.reuse_iterations,
                                          gmres_restart),
                                 false);
        if (n > 0)
          {
            reuse_iterations_left -= std::min(n, reuse_iterations_left);
            return n;
          }
        // Too ill-conditioned for them: double-precision factors, exact.
        if (!fallback)
          fallback = std::make_unique<MumpsSolver>(
            discretisation.dof_handler.get_communicator(),
            parameters.factorisation,
            parameters.ordering);
        fallback->factorize(A.trilinos_matrix());
        fallback->solve(x.trilinos_vector(), b.trilinos_vector());
        reuse_iterations_left = 0;
        return 1;
      }
    SolverControl                                  control(1, 0.);
    TrilinosWrappers::SolverDirect::AdditionalData data(
      false,
      parameters.direct_solver == DirectSolver::amesos_klu ? "Amesos_Klu"
                                                           : "Amesos_Mumps");
    TrilinosWrappers::SolverDirect direct(control, data);
    direct.solve(A, x, b);
    return 1;
  }



  namespace
  {
    /**
     * Stops GMRES on old factors once it cannot make its budget: from the
     * 5th iteration on, if the residual, falling at the mean rate of the
     * last 5 iterations, would need more than twice the iterations left to
     * reach the tolerance. Such runs (the factors of a matrix that has
     * changed too much) reduce the residual by 1e1-1e2 in their first
     * iterations where the tolerance asks for 1e8, and ran out the whole
     * budget: on prm/sent_coarse.prm 51 runs spent 2623 of 6186 triangular
     * solves. With the rule 79 runs give up, after 860 solves in all (of
     * 4507), with 229 factorisations instead of 255; the same Newton
     * iterations and answers, 370 s instead of 410 (benchmarks/performance,
     * where the rules tried are compared on logged histories). The check
     * values are global norms, so every rank stops at the same iteration.
     */
    class ProjectedGmresControl : public SolverControl
    {
    public:
      ProjectedGmresControl(const unsigned int max_iterations,
                            const double       tolerance,
                            const bool         give_up_early)
          : SolverControl(max_iterations, tolerance, false, false)
          , give_up_early(give_up_early)
      {
      }

      State
      check(const unsigned int step, const double value) override
      {
        const State state = SolverControl::check(step, value);
        history.push_back(value);
        constexpr unsigned int window = 5;
        if (state != iterate || !give_up_early || step < window ||
            history.size() <= window)
          return state;
        const double before = history[history.size() - 1 - window];
        if (!(value > 0.) || !(before > 0.))
          return state;
        const double rate   = std::pow(value / before, 1. / window);
        const double needed = rate < 1.
                                ? std::log(tolerance() / value) / std::log(rate)
                                : std::numeric_limits<double>::infinity();
        if (needed > 2. * (max_steps() - step))
          lcheck = failure;
        return lcheck;
      }

    private:
      const bool          give_up_early;
      std::vector<double> history;
    };
  } // namespace



  unsigned int
  LinearSolver::solve_with_old_factors(
    const TrilinosWrappers::SparseMatrix &A,
    TrilinosWrappers::MPI::Vector        &x,
    const TrilinosWrappers::MPI::Vector  &b,
    const TrilinosWrappers::MPI::Vector  *weights,
    const double                          enough,
    const unsigned int                    max_iterations,
    const bool                            give_up_early)
  {
    // The factors of an earlier matrix P as a right preconditioner of the
    // row-weighted system W A x = W b (W the diagonal of the weights, the
    // identity without them), as P W^-1: GMRES then tests the true
    // residual ||W (b - A x)||, and x is the solution of A x = b.
    // GMRES starts from r = b - A x with x = 0 here: the first product
    // with x is zero, not computed (one mat-vec per solve, ~2 % of
    // prm/block_on_plate.prm).
    struct WeightedMatrix
    {
      const TrilinosWrappers::SparseMatrix &A;
      const TrilinosWrappers::MPI::Vector  *weights;
      const TrilinosWrappers::MPI::Vector  *zero_start;
      mutable bool                          started = false;
      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        if (!started && &src == zero_start)
          {
            started = true;
            dst     = 0.;
            return;
          }
        started = true;
        A.vmult(dst, src);
        if (weights)
          dst.scale(*weights);
      }
    };
    struct OldFactors
    {
      MumpsSolver                          *mumps;
      const TrilinosWrappers::MPI::Vector  *inverse_weights;
      mutable TrilinosWrappers::MPI::Vector unweighted;
      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        if (!inverse_weights)
          {
            mumps->solve(dst.trilinos_vector(), src.trilinos_vector());
            return;
          }
        unweighted = src;
        unweighted.scale(*inverse_weights);
        mumps->solve(dst.trilinos_vector(), unweighted.trilinos_vector());
      }
    };
    TrilinosWrappers::MPI::Vector weighted_b, inverse_weights;
    if (weights)
      {
        weighted_b = b;
        weighted_b.scale(*weights);
        inverse_weights = *weights;
        for (auto &w : inverse_weights)
          w = 1. / w;
      }
    const TrilinosWrappers::MPI::Vector &rhs = weights ? weighted_b : b;
    ProjectedGmresControl                control(
      max_iterations,
      std::max(parameters.relative_tolerance * rhs.l2_norm(), enough),
      give_up_early);
    const WeightedMatrix matrix{A, weights, &x};
    const OldFactors     factors{mumps.get(),
                             weights ? &inverse_weights : nullptr,
                                 {}};
    x = 0.;
    try
      {
        if (mumps->exact())
          {
            SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
              control,
              SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
                gmres_restart, true));
            gmres.solve(matrix, x, rhs, factors);
          }
        else
          {
            // Single-precision triangular solves round their result, so
            // the preconditioner is not one fixed linear map: flexible
            // GMRES keeps the preconditioned vectors, and its residual
            // stays the true one.
            SolverFGMRES<TrilinosWrappers::MPI::Vector> fgmres(
              control,
              SolverFGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
                gmres_restart));
            fgmres.solve(matrix, x, rhs, factors);
          }
      }
    catch (const SolverControl::NoConvergence &)
      {
        return 0;
      }
    return std::max(1u, control.last_step());
  }
} // namespace DuctileContact
