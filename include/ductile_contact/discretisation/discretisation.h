#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/affine_constraints.h>

#include <ductile_contact/core/types.h>
#include <ductile_contact/discretisation/field_basis.h>

#include <array>
#include <map>
#include <vector>

namespace DuctileContact
{
  /// Which fields a body carries besides the displacement.
  struct BodyFields
  {
    bool hardening   = false; ///< alpha (plasticity)
    bool phase_field = false; ///< s (fracture)
  };

  /// The local DoFs of one element of the FE collection by field: the
  /// displacement DoFs with their component, alpha's and s's.
  struct LocalDofs
  {
    std::vector<unsigned int> u, u_component, alpha, s;
    /// The displacement DoFs of each component ordered by node (the index
    /// of their shape function in the scalar element).
    std::array<std::vector<unsigned int>, dim> u_by_component;
  };

  /**
   * The finite element layout of doc/model.md section 1 on one distributed
   * mesh: an hp::FECollection whose elements are FESystem(FE_Q(p)^3, alpha, s),
   * where alpha and s are Q_p on bodies that carry them and FE_Nothing
   * elsewhere: each FE_Q or, with FieldBasis::bernstein, BernsteinElement
   * (a bound on its DoFs, 0 <= s <= 1 or alpha_n <= alpha, then holds at
   * every point). DoFs are numbered block-wise [u | alpha | s] (Block::*), so a
   * scene without plasticity has an empty alpha block, not zero unknowns.
   *
   * The mapping is MappingQ(p) on every cell when the mesh has curved
   * manifolds (the round bar, Mesh/Gmsh/Curved boundaries) and MappingQ(1)
   * otherwise.
   *
   * Owns the DoFHandler, the index sets per block and the hanging-node
   * constraints; knows nothing of the equations.
   */
  class Discretisation
  {
  public:
    Discretisation(
      const dealii::parallel::distributed::Triangulation<dim> &tria,
      const unsigned int                                       degree,
      const std::map<dealii::types::material_id, BodyFields>  &bodies,
      const FieldBasis phase_field_basis = FieldBasis::lagrange,
      const FieldBasis hardening_basis   = FieldBasis::lagrange);

    /// Distributes and renumbers the DoFs; call after every mesh change.
    void
    setup();

    /// Index in the FE collection for a body with these fields.
    static unsigned int
    fe_index(const BodyFields &fields);

    /// The fields carried by the element @p fe_index of the collection.
    static BodyFields
    fields(const unsigned int fe_index);

    /// The fields a cell carries.
    template <typename CellIterator>
    BodyFields
    cell_fields(const CellIterator &cell) const
    {
      return fields(cell->active_fe_index());
    }

    /// The local DoFs by field of the element @p fe_index.
    const LocalDofs &
    local_dofs(const unsigned int fe_index) const
    {
      return dofs_by_field[fe_index];
    }

    const dealii::parallel::distributed::Triangulation<dim> &triangulation;
    const unsigned int                                       degree;
    const std::map<dealii::types::material_id, BodyFields>   bodies;

    dealii::hp::FECollection<dim>      fe_collection;
    dealii::hp::QCollection<dim>       quadrature;
    dealii::hp::QCollection<dim - 1>   face_quadrature;
    dealii::hp::MappingCollection<dim> mapping;
    dealii::DoFHandler<dim>            dof_handler;

    std::vector<dealii::types::global_dof_index> dofs_per_block;
    std::vector<dealii::IndexSet>                owned_partitioning;
    std::vector<dealii::IndexSet>                relevant_partitioning;
    dealii::IndexSet                             locally_owned_dofs;
    dealii::IndexSet                             locally_relevant_dofs;

    /// Hanging-node constraints only (closed).
    dealii::AffineConstraints<double> hanging_node_constraints;

    /// Per element of #fe_collection.
    std::vector<LocalDofs> dofs_by_field;

    const dealii::FEValuesExtractors::Vector displacement{
      Component::first_displacement};
    const dealii::FEValuesExtractors::Scalar hardening{Component::hardening};
    const dealii::FEValuesExtractors::Scalar phase_field{
      Component::phase_field};
  };
} // namespace DuctileContact
