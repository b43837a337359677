#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/app/run_parameters.h>
#include <ductile_contact/assembly/quadrature_history.h>
#include <ductile_contact/assembly/system_assembler.h>
#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/output/probe_points.h>
#include <ductile_contact/output/statistics.h>
#include <ductile_contact/output/tee_stream.h>

#include <map>
#include <memory>
#include <string>

namespace DuctileContact
{
  class ContactProblem;
  class CoupledProblem;
  class CoupledSolver;
  class LinearSolver;
  class NewtonSolver;
  struct StepReport;
  class SolutionWriter;

  /**
   * One quasi-static run: mesh, discretisation, and the load-step loop with
   * cut-back (model.md section 6). An accepted step commits the quadrature-
   * point history (a failed attempt leaves none). Per accepted step it
   * records reactions, mean boundary displacements, the energies (elastic
   * Psi^e, plastic work W_p and hardening energy, fracture energy g_c int
   * gamma, viscous phase-field dissipation D_f), external work (trapezoidal
   * rule, W += 1/2 (f_n + f_n+1) . (u_n+1 - u_n)) and the energy-balance
   * residual W_ext - Psi^e - W_p - g_c int gamma - D_f - D_c (D_c the
   * frictional dissipation (47) of the contact pairs), and writes the
   * statistics table and output.
   * Reaction forces are sums of f_int (condensed with the hanging-node
   * constraints) over the DoFs a boundary constrains.
   */
  class Simulation
  {
  public:
    Simulation(const RunParameters &parameters,
               const MPI_Comm       comm,
               TeeStream           &log);
    ~Simulation();

    /// Returns 0 when the end time is reached, 2 when the run gave up.
    int
    run();

  private:
    void
    setup();
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
    TeeStream                 &log;
    dealii::ConditionalOStream pcout;
    dealii::ConditionalOStream verbose_out;
    dealii::TimerOutput        timer;

    dealii::parallel::distributed::Triangulation<dim>            triangulation;
    std::map<dealii::types::material_id, const BodyParameters *> bodies;
    std::unique_ptr<Discretisation>                              discretisation;
    std::unique_ptr<SystemAssembler>                             assembler;
    std::unique_ptr<LinearSolver>                                linear_solver;
    std::unique_ptr<ContactProblem>                              contact;
    std::unique_ptr<ProbePoints>                                 probes;
    std::unique_ptr<CoupledProblem>                              problem;
    std::unique_ptr<NewtonSolver>                                newton;
    std::unique_ptr<CoupledSolver>                               solver;
    std::unique_ptr<SolutionWriter>                              writer;
    Statistics                                                   statistics;

    /// Owned DoFs of each constrained component on each boundary with
    /// conditions (empty for the other components).
    std::vector<std::array<dealii::IndexSet, dim>> boundary_dofs;

    dealii::TrilinosWrappers::MPI::BlockVector u, u_ghosted, internal_force,
      previous_internal_force, old_solution;
    QuadratureHistory history;
    CellQuantities    cell_quantities;
    AssemblyInfo      committed;
    double            external_work         = 0.;
    double            plastic_work          = 0.;
    double            fracture_viscous_work = 0.;
    /// Sum of AssemblyInfo::history_work_increment over accepted steps.
    double history_driving_work = 0.;
    /// min over s DoFs of s_n+1 - s_n of the last step (irreversibility).
    double min_phase_field_change = 0.;
    double max_phase_field        = 0.;
    double wall_start             = 0.;
  };
} // namespace DuctileContact
