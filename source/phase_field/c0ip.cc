#include <ductile_contact/phase_field/c0ip.h>

namespace DuctileContact
{
  using namespace dealii;

  double
  default_c0ip_penalty(const unsigned int degree)
  {
    // (d / 2) p (p + 1) in d dimensions.
    return 0.5 * dim * degree * (degree + 1.);
  }



  C0IPCoefficients
  C0IPCoefficients::crack_functional(const double         l_f,
                                     const double         g_c,
                                     const unsigned int   degree,
                                     const Regularisation order)
  {
    C0IPCoefficients c;
    c.gradient = g_c * l_f;
    c.penalty  = default_c0ip_penalty(degree);
    switch (order)
      {
      case Regularisation::fourth_order:
        c.mass        = g_c / (2. * l_f);
        c.bilaplacian = g_c * l_f * l_f * l_f / 2.;
        break;
      case Regularisation::second_order:
        c.mass        = g_c / l_f;
        c.bilaplacian = 0.;
        break;
      }
    return c;
  }



  void
  add_c0ip_cell_terms(const FEValues<dim>              &fe_values,
                      const FEValuesExtractors::Scalar &s,
                      const C0IPCoefficients           &c,
                      FullMatrix<double>               &cell_matrix)
  {
    const FiniteElement<dim> &fe = fe_values.get_fe();
    std::vector<unsigned int> dofs; // DoFs of the s component
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.system_to_component_index(i).first == s.component)
        dofs.push_back(i);
    const unsigned int          n = dofs.size();
    std::vector<double>         value(n), laplacian(n);
    std::vector<Tensor<1, dim>> gradient(n);
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        const double JxW = fe_values.JxW(q);
        for (unsigned int k = 0; k < n; ++k)
          {
            value[k]     = fe_values[s].value(dofs[k], q);
            gradient[k]  = fe_values[s].gradient(dofs[k], q);
            laplacian[k] = trace(fe_values[s].hessian(dofs[k], q));
          }
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int l = 0; l < n; ++l)
            cell_matrix(dofs[k], dofs[l]) +=
              (c.mass * value[k] * value[l] +
               c.gradient * gradient[k] * gradient[l] +
               c.bilaplacian * laplacian[k] * laplacian[l]) *
              JxW;
      }
  }



  void
  add_c0ip_face_terms(const FEInterfaceValues<dim>     &fiv,
                      const FEValuesExtractors::Scalar &s,
                      const C0IPCoefficients           &c,
                      const double                      h_inverse,
                      FullMatrix<double>               &face_matrix)
  {
    if (c.bilaplacian == 0.)
      return;
    const unsigned int  n = fiv.n_current_interface_dofs();
    std::vector<double> jump_dn(n), mean_laplacian(n);
    const double        gamma = c.penalty * h_inverse;
    // n_quadrature_points, not get_quadrature_points().size(): the points
    // themselves are there only with update_quadrature_points.
    for (unsigned int q = 0; q < fiv.n_quadrature_points; ++q)
      {
        const Tensor<1, dim> normal = fiv.normal(q);
        for (unsigned int i = 0; i < n; ++i)
          {
            jump_dn[i]        = fiv[s].jump_in_gradients(i, q) * normal;
            mean_laplacian[i] = trace(fiv[s].average_of_hessians(i, q));
          }
        const double JxW = fiv.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          if (jump_dn[i] != 0. || mean_laplacian[i] != 0.)
            for (unsigned int j = 0; j < n; ++j)
              face_matrix(i, j) += c.bilaplacian *
                                   (-mean_laplacian[i] * jump_dn[j] -
                                    jump_dn[i] * mean_laplacian[j] +
                                    gamma * jump_dn[i] * jump_dn[j]) *
                                   JxW;
      }
  }



  void
  for_each_interior_face(
    const DoFHandler<dim>  &dof_handler,
    FEInterfaceValues<dim> &fiv,
    const std::function<void(const FEInterfaceValues<dim> &, const double)>
                      &work,
    const unsigned int active_fe_index)
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          cell->active_fe_index() == active_fe_index)
        for_each_owned_interior_face(cell, fiv, work);
  }



  void
  for_each_owned_interior_face(
    const DoFHandler<dim>::active_cell_iterator &cell,
    FEInterfaceValues<dim>                      &fiv,
    const std::function<void(const FEInterfaceValues<dim> &, const double)>
      &work)
  {
    const auto extent = [](const auto &cell, const unsigned int f) {
      return cell->extent_in_direction(
        GeometryInfo<dim>::unit_normal_direction[f]);
    };
    const unsigned int active_fe_index = cell->active_fe_index();
    for (const unsigned int f : cell->face_indices())
      {
        // Periodic faces are interior faces of the periodic domain.
        const bool periodic = cell->has_periodic_neighbor(f);
        if (cell->at_boundary(f) && !periodic)
          continue;
        const auto neighbor =
          periodic ? cell->periodic_neighbor(f) : cell->neighbor(f);
        const unsigned int neighbor_face =
          periodic ? cell->periodic_neighbor_face_no(f)
                   : cell->neighbor_face_no(f);
        if (neighbor->has_children())
          continue; // visited from the finer side
        if (neighbor->active_fe_index() != active_fe_index)
          continue;
        const double h_inverse =
          0.5 * (1. / extent(cell, f) + 1. / extent(neighbor, neighbor_face));
        const bool coarser = periodic ? cell->periodic_neighbor_is_coarser(f)
                                      : cell->neighbor_is_coarser(f);
        if (coarser)
          {
            const auto [nf, nsf] =
              periodic ? cell->periodic_neighbor_of_coarser_periodic_neighbor(f)
                       : cell->neighbor_of_coarser_neighbor(f);
            fiv.reinit(
              cell, f, numbers::invalid_unsigned_int, neighbor, nf, nsf);
          }
        else
          {
            // (A cell can be its own periodic neighbour: then the face
            // with the smaller number takes the pair.)
            const bool mine =
              neighbor == cell
                ? f < neighbor_face
                : (neighbor->is_locally_owned()
                     ? cell->id() < neighbor->id()
                     : cell->subdomain_id() < neighbor->subdomain_id());
            if (!mine)
              continue;
            fiv.reinit(cell,
                       f,
                       numbers::invalid_unsigned_int,
                       neighbor,
                       neighbor_face,
                       numbers::invalid_unsigned_int);
          }
        work(fiv, h_inverse);
      }
  }
} // namespace DuctileContact
