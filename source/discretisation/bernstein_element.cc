#include <deal.II/base/geometry_info.h>
#include <deal.II/base/qprojector.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_tools.h>

#include <ductile_contact/discretisation/bernstein_element.h>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// The equispaced points k/p of FE_Q(p) in the numbering FE_Bernstein
    /// shares with it: the Greville points of the Bernstein basis.
    FE_Q<dim>
    greville_element(const unsigned int degree)
    {
      return FE_Q<dim>(QIterated<1>(QTrapezoid<1>(), degree));
    }
  } // namespace



  BernsteinElement::BernsteinElement(const unsigned int degree)
      : FE_Bernstein<dim>(degree)
      , greville(greville_element(degree).get_unit_support_points())
  {
    const unsigned int n   = this->n_dofs_per_cell();
    const unsigned int iso = RefinementCase<dim>::isotropic_refinement - 1;
    for (auto &m : this->prolongation[iso])
      m.reinit(n, n);
    FETools::compute_embedding_matrices(*this, this->prolongation, true);

    for (unsigned int c = 0; c < this->restriction[iso].size(); ++c)
      {
        FullMatrix<double> &R = this->restriction[iso][c];
        R.reinit(n, n);
        for (unsigned int i = 0; i < n; ++i)
          {
            const Point<dim> xi =
              GeometryInfo<dim>::cell_to_child_coordinates(greville[i], c);
            if (GeometryInfo<dim>::is_inside_unit_cell(xi, 1e-12))
              for (unsigned int j = 0; j < n; ++j)
                R(i, j) = this->shape_value(j, xi);
          }
      }
  }



  std::unique_ptr<FiniteElement<dim>>
  BernsteinElement::clone() const
  {
    return std::make_unique<BernsteinElement>(*this);
  }



  const FullMatrix<double> &
  BernsteinElement::get_prolongation_matrix(
    const unsigned int         child,
    const RefinementCase<dim> &refinement_case) const
  {
    AssertThrow(refinement_case == RefinementCase<dim>::isotropic_refinement,
                ExcNotImplemented());
    return this->prolongation[refinement_case - 1][child];
  }



  const FullMatrix<double> &
  BernsteinElement::get_restriction_matrix(
    const unsigned int         child,
    const RefinementCase<dim> &refinement_case) const
  {
    AssertThrow(refinement_case == RefinementCase<dim>::isotropic_refinement,
                ExcNotImplemented());
    return this->restriction[refinement_case - 1][child];
  }



  void
  BernsteinElement::get_face_interpolation_matrix(
    const FiniteElement<dim> &source,
    FullMatrix<double>       &matrix,
    const unsigned int        face_no) const
  {
    get_subface_interpolation_matrix(source,
                                     numbers::invalid_unsigned_int,
                                     matrix,
                                     face_no);
  }



  void
  BernsteinElement::get_subface_interpolation_matrix(
    const FiniteElement<dim> &source,
    const unsigned int        subface,
    FullMatrix<double>       &matrix,
    const unsigned int        face_no) const
  {
    if (dynamic_cast<const FE_Bernstein<dim> *>(&source) == nullptr)
      {
        FE_Bernstein<dim>::get_subface_interpolation_matrix(source,
                                                            subface,
                                                            matrix,
                                                            face_no);
        return;
      }
    // The source (fine) face's coefficients b of the coarse face field with
    // coefficients a: B b = C a at the fine face's Greville points, B the
    // fine face basis there, C the coarse one at the same points of the
    // subface. As FE_Bernstein, on face 0 in standard orientation.
    const unsigned int n_fine   = source.n_dofs_per_face(face_no);
    const unsigned int n_coarse = this->n_dofs_per_face(face_no);
    AssertDimension(matrix.m(), n_fine);
    AssertDimension(matrix.n(), n_coarse);
    const Quadrature<dim - 1> face_points(
      greville_element(source.degree).get_unit_face_support_points(face_no));
    AssertDimension(face_points.size(), n_fine);
    const ReferenceCell   cell = ReferenceCells::get_hypercube<dim>();
    const Quadrature<dim> fine_points =
      QProjector<dim>::project_to_face(cell, face_points, 0);
    std::vector<Point<dim>> coarse_points(face_points.size());
    if (subface == numbers::invalid_unsigned_int)
      coarse_points = fine_points.get_points();
    else
      QProjector<dim>::project_to_subface(
        cell, face_points, 0, subface, coarse_points);

    FullMatrix<double> B(n_fine, n_fine), C(n_fine, n_coarse);
    for (unsigned int k = 0; k < n_fine; ++k)
      {
        for (unsigned int i = 0; i < n_fine; ++i)
          B(k, i) = source.shape_value(source.face_to_cell_index(i, 0),
                                       fine_points.point(k));
        for (unsigned int j = 0; j < n_coarse; ++j)
          C(k, j) =
            this->shape_value(this->face_to_cell_index(j, 0), coarse_points[k]);
      }
    B.gauss_jordan();
    B.mmult(matrix, C);
    // Exact zeros and ones where subdivision gives them (vertex DoFs), as
    // the constraint code expects identities to be recognisable.
    for (unsigned int i = 0; i < n_fine; ++i)
      for (unsigned int j = 0; j < n_coarse; ++j)
        {
          if (std::abs(matrix(i, j)) < 1e-13)
            matrix(i, j) = 0.;
          else if (std::abs(matrix(i, j) - 1.) < 1e-13)
            matrix(i, j) = 1.;
        }
  }



  const std::vector<Point<dim>> &
  BernsteinElement::greville_points() const
  {
    return greville;
  }
} // namespace DuctileContact
