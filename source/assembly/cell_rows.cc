#include <ductile_contact/assembly/cell_rows.h>

#include <algorithm>
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
    alpha_value.resize(dofs.alpha.size());
    alpha_grad.resize(dofs.alpha.size());
    s_value.resize(dofs.s.size());
    const unsigned int n_nodes = dofs.u.size() / dim;
    for (unsigned int d = 0; d < dim; ++d)
      node_grad[d].resize(n_nodes);
    for (unsigned int k = 0; k < dofs.u.size(); ++k)
      u_grad[k] = fe_values.shape_grad(dofs.u[k], q);
    for (unsigned int j = 0; j < n_nodes; ++j)
      for (unsigned int d = 0; d < dim; ++d)
        node_grad[d][j] = fe_values.shape_grad(dofs.u_by_component[0][j], q)[d];
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
      body.crack.length_scale,
      body.crack.critical_energy_release_rate,
      degree,
      body.crack.regularisation);
    if (body.crack.interior_penalty > 0.)
      c.penalty = body.crack.interior_penalty;
    return c;
  }



  void
  add_displacement_rows(const MaterialResponse &m,
                        const BodyParameters   &body,
                        const PointShapes      &shapes,
                        const LocalDofs        &dofs,
                        const unsigned int      q,
                        const double            JxW,
                        const bool              tangent,
                        LocalRows              &rows)
  {
    const unsigned int              n_u = dofs.u.size();
    std::array<double *, dim * dim> left{};
    if (tangent)
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int D = 0; D < dim; ++D)
          {
            left[c * dim + D] = rows.blocks.u_u[c].left(q, D);
            double *right     = rows.blocks.u_u[c].right(q, D);
            std::copy(shapes.node_grad[D].begin(),
                      shapes.node_grad[D].end(),
                      right);
          }
    for (unsigned int k = 0; k < n_u; ++k)
      {
        const Tensor<1, dim> &grad = shapes.u_grad[k];
        const unsigned        a    = dofs.u_component[k];
        const double          term = in_plane(m.P[a], grad) * JxW;
        rows.f_int(dofs.u[k]) += term;
        // F = I + Grad u holds Grad u to eps in absolute terms, so P
        // carries errors of eps times the moduli.
        rows.magnitude(dofs.u[k]) +=
          (std::abs(term) +
           (body.shear_modulus + body.bulk_modulus) * grad.norm() * JxW);
        if (!tangent)
          continue;
        // sum_B dN_k/dX_B dP_aB/dF_cD JxW: the row of DoF k against the
        // node gradients dN_j/dX_D of component c.
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int D = 0; D < dim; ++D)
            {
              double v = 0;
              for (unsigned int B = 0; B < dim; ++B)
                v += grad[B] * m.dP_dF[a][B][c][D];
              left[c * dim + D][k] = v * JxW;
            }
      }
  }



  void
  add_hardening_rows(const MaterialResponse     &m,
                     const PlasticityParameters &plastic,
                     const double                gradient_coefficient,
                     const Tensor<1, dim>       &grad_alpha,
                     const PointShapes          &shapes,
                     const LocalDofs            &dofs,
                     const unsigned int          q,
                     const double                JxW,
                     const bool                  tangent,
                     LocalRows                  &rows)
  {
    const unsigned int n_u = dofs.u.size(), n_a = dofs.alpha.size();
    const auto        &a_value = shapes.alpha_value;
    const auto        &a_grad  = shapes.alpha_grad;
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
      }
    if (!tangent)
      return;
    CellTangentBlocks &blocks = rows.blocks;
    // alpha-u: N_k dr/dF : Grad dv; u-alpha: dP/dalpha : Grad N_k N_l.
    double *alpha_u_left  = blocks.alpha_u.left(q, 0);
    double *alpha_u_right = blocks.alpha_u.right(q, 0);
    double *u_alpha_left  = blocks.u_alpha.left(q, 0);
    for (unsigned int l = 0; l < n_u; ++l)
      {
        const unsigned int c = dofs.u_component[l];
        alpha_u_right[l]     = in_plane(m.dr_dF[c], shapes.u_grad[l]);
        u_alpha_left[l]      = in_plane(m.dP_dalpha[c], shapes.u_grad[l]) * JxW;
      }
    std::copy(a_value.begin(), a_value.end(), blocks.u_alpha.right(q, 0));
    for (unsigned int k = 0; k < n_a; ++k)
      alpha_u_left[k] = a_value[k] * JxW;
    // alpha-alpha: dr/dalpha N_k N_l + y_0 l_p^2 Grad N_k . Grad N_l;
    // alpha-s: dr/ds N_k N_l.
    blocks.alpha_alpha.set_scaled(q, 0, m.dr_dalpha * JxW, a_value, a_value);
    blocks.alpha_s.set_scaled(q, 0, m.dr_ds * JxW, a_value, shapes.s_value);
    for (unsigned int D = 0; D < dim; ++D)
      {
        double *left  = blocks.alpha_alpha.left(q, 1 + D);
        double *right = blocks.alpha_alpha.right(q, 1 + D);
        for (unsigned int k = 0; k < n_a; ++k)
          {
            left[k]  = gradient_coefficient * a_grad[k][D] * JxW;
            right[k] = a_grad[k][D];
          }
      }
  }



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
                       LocalRows              &rows)
  {
    const unsigned int n_u = dofs.u.size(), n_s = dofs.s.size();
    const double       eta_f = body.crack.viscosity;
    const double       g1 = driver.g1, psi_H = driver.psi_H;
    const double       scale =
      body.crack.critical_energy_release_rate / (2. * body.crack.length_scale);
    const auto &s_value = shapes.s_value;
    for (unsigned int k = 0; k < n_s; ++k)
      {
        const unsigned int i = dofs.s[k];
        rows.f_int(i) += (eta_f * rate + g1 * psi_H) * s_value[k] * JxW;
        rows.scale_s(i) += scale * s_value[k] * JxW;
        rows.magnitude(i) += (std::abs(eta_f * rate) + std::abs(g1 * psi_H)) *
                             std::abs(s_value[k]) * JxW;
      }
    if (!tangent)
      return;
    CellTangentBlocks &blocks = rows.blocks;
    // d(g' psi_H)/ds = g'' psi_H + g' dpsi_D/ds when loading (psi^+
    // depends on s at points that do not yield, see
    // MaterialResponse::dpsi_plus_ds).
    const DrivingEnergy &psi = driver.psi;
    const double         ds_coefficient =
      eta_f / dt + driver.g2 * psi_H + (driver.loading ? g1 * psi.d_ds : 0.);
    blocks.s_s.set_scaled(q, 0, ds_coefficient * JxW, s_value, s_value);
    // u-s: dP/ds : Grad N_k N_l.
    double *us_left = blocks.u_s.left(q, 0);
    for (unsigned int k = 0; k < n_u; ++k)
      us_left[k] =
        in_plane(m.dP_ds[dofs.u_component[k]], shapes.u_grad[k]) * JxW;
    std::copy(s_value.begin(), s_value.end(), blocks.u_s.right(q, 0));
    if (!driver.loading)
      return;
    // s-u and s-alpha: g' N_k dpsi_D/dF : Grad dv, g' N_k dpsi_D/dalpha N_l.
    double *su_left  = blocks.s_u.left(q, 0);
    double *su_right = blocks.s_u.right(q, 0);
    for (unsigned int k = 0; k < n_s; ++k)
      su_left[k] = g1 * s_value[k] * JxW;
    for (unsigned int l = 0; l < n_u; ++l)
      su_right[l] = in_plane(psi.d_dF[dofs.u_component[l]], shapes.u_grad[l]);
    blocks.s_alpha.set_scaled(
      q, 0, g1 * psi.d_dalpha * JxW, s_value, shapes.alpha_value);
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
