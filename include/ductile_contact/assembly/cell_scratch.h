#pragma once

#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/assembly/assembly_data.h>
#include <ductile_contact/assembly/cell_rows.h>
#include <ductile_contact/assembly/quadrature_history.h>
#include <ductile_contact/discretisation/discretisation.h>

#include <memory>
#include <vector>

namespace DuctileContact
{
  /**
   * Scratch of one cell: evaluation objects and the solution at the
   * quadrature points. Elastic cells need gradients only; cells with alpha
   * or s also values and the points (crack measures); hessians (for the
   * bi-Laplacian) only the one-off crack functional matrices of a mesh. A copy
   * builds its own evaluation objects (one per thread).
   */
  struct CellScratch
  {
    explicit CellScratch(const Discretisation &discretisation)
        : discretisation(discretisation)
        , elastic_values(discretisation.mapping,
                         discretisation.fe_collection,
                         discretisation.quadrature,
                         dealii::update_gradients | dealii::update_JxW_values)
        , coupled_values(discretisation.mapping,
                         discretisation.fe_collection,
                         discretisation.quadrature,
                         dealii::update_values | dealii::update_gradients |
                           dealii::update_quadrature_points |
                           dealii::update_JxW_values)
        , crack_values(discretisation.mapping,
                       discretisation.fe_collection,
                       discretisation.quadrature,
                       dealii::update_values | dealii::update_gradients |
                         dealii::update_hessians | dealii::update_JxW_values)
        , mass_values(discretisation.mapping,
                      discretisation.fe_collection,
                      discretisation.quadrature,
                      dealii::update_values | dealii::update_JxW_values)
        , face_values(discretisation.mapping,
                      discretisation.fe_collection,
                      discretisation.face_quadrature,
                      dealii::update_values | dealii::update_quadrature_points |
                        dealii::update_JxW_values)
    {
      // deal.II 9.4's FEInterfaceValues is not hp-aware: one per element
      // that carries s, used on the faces between two such cells.
      for (unsigned int i = 0; i < discretisation.fe_collection.size(); ++i)
        interface_values.emplace_back(
          Discretisation::fields(i).phase_field
            ? std::make_unique<dealii::FEInterfaceValues<dim>>(
                discretisation.mapping[0],
                discretisation.fe_collection[i],
                discretisation.face_quadrature[i],
                dealii::update_gradients | dealii::update_hessians |
                  dealii::update_normal_vectors | dealii::update_JxW_values)
            : nullptr);
    }

    CellScratch(const CellScratch &other)
        : CellScratch(other.discretisation)
    {
    }

    const Discretisation     &discretisation;
    dealii::hp::FEValues<dim> elastic_values, coupled_values;
    /// With hessians, for the crack functional's cell matrices (built once
    /// per mesh, SystemAssembler::crack_matrix()).
    dealii::hp::FEValues<dim> crack_values;
    /// Values only, for the mass matrices of dynamic runs.
    dealii::hp::FEValues<dim>     mass_values;
    dealii::hp::FEFaceValues<dim> face_values;
    std::vector<std::unique_ptr<dealii::FEInterfaceValues<dim>>>
      interface_values;

    std::vector<dealii::Tensor<2, dim>> grad_u, grad_u_old;
    std::vector<double>                 alpha, s, s_old;
    std::vector<dealii::Tensor<1, dim>> grad_alpha;
    std::vector<const PointHistory *>   history_n;
    const PointHistory                  default_history;
    dealii::Vector<double>              cell_values;
    PointShapes                         shapes;
    dealii::FullMatrix<double>          face_matrix;
    /// Of the face being assembled: its s DoFs (interface numbering) and
    /// their values.
    std::vector<unsigned int> face_s_dofs;
    dealii::Vector<double>    face_s_values;
    /// Inertia of a dynamic step: the cell's scalar mass matrix and the
    /// local values of the vectors it multiplies.
    dealii::FullMatrix<double> mass, mass_shapes, mass_weighted;
    dealii::Vector<double>     inertia_u, inertia_target, inertia_other;
  };

  /// What one cell adds: its rows, the rows of the C0IP faces it owns, its
  /// share of the reduction and its averages.
  struct CellCopy
  {
    LocalRows              cell;
    std::vector<LocalRows> faces;
    unsigned int           n_faces = 0;
    AssemblyReduction      sums;
    bool                   has_averages = false;
    unsigned int           cell_index   = 0;
    float von_mises = 0, mean_stress = 0, mean_J = 0, crack_driving_force = 0;
    dealii::SymmetricTensor<2, material_dim> kirchhoff, cauchy, b, Cp;
  };

} // namespace DuctileContact
