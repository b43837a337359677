#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/physics/elasticity/standard_tensors.h>

#include <ductile_contact/assembly/scatter.h>
#include <ductile_contact/assembly/system_assembler.h>
#include <ductile_contact/materials/body_material.h>
#include <ductile_contact/materials/degradation.h>
#include <ductile_contact/materials/neo_hooke.h>
#include <ductile_contact/phase_field/c0ip.h>

#include <cmath>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// int_0^alpha yhat(a) da for the saturation law (21).
    double
    integrated_hardening(const double alpha, const PlasticityParameters &p)
    {
      const double eta = p.saturation_exponent;
      const double saturation =
        eta > 0. ? alpha - (1. - std::exp(-eta * alpha)) / eta : 0.;
      return p.initial_yield * alpha +
             (p.saturation_yield - p.initial_yield) * saturation +
             0.5 * p.linear_hardening * alpha * alpha;
    }

    /// The coefficients of g_c gamma for a body that cracks.
    C0IPCoefficients
    crack_coefficients(const BodyParameters &body, const unsigned int degree)
    {
      C0IPCoefficients c = C0IPCoefficients::crack_functional(
        body.crack.length_scale,
        body.crack.critical_energy_release_rate,
        degree);
      if (body.crack.interior_penalty > 0.)
        c.penalty = body.crack.interior_penalty;
      return c;
    }

  } // namespace



  SystemAssembler::SystemAssembler(
    const Discretisation                                       &discretisation,
    const std::map<types::material_id, const BodyParameters *> &bodies,
    const std::deque<BoundaryCondition> &boundary_conditions,
    const bool                           crack_history)
      : discretisation(discretisation)
      , bodies(bodies)
      , boundary_conditions(boundary_conditions)
      , crack_history(crack_history)
      , elastic_values(discretisation.mapping,
                       discretisation.fe_collection,
                       discretisation.quadrature,
                       update_gradients | update_JxW_values)
      , coupled_values(discretisation.mapping,
                       discretisation.fe_collection,
                       discretisation.quadrature,
                       update_values | update_gradients | update_hessians |
                         update_JxW_values)
      , face_values(discretisation.mapping,
                    discretisation.fe_collection,
                    discretisation.face_quadrature,
                    update_values | update_quadrature_points |
                      update_JxW_values)
  {
    for (unsigned int i = 0; i < discretisation.fe_collection.size(); ++i)
      interface_values.emplace_back(
        (i & 2) ? std::make_unique<FEInterfaceValues<dim>>(
                    discretisation.mapping[0],
                    discretisation.fe_collection[i],
                    discretisation.face_quadrature[i],
                    update_gradients | update_hessians | update_normal_vectors |
                      update_JxW_values)
                : nullptr);
  }



  AssemblyInfo
  SystemAssembler::assemble(const TrilinosWrappers::MPI::BlockVector &u,
                            const StepData                           &step,
                            const AffineConstraints<double> &constraints,
                            const AssemblyTargets           &targets) const
  {
    const bool with_tangent = (targets.tangent != nullptr);
    if (targets.tangent)
      *targets.tangent = 0;
    for (auto *v :
         {targets.newton_rhs, targets.residual, targets.internal_force})
      if (v)
        *v = 0;
    CellQuantities *cq = targets.cell_quantities;
    if (cq)
      for (auto *v :
           {&cq->von_mises, &cq->mean_stress, &cq->J, &cq->crack_driving_force})
        v->reinit(discretisation.triangulation.n_active_cells());

    // Traction boundaries, looked up per face.
    std::map<types::boundary_id, const BoundaryCondition *> tractions;
    for (const BoundaryCondition &bc : boundary_conditions)
      if (bc.has_traction)
        tractions[bc.boundary_id] = &bc;

    // Elastic cells need gradients only; cells with alpha or s also values
    // and (for the bi-Laplacian) hessians.
    hp::FEValues<dim>     &hp_elastic     = elastic_values;
    hp::FEValues<dim>     &hp_coupled     = coupled_values;
    hp::FEFaceValues<dim> &hp_face_values = face_values;

    FullMatrix<double>                   cell_matrix, c0ip_matrix;
    Vector<double>                       cell_f_int, cell_rhs, cell_magnitude;
    Vector<double>                       cell_scale_alpha, cell_scale_s;
    std::vector<types::global_dof_index> dof_indices;
    std::vector<Tensor<2, dim>>          grad_u, grad_u_old;
    std::vector<double>                  alpha, s, s_old;
    std::vector<Tensor<1, dim>>          grad_alpha;
    std::vector<unsigned int>            u_dofs, u_component, a_dofs, s_dofs;
    std::vector<Tensor<1, dim>>          shape_grad;
    std::vector<Tensor<2, dim>>          grad_times_A; // w_i[c][D]
    std::vector<double>                  a_value, s_value;
    std::vector<Tensor<1, dim>>          a_grad;

    const PointHistory                default_history;
    std::vector<const PointHistory *> history_n;

    AssemblyInfo info;
    info.min_J     = std::numeric_limits<double>::max();
    using Switches = AssemblyTargets::Switches;
    // Bits of recorded_switches: chi_p, and psi^+ above its history maximum.
    constexpr unsigned char yielding_bit = 1, loading_bit = 2;
    if (targets.switches == Switches::record)
      recorded_switches.assign(discretisation.triangulation.n_active_cells(),
                               {});
    Assert(targets.switches != Switches::frozen ||
             recorded_switches.size() ==
               discretisation.triangulation.n_active_cells(),
           ExcMessage("frozen switches need recorded ones"));

    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int fe_index  = cell->active_fe_index();
          const bool         has_alpha = fe_index & 1;
          const bool         has_s     = fe_index & 2;
          hp::FEValues<dim> &hp_values =
            (has_alpha || has_s) ? hp_coupled : hp_elastic;
          hp_values.reinit(cell);
          const FEValues<dim> &fe_values = hp_values.get_present_fe_values();
          const FiniteElement<dim>   &fe = cell->get_fe();
          const unsigned int          n_dofs  = fe.n_dofs_per_cell();
          const unsigned int          n_q     = fe_values.n_quadrature_points;
          const BodyParameters       &body    = *bodies.at(cell->material_id());
          const PlasticityParameters  plastic = body.material();
          const DegradationParameters degradation{
            body.crack.degradation_a, body.crack.residual_stiffness};

          cell_matrix.reinit(n_dofs, n_dofs);
          cell_f_int.reinit(n_dofs);
          cell_magnitude.reinit(n_dofs);
          cell_rhs.reinit(n_dofs);
          cell_scale_alpha.reinit(n_dofs);
          cell_scale_s.reinit(n_dofs);
          dof_indices.resize(n_dofs);
          cell->get_dof_indices(dof_indices);

          u_dofs.clear();
          u_component.clear();
          a_dofs.clear();
          s_dofs.clear();
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              if (c < dim)
                {
                  u_dofs.push_back(i);
                  u_component.push_back(c);
                }
              else if (c == Component::hardening)
                a_dofs.push_back(i);
              else
                s_dofs.push_back(i);
            }
          const unsigned int n_u = u_dofs.size(), n_a = a_dofs.size(),
                             n_s = s_dofs.size();
          shape_grad.resize(n_u);
          grad_times_A.resize(n_u);
          a_value.resize(n_a);
          a_grad.resize(n_a);
          s_value.resize(n_s);

          grad_u.resize(n_q);
          fe_values[discretisation.displacement].get_function_gradients(u,
                                                                        grad_u);
          alpha.assign(n_q, 0.);
          grad_alpha.assign(n_q, Tensor<1, dim>());
          s.assign(n_q, 0.);
          s_old.assign(n_q, 0.);
          grad_u_old.assign(n_q, Tensor<2, dim>());
          if (has_alpha)
            {
              if (step.old_solution && targets.history)
                fe_values[discretisation.displacement].get_function_gradients(
                  *step.old_solution, grad_u_old);
              fe_values[discretisation.hardening].get_function_values(u, alpha);
              fe_values[discretisation.hardening].get_function_gradients(
                u, grad_alpha);
            }
          if (has_s)
            {
              fe_values[discretisation.phase_field].get_function_values(u, s);
              if (step.old_solution)
                fe_values[discretisation.phase_field].get_function_values(
                  *step.old_solution, s_old);
            }
          history_n.assign(n_q, &default_history);
          if (step.history && (has_alpha || has_s))
            for (unsigned int q = 0; q < n_q; ++q)
              history_n[q] = (*step.history)(cell) + q;
          PointHistory *history_new = (targets.history && (has_alpha || has_s))
                                        ? (*targets.history)(cell)
                                        : nullptr;

          double volume = 0, vm = 0, mean = 0, mean_J = 0, driver = 0;
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Tensor<2, dim> F =
                Physics::Elasticity::StandardTensors<dim>::I + grad_u[q];
              const double J = determinant(F);
              info.min_J     = std::min(info.min_J, J);
              if (!(J > 0.))
                {
                  info.inverted = true;
                  continue;
                }
              std::optional<bool> frozen;
              const unsigned int  index = cell->active_cell_index();
              if (has_alpha && targets.switches == Switches::frozen)
                frozen = (recorded_switches[index].at(q) & yielding_bit) != 0;
              const PointResponse m = evaluate_material(body,
                                                        F,
                                                        history_n[q]->plastic,
                                                        alpha[q],
                                                        s[q],
                                                        step.dt,
                                                        with_tangent,
                                                        frozen);
              if ((has_alpha || has_s) && targets.switches == Switches::record)
                {
                  recorded_switches[index].resize(n_q);
                  recorded_switches[index][q] = m.yielding ? yielding_bit : 0;
                }
              if (frozen && m.trial_yielding != *frozen)
                ++info.switch_flips;
              const double JxW = fe_values.JxW(q);
              info.stored_energy += m.psi_elastic * JxW;
              volume += JxW;
              vm += von_mises(m.tau) * JxW;
              mean += trace(m.tau) / 3. * JxW;
              mean_J += m.J * JxW;

              // Displacement rows: int P : Grad du.
              for (unsigned int k = 0; k < n_u; ++k)
                {
                  shape_grad[k]       = fe_values.shape_grad(u_dofs[k], q);
                  const unsigned a    = u_component[k];
                  const double   term = (m.P[a] * shape_grad[k]) * JxW;
                  cell_f_int(u_dofs[k]) += term;
                  // F = I + Grad u holds Grad u to eps in absolute terms,
                  // so P carries errors of eps times the moduli.
                  cell_magnitude(u_dofs[k]) +=
                    (std::abs(term) + (body.shear_modulus + body.bulk_modulus) *
                                        shape_grad[k].norm() * JxW);
                  if (with_tangent)
                    for (unsigned int c = 0; c < dim; ++c)
                      for (unsigned int D = 0; D < dim; ++D)
                        {
                          double sum = 0;
                          for (unsigned int B = 0; B < dim; ++B)
                            sum += shape_grad[k][B] * m.dP_dF[a][B][c][D];
                          grad_times_A[k][c][D] = sum * JxW;
                        }
                }
              if (with_tangent)
                for (unsigned int k = 0; k < n_u; ++k)
                  for (unsigned int l = 0; l < n_u; ++l)
                    cell_matrix(u_dofs[k], u_dofs[l]) +=
                      grad_times_A[k][u_component[l]] * shape_grad[l];

              for (unsigned int k = 0; k < n_a; ++k)
                {
                  a_value[k] = fe_values.shape_value(a_dofs[k], q);
                  a_grad[k]  = fe_values.shape_grad(a_dofs[k], q);
                }
              for (unsigned int k = 0; k < n_s; ++k)
                s_value[k] = fe_values.shape_value(s_dofs[k], q);

              // Hardening rows, (50).
              if (has_alpha)
                {
                  const double l_p = body.plastic_length_scale;
                  // The gradient term acts at every point, not only where
                  // chi_p = 1 (see plastic_update()).
                  const double gradient_coefficient =
                    plastic.initial_yield * l_p * l_p;
                  info.max_alpha = std::max(info.max_alpha, alpha[q]);
                  if (m.yielding)
                    info.min_yielding_alpha_increment =
                      std::min(info.min_yielding_alpha_increment,
                               alpha[q] - history_n[q]->plastic.alpha);
                  info.hardening_energy +=
                    (integrated_hardening(alpha[q], plastic) +
                     0.5 * gradient_coefficient * grad_alpha[q].norm_square()) *
                    JxW;
                  // Plastic work of the step: the elastic energy the flow
                  // C^p_n -> C^p releases, averaged over F_n and F (second
                  // order in dt; together with the trapezoidal external
                  // work the energy balance then closes as dt -> 0). Only
                  // needed when the step is committed.
                  if (history_new)
                    {
                      const SymmetricTensor<2, dim> &C_n =
                        history_n[q]->plastic.Cp_inv;
                      const Tensor<2, dim> F_n =
                        Physics::Elasticity::StandardTensors<dim>::I +
                        grad_u_old[q];
                      info.plastic_work_increment +=
                        0.5 *
                        (elastic_energy(F, C_n, s[q], plastic) - m.psi_elastic +
                         elastic_energy(F_n, C_n, s[q], plastic) -
                         elastic_energy(F_n, m.updated.Cp_inv, s[q], plastic)) *
                        JxW;
                    }
                  for (unsigned int k = 0; k < n_a; ++k)
                    {
                      const unsigned int i = a_dofs[k];
                      cell_f_int(i) +=
                        (m.r * a_value[k] +
                         gradient_coefficient * (a_grad[k] * grad_alpha[q])) *
                        JxW;
                      cell_scale_alpha(i) +=
                        plastic.initial_yield * a_value[k] * JxW;
                      // r compares stresses known to eps (mu + kappa).
                      cell_magnitude(i) +=
                        (std::abs(m.r) + plastic.shear_modulus +
                         plastic.bulk_modulus) *
                          std::abs(a_value[k]) * JxW +
                        std::abs(gradient_coefficient *
                                 (a_grad[k] * grad_alpha[q])) *
                          JxW;
                      if (!with_tangent)
                        continue;
                      for (unsigned int l = 0; l < n_u; ++l)
                        cell_matrix(i, u_dofs[l]) +=
                          a_value[k] *
                          (m.dr_dF[u_component[l]] * shape_grad[l]) * JxW;
                      for (unsigned int l = 0; l < n_a; ++l)
                        cell_matrix(i, a_dofs[l]) +=
                          (m.dr_dalpha * a_value[k] * a_value[l] +
                           gradient_coefficient * (a_grad[k] * a_grad[l])) *
                          JxW;
                      for (unsigned int l = 0; l < n_s; ++l)
                        cell_matrix(i, s_dofs[l]) +=
                          m.dr_ds * a_value[k] * s_value[l] * JxW;
                    }
                  if (with_tangent)
                    for (unsigned int k = 0; k < n_u; ++k)
                      for (unsigned int l = 0; l < n_a; ++l)
                        cell_matrix(u_dofs[k], a_dofs[l]) +=
                          (m.dP_dalpha[u_component[k]] * shape_grad[k]) *
                          a_value[l] * JxW;
                }

              // Phase-field rows, (51) without a(s, ds) (added below).
              if (has_s)
                {
                  const double eta_f = body.crack.viscosity;
                  const double psi_max =
                    crack_history ? history_n[q]->psi_plus_max : 0.;
                  bool loading = m.psi_plus > psi_max;
                  if (targets.switches == Switches::record)
                    recorded_switches[index][q] |= loading ? loading_bit : 0;
                  else if (targets.switches == Switches::frozen)
                    {
                      const bool frozen_loading =
                        (recorded_switches[index].at(q) & loading_bit) != 0;
                      if (frozen_loading != loading)
                        ++info.switch_flips;
                      loading = frozen_loading;
                    }
                  const double psi_H = loading ? m.psi_plus : psi_max;
                  const double g1 = degradation_derivative(s[q], degradation);
                  const double g2 =
                    degradation_second_derivative(s[q], degradation);
                  const double rate = (s[q] - s_old[q]) / step.dt;
                  driver += -g1 * psi_H * JxW;
                  info.fracture_viscous_work_increment +=
                    eta_f * rate * rate * step.dt * JxW;
                  if (history_new)
                    {
                      history_new[q].psi_plus_max = psi_H;
                      info.history_work_increment +=
                        -g1 * (psi_H - m.psi_plus) * (s[q] - s_old[q]) * JxW;
                    }
                  const double scale = body.crack.critical_energy_release_rate /
                                       (2. * body.crack.length_scale);
                  // d(g' psi_H)/ds = g'' psi_H + g' dpsi^+/ds when loading
                  // (psi^+ depends on s at points that do not yield, see
                  // PlasticResponse::dpsi_plus_ds).
                  const double ds_coefficient =
                    eta_f / step.dt + g2 * psi_H +
                    (loading ? g1 * m.dpsi_plus_ds : 0.);
                  for (unsigned int k = 0; k < n_s; ++k)
                    {
                      const unsigned int i = s_dofs[k];
                      cell_f_int(i) +=
                        (eta_f * rate + g1 * psi_H) * s_value[k] * JxW;
                      cell_scale_s(i) += scale * s_value[k] * JxW;
                      cell_magnitude(i) +=
                        (std::abs(eta_f * rate) + std::abs(g1 * psi_H)) *
                        std::abs(s_value[k]) * JxW;
                      if (!with_tangent)
                        continue;
                      for (unsigned int l = 0; l < n_s; ++l)
                        cell_matrix(i, s_dofs[l]) +=
                          ds_coefficient * s_value[k] * s_value[l] * JxW;
                      if (loading)
                        {
                          for (unsigned int l = 0; l < n_u; ++l)
                            cell_matrix(i, u_dofs[l]) +=
                              g1 * s_value[k] *
                              (m.dpsi_plus_dF[u_component[l]] * shape_grad[l]) *
                              JxW;
                          for (unsigned int l = 0; l < n_a; ++l)
                            cell_matrix(i, a_dofs[l]) +=
                              g1 * m.dpsi_plus_dalpha * s_value[k] *
                              a_value[l] * JxW;
                        }
                    }
                  if (with_tangent)
                    for (unsigned int k = 0; k < n_u; ++k)
                      for (unsigned int l = 0; l < n_s; ++l)
                        cell_matrix(u_dofs[k], s_dofs[l]) +=
                          (m.dP_ds[u_component[k]] * shape_grad[k]) *
                          s_value[l] * JxW;
                }
              if (history_new && has_alpha)
                history_new[q].plastic = m.updated;
            }

          // The crack functional's cell terms a_K(s, ds): linear in s.
          if (has_s)
            {
              c0ip_matrix.reinit(n_dofs, n_dofs);
              add_c0ip_cell_terms(fe_values,
                                  discretisation.phase_field,
                                  crack_coefficients(body,
                                                     discretisation.degree),
                                  c0ip_matrix);
              for (unsigned int k = 0; k < n_s; ++k)
                {
                  double sum = 0;
                  for (unsigned int l = 0; l < n_s; ++l)
                    {
                      sum += c0ip_matrix(s_dofs[k], s_dofs[l]) *
                             u(dof_indices[s_dofs[l]]);
                      // s is known to eps in absolute terms (s <= 1).
                      cell_magnitude(s_dofs[k]) +=
                        std::abs(c0ip_matrix(s_dofs[k], s_dofs[l]));
                    }
                  cell_f_int(s_dofs[k]) += sum;
                  info.fracture_energy += 0.5 * u(dof_indices[s_dofs[k]]) * sum;
                }
              if (with_tangent)
                cell_matrix.add(1., c0ip_matrix);
            }

          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              info.residual_magnitude[c < dim ? Block::displacement
                                      : c == Component::hardening
                                        ? Block::hardening
                                        : Block::phase_field] +=
                cell_magnitude(i) * cell_magnitude(i);
            }
          info.residual_scale[Block::hardening] += cell_scale_alpha.norm_sqr();
          info.residual_scale[Block::phase_field] += cell_scale_s.norm_sqr();
          if (cq && volume > 0.)
            {
              const auto i               = cell->active_cell_index();
              cq->von_mises[i]           = vm / volume;
              cq->mean_stress[i]         = mean / volume;
              cq->J[i]                   = mean_J / volume;
              cq->crack_driving_force[i] = driver / volume;
            }

          // R = f_int - f_ext; the Newton right-hand side is -R.
          for (unsigned int i = 0; i < n_dofs; ++i)
            cell_rhs(i) = -cell_f_int(i);

          if (!tractions.empty())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                {
                  const auto it = tractions.find(cell->face(f)->boundary_id());
                  if (it == tractions.end())
                    continue;
                  hp_face_values.reinit(cell, f);
                  const FEFaceValues<dim> &fv =
                    hp_face_values.get_present_fe_values();
                  for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                    {
                      const Tensor<1, dim> T =
                        it->second->traction_at(fv.quadrature_point(q), step.t);
                      for (unsigned int k = 0; k < n_u; ++k)
                        cell_rhs(u_dofs[k]) += fv.shape_value(u_dofs[k], q) *
                                               T[u_component[k]] * fv.JxW(q);
                    }
                }

          scatter(cell_matrix,
                  cell_rhs,
                  cell_f_int,
                  dof_indices,
                  constraints,
                  discretisation.hanging_node_constraints,
                  targets);
        }

    if (discretisation.dofs_per_block[Block::phase_field] > 0)
      assemble_faces(u, constraints, targets, info);

    if (targets.tangent)
      targets.tangent->compress(VectorOperation::add);
    for (auto *v :
         {targets.newton_rhs, targets.residual, targets.internal_force})
      if (v)
        v->compress(VectorOperation::add);

    const MPI_Comm comm = discretisation.dof_handler.get_communicator();
    info.inverted       = Utilities::MPI::max(info.inverted ? 1 : 0, comm) > 0;
    info.min_J          = Utilities::MPI::min(info.min_J, comm);
    info.max_alpha      = Utilities::MPI::max(info.max_alpha, comm);
    info.min_yielding_alpha_increment =
      Utilities::MPI::min(info.min_yielding_alpha_increment, comm);
    info.switch_flips = Utilities::MPI::sum(info.switch_flips, comm);
    std::vector<double> sums{info.stored_energy,
                             info.hardening_energy,
                             info.fracture_energy,
                             info.plastic_work_increment,
                             info.fracture_viscous_work_increment,
                             info.residual_magnitude[Block::displacement],
                             info.residual_scale[Block::hardening],
                             info.residual_scale[Block::phase_field],
                             info.residual_magnitude[Block::hardening],
                             info.residual_magnitude[Block::phase_field],
                             info.history_work_increment};
    Utilities::MPI::sum(sums, comm, sums);
    info.history_work_increment                  = sums[10];
    info.stored_energy                           = sums[0];
    info.hardening_energy                        = sums[1];
    info.fracture_energy                         = sums[2];
    info.plastic_work_increment                  = sums[3];
    info.fracture_viscous_work_increment         = sums[4];
    info.force_magnitude                         = std::sqrt(sums[5]);
    info.residual_magnitude[Block::displacement] = info.force_magnitude;
    info.residual_magnitude[Block::hardening]    = std::sqrt(sums[8]);
    info.residual_magnitude[Block::phase_field]  = std::sqrt(sums[9]);
    info.residual_scale[Block::displacement]     = info.force_magnitude;
    info.residual_scale[Block::hardening]        = std::sqrt(sums[6]);
    info.residual_scale[Block::phase_field]      = std::sqrt(sums[7]);
    return info;
  }



  void
  SystemAssembler::assemble_faces(const TrilinosWrappers::MPI::BlockVector &u,
                                  const AffineConstraints<double> &constraints,
                                  const AssemblyTargets           &targets,
                                  AssemblyInfo                    &info) const
  {
    // The s block starts after u and alpha in the global numbering.
    const types::global_dof_index first_s =
      discretisation.dofs_per_block[Block::displacement] +
      discretisation.dofs_per_block[Block::hardening];

    FullMatrix<double>                   face_matrix, s_matrix;
    Vector<double>                       s_values, s_f_int, s_rhs;
    std::vector<unsigned int>            s_local;
    std::vector<types::global_dof_index> s_indices;

    // FEInterfaceValues of deal.II 9.4 is not hp-aware: one object per
    // element that carries s, each used on the faces between two such cells.
    for (unsigned int fe_index = 0;
         fe_index < discretisation.fe_collection.size();
         ++fe_index)
      {
        if (!(fe_index & 2))
          continue;
        FEInterfaceValues<dim> &fiv = *interface_values[fe_index];
        for_each_interior_face(
          discretisation.dof_handler,
          fiv,
          [&](const FEInterfaceValues<dim> &fiv, const double h_inverse) {
            const auto           &cell = fiv.get_fe_face_values(0).get_cell();
            const BodyParameters &body = *bodies.at(cell->material_id());
            const unsigned int    n    = fiv.n_current_interface_dofs();
            face_matrix.reinit(n, n);
            add_c0ip_face_terms(fiv,
                                discretisation.phase_field,
                                crack_coefficients(body, discretisation.degree),
                                h_inverse,
                                face_matrix);

            // Only the s DoFs carry face terms: keep the matrix to them,
            // the sparsity pattern couples nothing else across faces.
            const auto indices = fiv.get_interface_dof_indices();
            s_local.clear();
            for (unsigned int i = 0; i < n; ++i)
              if (indices[i] >= first_s)
                s_local.push_back(i);
            const unsigned int m = s_local.size();
            s_matrix.reinit(m, m);
            s_values.reinit(m);
            s_indices.resize(m);
            for (unsigned int k = 0; k < m; ++k)
              {
                s_indices[k] = indices[s_local[k]];
                s_values(k)  = u(s_indices[k]);
                for (unsigned int l = 0; l < m; ++l)
                  s_matrix(k, l) = face_matrix(s_local[k], s_local[l]);
              }
            s_f_int.reinit(m);
            s_matrix.vmult(s_f_int, s_values);
            info.fracture_energy += 0.5 * (s_values * s_f_int);

            s_rhs = s_f_int;
            s_rhs *= -1.;
            scatter(s_matrix,
                    s_rhs,
                    s_f_int,
                    s_indices,
                    constraints,
                    discretisation.hanging_node_constraints,
                    targets);
          },
          fe_index);
      }
  }
} // namespace DuctileContact
