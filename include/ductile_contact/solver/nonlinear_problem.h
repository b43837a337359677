#pragma once

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/solver/constrained_rows.h>

#include <limits>
#include <string>
#include <vector>

namespace DuctileContact
{
  /**
   * What a nonlinear problem reports of one residual evaluation, per block
   * b of its unknowns. Newton's tolerance of block b is
   *
   *   tol_b = rtol * relative_scale_b + atol * absolute_scale_b,
   *
   * (rtol, atol: Newton/Relative and Absolute tolerance), and the block's
   * residual norm cannot fall much below round_off_b (eps times the size of
   * the terms summed into it; 0 for a block that is not solved for).
   */
  struct ResidualEvaluation
  {
    std::vector<double> norms;
    std::vector<double> relative_scale;
    std::vector<double> absolute_scale;
    std::vector<double> round_off;
    /// False when the state cannot be accepted whatever its residual (then
    /// #inadmissible says why, e.g. "inverts an element").
    bool        admissible = true;
    std::string inadmissible;
    /// Points of the state whose branch (of a non-smooth law) differs from
    /// the one frozen by the last assemble_system(): with none, the
    /// residual of assemble_residual() is the true one.
    unsigned int branch_changes = 0;
  };

  /**
   * The interface through which NewtonSolver sees a problem R(x) = 0 on a
   * block vector x: it knows blocks, norms and a linear system, nothing of
   * the physics behind them. One Newton iteration calls, in this order,
   *
   *   begin_iteration(x)       constraints of the iterate (prescribed
   *                            values reached through the update);
   *   assemble_system(x)       tangent K, right-hand side -R and R; the
   *                            branches of non-smooth terms are recorded
   *                            (assemble_right_hand_side(x) in a chord
   *                            step: -R and R only, K kept);
   *   [converged(x, tol)]      when every block meets its tolerance;
   *   modify_linear_system(x)  the problem's own row modifications;
   *   linear solve K d = -R,   distribute(d);
   *   assemble_residual(x + l d) for the line search (recorded branches).
   *
   * A problem whose converged() returns false changes its equations at
   * that state (e.g. it engages an inequality constraint): Newton goes on
   * and restarts the record of its convergence rate.
   */
  class NonlinearProblem
  {
  public:
    using Vector = dealii::TrilinosWrappers::MPI::BlockVector;
    using Matrix = dealii::TrilinosWrappers::BlockSparseMatrix;

    virtual ~NonlinearProblem() = default;

    /// Short names of the blocks, for the screen.
    virtual std::vector<std::string>
    block_names() const = 0;

    /// Whether block @p b has unknowns and is solved for.
    virtual bool
    block_solved(const unsigned int b) const = 0;

    /// Number of blocks that have unknowns (solved for or not).
    virtual unsigned int
    n_nonempty_blocks() const = 0;

    /// Called once at the start of each Newton solve.
    virtual void
    begin_solve()
    {
    }

    /// Constraints of the iterate @p x; returns whether prescribed values
    /// are still pending (not reached by @p x beyond round-off: Newton then
    /// takes the next update without the line search's merit test).
    virtual bool
    begin_iteration(const Vector &x) = 0;

    /// Tangent, right-hand side and residual at @p x, with the problem's
    /// active row modifications.
    virtual ResidualEvaluation
    assemble_system(const Vector &x) = 0;

    /// Residual at @p x with the branches of the last assemble_system().
    virtual ResidualEvaluation
    assemble_residual(const Vector &x) = 0;

    /// Whether the next iteration may keep the linear system's matrix of
    /// the last assemble_system() (a chord step, Newton/Tangent update):
    /// false while the problem's own row modifications depend on the
    /// iterate.
    virtual bool
    keeps_tangent() const
    {
      return false;
    }
    /// Right-hand side and residual at @p x with its branches recorded, as
    /// assemble_system() makes them, the matrix left as the last
    /// assemble_system() made it: for a chord step (where keeps_tangent())
    /// and for the first guesses of a step (NewtonSolver::best_start),
    /// whose residuals it compares.
    virtual ResidualEvaluation
    assemble_right_hand_side(const Vector &x)
    {
      (void)x;
      AssertThrow(false, dealii::ExcNotImplemented());
      return {};
    }
    /// Called when every block of the state @p x meets @p tolerances;
    /// false when the problem changes its equations there.
    virtual bool
    converged(const Vector &x, const std::vector<double> &tolerances)
    {
      (void)x;
      (void)tolerances;
      return true;
    }

    /// Applies row modifications that converged() switched on to the
    /// system of the current iterate @p x (nothing if already applied) and
    /// returns the residual norms after them.
    virtual std::vector<double>
    modify_linear_system(const Vector &x) = 0;

    virtual const Matrix &
    system_matrix() const = 0;

    virtual const Vector &
    system_rhs() const = 0;

    /// The rows of system_matrix() that hold constraints (null: none),
    /// which an iterative linear solver may eliminate.
    virtual const ConstrainedNodes *
    constrained_rows() const
    {
      return nullptr;
    }

    /// Sets the constrained entries of a solution @p d of the linear
    /// system.
    virtual void
    distribute(Vector &d) const = 0;

    /// Text for the iteration line (state of the problem's own sets), may
    /// be empty.
    virtual std::string
    describe() const
    {
      return {};
    }

    /// For the tangent check: K @p d and R(@p x) with the branches of the
    /// last assemble_system(), both with the rows that the linear system
    /// does not hold (constrained or modified) set to zero.
    virtual void
    compared_product(const Vector &d, Vector &k_d) const = 0;
    virtual void
    compared_residual(const Vector &x, Vector &r) = 0;
  };
} // namespace DuctileContact
