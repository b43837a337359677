#pragma once

#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/assembly/quadrature_history.h>
#include <ductile_contact/discretisation/boundary_condition.h>
#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/materials/body_parameters.h>

#include <array>
#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <vector>

namespace DuctileContact
{
  /// What one assembly pass found (all values summed over MPI ranks).
  struct AssemblyInfo
  {
    /// An element is inverted (J <= 0 at a quadrature point): the state
    /// is not admissible and nothing else here is meaningful.
    bool   inverted = false;
    double min_J    = 1.;
    /// int Psi^e dV over the reference configuration [J] (degraded).
    double stored_energy = 0.;
    /// int (int_0^alpha yhat da + y_0 l_p^2/2 |grad alpha|^2) dV [J], (20).
    double hardening_energy = 0.;
    /// g_c int gamma dV with the C0IP-consistent bi-Laplacian [J]:
    /// a(s, s)/2 of phase_field/c0ip.h.
    double fracture_energy = 0.;
    /// Of the step from the committed state to this one [J]: the plastic
    /// work, i.e. the elastic energy the plastic flow releases at fixed F,
    /// int Psi^e(F, C^p_n) - Psi^e(F, C^p) dV (= int tau : d^p dt to first
    /// order in dt; exactly consistent with Psi^e, so that the energy
    /// balance closes as dt -> 0), and the viscous dissipation of the
    /// phase field int eta_f (s - s_n)^2/dt. The plastic work is only
    /// computed when the history is committed (AssemblyTargets::history).
    double plastic_work_increment          = 0.;
    double fracture_viscous_work_increment = 0.;
    /// Of the committed step [J]: the work of the crack-driver history
    /// beyond the current elastic state, int (-g_k'(s)) (psi_H - psi^+)
    /// (s - s_n) dV >= 0 (psi_H the history maximum of psi^+, model.md
    /// (27)). It is nonzero where psi^+ has fallen below its maximum while s
    /// still grows (material unloading beside a running crack). The history
    /// driver is not the derivative of an energy, so the energy balance
    /// W_ext = Psi^e + plastic work + fracture energy + viscous work misses
    /// about minus this (to first order in dt); see the statistics column
    /// history_driving_work.
    double history_work_increment = 0.;
    /// Largest alpha at a quadrature point, and the smallest alpha -
    /// alpha_n over the yielding ones (chi_p = 1; +inf if none yields): a
    /// negative value is plastic flow reversed by the gradient term.
    double max_alpha                    = 0.;
    double min_yielding_alpha_increment = std::numeric_limits<double>::max();
    /// Quadrature points whose yield switch chi_p or crack-driver branch
    /// (loading: psi^+ above its history maximum) differs from the frozen
    /// one (Switches::frozen only): with none, R is the true residual.
    unsigned int switch_flips = 0;
    /// Size of the terms summed into f_int: sqrt of the sum over cells and
    /// DoFs of (sum over quadrature points of (|P : Grad N_i| + (mu + kappa)
    /// |Grad N_i|) JxW)^2 [N]. F = I + Grad u resolves Grad u only to eps,
    /// so P is uncertain by eps (mu + kappa): ||R|| cannot drop much below
    /// eps times this, whatever the solver does.
    double force_magnitude = 0.;
    /// Residual scale of each block: for alpha y_0 and for s g_c/(2 l_f)
    /// times sqrt(sum over cells and DoFs of (int N_i dV)^2), i.e. the size
    /// of the local terms at alpha = 1 or s = 1 [J]; force_magnitude for u.
    std::array<double, Block::n_blocks> residual_scale{{0., 0., 0.}};
    /// Size of the terms summed into each block of R, as force_magnitude
    /// (which is the u entry): eps times it is the round-off floor of the
    /// block's residual norm.
    std::array<double, Block::n_blocks> residual_magnitude{{0., 0., 0.}};
  };

  /// Cell averages for graphical output, indexed by active cell index.
  struct CellQuantities
  {
    dealii::Vector<float> von_mises, mean_stress, J, crack_driving_force;
  };

