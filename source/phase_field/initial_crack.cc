#include <deal.II/base/function_parser.h>

#include <ductile_contact/core/expression.h>
#include <ductile_contact/discretisation/bernstein_element.h>
#include <ductile_contact/phase_field/initial_crack.h>

#include <algorithm>
#include <map>
#include <memory>

namespace DuctileContact
{
  using namespace dealii;

  bool
  set_initial_crack(const Discretisation               &discretisation,
                    const std::deque<BodyParameters>   &bodies,
                    TrilinosWrappers::MPI::BlockVector &u)
  {
    std::map<types::material_id, std::unique_ptr<FunctionParser<dim>>> cracks;
    for (const BodyParameters &b : bodies)
      if (b.fracture && !b.crack.initial_crack.empty())
        {
          auto f = std::make_unique<FunctionParser<dim>>(1);
          f->initialize(coordinate_variables(), b.crack.initial_crack, {});
          cracks.emplace(b.material_id, std::move(f));
        }
    if (cracks.empty())
      return false;

    const IndexSet &owned = discretisation.locally_owned_dofs;
    std::vector<types::global_dof_index> indices;
    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      {
        const auto crack = cracks.find(cell->material_id());
        if (!cell->is_locally_owned() || crack == cracks.end())
          continue;
        const FiniteElement<dim> &fe = cell->get_fe();
        indices.resize(fe.n_dofs_per_cell());
        cell->get_dof_indices(indices);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          if (fe.system_to_component_index(i).first == Component::phase_field &&
              owned.is_element(indices[i]))
            {
              // The node of this DoF, from the base element (FESystem's
              // own support points need every base to have them); for a
              // Bernstein coefficient its Greville point (the coefficient
              // is the value there, the quasi-interpolant that keeps
              // 0 <= s <= 1).
              const auto                base = fe.system_to_base_index(i);
              const FiniteElement<dim> &scalar =
                fe.base_element(base.first.first);
              const auto *bernstein =
                dynamic_cast<const BernsteinElement *>(&scalar);
              const Point<dim> X =
                discretisation.mapping[0].transform_unit_to_real_cell(
                  cell,
                  bernstein != nullptr
                    ? bernstein->greville_points()[base.second]
                    : scalar.unit_support_point(base.second));
              u(indices[i]) = std::clamp(crack->second->value(X), 0., 1.);
            }
      }
    u.compress(VectorOperation::insert);
    return true;
  }
} // namespace DuctileContact
