#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <ductile_contact/discretisation/bernstein_element.h>
#include <ductile_contact/discretisation/discretisation.h>

namespace DuctileContact
{
  using namespace dealii;

  Discretisation::Discretisation(
    const parallel::distributed::Triangulation<dim> &tria,
    const unsigned int                               degree,
    const std::map<types::material_id, BodyFields>  &bodies,
    const FieldBasis                                 phase_field_basis,
    const FieldBasis                                 hardening_basis)
      : triangulation(tria)
      , degree(degree)
      , bodies(bodies)
      , dof_handler(tria)
  {
    // Four elements, indexed by fe_index(): (alpha?, s?) in {0,1}^2.
    for (unsigned int index = 0; index < 4; ++index)
      {
        const bool with_alpha = fields(index).hardening;
        const bool with_s     = fields(index).phase_field;
        const auto scalar     = [&](const bool       present,
                                const FieldBasis field_basis)
          -> std::unique_ptr<FiniteElement<dim>> {
          if (present && field_basis == FieldBasis::bernstein)
            return std::make_unique<BernsteinElement>(degree);
          if (present)
            return std::make_unique<FE_Q<dim>>(degree);
          return std::make_unique<FE_Nothing<dim>>();
        };
        fe_collection.push_back(
          FESystem<dim>(FE_Q<dim>(degree),
                        dim,
                        *scalar(with_alpha, hardening_basis),
                        1,
                        *scalar(with_s, phase_field_basis),
                        1));
        quadrature.push_back(QGauss<dim>(degree + 1));
        face_quadrature.push_back(QGauss<dim - 1>(degree + 1));

        LocalDofs                 dofs;
        const FiniteElement<dim> &fe = fe_collection[index];
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            if (c < dim)
              {
                dofs.u.push_back(i);
                dofs.u_component.push_back(c);
                const unsigned int node =
                  fe.system_to_component_index(i).second;
                if (dofs.u_by_component[c].size() <= node)
                  dofs.u_by_component[c].resize(node + 1);
                dofs.u_by_component[c][node] = i;
              }
            else if (c == Component::hardening)
              dofs.alpha.push_back(i);
            else
              dofs.s.push_back(i);
          }
        dofs_by_field.push_back(dofs);
      }
    // Curved geometry (a manifold other than flat, e.g. the round bar's
    // hull) is represented to the order of the elements; straight-sided
    // meshes keep the cheaper bilinear mapping.
    bool curved = false;
    for (const types::manifold_id id : tria.get_manifold_ids())
      curved = curved || id != numbers::flat_manifold_id;
    mapping.push_back(MappingQ<dim>(curved ? degree : 1));
  }



  unsigned int
  Discretisation::fe_index(const BodyFields &fields)
  {
    return (fields.hardening ? 1 : 0) + (fields.phase_field ? 2 : 0);
  }



  BodyFields
  Discretisation::fields(const unsigned int fe_index)
  {
    return BodyFields{(fe_index & 1) != 0, (fe_index & 2) != 0};
  }



  void
  Discretisation::setup()
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        cell->set_active_fe_index(fe_index(bodies.at(cell->material_id())));
    dof_handler.distribute_dofs(fe_collection);

    std::vector<unsigned int> block_component(Component::n_components,
                                              Block::displacement);
    block_component[Component::hardening]   = Block::hardening;
    block_component[Component::phase_field] = Block::phase_field;
    DoFRenumbering::component_wise(dof_handler, block_component);
    dofs_per_block =
      DoFTools::count_dofs_per_fe_block(dof_handler, block_component);

    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);
    owned_partitioning.clear();
    relevant_partitioning.clear();
    types::global_dof_index offset = 0;
    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      {
        owned_partitioning.push_back(
          locally_owned_dofs.get_view(offset, offset + dofs_per_block[b]));
        relevant_partitioning.push_back(
          locally_relevant_dofs.get_view(offset, offset + dofs_per_block[b]));
        offset += dofs_per_block[b];
      }

    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler,
                                            hanging_node_constraints);
    hanging_node_constraints.close();
  }
} // namespace DuctileContact