  /// Where assemble() writes; null members are skipped.
  struct AssemblyTargets
  {
    /// Newton tangent K, condensed with the Newton constraints.
    dealii::TrilinosWrappers::BlockSparseMatrix *tangent = nullptr;
    /// -R condensed with the (inhomogeneous) Newton constraints: the
    /// right-hand side of K delta = -R.
    dealii::TrilinosWrappers::MPI::BlockVector *newton_rhs = nullptr;
    /// R on free DoFs (constrained entries zero): its norm decides
    /// convergence.
    dealii::TrilinosWrappers::MPI::BlockVector *residual = nullptr;
    /// f_int condensed with the hanging-node constraints only (Dirichlet
    /// rows kept): reactions and external work come from it.
    dealii::TrilinosWrappers::MPI::BlockVector *internal_force = nullptr;
    /// The history after this state (commit of an accepted step).
    QuadratureHistory *history = nullptr;
    /// Cell averages for output.
    CellQuantities *cell_quantities = nullptr;
    /// The two switches of a quadrature point, the yield switch chi_p of
    /// (50) and the branch of the crack driver max(psi^+, H_n) (Miehe's
    /// history field: loading where psi^+ > H_n): from the current state
    /// (evaluate), from the current state and remembered (record: Newton's
    /// tangent assemblies), or the remembered ones (frozen: line search and
    /// tangent check, so that R is smooth along the Newton direction and
    /// its derivative there is the tangent's).
    enum class Switches
    {
      evaluate,
      record,
      frozen
    } switches = Switches::evaluate;
  };

  /// The load step being solved: time, step and the accepted state before.
  struct StepData
  {
    double t  = 0.;
    double dt = 1.;
    /// Solution of the last accepted step, with ghost entries.
    const dealii::TrilinosWrappers::MPI::BlockVector *old_solution = nullptr;
    const QuadratureHistory                          *history      = nullptr;
  };

  /**
   * Residual and exact tangent of the coupled total-Lagrangian problem
   * [u | alpha | s] (model.md sections 2-4):
   *
   *   R_u     = int P : Grad du dV - int_dB T . du dA
   *   R_alpha = int dalpha r(F, alpha, s) + chi_p y_0 l_p^2 grad dalpha .
   *             grad alpha dV                                          (50)
   *   R_s     = int eta_f (s - s_n)/dt ds + g_k'(s) psi^+_H ds dV
   *             + a(s, ds)                                             (51)
   *
   * with P and r from evaluate_material(), psi^+_H = max(psi^+_hist,
   * psi^+(F, alpha)) the crack driver with history (irreversibility,
   * chi_f = 1; psi^+ alone without @p crack_history), and a(., .) the C0IP form
   * of g_c gamma (phase_field/c0ip.h) with cell and interior-face terms.
   * Dead-load nominal tractions T. A pure assembly: it does not own vectors,
   * know the load history or decide anything.
   */
  class SystemAssembler
  {
  public:
    SystemAssembler(const Discretisation                   &discretisation,
                    const std::map<dealii::types::material_id,
                                   const BodyParameters *> &bodies,
                    const std::deque<BoundaryCondition>    &boundary_conditions,
                    const bool crack_history = true);

    /// @p u must have ghost entries. Matrices/vectors in @p targets are
    /// zeroed and compressed here.
    AssemblyInfo
    assemble(const dealii::TrilinosWrappers::MPI::BlockVector &u,
             const StepData                                   &step,
             const dealii::AffineConstraints<double>          &constraints,
             const AssemblyTargets                            &targets) const;

  private:
    void
    assemble_faces(const dealii::TrilinosWrappers::MPI::BlockVector &u,
                   const dealii::AffineConstraints<double> &constraints,
                   const AssemblyTargets                   &targets,
                   AssemblyInfo                            &info) const;

    const Discretisation &discretisation;
    /// The switches per (active cell index, quadrature point) of the last
    /// Switches::record assembly: bit 0 chi_p, bit 1 crack-driver loading.
    mutable std::vector<std::vector<unsigned char>> recorded_switches;
    const std::map<dealii::types::material_id, const BodyParameters *> bodies;
    const std::deque<BoundaryCondition> &boundary_conditions;
    /// Whether the crack driver keeps the history maximum of psi^+
    /// (Coupling/Irreversibility other than `bound`).
    const bool crack_history;

    // Evaluation objects, built once: their shape data (in particular the
    // hessians on all subfaces of FEInterfaceValues) are expensive to set
    // up. Mutable scratch of a const assembly.
    mutable dealii::hp::FEValues<dim>     elastic_values, coupled_values;
    mutable dealii::hp::FEFaceValues<dim> face_values;
    /// One per element that carries s (deal.II 9.4's FEInterfaceValues is
    /// not hp-aware); null for the others.
    mutable std::vector<std::unique_ptr<dealii::FEInterfaceValues<dim>>>
      interface_values;
  };
} // namespace DuctileContact
