#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/assembly/system_assembler.h>
#include <ductile_contact/coupled/coupling_parameters.h>
#include <ductile_contact/coupled/field_bound.h>
#include <ductile_contact/discretisation/boundary_condition.h>
#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/modules/physics_module.h>
#include <ductile_contact/solver/nonlinear_problem.h>

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace DuctileContact
{
  /**
   * The coupled problem R(u, alpha, s) = 0 of one load step (doc/model.md
   * sections 2-5) as Newton sees it (NonlinearProblem): it owns the system
   * (sparsity pattern with the C0IP couplings and those of the modules,
   * tangent, right-hand side, residual, internal force) and combines the
   * bulk cells and C0IP faces (SystemAssembler), the physics modules
   * (PhysicsModule: the contact pairs, if any) and the bounds on the DoFs
   * (FieldBound): s_n <= s <= 1 if Coupling/Irreversibility asks for it,
   * alpha_n <= alpha with Plasticity/Loading condition = bound.
   *
   * Prescribed displacements enter through the Newton constraints
   * (make_newton_constraints()): each iterate's update moves the boundary
   * values to those of the step. Blocks marked by freeze() keep their
   * values (the staggered scheme).
   *
   * Block tolerances (ResidualEvaluation): for u, rtol ||f_int,u|| + atol
   * force_scale (f_int holds the reactions, so the test is relative to the
   * load carried); for alpha and s, rtol S_b (S_b the local terms at
   * alpha = 1 or s = 1, AssemblyInfo::residual_scale).
   *
   * Each bound is engaged lazily: Newton iterates without it, and only if
   * its converged state violates the bound's KKT conditions (the
   * complementarity residual C of FieldBound above the block's tolerance)
   * is its active set switched on (converged() returns false); from then
   * on the block's rows of the norms are C, and every tangent assembly
   * refines the active set on the block (FieldBound::identify_active_set)
   * before the rows of the set are replaced by the bound. Engaged from the
   * start, the active set of the first, far-off iterates holds DoFs that
   * the solution leaves free, and steps that never touch the bound took 5
   * instead of 3 iterations (notched tension).
   */
  class CoupledProblem : public NonlinearProblem
  {
  public:
    CoupledProblem(const Discretisation                &discretisation,
                   const SystemAssembler               &assembler,
                   const std::deque<BoundaryCondition> &boundary_conditions,
                   const CouplingParameters            &coupling,
                   const double                         force_scale,
                   dealii::ConditionalOStream          &verbose_out,
                   dealii::TimerOutput                 &timer,
                   const std::vector<PhysicsModule *>  &modules = {});

    /// Sparsity pattern and vectors; call after every DoF distribution.
    void
    setup();

    /// Starts the load step @p step from @p u: every module's begin_step()
    /// on the state @p u (e.g. the contact search; a new sparsity pattern
    /// when a module's couplings changed).
    void
    begin_step(const StepData &step, const Vector &u);

    /// Blocks whose values are kept in the following solves.
    void
    freeze(const std::array<bool, Block::n_blocks> &frozen);

    /// f_int at the last converged state (hanging-node constraints only).
    const Vector &
    internal_force() const
    {
      return force;
    }

    /// What the assembly found at the last converged state.
    const AssemblyInfo &
    converged_info() const
    {
      return accepted_info;
    }

    /// Whether the phase-field block has unknowns.
    bool
    has_phase_field() const;

    // NonlinearProblem
    std::vector<std::string>
    block_names() const override;
    bool
    block_solved(const unsigned int b) const override;
    unsigned int
    n_nonempty_blocks() const override;
    void
    begin_solve() override;
    bool
    begin_iteration(const Vector &x) override;
    ResidualEvaluation
    assemble_system(const Vector &x) override;
    ResidualEvaluation
    assemble_residual(const Vector &x) override;
    bool
    keeps_tangent() const override;
    ResidualEvaluation
    assemble_right_hand_side(const Vector &x) override;
    bool
    converged(const Vector &x, const std::vector<double> &tolerances) override;
    std::vector<double>
    modify_linear_system(const Vector &x) override;
    const Matrix &
    system_matrix() const override
    {
      return tangent;
    }
    const Vector &
    system_rhs() const override
    {
      return newton_rhs;
    }
    const ConstrainedNodes *
    constrained_rows() const override
    {
      return &constrained;
    }
    void
    distribute(Vector &d) const override;
    std::string
    describe() const override;
    void
    compared_product(const Vector &d, Vector &k_d) const override;
    void
    compared_residual(const Vector &x, Vector &r) override;

  private:
    /// Bulk and module terms at #u_ghosted into @p targets (each module
    /// under the timer "<name>: integration, tangent" or ", residual").
    AssemblyInfo
    assemble(const AssemblyTargets &targets);

    /// -R and R (and the tangent into @p matrix unless null) at @p x with
    /// the branches recorded, the bound's rows if engaged: assemble_system()
    /// and, without the matrix, assemble_right_hand_side().
    ResidualEvaluation
    assemble_recording(const Vector &x, Matrix *matrix);

    /// Norms and scales of #residual at the state of @p info.
    ResidualEvaluation
    evaluation(const AssemblyInfo &info) const;

    std::vector<double>
    residual_norms() const;

    /// The active sets of the engaged bounds at @p x, each refined on its
    /// block, put into the fresh tangent, right-hand side and residual.
    void
    apply_bounds(const Vector &x);

    /// Whether a bound of the current solve is engaged.
    bool
    any_bound_engaged() const;

    /// The sparse LU of the active-set sweeps of @p block's bound.
    DirectSolve &
    bound_solver(const unsigned int block);

    const Discretisation &discretisation;
    /// Why the prescribed values of the current iterate are unusable ("":
    /// they are finite).
    std::string                          prescribed_fault;
    const SystemAssembler               &assembler;
    const std::deque<BoundaryCondition> &boundary_conditions;
    const CouplingParameters            &coupling;
    const double                         force_scale;
    dealii::ConditionalOStream          &verbose_out;
    dealii::TimerOutput                 &timer;
    const std::vector<PhysicsModule *>   modules;

    StepData                          step;
    std::array<bool, Block::n_blocks> frozen{{false, false, false}};
    dealii::AffineConstraints<double> constraints;

    dealii::TrilinosWrappers::BlockSparseMatrix tangent;
    /// The name of tangent's sparsity pattern (AssemblyTargets::pattern).
    std::uint64_t tangent_pattern = 0;
    Vector        newton_rhs, residual, force, u_ghosted;
    /// The modules' constraint rows in #tangent.
    ConstrainedNodes constrained;

    AssemblyInfo last_info, accepted_info;
    /// The branches of the last tangent assembly (frozen in the line
    /// search and the tangent check).
    BranchRecord branches;

    /// A bound of the current solve and where it stands.
    struct BoundState
    {
      FieldBound                      bound;
      bool                            engaged    = false;
      bool                            applied    = false;
      dealii::types::global_dof_index n_on_bound = 0;
      /// Whether a chord step may keep the tangent with this bound's rows
      /// while its active set stays (alpha's; the phase field's set follows
      /// a growing crack and goes with a fresh tangent every iteration).
      bool chord = false;
      /// Whether the last chord assembly found the tangent's active set.
      bool rows_kept = true;
    };
    /// The bounds' rows for a chord step (assemble_right_hand_side()).
    void
    keep_bound_rows(const Vector &x);
    /// The sparse LU of each block's bound's active-set sweeps (double
    /// precision, kept so that its analysis carries over), made when first
    /// needed.
    std::array<std::unique_ptr<DirectSolve>, Block::n_blocks> bound_solvers;
    /// The bounds of the current solve (those that are on).
    std::vector<BoundState> bounds;
    /// Per block: the last converged solve held DoFs on its bound, so the
    /// next one engages it from its first iteration instead of first
    /// converging without it.
    std::array<bool, Block::n_blocks> bound_last_solve{{false, false, false}};
  };
} // namespace DuctileContact
