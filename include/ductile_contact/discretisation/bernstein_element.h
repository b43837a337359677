#pragma once

#include <deal.II/base/point.h>
#include <deal.II/fe/fe_bernstein.h>
#include <deal.II/lac/full_matrix.h>

#include <ductile_contact/core/types.h>

#include <memory>
#include <vector>

namespace DuctileContact
{
  /**
   * The space Q_p in the Bernstein basis (deal.II's FE_Bernstein), made
   * usable on adaptively refined meshes. Its basis functions are
   * non-negative and sum to 1, so a field is a convex combination of its
   * coefficients c_i at every point,
   *
   *   min_i c_i <= u(x) <= max_i c_i   on each cell,
   *
   * and a bound imposed on the DoFs (0 <= s <= 1, alpha >= alpha_n) holds
   * everywhere, not only at nodes (doc/model.md section 4.2).
   *
   * FE_Bernstein has neither prolongation nor restriction matrices, and its
   * hanging-node constraints set the fine coefficients to the coarse field's
   * values at the fine Greville points, which is exact for p = 1 only. Here:
   *  - prolongation: exact subdivision of the coarse polynomial (de
   *    Casteljau), FETools::compute_embedding_matrices;
   *  - hanging-node (subface) constraints: exact subdivision of the coarse
   *    face polynomial, by collocation at the fine face's Greville points;
   *  - restriction (coarsening): each coefficient becomes the fine field's
   *    value at its Greville point g_i (the control point abscissae k/p):
   *    Schoenberg's variation-diminishing quasi-interpolant, exact for
   *    multilinear fields, second order otherwise, and bound-preserving
   *    (values of a field in [a, b] are coefficients in [a, b]).
   */
  class BernsteinElement : public dealii::FE_Bernstein<dim>
  {
  public:
    explicit BernsteinElement(const unsigned int degree);

    std::unique_ptr<dealii::FiniteElement<dim>>
    clone() const override;

    const dealii::FullMatrix<double> &
    get_prolongation_matrix(
      const unsigned int                 child,
      const dealii::RefinementCase<dim> &refinement_case =
        dealii::RefinementCase<dim>::isotropic_refinement) const override;

    const dealii::FullMatrix<double> &
    get_restriction_matrix(
      const unsigned int                 child,
      const dealii::RefinementCase<dim> &refinement_case =
        dealii::RefinementCase<dim>::isotropic_refinement) const override;

    void
    get_face_interpolation_matrix(
      const dealii::FiniteElement<dim> &source,
      dealii::FullMatrix<double>       &matrix,
      const unsigned int                face_no = 0) const override;

    void
    get_subface_interpolation_matrix(
      const dealii::FiniteElement<dim> &source,
      const unsigned int                subface,
      dealii::FullMatrix<double>       &matrix,
      const unsigned int                face_no = 0) const override;

    /// The Greville points of the unit cell in DoF order: the coefficients
    /// of a multilinear field are its values there.
    const std::vector<dealii::Point<dim>> &
    greville_points() const;

  private:
    std::vector<dealii::Point<dim>> greville;
  };
} // namespace DuctileContact
