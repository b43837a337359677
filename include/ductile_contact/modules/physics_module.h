#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <ductile_contact/assembly/assembly_data.h>
#include <ductile_contact/output/output_parameters.h>
#include <ductile_contact/output/statistics.h>
#include <ductile_contact/solver/constrained_rows.h>

#include <string>
#include <utility>
#include <vector>

namespace DuctileContact
{
  /**
   * A physics that adds its own terms to the coupled system R(u, alpha, s)
   * = 0 beside the bulk cells and faces (SystemAssembler), with a state of
   * its own that follows the load steps: today the mortar contact pairs
   * (ContactProblem, doc/model.md section 5). Simulation, CoupledProblem
   * and CoupledSolver drive every module through this lifecycle and never
   * ask which physics it is:
   *
   *  - mesh: setup() after every DoF distribution; written_rows() and
   *    add_couplings() for the sparsity pattern;
   *  - step: begin_step() (true when its couplings changed, so that the
   *    pattern is rebuilt), assemble() into the bulk targets at every
   *    Newton iteration, add_constrained_rows() after a tangent, fault()
   *    when a state must not be accepted, outer_update() between Newton
   *    solves (e.g. Uzawa updates of the augmented Lagrangian), commit() on
   *    an accepted step;
   *  - account and output: dissipation() for the energy balance,
   *    add_columns() for the statistics, write_output();
   *  - checkpoint: committed_state() and restore_committed_state(), the
   *    series of its output files;
   *  - mesh change: keep_committed_state() before, transfer_committed_state()
   *    after, add_committed_forces() for the accepted force on the new mesh.
   */
  class PhysicsModule
  {
  public:
    /// Per output series: (time, file name) records.
    using OutputSeries =
      std::vector<std::vector<std::pair<double, std::string>>>;

    virtual ~PhysicsModule() = default;

    /// What the module is, in messages and timer sections ("contact").
    virtual std::string
    name() const = 0;

    /// After every DoF distribution.
    virtual void
    setup() = 0;

    /// Rows beyond the locally relevant ones that assemble() writes.
    virtual dealii::IndexSet
    written_rows() const = 0;

    /// Adds the couplings of the current state to @p sp.
    virtual void
    add_couplings(
      dealii::TrilinosWrappers::BlockSparsityPattern &sp,
      const dealii::AffineConstraints<double>        &constraints) const = 0;

    /// At the start of a load step, on the state @p u (ghosted); true when
    /// the couplings changed (the sparsity pattern must be rebuilt).
    virtual bool
    begin_step(const dealii::TrilinosWrappers::MPI::BlockVector &u) = 0;

    /// Whether assemble() reads the bulk terms, which must then be
    /// compressed before it.
    virtual bool
    needs_compressed_bulk() const = 0;

    /// Adds its terms at @p u (ghosted) to @p targets, which hold the bulk
    /// terms, and compresses them.
    virtual void
    assemble(const dealii::TrilinosWrappers::MPI::BlockVector &u,
             const dealii::AffineConstraints<double>          &constraints,
             const AssemblyTargets                            &targets) = 0;

    /// Adds the rows of the last tangent assembly that hold constraints
    /// (none by default).
    virtual void
    add_constrained_rows(ConstrainedNodes &nodes) const
    {
      (void)nodes;
    }

    /// Why the state of the last assembly cannot be accepted ("" when it
    /// can).
    virtual std::string
    fault() const = 0;

    /// Outer updates per load step at most (0: it has none).
    virtual unsigned int
    max_outer_updates() const = 0;

    /// After a converged Newton solve: true when the module's equations
    /// hold as they are; otherwise it updates them for another solve and
    /// writes what it found to @p report.
    virtual bool
    outer_update(std::string &report) = 0;

    /// The state of the accepted step becomes the committed one.
    virtual void
    commit() = 0;

    /// The energy it has dissipated up to the last assembly [J] (the
    /// energy account's D_c).
    virtual double
    dissipation() const = 0;

    /// Adds its columns to the statistics row.
    virtual void
    add_columns(Statistics &statistics) const = 0;

    /// Writes its output files of step @p step (collective).
    virtual void
    write_output(const std::string &directory,
                 const OutputFormat format,
                 const unsigned int step,
                 const double       time) = 0;

    /// The committed state for a checkpoint.
    virtual std::vector<double>
    committed_state() const = 0;

    /// Restores committed_state() after setup().
    virtual void
    restore_committed_state(const std::vector<double> &state) = 0;

    /// The series of its output files (checkpoints).
    virtual OutputSeries &
    output_series() = 0;

    /// Before a mesh change: keeps the committed state.
    virtual void
    keep_committed_state() = 0;

    /// After a mesh change and setup(): the kept state on the new mesh,
    /// @p accepted the accepted step's solution there.
    virtual void
    transfer_committed_state(
      const dealii::TrilinosWrappers::MPI::BlockVector &accepted) = 0;

    /// Adds the forces of the committed state at @p u (ghosted) to @p force
    /// as assemble() adds them to the internal force.
    virtual void
    add_committed_forces(const dealii::TrilinosWrappers::MPI::BlockVector &u,
                         dealii::TrilinosWrappers::MPI::BlockVector &force) = 0;
  };
} // namespace DuctileContact
