#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/lac/full_matrix.h>

#include <ductile_contact/core/types.h>
#include <ductile_contact/phase_field/regularisation.h>

#include <functional>

namespace DuctileContact
{
  /**
   * Coefficients of the symmetric bilinear form of the crack regularisation
   * (doc/model.md (3) and (51)):
   *
   *   a(s, v) = int mass s v + gradient grad s . grad v
   *                 + bilaplacian Lap s Lap v dV          (cells)
   *           + bilaplacian sum_F int_F ( -{Lap v}[d_n s] - [d_n v]{Lap s}
   *                 + penalty / h_F [d_n v][d_n s] ) dA   (interior faces)
   *
   * the C0 interior-penalty (C0IP) form of the bi-Laplacian in its
   * Laplacian (not Hessian) form for FE_Q of degree p >= 2; no boundary-face
   * terms, so the natural conditions (10) hold weakly. For the crack
   * functional gamma: mass = 1/(2 l_f), gradient = l_f, bilaplacian =
   * l_f^3/2 (times g_c), and int gamma dV = a(s, s)/2. The second-order
   * (AT2) functional is the same form with mass = 1/l_f, gradient = l_f
   * and bilaplacian = 0, and then no face terms.
   */
  struct C0IPCoefficients
  {
    double mass        = 0.;
    double gradient    = 0.;
    double bilaplacian = 0.;
    /// gamma_IP, see default_c0ip_penalty().
    double penalty = 9.;

    /// The coefficients of g_c gamma for the length scale l_f and the
    /// regularisation @p order.
    static C0IPCoefficients
    crack_functional(const double         l_f,
                     const double         g_c,
                     const unsigned int   degree,
                     const Regularisation order = Regularisation::fourth_order);
  };

  /**
   * Default penalty gamma_IP = (d/2) p (p+1): 1.5 p(p+1) in 3-D, p(p+1) in
   * 2-D. doc/model.md
   * suggests p(p+1), the 2-D value of deal.II step-47; in 3-D with the
   * Laplacian form that is at the edge of stability: for Q2 the
   * manufactured solution's error jumps up at h = 1/8 (a near-singular
   * mode) with gamma = 6 and 7, and converges at the expected orders from
   * gamma = 8 on (tests/c0ip_manufactured, benchmarks/phase_field). The
   * factor d/2 = 1.5 is the dimension scaling of the trace inverse
   * inequality.
   */
  double
  default_c0ip_penalty(const unsigned int degree);

  /**
   * Adds the cell terms of a(s, v) for the scalar field @p s of the element
   * behind @p fe_values (which needs values, gradients, hessians and JxW) to
   * @p cell_matrix (indexed by the cell's DoFs; other components untouched).
   */
  void
  add_c0ip_cell_terms(const dealii::FEValues<dim>              &fe_values,
                      const dealii::FEValuesExtractors::Scalar &s,
                      const C0IPCoefficients                   &c,
                      dealii::FullMatrix<double>               &cell_matrix);

  /**
   * Adds the face terms of a(s, v) on one interior face to @p face_matrix
   * (indexed by the interface DoFs of @p fiv, which needs gradients,
   * hessians, normals and JxW). @p h_inverse is the mean of 1/h of the two
   * cells in the face-normal direction. Adds nothing when
   * c.bilaplacian = 0 (the second-order functional).
   */
  void
  add_c0ip_face_terms(const dealii::FEInterfaceValues<dim>     &fiv,
                      const dealii::FEValuesExtractors::Scalar &s,
                      const C0IPCoefficients                   &c,
                      const double                              h_inverse,
                      dealii::FullMatrix<double>               &face_matrix);

  /**
   * Calls @p work(cell, face_no, neighbor_face_info) once for every interior
   * face of the mesh that touches a locally owned cell, in MPI parallel: a
   * face between equal cells is visited from the cell with the smaller id
   * (owned) or smaller subdomain (ghost neighbour); a face with hanging
   * nodes from the finer side. @p fiv is reinitialised on the face before
   * the call and the mean inverse normal extent is passed. Only faces
   * between cells with the same active FE index are visited (C0IP terms
   * couple a field only where it lives on both sides).
   */
  void
  for_each_interior_face(
    const dealii::DoFHandler<dim>                     &dof_handler,
    dealii::FEInterfaceValues<dim>                    &fiv,
    const std::function<void(const dealii::FEInterfaceValues<dim> &fiv,
                             const double h_inverse)> &work,
    const unsigned int                                 active_fe_index = 0);

  /**
   * The faces of for_each_interior_face() that the locally owned @p cell
   * visits (the rule there decides which of two cells takes a face), for
   * an assembly that adds the face terms of a cell with its cell terms.
   */
  void
  for_each_owned_interior_face(
    const dealii::DoFHandler<dim>::active_cell_iterator &cell,
    dealii::FEInterfaceValues<dim>                      &fiv,
    const std::function<void(const dealii::FEInterfaceValues<dim> &fiv,
                             const double h_inverse)>   &work);
} // namespace DuctileContact
