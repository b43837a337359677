#include <deal.II/base/exceptions.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_solver.h>

#include <ductile_contact/solver/linear_solver.h>

#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <Teuchos_ParameterList.hpp>

namespace DuctileContact
{
  using namespace dealii;

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
    // the support points. Mode r at a DoF of component c and point x:
    // translations e_r, rotations (-y, x, 0), (0, -z, y), (z, 0, -x).
    const IndexSet &owned =
      discretisation.owned_partitioning[Block::displacement];
    std::vector<int> global_ids;
    for (const auto i : owned)
      global_ids.push_back(static_cast<int>(i));
    const Epetra_Map map(-1,
                         static_cast<int>(global_ids.size()),
                         global_ids.data(),
                         0,
                         Epetra_MpiComm(
                           discretisation.dof_handler.get_communicator()));
    rigid_body_modes = std::make_unique<Epetra_MultiVector>(map, 6);

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
              const int row     = map.LID(static_cast<int>(dof_indices[i]));
              double    mode[6] = {0, 0, 0, 0, 0, 0};
              mode[c]           = 1.;
              const double rot[3][3] = {{-x[1], x[0], 0.},
                                        {0., -x[2], x[1]},
                                        {x[2], 0., -x[0]}};
              for (unsigned int r = 0; r < 3; ++r)
                mode[3 + r] = rot[r][c];
              for (unsigned int r = 0; r < 6; ++r)
                (*rigid_body_modes)[r][row] = mode[r];
            }
        }
  }



  unsigned int
  LinearSolver::solve(const TrilinosWrappers::BlockSparseMatrix &K,
                      TrilinosWrappers::MPI::BlockVector        &x,
                      const TrilinosWrappers::MPI::BlockVector  &b)
  {
    AssertThrow(discretisation.dofs_per_block[Block::hardening] == 0 &&
                  discretisation.dofs_per_block[Block::phase_field] == 0,
                ExcMessage("The linear solver handles the displacement block "
                           "only; alpha and s have no equations yet."));
    const auto &A  = K.block(Block::displacement, Block::displacement);
    auto       &xu = x.block(Block::displacement);
    const auto &bu = b.block(Block::displacement);

    if (parameters.type == "direct")
      {
        SolverControl                                  control(1, 0.);
        TrilinosWrappers::SolverDirect::AdditionalData data(
          false, parameters.direct_solver);
        TrilinosWrappers::SolverDirect direct(control, data);
        direct.solve(A, xu, bu);
        return 1;
      }

    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = (discretisation.degree > 1);
    data.smoother_sweeps       = parameters.smoother_sweeps;
    data.aggregation_threshold = parameters.aggregation_threshold;
    Teuchos::ParameterList              ml_list;
    std::unique_ptr<Epetra_MultiVector> unused_modes;
    data.set_parameters(ml_list, unused_modes, A);
    ml_list.set("null space: type", "pre-computed");
    ml_list.set("null space: dimension", rigid_body_modes->NumVectors());
    ml_list.set("null space: vectors", rigid_body_modes->Values());
    TrilinosWrappers::PreconditionAMG amg;
    amg.initialize(A, ml_list);

    SolverControl control(parameters.max_iterations,
                          parameters.relative_tolerance * bu.l2_norm());
    if (parameters.type == "cg-amg")
      {
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        cg.solve(A, xu, bu, amg);
      }
    else
      {
        SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
          control,
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(100));
        gmres.solve(A, xu, bu, amg);
      }
    return control.last_step();
  }
} // namespace DuctileContact
