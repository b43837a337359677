#include <ductile_contact/assembly/cell_rows.h>

#include <cmath>

namespace DuctileContact
{
  using namespace dealii;

  void
  LocalRows::reinit(const unsigned int n_dofs)
  {
    matrix.reinit(n_dofs, n_dofs);
    f_int.reinit(n_dofs);
    rhs.reinit(n_dofs);
    magnitude.reinit(n_dofs);
    scale_alpha.reinit(n_dofs);
    scale_s.reinit(n_dofs);
    indices.resize(n_dofs);
  }



  void
  PointShapes::reinit(const FEValues<dim> &fe_values,
                      const unsigned int   q,
                      const LocalDofs     &dofs)
  {
    u_grad.resize(dofs.u.size());
    grad_times_A.resize(dofs.u.size());
    alpha_value.resize(dofs.alpha.size());
    alpha_grad.resize(dofs.alpha.size());
    s_value.resize(dofs.s.size());
    for (unsigned int k = 0; k < dofs.u.size(); ++k)
      u_grad[k] = fe_values.shape_grad(dofs.u[k], q);
    for (unsigned int k = 0; k < dofs.alpha.size(); ++k)
      {
        alpha_value[k] = fe_values.shape_value(dofs.alpha[k], q);
        alpha_grad[k]  = fe_values.shape_grad(dofs.alpha[k], q);
      }
    for (unsigned int k = 0; k < dofs.s.size(); ++k)
      s_value[k] = fe_values.shape_value(dofs.s[k], q);
  }



  C0IPCoefficients
  crack_coefficients(const BodyParameters &body, const unsigned int degree)
  {
    C0IPCoefficients c = C0IPCoefficients::crack_functional(
      body.crack.length_scale, body.crack.critical_energy_release_rate, degree);
    if (body.crack.interior_penalty > 0.)
      c.penalty = body.crack.interior_penalty;
    return c;
  }



