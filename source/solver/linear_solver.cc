#include <deal.II/base/exceptions.h>

#include <ductile_contact/solver/amg.h>
#include <ductile_contact/solver/linear_solver.h>

namespace DuctileContact
{
  using namespace dealii;



  LinearSolver::LinearSolver(const LinearSolverParameters &parameters,
                             const Discretisation         &discretisation)
      : context{parameters,
                discretisation,
                nullptr,
                nullptr,
                DirectSolve(discretisation.dof_handler.get_communicator(),
                            DirectSolveSettings::of(parameters))}
      , displacement_direct(context)
      , displacement_krylov(context)
      , coupled_direct(context)
      , coupled_krylov(context)
  {
  }



  void
  LinearSolver::setup()
  {
    context.rigid_body_modes =
      make_rigid_body_modes(context.discretisation,
                            context.parameters.rigid_body_modes ==
                              RigidBodyModes::per_body);
    context.phase_field_modes = make_phase_field_modes(context.discretisation);
    // The DoFs changed: the monolithic copy is rebuilt on the next solve,
    // and so is the direct solver's analysis.
    context.direct.reset();
    for (SolveStrategy *s :
         std::initializer_list<SolveStrategy *>{&displacement_direct,
                                                &displacement_krylov,
                                                &coupled_direct,
                                                &coupled_krylov})
      s->reset();
  }



  SolveStrategy &
  LinearSolver::strategy()
  {
    const Discretisation &d      = context.discretisation;
    const bool            direct = type() == LinearSolverType::direct;
    if (d.dofs_per_block[Block::hardening] == 0 &&
        d.dofs_per_block[Block::phase_field] == 0)
      return direct ? static_cast<SolveStrategy &>(displacement_direct)
                    : displacement_krylov;
    return direct ? static_cast<SolveStrategy &>(coupled_direct)
                  : coupled_krylov;
  }



  unsigned int
  LinearSolver::solve(const TrilinosWrappers::BlockSparseMatrix &K,
                      TrilinosWrappers::MPI::BlockVector        &x,
                      const TrilinosWrappers::MPI::BlockVector  &b,
                      const SolveAccuracy                       &accuracy,
                      const bool                                 same_matrix,
                      const ConstrainedNodes                    *constrained)
  {
    Assert(accuracy.block_weights.empty() ||
             accuracy.block_weights.size() == b.n_blocks(),
           ExcDimensionMismatch(accuracy.block_weights.size(), b.n_blocks()));
    for (unsigned int i = 0; i < accuracy.block_weights.size(); ++i)
      Assert(b.block(i).size() == 0 || accuracy.block_weights[i] > 0.,
             ExcMessage("every block with DoFs needs a positive weight"));
    // The parameters may change between solves (a resumed run, the tests).
    context.direct.configure(DirectSolveSettings::of(context.parameters));
    context.constrained = constrained;
    return strategy().solve(K, x, b, accuracy, same_matrix);
  }



  LinearSolverType
  LinearSolver::type() const
  {
    return context.parameters.resolved_type(
      context.discretisation.dof_handler.n_dofs());
  }



  std::string
  LinearSolver::describe() const
  {
    const std::string name = name_of(linear_solver_type_names(), type());
    if (context.parameters.type != LinearSolverType::automatic)
      return name;
    const types::global_dof_index n =
      context.discretisation.dof_handler.n_dofs();
    return name + " (automatic: " + std::to_string(n) +
           (type() == LinearSolverType::direct ? " <= " : " > ") +
           std::to_string(context.parameters.direct_limit) + " unknowns)";
  }



  void
  LinearSolver::print_summary(std::ostream &out) const
  {
    context.direct.print_summary(out);
  }



  unsigned int
  LinearSolver::fallback_factorisations() const
  {
    return context.direct.fallback_factorisations();
  }



  std::pair<unsigned int, unsigned int>
  LinearSolver::failed_reuse_counts() const
  {
    return {context.direct.failed_reuse_counts()};
  }
} // namespace DuctileContact
