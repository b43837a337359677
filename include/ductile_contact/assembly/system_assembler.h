#pragma once

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/assembly/assembly_data.h>
#include <ductile_contact/assembly/quadrature_history.h>
#include <ductile_contact/assembly/scatter.h>
#include <ductile_contact/discretisation/boundary_condition.h>
#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/materials/body_material.h>
#include <ductile_contact/materials/body_parameters.h>
#include <ductile_contact/materials/degradation.h>

#include <boost/signals2/connection.hpp>
#include <deque>
#include <map>
#include <memory>

namespace DuctileContact
{
  struct CellScratch;
  struct CellCopy;
  struct LocalRows;

  /**
   * Residual and exact tangent of the coupled total-Lagrangian problem
   * [u | alpha | s] (doc/model.md sections 2-4):
   *
   *   R_u     = int P : Grad du dV - int_dB T . du dA
   *   R_alpha = int dalpha r(F, alpha, s) + y_0 l_p^2 grad dalpha .
   *             grad alpha dV                                          (50)
   *   R_s     = int eta_f (s - s_n)/dt ds + g_k'(s) psi^+_H ds dV
   *             + a(s, ds)                                             (51)
   *
   * with P and r from evaluate_material(), psi^+_H = max(psi^+_hist,
   * psi^+(F, alpha)) the crack driver with history (irreversibility,
   * chi_f = 1; psi^+ alone without @p crack_history), and a(., .) the C0IP
   * form of g_c gamma (phase_field/c0ip.h) with cell and interior-face
   * terms. Dead-load nominal tractions T. The gradient term of (50) acts at
   * every point, not only where chi_p = 1 (see plastic_update()).
   *
   * One WorkStream loop over the locally owned cells; a cell assembles the
   * rows of each field it carries (cell_rows.h) and the C0IP terms of the
   * interior faces it owns. A pure assembly: it does not own vectors, know
   * the load history or decide anything.
   */
  class SystemAssembler
  {
  public:
    SystemAssembler(const Discretisation                   &discretisation,
                    const std::map<dealii::types::material_id,
                                   const BodyParameters *> &bodies,
                    const std::deque<BoundaryCondition>    &boundary_conditions,
                    const bool crack_history = true);
    ~SystemAssembler();

    /// Residual, tangent and internal force at @p u (with ghost entries)
    /// into @p targets, which are zeroed and, if @p finish, compressed
    /// here (else a later compress() adds what went to other ranks); the
    /// energies of the state.
    AssemblyInfo
    assemble(const dealii::TrilinosWrappers::MPI::BlockVector &u,
             const StepData                                   &step,
             const dealii::AffineConstraints<double>          &constraints,
             const AssemblyTargets                            &targets,
             const bool finish = true) const;

    /// The commit of an accepted state @p u: the quadrature-point history
    /// after it into @p updated, its energies with the increments of the
    /// step (plastic work, history driving work) and, in the same pass, its
    /// cell averages for the output into @p quantities.
    AssemblyInfo
    commit(const dealii::TrilinosWrappers::MPI::BlockVector &u,
           const StepData                                   &step,
           QuadratureHistory                                &updated,
           CellQuantities                                   &quantities) const;

    /// Why the state of @p info is not admissible, with where it happens
    /// ("" when it is): an inverted element (J <= 0) or a non-finite
    /// residual, the cell's position and its body.
    std::string
    fault(const AssemblyInfo &info) const;

    /// Cell averages of @p u for the output (commit() makes them too).
    void
    cell_averages(const dealii::TrilinosWrappers::MPI::BlockVector &u,
                  const StepData                                   &step,
                  CellQuantities &quantities) const;

  private:
    /// Sizes @p quantities to one entry per active cell.
    void
    resize(CellQuantities &quantities) const;

    /// What a pass computes besides the rows.
    struct Pass
    {
      const dealii::TrilinosWrappers::MPI::BlockVector *u;
      const StepData                                   *step;
      const AssemblyTargets                            *targets;
      QuadratureHistory                                *updated_history;
      /// Cell averages for the output: alone (no rows, no history) or
      /// with a commit.
      bool averages;
    };

    AssemblyInfo
    run(const Pass                              &pass,
        const dealii::AffineConstraints<double> &constraints,
        CellQuantities                          *quantities) const;

    void
    cell_worker(const dealii::DoFHandler<dim>::active_cell_iterator &cell,
                CellScratch                                         &scratch,
                CellCopy                                            &copy,
                const Pass &pass) const;

    /// The material law at point @p q of the cell @p cell_index with the
    /// branches of @p pass (evaluated, recorded or frozen).
    MaterialResponse
    point_response(const BodyParameters                  &body,
                   const dealii::Tensor<2, material_dim> &F,
                   const unsigned int                     q,
                   const unsigned int                     cell_index,
                   const BodyFields                      &fields,
                   const CellScratch                     &scratch,
                   const Pass                            &pass,
                   AssemblyReduction                     &sums) const;

    /// The hardening terms of point @p q: energy, extremes, plastic work
    /// (when @p committing) and the rows of (50).
    void
    hardening_point(const MaterialResponse                &m,
                    const BodyParameters                  &body,
                    const PlasticityParameters            &plastic,
                    const dealii::Tensor<2, material_dim> &F,
                    const unsigned int                     q,
                    const bool                             committing,
                    const CellScratch                     &scratch,
                    const LocalDofs                       &dofs,
                    const double                           JxW,
                    const bool                             tangent,
                    LocalRows                             &rows,
                    AssemblyReduction                     &sums) const;

