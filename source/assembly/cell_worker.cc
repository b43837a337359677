#include <deal.II/base/mpi.h>
#include <deal.II/physics/elasticity/standard_tensors.h>

#include <ductile_contact/assembly/cell_rows.h>
#include <ductile_contact/assembly/cell_scratch.h>
#include <ductile_contact/assembly/system_assembler.h>
#include <ductile_contact/materials/body_material.h>
#include <ductile_contact/materials/degradation.h>
#include <ductile_contact/materials/neo_hooke.h>
#include <ductile_contact/materials/plane_stress.h>
#include <ductile_contact/phase_field/c0ip.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// The crack driver of (51) at point @p q: psi_H = max(psi_D, H_n)
    /// with the branch evaluated, recorded or frozen.
    CrackDriver
    crack_driver(const DrivingEnergy         &psi,
                 const double                 psi_max,
                 const double                 s,
                 const DegradationParameters &degradation,
                 const AssemblyTargets       *targets,
                 const unsigned int           cell_index,
                 const unsigned int           q,
                 AssemblyReduction           &sums)
    {
      CrackDriver d;
      d.psi     = psi;
      d.loading = psi.value > psi_max;
      if (targets && targets->branches == Branches::record)
        targets->branch_record->set(cell_index,
                                    q,
                                    d.loading ? BranchRecord::loading : 0);
      else if (targets && targets->branches == Branches::frozen)
        {
          const bool frozen_loading =
            targets->branch_record->get(cell_index, q, BranchRecord::loading);
          if (frozen_loading != d.loading)
            ++sums.switch_flips;
          d.loading = frozen_loading;
        }
      d.psi_H = d.loading ? psi.value : psi_max;
      d.g1    = degradation_derivative(s, degradation);
      d.g2    = degradation_second_derivative(s, degradation);
      return d;
    }



    /// The solution @p u and the history of @p step on @p cell at the
    /// quadrature points.
    void
    load_cell_state(const FEValues<dim>                         &fe_values,
                    const Discretisation                        &discretisation,
                    const BodyFields                            &fields,
                    const TrilinosWrappers::MPI::BlockVector    &u,
                    const StepData                              &step,
                    const bool                                   committing,
                    const DoFHandler<dim>::active_cell_iterator &cell,
                    CellScratch                                 &scratch)
    {
      const unsigned int n_q = fe_values.n_quadrature_points;
      scratch.history_n.assign(n_q, &scratch.default_history);
      if (step.history && (fields.hardening || fields.phase_field))
        for (unsigned int q = 0; q < n_q; ++q)
          scratch.history_n[q] = (*step.history)(cell) + q;
      scratch.grad_u.resize(n_q);
      fe_values[discretisation.displacement].get_function_gradients(
        u, scratch.grad_u);
      scratch.alpha.assign(n_q, 0.);
      scratch.grad_alpha.assign(n_q, Tensor<1, dim>());
      scratch.s.assign(n_q, 0.);
      scratch.s_old.assign(n_q, 0.);
      scratch.grad_u_old.assign(n_q, Tensor<2, dim>());
      if (fields.hardening)
        {
          if (step.old_solution && committing)
            fe_values[discretisation.displacement].get_function_gradients(
              *step.old_solution, scratch.grad_u_old);
          fe_values[discretisation.hardening].get_function_values(
            u, scratch.alpha);
          fe_values[discretisation.hardening].get_function_gradients(
            u, scratch.grad_alpha);
        }
      if (fields.phase_field)
        {
          fe_values[discretisation.phase_field].get_function_values(u,
                                                                    scratch.s);
          if (step.old_solution)
            fe_values[discretisation.phase_field].get_function_values(
              *step.old_solution, scratch.s_old);
        }
    }



    /// The plastic work of the step at one point (plastic_work_of_step());
    /// in plane stress F_n takes the accepted step's stretch.
    double
    plastic_work(const Tensor<2, material_dim> &F,
                 const Tensor<2, dim>          &grad_u_old,
                 const bool                     plane_stress,
                 const MaterialResponse        &m,
                 const PlasticHistory          &history_n,
                 const double                   s_n,
                 const double                   s,
                 const PlasticityParameters    &plastic)
    {
      const Tensor<2, material_dim> F_n = deformation_gradient(grad_u_old);
      return plastic_work_of_step(plane_stress
                                    ? with_stretch(F_n, history_n.stretch)
                                    : F_n,
                                  F,
                                  history_n,
                                  m.updated.Cp_inv,
                                  s_n,
                                  s,
                                  plastic);
    }

    /// The change of Psi^p_loc over a step split into its parts by alpha
    /// and by s, in the order of the backward Euler step: alpha moves at
    /// the new s (the flow resistance of (50) is taken at s_n+1), s at the
    /// old alpha. The parts add up to the change exactly. (The mean of the
    /// two orderings would leave a residual of first order in dt in the
    /// energy balance while the crack grows: the flow resistance of the
    /// step is the one at s_n+1.)
    struct PlasticEnergySplit
    {
      double by_alpha = 0., by_s = 0.;
    };

    PlasticEnergySplit
    split_plastic_energy_change(const double                alpha_n,
                                const double                alpha,
                                const double                s_n,
                                const double                s,
                                const PlasticityParameters &plastic)
    {
      const double e00 = plastic_energy_density(alpha_n, s_n, plastic),
                   e01 = plastic_energy_density(alpha_n, s, plastic),
                   e11 = plastic_energy_density(alpha, s, plastic);
      return {e11 - e01, e01 - e00};
    }

    /// The squared magnitudes and scales of the cell's rows by block.
    void
    reduce_rows(const LocalRows   &rows,
                const LocalDofs   &dofs,
                AssemblyReduction &sums)
    {
      for (const unsigned int i : dofs.u)
        sums.magnitude_squared[Block::displacement] +=
          rows.magnitude(i) * rows.magnitude(i);
      for (const unsigned int i : dofs.alpha)
        sums.magnitude_squared[Block::hardening] +=
          rows.magnitude(i) * rows.magnitude(i);
      for (const unsigned int i : dofs.s)
        sums.magnitude_squared[Block::phase_field] +=
          rows.magnitude(i) * rows.magnitude(i);
      sums.scale_squared[Block::hardening] += rows.scale_alpha.norm_sqr();
      sums.scale_squared[Block::phase_field] += rows.scale_s.norm_sqr();
    }

    /// @p copy emptied for @p cell: its rows sized and indexed.
    LocalRows &
    start_copy(const DoFHandler<dim>::active_cell_iterator &cell,
               CellCopy                                    &copy)
    {
      copy.sums         = AssemblyReduction();
      copy.n_faces      = 0;
      copy.has_averages = false;
      copy.cell_index   = cell->active_cell_index();
      copy.cell.reinit(cell->get_fe().n_dofs_per_cell());
      cell->get_dof_indices(copy.cell.indices);
      return copy.cell;
    }

    /// Volume averages of a cell's point quantities (CellCopy's output
    /// fields), summed over its points.
    struct CellAverages
    {
      double volume = 0, vm = 0, mean = 0, mean_J = 0, driver = 0;
      SymmetricTensor<2, material_dim> tau, sigma, b, Cp;

      /// Adds a point of weight @p JxW with its whole deformation gradient
      /// @p F; the tensors only if @p tensors.
      void
      add(const MaterialResponse        &m,
          const Tensor<2, material_dim> &F,
          const double                   JxW,
          const bool                     tensors)
      {
        volume += JxW;
        vm += von_mises(m.tau) * JxW;
        mean += trace(m.tau) / 3. * JxW;
        mean_J += m.J * JxW;
        if (!tensors)
          return;
        tau += JxW * m.tau;
        sigma += (JxW / m.J) * m.tau;
        b += JxW * symmetrize(F * transpose(F));
        Cp += JxW * invert(m.updated.Cp_inv);
      }

      /// The averages into @p copy (none for a cell without volume).
      void
      write(CellCopy &copy) const
      {
        copy.has_averages = volume > 0.;
        if (!copy.has_averages)
          return;
        copy.von_mises           = vm / volume;
        copy.mean_stress         = mean / volume;
        copy.mean_J              = mean_J / volume;
        copy.crack_driving_force = driver / volume;
        copy.kirchhoff           = tau / volume;
        copy.cauchy              = sigma / volume;
        copy.b                   = b / volume;
        copy.Cp                  = Cp / volume;
      }
    };
  } // namespace



  MaterialResponse
  SystemAssembler::point_response(const BodyParameters          &body,
                                  const Tensor<2, material_dim> &F,
                                  const unsigned int             q,
                                  const unsigned int             cell_index,
                                  const BodyFields              &fields,
                                  const CellScratch             &scratch,
                                  const Pass                    &pass,
                                  AssemblyReduction             &sums) const
  {
    const AssemblyTargets *targets = pass.targets;
    const Branches      mode = targets ? targets->branches : Branches::evaluate;
    std::optional<bool> frozen;
    if (fields.hardening && mode == Branches::frozen)
      frozen =
        targets->branch_record->get(cell_index, q, BranchRecord::yielding);
    const MaterialResponse m = evaluate_material(body,
                                                 F,
                                                 scratch.history_n[q]->plastic,
                                                 scratch.alpha[q],
                                                 scratch.s[q],
                                                 pass.step->dt,
                                                 targets && targets->tangent,
                                                 frozen);
    if (mode == Branches::record && (fields.hardening || fields.phase_field) &&
        m.yielding)
      targets->branch_record->set(cell_index, q, BranchRecord::yielding);
    if (frozen && m.trial_yielding != *frozen)
      ++sums.switch_flips;
    return m;
  }



  void
  SystemAssembler::hardening_point(const MaterialResponse        &m,
                                   const BodyParameters          &body,
                                   const PlasticityParameters    &plastic,
                                   const Tensor<2, material_dim> &F,
                                   const unsigned int             q,
                                   const bool                     committing,
                                   const CellScratch             &scratch,
                                   const LocalDofs               &dofs,
                                   const double                   JxW,
                                   const bool                     tangent,
                                   LocalRows                     &rows,
                                   AssemblyReduction             &sums) const
  {
    const PointHistory &history = *scratch.history_n[q];
    const double        l_p     = body.plastic_length_scale;
    // The gradient term acts at every point, not only where chi_p = 1 (see
    // plastic_update()).
    const double gradient_coefficient = plastic.initial_yield * l_p * l_p;
    const double alpha                = scratch.alpha[q];
    const double s                    = scratch.s[q];
    sums.max_alpha                    = std::max(sums.max_alpha, alpha);
    sums.min_alpha                    = std::min(sums.min_alpha, alpha);
    if (m.yielding)
      sums.min_yielding_alpha_increment =
        std::min(sums.min_yielding_alpha_increment,
                 alpha - history.plastic.alpha);
    sums.hardening_energy +=
      (plastic_energy_density(alpha, s, plastic) +
       0.5 * gradient_coefficient * scratch.grad_alpha[q].norm_square()) *
      JxW;
    if (committing)
      {
        const double work = plastic_work(F,
                                         scratch.grad_u_old[q],
                                         body.plane_stress,
                                         m,
                                         history.plastic,
                                         scratch.s_old[q],
                                         s,
                                         plastic);
        sums.plastic_work_increment += work * JxW;
        const PlasticEnergySplit split = split_plastic_energy_change(
          history.plastic.alpha, alpha, scratch.s_old[q], s, plastic);
        sums.plastic_energy_release_increment += -split.by_s * JxW;
        // The local plastic dissipation of the backward Euler step
        // (doc/model.md section 3.2): the work of the flow at the step's
        // end deformation less the stored energy it gained, plus the
        // energy r dalpha the point received from the rest of the field
        // through the weak equation (50) (the gradient term; summed over
        // the points this is the change of the gradient energy less the
        // numerical dissipation of its step).
        const double local_dissipation =
          flow_work(F, history.plastic, m.updated.Cp_inv, s, plastic) -
          split.by_alpha + m.r * (alpha - history.plastic.alpha);
        sums.min_plastic_dissipation =
          std::min(sums.min_plastic_dissipation, local_dissipation);
      }
    add_hardening_rows(m,
                       plastic,
                       gradient_coefficient,
                       scratch.grad_alpha[q],
                       scratch.shapes,
                       dofs,
                       q,
                       JxW,
                       tangent,
                       rows);
  }



  double
  SystemAssembler::phase_field_point(const MaterialResponse      &m,
                                     const DrivingEnergy         &psi,
                                     const BodyParameters        &body,
                                     const DegradationParameters &degradation,
                                     const unsigned int           q,
                                     PointHistory                *history_new,
                                     const CellScratch           &scratch,
                                     const LocalDofs             &dofs,
                                     const double                 dt,
                                     const double                 JxW,
                                     const AssemblyTargets       *targets,
                                     const unsigned int           cell_index,
                                     LocalRows                   &rows,
                                     AssemblyReduction           &sums) const
  {
    const double psi_max =
      crack_history ? scratch.history_n[q]->driving_energy_max : 0.;
    const CrackDriver driver = crack_driver(
      psi, psi_max, scratch.s[q], degradation, targets, cell_index, q, sums);
    const double ds   = scratch.s[q] - scratch.s_old[q];
    const double rate = ds / dt;
    sums.fracture_viscous_work_increment +=
      body.crack.viscosity * rate * rate * dt * JxW;
    if (history_new)
      {
        history_new[q].driving_energy_max = driver.psi_H;
        sums.history_work_increment +=
          -driver.g1 * (driver.psi_H - psi.variational) * ds * JxW;
      }
    add_phase_field_rows(m,
                         driver,
                         body,
                         rate,
                         dt,
                         scratch.shapes,
                         dofs,
                         q,
                         JxW,
                         targets && targets->tangent,
                         rows);
    return -driver.g1 * driver.psi_H * JxW;
  }



  void
  SystemAssembler::cell_worker(
    const DoFHandler<dim>::active_cell_iterator &cell,
    CellScratch                                 &scratch,
    CellCopy                                    &copy,
    const Pass                                  &pass) const
  {
    const StepData        &step      = *pass.step;
    const AssemblyTargets *targets   = pass.targets;
    const BodyFields       fields    = discretisation.cell_fields(cell);
    const bool             has_alpha = fields.hardening;
    const bool             has_s     = fields.phase_field;
    const bool             tangent   = targets && targets->tangent;
    const Branches     mode  = targets ? targets->branches : Branches::evaluate;
    const unsigned int index = cell->active_cell_index();
    hp::FEValues<dim> &hp_values =
      (has_alpha || has_s) ? scratch.coupled_values : scratch.elastic_values;
    hp_values.reinit(cell);
    const FEValues<dim>        &fe_values = hp_values.get_present_fe_values();
    const unsigned int          n_q       = fe_values.n_quadrature_points;
    const BodyParameters       &body      = *bodies.at(cell->material_id());
    const PlasticityParameters  plastic   = body.material();
    const DegradationParameters degradation{body.crack.degradation_a,
                                            body.crack.residual_stiffness};
    const LocalDofs &dofs = discretisation.local_dofs(cell->active_fe_index());

    LocalRows         &rows = start_copy(cell, copy);
    AssemblyReduction &sums = copy.sums;

    load_cell_state(fe_values,
                    discretisation,
                    fields,
                    *pass.u,
                    step,
                    pass.updated_history != nullptr,
                    cell,
                    scratch);
    PointHistory *history_new = (pass.updated_history && (has_alpha || has_s))
                                  ? (*pass.updated_history)(cell)
                                  : nullptr;
    if (mode == Branches::record && (has_alpha || has_s))
      targets->branch_record->start_cell(index, n_q);
    if (tangent)
      rows.blocks.reinit(dofs, n_q);

    CellAverages averages;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const Tensor<2, material_dim> F =
          deformation_gradient(scratch.grad_u[q]);
        const double J = determinant(F);
        if (!(J >= sums.min_J))
          sums.note_J(J, {cell->center(), cell->material_id()});
        if (!(J > 0.))
          continue;
        const MaterialResponse m =
          point_response(body, F, q, index, fields, scratch, pass, sums);
        // In plane stress F_33 is the stretch the material point found.
        const Tensor<2, material_dim> F_point =
          body.plane_stress ? with_stretch(F, m.updated.stretch) : F;
        const double JxW = fe_values.JxW(q);
        sums.stored_energy += m.psi_elastic * JxW;
        averages.add(m, F_point, JxW, pass.averages);
        if (has_s)
          sums.max_s_point = std::max(sums.max_s_point, scratch.s[q]);
        if (has_s && scratch.s[q] >= cracked_threshold)
          sums.note_cracked(fe_values.quadrature_point(q), JxW);
        const DrivingEnergy psi_D =
          has_s ? crack_driving_energy(m,
                                       scratch.alpha[q],
                                       body.crack.driver,
                                       body.crack.work_driver,
                                       plastic)
                : DrivingEnergy();
        if (pass.averages && !pass.updated_history)
          {
            // Only the cell averages: the crack driver, no rows.
            if (has_s)
              {
                const CrackDriver d =
                  crack_driver(psi_D,
                               crack_history
                                 ? scratch.history_n[q]->driving_energy_max
                                 : 0.,
                               scratch.s[q],
                               degradation,
                               nullptr,
                               index,
                               q,
                               sums);
                averages.driver += -d.g1 * d.psi_H * JxW;
              }
            continue;
          }

        // A commit needs no displacement rows, and shape functions only
        // for the hardening and crack terms.
        if (targets || has_alpha || has_s)
          scratch.shapes.reinit(fe_values, q, dofs);
        if (targets)
          add_displacement_rows(
            m, body, scratch.shapes, dofs, q, JxW, tangent, rows);

        if (has_alpha)
          hardening_point(m,
                          body,
                          plastic,
                          F_point,
                          q,
                          history_new != nullptr,
                          scratch,
                          dofs,
                          JxW,
                          tangent,
                          rows,
                          sums);
        if (has_s)
          averages.driver += phase_field_point(m,
                                               psi_D,
                                               body,
                                               degradation,
                                               q,
                                               history_new,
                                               scratch,
                                               dofs,
                                               step.dt,
                                               JxW,
                                               targets,
                                               index,
                                               rows,
                                               sums);
        if (history_new && has_alpha)
          history_new[q].plastic = m.updated;
      }

    if (pass.averages)
      {
        averages.write(copy);
        if (!pass.updated_history)
          return;
      }
    if (step.inertia && body.density > 0.)
      inertia_terms(cell, body, dofs, scratch, copy, pass);
    if (tangent)
      rows.add_blocks(dofs);
    finish_rows(cell, body, dofs, scratch, copy, pass);
  }



  void
  SystemAssembler::finish_rows(
    const DoFHandler<dim>::active_cell_iterator &cell,
    const BodyParameters                        &body,
    const LocalDofs                             &dofs,
    CellScratch                                 &scratch,
    CellCopy                                    &copy,
    const Pass                                  &pass) const
  {
    LocalRows   &rows          = copy.cell;
    const bool   has_s         = !dofs.s.empty();
    const double energy_before = copy.sums.fracture_energy;
    if (has_s)
      {
        scratch.cell_values.reinit(rows.f_int.size());
        cell->get_dof_values(*pass.u, scratch.cell_values);
        copy.sums.fracture_energy +=
          add_crack_functional_rows(crack_matrix(cell, body, dofs, scratch),
                                    scratch.cell_values,
                                    dofs,
                                    pass.targets && pass.targets->tangent,
                                    rows);
      }
    reduce_rows(rows, dofs, copy.sums);

    // R = f_int - f_ext; the Newton right-hand side is -R.
    for (unsigned int i = 0; i < rows.rhs.size(); ++i)
      rows.rhs(i) = -rows.f_int(i);
    add_traction_rows(cell, scratch, pass.step->t, dofs, rows);
    if (!copy.sums.non_finite)
      for (unsigned int i = 0; i < rows.rhs.size(); ++i)
        if (!std::isfinite(rows.rhs(i)))
          {
            copy.sums.non_finite      = true;
            copy.sums.non_finite_site = {cell->center(), cell->material_id()};
            break;
          }
    if (has_s)
      {
        face_terms(cell, scratch, copy, pass);
        copy.sums.crack_area += (copy.sums.fracture_energy - energy_before) /
                                body.crack.critical_energy_release_rate;
      }
  }



  void
  SystemAssembler::add_traction_rows(
    const DoFHandler<dim>::active_cell_iterator &cell,
    CellScratch                                 &scratch,
    const double                                 t,
    const LocalDofs                             &dofs,
    LocalRows                                   &rows) const
  {
    if (tractions.empty())
      return;
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        {
          const auto it = tractions.find(cell->face(f)->boundary_id());
          if (it == tractions.end())
            continue;
          scratch.face_values.reinit(cell, f);
          const FEFaceValues<dim> &fv =
            scratch.face_values.get_present_fe_values();
          for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
            {
              const Tensor<1, dim> T =
                it->second->traction_at(fv.quadrature_point(q), t);
              for (unsigned int k = 0; k < dofs.u.size(); ++k)
                rows.rhs(dofs.u[k]) += fv.shape_value(dofs.u[k], q) *
                                       T[dofs.u_component[k]] * fv.JxW(q);
            }
        }
  }



  const FullMatrix<double> &
  SystemAssembler::crack_matrix(
    const DoFHandler<dim>::active_cell_iterator &cell,
    const BodyParameters                        &body,
    const LocalDofs                             &dofs,
    CellScratch                                 &scratch) const
  {
    FullMatrix<double> &a_K = crack_matrices[cell->active_cell_index()];
    if (a_K.empty())
      {
        scratch.crack_values.reinit(cell);
        a_K =
          crack_functional_matrix(scratch.crack_values.get_present_fe_values(),
                                  discretisation,
                                  body,
                                  dofs);
      }
    return a_K;
  }



  const std::vector<SystemAssembler::FaceMatrix> &
  SystemAssembler::face_matrices(
    const DoFHandler<dim>::active_cell_iterator &cell,
    CellScratch                                 &scratch) const
  {
    CellFaceMatrices &cached = cell_face_matrices[cell->active_cell_index()];
    if (cached.computed)
      return cached.faces;

    // The s block starts after u and alpha in the global numbering.
    const types::global_dof_index first_s =
      discretisation.dofs_per_block[Block::displacement] +
      discretisation.dofs_per_block[Block::hardening];
    const BodyParameters   &body = *bodies.at(cell->material_id());
    FEInterfaceValues<dim> &fiv =
      *scratch.interface_values[cell->active_fe_index()];
    cached.faces.clear();
    // The second-order functional has no face terms.
    if (body.crack.regularisation == Regularisation::second_order)
      {
        cached.computed = true;
        return cached.faces;
      }
    for_each_owned_interior_face(
      cell,
      fiv,
      [&](const FEInterfaceValues<dim> &fiv, const double h_inverse) {
        const unsigned int n = fiv.n_current_interface_dofs();
        scratch.face_matrix.reinit(n, n);
        add_c0ip_face_terms(fiv,
                            discretisation.phase_field,
                            crack_coefficients(body, discretisation.degree),
                            h_inverse,
                            scratch.face_matrix);

        // Only the s DoFs carry face terms: keep the matrix to them, the
        // sparsity pattern couples nothing else across faces.
        const auto                 indices = fiv.get_interface_dof_indices();
        std::vector<unsigned int> &s_local = scratch.face_s_dofs;
        s_local.clear();
        for (unsigned int i = 0; i < n; ++i)
          if (indices[i] >= first_s)
            s_local.push_back(i);
        const unsigned int m    = s_local.size();
        FaceMatrix        &face = cached.faces.emplace_back();
        face.indices.resize(m);
        face.matrix.reinit(m, m);
        for (unsigned int k = 0; k < m; ++k)
          {
            face.indices[k] = indices[s_local[k]];
            for (unsigned int l = 0; l < m; ++l)
              face.matrix(k, l) = scratch.face_matrix(s_local[k], s_local[l]);
          }
      });
    cached.computed = true;
    return cached.faces;
  }



  void
  SystemAssembler::face_terms(const DoFHandler<dim>::active_cell_iterator &cell,
                              CellScratch &scratch,
                              CellCopy    &copy,
                              const Pass  &pass) const
  {
    for (const FaceMatrix &cached : face_matrices(cell, scratch))
      {
        const unsigned int m = cached.indices.size();
        if (copy.faces.size() <= copy.n_faces)
          copy.faces.emplace_back();
        LocalRows &face = copy.faces[copy.n_faces++];
        face.reinit(m);
        face.indices = cached.indices;
        // The matrix goes to the tangent only; residual passes need f_int.
        if (pass.targets && pass.targets->tangent)
          face.matrix = cached.matrix;
        Vector<double> &s_values = scratch.face_s_values;
        s_values.reinit(m);
        for (unsigned int k = 0; k < m; ++k)
          s_values(k) = (*pass.u)(face.indices[k]);
        cached.matrix.vmult(face.f_int, s_values);
        copy.sums.fracture_energy += 0.5 * (s_values * face.f_int);
        face.rhs = face.f_int;
        face.rhs *= -1.;
      }
  }
} // namespace DuctileContact