  void
  add_displacement_rows(const MaterialResponse &m,
                        const BodyParameters   &body,
                        PointShapes            &shapes,
                        const LocalDofs        &dofs,
                        const double            JxW,
                        const bool              tangent,
                        LocalRows              &rows)
  {
    const unsigned int n_u = dofs.u.size();
    for (unsigned int k = 0; k < n_u; ++k)
      {
        const Tensor<1, dim> &grad = shapes.u_grad[k];
        const unsigned        a    = dofs.u_component[k];
        const double          term = (m.P[a] * grad) * JxW;
        rows.f_int(dofs.u[k]) += term;
        // F = I + Grad u holds Grad u to eps in absolute terms, so P
        // carries errors of eps times the moduli.
        rows.magnitude(dofs.u[k]) +=
          (std::abs(term) +
           (body.shear_modulus + body.bulk_modulus) * grad.norm() * JxW);
        if (tangent)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int D = 0; D < dim; ++D)
              {
                double sum = 0;
                for (unsigned int B = 0; B < dim; ++B)
                  sum += grad[B] * m.dP_dF[a][B][c][D];
                shapes.grad_times_A[k][c][D] = sum * JxW;
              }
      }
    if (tangent && m.symmetric_tangent)
      for (unsigned int k = 0; k < n_u; ++k)
        {
          rows.matrix(dofs.u[k], dofs.u[k]) +=
            shapes.grad_times_A[k][dofs.u_component[k]] * shapes.u_grad[k];
          for (unsigned int l = k + 1; l < n_u; ++l)
            {
              const double v =
                shapes.grad_times_A[k][dofs.u_component[l]] * shapes.u_grad[l];
              rows.matrix(dofs.u[k], dofs.u[l]) += v;
              rows.matrix(dofs.u[l], dofs.u[k]) += v;
            }
        }
    else if (tangent)
      for (unsigned int k = 0; k < n_u; ++k)
        for (unsigned int l = 0; l < n_u; ++l)
          rows.matrix(dofs.u[k], dofs.u[l]) +=
            shapes.grad_times_A[k][dofs.u_component[l]] * shapes.u_grad[l];
  }



  void
  add_hardening_rows(const MaterialResponse     &m,
                     const PlasticityParameters &plastic,
                     const double                gradient_coefficient,
                     const Tensor<1, dim>       &grad_alpha,
                     const PointShapes          &shapes,
                     const LocalDofs            &dofs,
                     const double                JxW,
                     const bool                  tangent,
                     LocalRows                  &rows)
  {
    const unsigned int n_u = dofs.u.size(), n_a = dofs.alpha.size(),
                       n_s = dofs.s.size();
    const auto &a_value    = shapes.alpha_value;
    const auto &a_grad     = shapes.alpha_grad;
    for (unsigned int k = 0; k < n_a; ++k)
      {
        const unsigned int i = dofs.alpha[k];
        rows.f_int(i) +=
          (m.r * a_value[k] + gradient_coefficient * (a_grad[k] * grad_alpha)) *
          JxW;
        rows.scale_alpha(i) += plastic.initial_yield * a_value[k] * JxW;
        // r compares stresses known to eps (mu + kappa).
        rows.magnitude(i) +=
          (std::abs(m.r) + plastic.shear_modulus + plastic.bulk_modulus) *
            std::abs(a_value[k]) * JxW +
          std::abs(gradient_coefficient * (a_grad[k] * grad_alpha)) * JxW;
        if (!tangent)
          continue;
        for (unsigned int l = 0; l < n_u; ++l)
          rows.matrix(i, dofs.u[l]) +=
            a_value[k] * (m.dr_dF[dofs.u_component[l]] * shapes.u_grad[l]) *
            JxW;
        for (unsigned int l = 0; l < n_a; ++l)
          rows.matrix(i, dofs.alpha[l]) +=
            (m.dr_dalpha * a_value[k] * a_value[l] +
             gradient_coefficient * (a_grad[k] * a_grad[l])) *
            JxW;
        for (unsigned int l = 0; l < n_s; ++l)
          rows.matrix(i, dofs.s[l]) +=
            m.dr_ds * a_value[k] * shapes.s_value[l] * JxW;
      }
    if (tangent)
      for (unsigned int k = 0; k < n_u; ++k)
        for (unsigned int l = 0; l < n_a; ++l)
          rows.matrix(dofs.u[k], dofs.alpha[l]) +=
            (m.dP_dalpha[dofs.u_component[k]] * shapes.u_grad[k]) * a_value[l] *
            JxW;
  }



  void
  add_phase_field_rows(const MaterialResponse &m,
                       const CrackDriver      &driver,
                       const BodyParameters   &body,
                       const double            rate,
                       const double            dt,
                       const PointShapes      &shapes,
                       const LocalDofs        &dofs,
                       const double            JxW,
                       const bool              tangent,
                       LocalRows              &rows)
  {
    const unsigned int n_u = dofs.u.size(), n_a = dofs.alpha.size(),
                       n_s = dofs.s.size();
    const double eta_f     = body.crack.viscosity;
    const double g1 = driver.g1, psi_H = driver.psi_H;
    const double scale =
      body.crack.critical_energy_release_rate / (2. * body.crack.length_scale);
    // d(g' psi_H)/ds = g'' psi_H + g' dpsi_D/ds when loading (psi^+
    // depends on s at points that do not yield, see
    // MaterialResponse::dpsi_plus_ds).
    const DrivingEnergy &psi = driver.psi;
    const double         ds_coefficient =
      eta_f / dt + driver.g2 * psi_H + (driver.loading ? g1 * psi.d_ds : 0.);
    const auto &s_value = shapes.s_value;
    for (unsigned int k = 0; k < n_s; ++k)
      {
        const unsigned int i = dofs.s[k];
        rows.f_int(i) += (eta_f * rate + g1 * psi_H) * s_value[k] * JxW;
        rows.scale_s(i) += scale * s_value[k] * JxW;
        rows.magnitude(i) += (std::abs(eta_f * rate) + std::abs(g1 * psi_H)) *
                             std::abs(s_value[k]) * JxW;
        if (!tangent)
          continue;
        for (unsigned int l = 0; l < n_s; ++l)
          rows.matrix(i, dofs.s[l]) +=
            ds_coefficient * s_value[k] * s_value[l] * JxW;
        if (driver.loading)
          {
            for (unsigned int l = 0; l < n_u; ++l)
              rows.matrix(i, dofs.u[l]) +=
                g1 * s_value[k] *
                (psi.d_dF[dofs.u_component[l]] * shapes.u_grad[l]) * JxW;
            for (unsigned int l = 0; l < n_a; ++l)
              rows.matrix(i, dofs.alpha[l]) +=
                g1 * psi.d_dalpha * s_value[k] * shapes.alpha_value[l] * JxW;
          }
      }
    if (tangent)
      for (unsigned int k = 0; k < n_u; ++k)
        for (unsigned int l = 0; l < n_s; ++l)
          rows.matrix(dofs.u[k], dofs.s[l]) +=
            (m.dP_ds[dofs.u_component[k]] * shapes.u_grad[k]) * s_value[l] *
            JxW;
  }



  FullMatrix<double>
  crack_functional_matrix(const FEValues<dim>  &fe_values,
                          const Discretisation &discretisation,
                          const BodyParameters &body,
                          const LocalDofs      &dofs)
  {
    const unsigned int n_dofs = fe_values.get_fe().n_dofs_per_cell();
    FullMatrix<double> cell_matrix(n_dofs, n_dofs);
    add_c0ip_cell_terms(fe_values,
                        discretisation.phase_field,
                        crack_coefficients(body, discretisation.degree),
                        cell_matrix);
    const unsigned int n_s = dofs.s.size();
    FullMatrix<double> a_K(n_s, n_s);
    for (unsigned int k = 0; k < n_s; ++k)
      for (unsigned int l = 0; l < n_s; ++l)
        a_K(k, l) = cell_matrix(dofs.s[k], dofs.s[l]);
    return a_K;
  }



  double
  add_crack_functional_rows(const FullMatrix<double> &a_K,
                            const Vector<double>     &cell_values,
                            const LocalDofs          &dofs,
                            const bool                tangent,
                            LocalRows                &rows)
  {
    const unsigned int n_s    = dofs.s.size();
    double             energy = 0;
    for (unsigned int k = 0; k < n_s; ++k)
      {
        double sum = 0;
        for (unsigned int l = 0; l < n_s; ++l)
          {
            sum += a_K(k, l) * cell_values(dofs.s[l]);
            // s is known to eps in absolute terms (s <= 1).
            rows.magnitude(dofs.s[k]) += std::abs(a_K(k, l));
          }
        rows.f_int(dofs.s[k]) += sum;
        energy += 0.5 * cell_values(dofs.s[k]) * sum;
      }
    if (tangent)
      for (unsigned int k = 0; k < n_s; ++k)
        for (unsigned int l = 0; l < n_s; ++l)
          rows.matrix(dofs.s[k], dofs.s[l]) += a_K(k, l);
    return energy;
  }
} // namespace DuctileContact
