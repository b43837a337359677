#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/assembly/point_products.h>
#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/materials/body_material.h>
#include <ductile_contact/materials/body_parameters.h>
#include <ductile_contact/phase_field/c0ip.h>

#include <array>
#include <vector>

namespace DuctileContact
{
  /**
   * F = I + Grad u as the material point's 3 x 3 tensor: in 2-D the
   * plane-strain F = [[I + Grad u, 0], [0, 1]].
   */
  inline dealii::Tensor<2, material_dim>
  deformation_gradient(const dealii::Tensor<2, dim> &grad_u)
  {
    dealii::Tensor<2, material_dim> F;
    for (unsigned int i = 0; i < material_dim; ++i)
      F[i][i] = 1.;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        F[i][j] += grad_u[i][j];
    return F;
  }

  /**
   * Row @p row of a material-point tensor (3 x 3: P, dP/dalpha, dr/dF, ...)
   * against the gradient @p g of a shape function, sum_{B < dim} row[B]
   * g[B]: in plane strain the out-of-plane column meets no gradient.
   */
  inline double
  in_plane(const dealii::Tensor<1, material_dim> &row,
           const dealii::Tensor<1, dim>          &g)
  {
    double v = 0.;
    for (unsigned int B = 0; B < dim; ++B)
      v += row[B] * g[B];
    return v;
  }

  /**
   * The rows one cell (or one C0IP face) adds to the system: the local
   * tangent, f_int and the Newton right-hand side -R over its DoFs, and per
   * DoF the size of the terms summed into it (AssemblyInfo::
   * residual_magnitude) and the scale of the local terms of alpha and s
   * (AssemblyInfo::residual_scale).
   */
  struct LocalRows
  {
    dealii::FullMatrix<double>                   matrix;
    dealii::Vector<double>                       f_int, rhs, magnitude;
    dealii::Vector<double>                       scale_alpha, scale_s;
    std::vector<dealii::types::global_dof_index> indices;
    /// What the points of a cell add to `matrix`, gathered by block and
    /// added by add_blocks() when the cell is done.
    CellTangentBlocks blocks;

    void
    reinit(const unsigned int n_dofs);

    /// Adds `blocks` to `matrix`.
    void
    add_blocks(const LocalDofs &dofs)
    {
      blocks.add_to(dofs, matrix);
    }
  };

  /// Shape functions of one quadrature point by field (scratch of the
  /// row functions).
  struct PointShapes
  {
    std::vector<dealii::Tensor<1, dim>> u_grad;
    /// The gradient of each node's scalar shape function by direction:
    /// node_grad[D][j] (the u_grad of the node's DoFs; the right factors
    /// of the u-u block, CellTangentBlocks).
    std::array<std::vector<double>, dim> node_grad;
    std::vector<double>                  alpha_value, s_value;
    std::vector<dealii::Tensor<1, dim>>  alpha_grad;

    /// The shapes of point @p q of @p fe_values for the DoFs @p dofs.
    void
    reinit(const dealii::FEValues<dim> &fe_values,
           const unsigned int           q,
           const LocalDofs             &dofs);
  };

  /// The crack driver of (51) at a point: the driving energy psi_D of the
  /// body's driver (crack_driving_energy()), its history maximum psi_H =
  /// max(psi_D, H_n) and branch, and the derivatives of the degradation.
  struct CrackDriver
  {
    DrivingEnergy psi;
    double        psi_H   = 0.;
    bool          loading = false;  ///< psi_H = psi_D (above H_n)
    double        g1 = 0., g2 = 0.; ///< g_k'(s), g_k''(s)
  };

  /**
   * The quadrature of the mass matrix of a Q2 cell with nodes on a contact
   * surface (@p massless_nodes, unit-cell positions): QGauss(@p n_gauss) in
   * every reference direction except the midpoint rule in directions d
   * chosen so that every such node lies on a face xi_d = 0 or 1 of one of
   * them (greedily, the direction holding most nodes first). The Q2 shape
   * functions of those faces vanish at xi_d = 1/2, so these nodes get no
   * mass, and the midpoint rule, exact for linear functions, keeps the
   * mass and centre of mass of a parallelepiped cell.
   */
  dealii::Quadrature<dim>
  redistributed_mass_rule(const std::vector<dealii::Point<dim>> &massless_nodes,
                          const unsigned int                     n_gauss);

  /// The coefficients of g_c gamma for a body that cracks.
  C0IPCoefficients
  crack_coefficients(const BodyParameters &body, const unsigned int degree);

  /// Displacement rows int P : Grad du dV at point @p q, and their
  /// tangent dP/dF (u-u block).
  void
  add_displacement_rows(const MaterialResponse &m,
                        const BodyParameters   &body,
                        const PointShapes      &shapes,
                        const LocalDofs        &dofs,
                        const unsigned int      q,
                        const double            JxW,
                        const bool              tangent,
                        LocalRows              &rows);

  /// Hardening rows (50) at one point, int dalpha r + y_0 l_p^2 grad
  /// dalpha . grad alpha dV, with their tangent (alpha rows and the u-alpha
  /// coupling).
  void
  add_hardening_rows(const MaterialResponse       &m,
                     const PlasticityParameters   &plastic,
                     const double                  gradient_coefficient,
                     const dealii::Tensor<1, dim> &grad_alpha,
                     const PointShapes            &shapes,
                     const LocalDofs              &dofs,
                     const unsigned int            q,
                     const double                  JxW,
                     const bool                    tangent,
                     LocalRows                    &rows);

  /// Phase-field rows of (51) at one point without a(s, ds) (added by
  /// add_crack_functional_rows()): int (eta_f (s - s_n)/dt + g_k'(s)
  /// psi^+_H) ds dV, with their tangent (s rows and the u-s coupling).
  void
  add_phase_field_rows(const MaterialResponse &m,
                       const CrackDriver      &driver,
                       const BodyParameters   &body,
                       const double            rate,
                       const double            dt,
                       const PointShapes      &shapes,
                       const LocalDofs        &dofs,
                       const unsigned int      q,
                       const double            JxW,
                       const bool              tangent,
                       LocalRows              &rows);

  /// The s-s block of the crack functional's cell matrix a_K (phase_field/
  /// c0ip.h; indexed by the positions in @p dofs.s): it depends on the cell
  /// and l_f only. @p fe_values needs values, gradients and hessians.
  dealii::FullMatrix<double>
  crack_functional_matrix(const dealii::FEValues<dim> &fe_values,
                          const Discretisation        &discretisation,
                          const BodyParameters        &body,
                          const LocalDofs             &dofs);

  /// The crack functional's cell terms a_K(s, ds) (linear in s) from its
  /// s-s block @p a_K with the local values @p s_values of all cell DoFs;
  /// returns a_K(s, s)/2.
  double
  add_crack_functional_rows(const dealii::FullMatrix<double> &a_K,
                            const dealii::Vector<double>     &cell_values,
                            const LocalDofs                  &dofs,
                            const bool                        tangent,
                            LocalRows                        &rows);
} // namespace DuctileContact
