#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/assembly/quadrature_history.h>
#include <ductile_contact/core/types.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace DuctileContact
{
  /// Where an assembly met a numerical fault: a reference position and
  /// the body (material id) there.
  struct FaultSite
  {
    dealii::Point<dim> position;
    unsigned int       body = 0;
  };

  /// What one assembly pass found (all values summed over MPI ranks).
  struct AssemblyInfo
  {
    /// An element is inverted (J <= 0 at a quadrature point): the state
    /// is not admissible and nothing else here is meaningful.
    bool   inverted = false;
    double min_J    = 1.;
    /// The cell (centre) with the smallest J.
    FaultSite min_J_site;
    /// A cell's residual rows are not finite (NaN or Inf), first at
    /// non_finite_site (a cell centre): the state is not admissible.
    bool      non_finite = false;
    FaultSite non_finite_site;
    /// int Psi^e dV over the reference configuration [J] (degraded).
    double stored_energy = 0.;
    /// int (Psi^p_loc(alpha, s) + y_0 l_p^2/2 |grad alpha|^2) dV [J], (20)
    /// with Psi^p_loc of plastic_energy_density() (int_0^alpha yhat da
    /// unless the plastic energy is degraded).
    double hardening_energy = 0.;
    /// Commit of a dynamic step: the kinetic energy int rho |v|^2/2 dV
    /// [J] and the momentum int rho v dV [kg m/s] of the accepted state,
    /// and the step's inertial work int rho (u_n+1 - u_n) . (a_m,n +
    /// a_m,n+1)/2 dV [J] (its change of kinetic energy plus the scheme's
    /// numerical dissipation).
    double                 kinetic_energy = 0.;
    dealii::Tensor<1, dim> momentum;
    double                 inertial_work_increment = 0.;
    /// g_c int gamma dV with the C0IP-consistent bi-Laplacian [J]:
    /// a(s, s)/2 of phase_field/c0ip.h.
    double fracture_energy = 0.;
    /// Of the step from the committed state to this one [J]: the plastic
    /// work, i.e. the elastic energy the plastic flow releases at fixed F,
    /// int Psi^e(F, C^p_n) - Psi^e(F, C^p) dV (= int tau : d^p dt to first
    /// order in dt; exactly consistent with Psi^e, so that the energy
    /// balance closes as dt -> 0), and the viscous dissipation of the
    /// phase field int eta_f (s - s_n)^2/dt. The plastic work is only
    /// computed by the commit pass (SystemAssembler::commit()).
    double plastic_work_increment          = 0.;
    double fracture_viscous_work_increment = 0.;
    /// Of the committed step [J]: the work of the crack driver beyond the
    /// current elastic state, int (-g_k'(s)) (psi_H - psi^+) (s - s_n) dV
    /// (psi_H the history maximum of the driving energy psi_D, doc/model.md
    /// (27); crack_driving_energy()). With the elastic driver it is >= 0
    /// and nonzero where psi^+ has fallen below its maximum while s still
    /// grows (material unloading beside a running crack); with the plastic
    /// work driver it also holds the work of W_p - w_c on s. The history
    /// driver is not the derivative of an energy, so the energy balance
    /// W_ext = Psi^e + plastic work + fracture energy + viscous work misses
    /// about minus this (to first order in dt); see the statistics column
    /// history_driving_work.
    double history_work_increment = 0.;
    /// Of the committed step [J]: the plastic energy the crack releases,
    /// int -(Psi^p_loc(alpha_n, s) - Psi^p_loc(alpha_n, s_n)) dV (the s
    /// part of the step's change in backward Euler order: s at the old
    /// alpha; 0 unless the plastic energy is degraded; >= 0 while the crack
    /// grows).
    double plastic_energy_release_increment = 0.;
    /// Of the committed step [J/m^3]: the smallest local plastic
    /// dissipation over the quadrature points, the plastic work of the step
    /// minus the change of Psi^p_loc at fixed s (without the gradient term,
    /// which couples the points); +max if no point has alpha.
    double min_plastic_dissipation = std::numeric_limits<double>::max();
    /// Smallest alpha at a quadrature point (+max if none).
    double min_alpha = std::numeric_limits<double>::max();
    /// Largest s at a quadrature point (lowest if none): the field between
    /// the nodes, where the bound on the DoFs holds only with the Bernstein
    /// basis.
    double max_s_point = std::numeric_limits<double>::lowest();
    /// Crack measures of the pass (commit: of the accepted state): the
    /// regularised crack area Gamma_l(s) = int gamma(s, grad s, Hess s) dV
    /// [m^2] (the fracture energy over g_c, body by body), the volume where
    /// s >= cracked_threshold at the quadrature points [m^3], and the
    /// bounding box of those points in the reference configuration [m]
    /// (the crack tip of a through-crack is its far end; zero if none).
    double             crack_area     = 0.;
    double             cracked_volume = 0.;
    dealii::Point<dim> cracked_min, cracked_max;
    /// Largest alpha at a quadrature point, and the smallest alpha -
    /// alpha_n over the yielding ones (chi_p = 1; +inf if none yields): a
    /// negative value is plastic flow reversed by the gradient term.
    double max_alpha                    = 0.;
    double min_yielding_alpha_increment = std::numeric_limits<double>::max();
    /// Quadrature points whose yield switch chi_p or crack-driver branch
    /// (loading: psi^+ above its history maximum) differs from the frozen
    /// one (Branches::frozen only): with none, R is the true residual.
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

  /**
   * The per-rank sums of one assembly pass, by name: each cell adds its
   * own (AssemblyReduction::add), and the pass ends with one reduction over
   * the MPI ranks (sum_over_ranks()).
   */
  struct AssemblyReduction
  {
    double                 stored_energy                    = 0.;
    double                 hardening_energy                 = 0.;
    double                 fracture_energy                  = 0.;
    double                 plastic_work_increment           = 0.;
    double                 fracture_viscous_work_increment  = 0.;
    double                 history_work_increment           = 0.;
    double                 plastic_energy_release_increment = 0.;
    double                 kinetic_energy                   = 0.;
    double                 inertial_work_increment          = 0.;
    dealii::Tensor<1, dim> momentum;
    double min_plastic_dissipation = std::numeric_limits<double>::max();
    double min_alpha               = std::numeric_limits<double>::max();
    double max_s_point             = std::numeric_limits<double>::lowest();
    double crack_area              = 0.;
    double cracked_volume          = 0.;
    /// The box of the cracked points (meaningful where cracked_volume > 0).
    dealii::Point<dim> cracked_min, cracked_max;
    /// Sums of squares of the cell magnitudes and scales per block (the
    /// scale of u is its magnitude).
    std::array<double, Block::n_blocks> magnitude_squared{{0., 0., 0.}};
    std::array<double, Block::n_blocks> scale_squared{{0., 0., 0.}};
    double    min_J = std::numeric_limits<double>::max();
    FaultSite min_J_site;
    double    max_alpha                    = 0.;
    double    min_yielding_alpha_increment = std::numeric_limits<double>::max();
    bool      inverted                     = false;
    bool      non_finite                   = false;
    FaultSite non_finite_site;
    unsigned int switch_flips = 0;

    /// Notes a value J below min_J (or not finite) at @p site.
    void
    note_J(const double J, const FaultSite &site)
    {
      min_J      = std::isfinite(J) ? J : -std::numeric_limits<double>::max();
      min_J_site = site;
      if (!(J > 0.))
        inverted = true;
    }

    /// A quadrature point at @p p with weight @p JxW has s >= the threshold.
    void
    note_cracked(const dealii::Point<dim> &p, const double JxW)
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          cracked_min[d] =
            cracked_volume > 0. ? std::min(cracked_min[d], p[d]) : p[d];
          cracked_max[d] =
            cracked_volume > 0. ? std::max(cracked_max[d], p[d]) : p[d];
        }
      cracked_volume += JxW;
    }

    void
    add(const AssemblyReduction &other);

    AssemblyInfo
    sum_over_ranks(const MPI_Comm comm) const;
  };

  /// A point counts as cracked where s is at least this (crack measures).
  constexpr double cracked_threshold = 0.95;

  /// Cell averages for graphical output, indexed by active cell index:
  /// von Mises and mean Kirchhoff stress, J, the crack driving force, and
  /// the averages of the Kirchhoff stress tau, the Cauchy stress tau / J,
  /// the left Cauchy-Green tensor b = F F^T and C^p = F^pT F^p (the
  /// identity in elastic bodies), from which the output takes the strains.
  struct CellQuantities
  {
    dealii::Vector<float> von_mises, mean_stress, J, crack_driving_force;
    std::vector<dealii::SymmetricTensor<2, material_dim>> kirchhoff, cauchy, b,
      Cp;
  };

  /**
   * The branches of the non-smooth terms at each quadrature point: the
   * yield switch chi_p of (50), and the branch of the crack driver
   * max(psi^+, H_n) (Miehe's history field: loading where psi^+ > H_n).
   * A tangent assembly records them (Branches::record), the line search
   * and the tangent check evaluate with them (Branches::frozen), so that R
   * is smooth along the Newton direction and its derivative there is the
   * tangent's. Indexed by active cell index; empty for cells without alpha
   * and s.
   */
  class BranchRecord
  {
  public:
    static constexpr unsigned char yielding = 1, loading = 2;

    /// Forgets every branch (before a recording pass).
    void
    reset(const unsigned int n_active_cells)
    {
      bits.assign(n_active_cells, {});
    }

    /// Whether a recording pass has filled the record for this mesh.
    bool
    covers(const unsigned int n_active_cells) const
    {
      return bits.size() == n_active_cells;
    }

    /// Starts the record of cell @p cell with @p n_points points.
    void
    start_cell(const unsigned int cell, const unsigned int n_points)
    {
      bits[cell].assign(n_points, 0);
    }

    void
    set(const unsigned int cell, const unsigned int q, const unsigned char b)
    {
      bits[cell][q] |= b;
    }

    bool
    get(const unsigned int  cell,
        const unsigned int  q,
        const unsigned char b) const
    {
      return (bits[cell].at(q) & b) != 0;
    }

  private:
    std::vector<std::vector<unsigned char>> bits;
  };

  /// How an assembly treats the branches of non-smooth terms.
  enum class Branches
  {
    /// from the current state;
    evaluate,
    /// from the current state, and written into the BranchRecord;
    record,
    /// those of the BranchRecord.
    frozen
  };

  /// Where an assembly of the system writes; null members are skipped.
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
    /// The branch record that Branches::record writes and
    /// Branches::frozen reads.
    BranchRecord *branch_record = nullptr;
    Branches      branches      = Branches::evaluate;
    /// Names the sparsity pattern of @p tangent: a number that its owner
    /// takes from new_pattern_id() (scatter.h) whenever it builds the
    /// pattern, or 0 when unknown. With a name, the bulk assembly keeps
    /// where each cell's entries lie in the matrix (CellPositions) from
    /// one assembly to the next.
    std::uint64_t pattern = 0;
  };

  /**
   * The inertia of a dynamic step (doc/model.md section 6.5): the
   * acceleration at which the momentum balance takes the inertia is
   * linear in the step's displacements, a_m = c (u - u*), so that a body
   * of density rho adds int rho a_m . du dV to R_u (and to f_int, whose
   * Dirichlet rows are then the reactions of the moving bodies) and c M
   * to the tangent. The commit pass also reads the accepted state's
   * velocity and the mean inertial acceleration of the step.
   */
  struct InertiaTerms
  {
    /// c [1/s^2].
    double mass_factor = 0.;
    /// u* with ghost entries (displacement block).
    const dealii::TrilinosWrappers::MPI::BlockVector *target = nullptr;
    /// The DoFs of the contact surfaces (sorted, locally relevant), which
    /// carry no mass: a cell with such DoFs takes its mass matrix from the
    /// redistributing rule of redistributed_mass_rule() (null or empty:
    /// the consistent mass everywhere).
    const std::vector<dealii::types::global_dof_index> *massless = nullptr;
    /// Commit only: v_n+1, and (a_m,n + a_m,n+1)/2, with ghost entries.
    const dealii::TrilinosWrappers::MPI::BlockVector *velocity = nullptr;
    const dealii::TrilinosWrappers::MPI::BlockVector *mean_acceleration =
      nullptr;
  };

  /// The load step being solved: time, step and the accepted state before.
  struct StepData
  {
    double t  = 0.;
    double dt = 1.;
    /// Solution of the last accepted step, with ghost entries.
    const dealii::TrilinosWrappers::MPI::BlockVector *old_solution = nullptr;
    const QuadratureHistory                          *history      = nullptr;
    /// Dynamic runs only (null: quasi-static).
    const InertiaTerms *inertia = nullptr;
  };
} // namespace DuctileContact
