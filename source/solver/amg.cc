// The AMG of the iterative solves: ML's settings and the near-null spaces
// of the displacement and phase-field blocks.
#include <deal.II/fe/mapping.h>

#include <ductile_contact/discretisation/bernstein_element.h>
#include <ductile_contact/solver/amg.h>

#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <Teuchos_ParameterList.hpp>
#include <map>
#include <vector>

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



  void
  initialize_amg(const TrilinosWrappers::SparseMatrix &A,
                 TrilinosWrappers::PreconditionAMG    &amg,
                 const LinearSolverParameters         &parameters,
                 const unsigned int                    degree,
                 const double                          aggregation_threshold,
                 const Epetra_MultiVector             *modes)
  {
    initialize_amg(A.trilinos_matrix(),
                   amg,
                   parameters,
                   degree,
                   aggregation_threshold,
                   modes);
  }



  void
  initialize_amg(const Epetra_RowMatrix            &A,
                 TrilinosWrappers::PreconditionAMG &amg,
                 const LinearSolverParameters      &parameters,
                 const unsigned int                 degree,
                 const double                       aggregation_threshold,
                 const Epetra_MultiVector          *modes)
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = (degree > 1);
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



  std::unique_ptr<Epetra_MultiVector>
  make_rigid_body_modes(const Discretisation &discretisation,
                        const bool            per_body)
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
    std::map<types::material_id, unsigned int> body_index;
    if (per_body)
      for (const auto &entry : discretisation.bodies)
        body_index.emplace(entry.first, body_index.size());
    const unsigned int n_sets = std::max<std::size_t>(1, body_index.size());
    auto modes = std::make_unique<Epetra_MultiVector>(map, n_modes * n_sets);

    std::vector<types::global_dof_index> dof_indices;
    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int set =
            body_index.empty() ? 0 : body_index.at(cell->material_id());
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
                (*modes)[set * n_modes + k][row] = mode[k];
            }
        }
    return modes;
  }



  std::unique_ptr<Epetra_MultiVector>
  make_phase_field_modes(const Discretisation &discretisation)
  {
    if (discretisation.dofs_per_block[Block::phase_field] == 0)
      return nullptr;
    const IndexSet &owned =
      discretisation.owned_partitioning[Block::phase_field];
    const types::global_dof_index offset =
      discretisation.dofs_per_block[Block::displacement] +
      discretisation.dofs_per_block[Block::hardening];
    const Epetra_Map map =
      block_map(owned, discretisation.dof_handler.get_communicator());
    auto modes = std::make_unique<Epetra_MultiVector>(map, 1 + dim);

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
              (*modes)[0][row] = 1.;
              for (unsigned int d = 0; d < dim; ++d)
                (*modes)[1 + d][row] = x[d];
            }
        }
    return modes;
  }
} // namespace DuctileContact