    /// The phase-field terms of point @p q with the driving energy @p psi
    /// (crack_driving_energy()): the history maximum with its branch,
    /// viscous work, the history (into @p history_new if not null) and the
    /// rows of (51); returns the driver -g_k' psi_H JxW.
    double
    phase_field_point(const MaterialResponse      &m,
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
                      AssemblyReduction           &sums) const;

    /// The rows of the nominal tractions T on the boundary faces of @p cell.
    void
    add_traction_rows(const dealii::DoFHandler<dim>::active_cell_iterator &cell,
                      CellScratch     &scratch,
                      const double     t,
                      const LocalDofs &dofs,
                      LocalRows       &rows) const;

    /// After the points of @p cell: the crack functional's cell terms, the
    /// magnitudes, -R, the tractions and the C0IP faces of the cell.
    /// The inertia of a dynamic step on @p cell (body density > 0): its
    /// rows int rho a_m . du dV with a_m = c (u - u*) and tangent c M in
    /// an assembly with targets, its kinetic energy, momentum and inertial
    /// work in a commit (source/assembly/inertia_rows.cc).
    void
    inertia_terms(const dealii::DoFHandler<dim>::active_cell_iterator &cell,
                  const BodyParameters                                &body,
                  const LocalDofs                                     &dofs,
                  CellScratch                                         &scratch,
                  CellCopy                                            &copy,
                  const Pass &pass) const;

    void
    finish_rows(const dealii::DoFHandler<dim>::active_cell_iterator &cell,
                const BodyParameters                                &body,
                const LocalDofs                                     &dofs,
                CellScratch                                         &scratch,
                CellCopy                                            &copy,
                const Pass &pass) const;

    /// The C0IP face terms of the interior faces that @p cell owns.
    void
    face_terms(const dealii::DoFHandler<dim>::active_cell_iterator &cell,
               CellScratch                                         &scratch,
               CellCopy                                            &copy,
               const Pass                                          &pass) const;

    const Discretisation &discretisation;
    const std::map<dealii::types::material_id, const BodyParameters *> bodies;
    const std::deque<BoundaryCondition> &boundary_conditions;
    /// Whether the crack driver keeps the history maximum of psi^+
    /// (Coupling/Irreversibility other than `bound`).
    const bool crack_history;
    /// The evaluation objects and local rows of the cell loop, built on
    /// the first pass and kept: the shape data of FEInterfaceValues on all
    /// subfaces with hessians cost more to set up than an assembly of a
    /// small mesh. A cache, not state: every pass overwrites what it uses.
    /// With more than one thread WorkStream copies the scratch per thread.
    mutable std::unique_ptr<CellScratch> scratch;
    mutable std::unique_ptr<CellCopy>    copy_data;
    /// The s-s block of the crack functional's cell matrix a_K of @p cell
    /// (crack_functional_matrix()), computed on first use after a change of
    /// the mesh and kept: it depends on the cell and l_f only.
    const dealii::FullMatrix<double> &
    crack_matrix(const dealii::DoFHandler<dim>::active_cell_iterator &cell,
                 const BodyParameters                                &body,
                 const LocalDofs                                     &dofs,
                 CellScratch &scratch) const;

    /// crack_matrix() per active cell index (empty: not computed yet), and
    /// the number of active cells it was sized for; cleared when the mesh
    /// changes. Each cell's entry is written only by the pass over that
    /// cell, so threads do not share entries.
    mutable std::vector<dealii::FullMatrix<double>> crack_matrices;

    /// The s-s block of the C0IP face matrix of one interior face (the
    /// jump and average terms of the crack functional, "C0IP form" in
    /// doc/model.md) and the global s DoFs it couples.
    struct FaceMatrix
    {
      std::vector<dealii::types::global_dof_index> indices;
      dealii::FullMatrix<double>                   matrix;
    };
    /// The face matrices of the interior faces that a cell owns.
    struct CellFaceMatrices
    {
      bool                    computed = false;
      std::vector<FaceMatrix> faces;
    };
    /// The face matrices of the interior faces that @p cell owns
    /// (for_each_owned_interior_face()), computed on first use after a
    /// change of the mesh and kept like crack_matrix(): they depend on the
    /// two cells and l_f only. Evaluating them takes FEInterfaceValues
    /// with the hessians of every shape function of both cells, which
    /// cost ~15 % of a phase-field run when it was done in every pass.
    const std::vector<FaceMatrix> &
    face_matrices(const dealii::DoFHandler<dim>::active_cell_iterator &cell,
                  CellScratch &scratch) const;

    /// face_matrices() per active cell index, sized and cleared with
    /// crack_matrices (same ownership rule).
    mutable std::vector<CellFaceMatrices> cell_face_matrices;
    /// Where each cell's tangent entries lie (AssemblyTargets::pattern).
    mutable CellPositions       cell_positions;
    boost::signals2::connection mesh_changed;

    /// Traction boundaries, looked up per face.
    std::map<dealii::types::boundary_id, const BoundaryCondition *> tractions;
  };
} // namespace DuctileContact
