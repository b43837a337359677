#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/app/checkpoint.h>
#include <ductile_contact/app/energy_account.h>
#include <ductile_contact/app/run_parameters.h>
#include <ductile_contact/app/step_controller.h>
#include <ductile_contact/assembly/quadrature_history.h>
#include <ductile_contact/assembly/system_assembler.h>
#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/discretisation/mesh_adaptation.h>
#include <ductile_contact/modules/physics_module.h>
#include <ductile_contact/output/probe_points.h>
#include <ductile_contact/output/statistics.h>
#include <ductile_contact/output/tee_stream.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace DuctileContact
{
  class CoupledProblem;
  class CoupledSolver;
  class LinearSolver;
  class NewtonSolver;
  struct StepReport;
  class SolutionWriter;
  class TimeIntegrator;

  /**
   * One run, quasi-static or dynamic (doc/model.md section 6; the inertia
   * of a dynamic run is TimeIntegrator's): the mesh and the objects of
   * the coupled problem are set up, then the load-step loop: a step is
   * solved by the CoupledSolver; a failed step is repeated with a smaller
   * increment (StepController), an accepted one commits the quadrature-
   * point history and the contact state (a failed attempt leaves none),
   * adds to the EnergyAccount, writes a row of the statistics table and
   * the output, and prints a ProgressLine.
   * Reaction forces are sums of f_int (condensed with the hanging-node
   * constraints) over the DoFs a boundary constrains.
   *
   * With Mesh/Adaptive refinement, a converged step is first offered to
   * MeshAdaptation: if it refines the mesh, the accepted state is carried
   * over and the step is solved again (adapt_mesh(), predictor-corrector).
   *
   * Every Checkpoint/Interval accepted steps, and when a SIGTERM or SIGINT
   * arrived during a step, the state is written to a Checkpoint; a run
   * constructed with a checkpoint folder continues from it.
   */
  class Simulation
  {
  public:
    /// @p resume_from: the checkpoint folder to continue from ("": start
    /// at t = 0).
    Simulation(const RunParameters &parameters,
               const MPI_Comm       comm,
               TeeStream           &log,
               const std::string   &resume_from = "");
    ~Simulation();

    /// Exit codes of run().
    enum ExitCode : int
    {
      finished = 0, ///< the end time is reached
      gave_up  = 2, ///< a step failed at the minimum step size
      stopped  = 3  ///< stopped by SIGTERM or SIGINT after a complete step
    };

    /// Returns an ExitCode.
    int
    run();

  private:
    void
    setup();
    /// At the end of a run: the direct solver's work and the ranks' peak
    /// memory (collective).
    void
    print_resources();
    /// Load stepping/Predictor: the first guess @p u of a step (the last
    /// accepted state on entry) moved along the last increment scaled by
    /// @p ratio (the ratio of the step sizes); returns the other first
    /// guesses Newton chooses among (best linear: the displacements'
    /// extrapolation alone).
    std::vector<dealii::TrilinosWrappers::MPI::BlockVector>
    predict(double ratio, dealii::TrilinosWrappers::MPI::BlockVector &u) const;
    /// Distributes the DoFs and sizes everything that depends on them:
    /// once in setup() and after every refinement of the mesh.
    void
    setup_dofs();
    /// The corrector of adaptive refinement: flags cells by the converged
    /// trial state @p trial of the step that starts from the accepted
    /// state; if any are flagged, refines them and carries the accepted
    /// state (u, the quadrature-point history, the last increment) to the
    /// new mesh, and @p trial with it (the next attempt's initial guess);
    /// the last force is assembled anew. Returns whether the mesh changed.
    bool
    adapt_mesh(dealii::TrilinosWrappers::MPI::BlockVector &trial);
    /// After a transfer: the force of the last accepted step (the
    /// trapezoidal rule of the external work) assembled on the new mesh.
    void
    accepted_force_on_new_mesh();
    /// The columns cells, dofs and refinements (of the step) of an
    /// adaptive run.
    void
    add_mesh_columns();
    /// After a transfer: alpha_n of the history at each point set to the
    /// carried alpha field of #old_solution there (>= 0), the value the
    /// commit of an accepted step would have given it.
    void
    align_hardening_history();
    /// The coarse mesh and, when resuming, the checkpoint's refined mesh.
    void
    create_mesh();
    /// The state at t = 0, its statistics row and output.
    void
    start();
    /// The state of the checkpoint resume_from.
    void
    restore();
    /// Writes a checkpoint of the last accepted step.
    void
    write_checkpoint();
    /// The run state that is not on the mesh, as written to state.bin.
    std::string
    run_state() const;
    void
    load_run_state(const std::string &text);
    /// The columns of the boundaries (mean displacement, force) and of
    /// the probes.
    void
    add_boundary_columns(const double t);
    /// max_alpha, min_alpha_change_yielding, max_s, min_s_change.
    void
    add_field_columns();
    void
    add_solver_columns(const StepReport &report, const unsigned int cutbacks);
    /// Whether block @p b has unknowns.
    bool
    has_block(const unsigned int b) const;
    /// Marks the converged step from @p u_old to @p u (increment @p dt) as
    /// failed in @p report when s rose by more than Load stepping/Maximum
    /// phase-field increment at a DoF.
    void
    limit_phase_field_increment(
      const dealii::TrilinosWrappers::MPI::BlockVector &u,
      const dealii::TrilinosWrappers::MPI::BlockVector &u_old,
      const double                                      dt,
      StepReport                                       &report) const;
    /// In a dynamic run: the local error estimate of the converged step
    /// from @p u_old to @p u (increment @p dt) into #local_error; marks the
    /// step as failed in @p report when it exceeds Load stepping/Local
    /// error tolerance. Returns the factor the next increment may be of
    /// this one (infinite without a tolerance).
    double
    limit_local_error(const dealii::TrilinosWrappers::MPI::BlockVector &u,
                      const dealii::TrilinosWrappers::MPI::BlockVector &u_old,
                      const double                                      dt,
                      StepReport                                       &report);
    void
    write_output(const unsigned int step, const double t);
    /// Commits the accepted state #u of @p step_data (the step started
    /// from @p u_old).
    void
    accept_step(const StepData                                   &step_data,
                const dealii::TrilinosWrappers::MPI::BlockVector &u_old);
    void
    record_step(const unsigned int step,
                const double       t,
                const double       dt,
                const StepReport  &report,
                const unsigned int cutbacks);
    /// Stores the history of the accepted state u (step @p step_data) and
    /// returns its energies; also refreshes the output cell data.
    AssemblyInfo
    commit(const StepData &step_data);
    /// Area-weighted mean displacement and integrated traction per
    /// boundary with conditions.
    struct BoundaryIntegrals
    {
      dealii::Tensor<1, dim> mean_displacement;
      dealii::Tensor<1, dim> traction_force;
    };
    std::vector<BoundaryIntegrals>
    boundary_integrals(const dealii::TrilinosWrappers::MPI::BlockVector &u,
                       const double t) const;

    const RunParameters       &parameters;
    const MPI_Comm             comm;
    const std::string          resume_from;
    TeeStream                 &log;
    dealii::ConditionalOStream pcout;
    dealii::ConditionalOStream verbose_out;
    dealii::TimerOutput        timer;

    dealii::parallel::distributed::Triangulation<dim>            triangulation;
    std::map<dealii::types::material_id, const BodyParameters *> bodies;
    std::unique_ptr<Discretisation>                              discretisation;
    std::unique_ptr<SystemAssembler>                             assembler;
    std::unique_ptr<LinearSolver>                                linear_solver;
    /// The physics beside the bulk (make_physics_modules()).
    std::vector<std::unique_ptr<PhysicsModule>> modules;
    std::unique_ptr<ProbePoints>                probes;
    std::unique_ptr<CoupledProblem>             problem;
    std::unique_ptr<NewtonSolver>               newton;
    std::unique_ptr<CoupledSolver>              solver;
    std::unique_ptr<SolutionWriter>             writer;
    /// The inertia of a dynamic run (null when quasi-static).
    std::unique_ptr<TimeIntegrator> dynamics;
    /// Mesh/Adaptive refinement (null when off).
    std::unique_ptr<MeshAdaptation> adaptation;
    /// Whether Maximum cells has held back refinement (noted once).
    bool cell_limit_noted = false;
    /// Refinements of the current load step so far.
    unsigned int refinements = 0;
    Statistics   statistics;

    /// Owned DoFs of each constrained component on each boundary with
    /// conditions (empty for the other components).
    std::vector<std::array<dealii::IndexSet, dim>> boundary_dofs;

    dealii::TrilinosWrappers::MPI::BlockVector u, u_ghosted, internal_force,
      old_solution;
    QuadratureHistory history;
    CellQuantities    cell_quantities;
    AssemblyInfo      committed;
    EnergyAccount     energy;
    /// min over s DoFs of s_n+1 - s_n of the last step (irreversibility).
    double min_phase_field_change = 0.;
    double max_phase_field        = 0.;
    double wall_start             = 0.;

    // The load-step loop.
    StepController controller;
    double         t    = 0.;
    unsigned int   step = 0;
    /// The local error estimate of the last step (dynamic runs).
    double local_error = 0.;
    /// The last accepted increment and its step size (linear predictor).
    dealii::TrilinosWrappers::MPI::BlockVector last_increment;
    double                                     last_dt = 0.;
    /// Wall, assembly and linear-solve time [s].
    struct Times
    {
      double wall = 0., assembly = 0., solve = 0.;
    };
    /// Those of the runs before a resume, added to this run's.
    Times earlier;
    /// The statistics' timing columns: this run's times plus earlier.
    Times
               cumulative_times() const;
    Checkpoint checkpoints;
  };
} // namespace DuctileContact
