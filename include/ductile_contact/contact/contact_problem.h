#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <ductile_contact/assembly/assembly_data.h>
#include <ductile_contact/contact/contact_pair.h>
#include <ductile_contact/contact/contact_parameters.h>
#include <ductile_contact/contact/contact_surface.h>
#include <ductile_contact/contact/enforcement.h>
#include <ductile_contact/contact/mortar_operators.h>
#include <ductile_contact/contact/nodal_complementarity.h>
#include <ductile_contact/contact/nodal_contact.h>
#include <ductile_contact/materials/body_parameters.h>
#include <ductile_contact/modules/physics_module.h>
#include <ductile_contact/output/output_parameters.h>
#include <ductile_contact/output/statistics.h>

#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace DuctileContact
{
  /**
   * Mortar contact with Coulomb friction between deformable bodies
   * (doc/model.md section 5, doc/contact.md), one or more pairs of boundary
   * surfaces.
   *
   * Discretisation: dual (biorthogonal) multiplier basis Phi_j on the slave
   * faces (quad9, line3; or the standard Phi_j = N_j), segment-based
   * integration (mortar_points()) on the current geometry of
   *
   *   D_jk = int Phi_j N_k dA,  M_jl = int Phi_j (N_l o chi) dA,
   *   A_j = sum_k D_jk,  g_j = n_j . (sum_l M_jl x_l - sum_k D_jk x_k),
   *
   * over the overlap of each slave face with its candidate master faces,
   * n_j the averaged nodal normal (g_j >= 0 open).
   *
   * Enforcement (KKT (44)) and friction (48) per slave node: the pair's
   * Enforcement (`Contact pair/Enforcement`), SemiSmoothNewton (the
   * tractions condensed from the bulk rows, no outer loop) or
   * AugmentedLagrangian (the nodal law on fixed multipliers, Uzawa updates
   * by outer_update()). This class gives them the geometry, the operators
   * and the derivatives; they make the tractions and the rows.
   *
   * Consistent linearisation: d(D_jk f_j) = dD_jk f_j + D_jk (df_j/da)
   * (da/dx), with a = (A_j, G_j, H_j, n_j) the nodal aggregates
   * (nodal_contact.h). dD and dM come from forward AD through the whole
   * segment-based integration of each face pair (MortarFace: clipping,
   * auxiliary planes, back-projection, dual basis coefficients), dn_j from
   * the analytic derivative of the face normals it averages, df_j/da from
   * AD of the nodal law. The tangent is therefore exact for the branch
   * taken (active set, stick/slip, which polygon vertices are clipped), and
   * not symmetric.
   *
   * Search: a bounding-box broad phase (boxes enlarged by the search
   * radius) once per load step in begin_step(); the candidates fix the
   * sparsity couplings of the step. The exact pair checks and the
   * integration run at every assembly on the current geometry.
   *
   * Parallel layout: the surfaces are replicated (ContactSurface); the
   * ranks integrate equal shares of the face pairs and gather D and M
   * (integrate()); each assembles the rows of the slave nodes whose DoFs
   * it owns, which touch master rows owned by other ranks: those are added
   * through the distributed matrix and vectors (compress(add)). The
   * derivatives of D and M (the expensive part of a tangent assembly) are
   * needed for the face pairs that touch an active slave node: integrate()
   * makes those of its share for semi-smooth Newton, linearise_operators()
   * those of an equal share of the pairs it needs otherwise. The augmented
   * Lagrangian sends the derivatives to the nodes' owners; the condensation of
   * semi-smooth Newton, whose tangent terms are linear in them, adds each
   * rank's partial derivatives where they were made. Results are
   * the same on any number of ranks up to round-off.
   *
   * Files: contact_problem.cc (setup, the step, the module lifecycle),
   * contact_search.cc, contact_couplings.cc, contact_integration.cc (D, M,
   * aggregates), contact_tangent.cc (their derivatives), contact_state.cc
   * (committed state, checkpoint, transfer), the enforcements in
   * semi_smooth_newton.cc and augmented_lagrangian.cc.
   *
   * The driver sees it as a PhysicsModule.
   */
  class ContactProblem : public PhysicsModule
  {
  public:
    ContactProblem(const std::deque<ContactPairParameters> &pairs,
                   const Discretisation                    &discretisation,
                   const std::map<dealii::types::material_id,
                                  const BodyParameters *>  &bodies);

    std::string
    name() const override
    {
      return "contact";
    }

    /// Gathers the surfaces; call after every DoF distribution.
    void
    setup() override;

    /// Whether assemble() needs the bulk terms compressed before it: the
    /// condensation reads the bulk rows of the slave nodes, and another
    /// rank's cells may add to them. Otherwise the bulk assembly can leave
    /// its terms to the one compress at the end of assemble().
    bool
    needs_compressed_bulk() const override
    {
      return !bulk_rows_here;
    }

    /// Candidate search on the geometry of @p u (ghosted) and reset of the
    /// multipliers to their committed values; returns true when the
    /// candidate couplings changed (the sparsity pattern must be rebuilt).
    bool
    begin_step(const dealii::TrilinosWrappers::MPI::BlockVector &u) override;

    /// All DoFs of the contact surfaces (rows the assembly may write).
    dealii::IndexSet
    surface_dofs() const;

    dealii::IndexSet
    written_rows() const override
    {
      return surface_dofs();
    }

    /// Adds the couplings of the current candidates.
    void
    add_couplings(
      dealii::TrilinosWrappers::BlockSparsityPattern &sp,
      const dealii::AffineConstraints<double> &constraints) const override;

    /// Adds the contact contributions at @p u (ghosted) to @p targets (which
    /// hold the bulk terms) and compresses them.
    void
    assemble(const dealii::TrilinosWrappers::MPI::BlockVector &u,
             const dealii::AffineConstraints<double>          &constraints,
             const AssemblyTargets &targets) override;

    /// Uzawa update after a converged Newton solve; returns true when every
    /// pair meets its penetration tolerance (then nothing changed).
    bool
    augment();

    /// The largest augmentations per step of the pairs.
    unsigned int
    max_outer_updates() const override;

    /// augment(); @p report names the largest penetration of each pair
    /// before the update.
    bool
    outer_update(std::string &report) override;

    /// The multipliers of the accepted step become the committed ones.
    void
    commit() override;

    /// Writes the slave surfaces with pressure and gap of the last
    /// assembly in @p format (contact_writer.h; collective, every rank
    /// writes its share of the replicated surfaces).
    void
    write_output(const std::string &directory,
                 const OutputFormat format,
                 const unsigned int step,
                 const double       time) override;

    /// Why the state of the last assembly cannot be accepted ("" when it
    /// can): a master face came within reach of a slave face (its overlap
    /// would count) without being one of the step's candidates, so that
    /// the pattern holds no couplings for it. The search radius of the
    /// pair doubles for the next begin_step().
    std::string
    fault() const override;

    /// The active slave nodes of the pairs that condense (semi-smooth
    /// Newton): their normal rows, and their tangential rows where they
    /// stick, hold the complementarity function.
    void
    add_constrained_rows(ConstrainedNodes &nodes) const override;

    const std::vector<ContactPairSummary> &
    summary() const
    {
      return summaries;
    }

    /// Adds the columns contact<number>_... of every pair (its summary
    /// after the last assembly) to the statistics row.
    void
    add_columns(Statistics &statistics) const override;

    /// The frictional dissipation of every pair (47) [J].
    double
    dissipation() const override;

    /// The committed state of every pair (multipliers, tangential
    /// tractions, node positions, dissipation) for a checkpoint: per node a
    /// record that starts with its reference position, since the node
    /// order depends on the partition.
    std::vector<double>
    committed_state() const override;

    /// Restores committed_state() after setup(); throws InputError when
    /// the surfaces do not match the records.
    void
    restore_committed_state(const std::vector<double> &state) override;

    /// Before a mesh change (adaptive refinement): keeps the committed
    /// state of the current surfaces for transfer_committed_state().
    void
    keep_committed_state() override;

    /**
     * After a mesh change and setup(): the committed state kept by
     * keep_committed_state() on the new surfaces. The positions of the
     * last accepted step are X + u_n with @p accepted (u_n on the new
     * mesh, which refinement carries exactly); a slave node that existed
     * before keeps its multiplier and tangential traction, a new one (on a
     * refined slave face) gets them interpolated on the old face that
     * contains it (face shape functions at its reference position); the
     * dissipation so far and the output series carry over.
     */
    void
    transfer_committed_state(
      const dealii::TrilinosWrappers::MPI::BlockVector &accepted) override;

    /**
     * Adds the contact forces of the committed state at @p u (ghosted) to
     * @p force (compressed here), as the assembly adds them to the
     * internal force: the accepted step's nodal force on a new mesh
     * (Simulation::accepted_force_on_new_mesh()). The traction of slave
     * node j is lambda_j n_j + t_j from the committed multipliers and
     * tangential tractions (semi-smooth Newton commits both from its
     * condensed tractions).
     */
    void
    add_committed_forces(
      const dealii::TrilinosWrappers::MPI::BlockVector &u,
      dealii::TrilinosWrappers::MPI::BlockVector       &force) override;

    /// The series of the contact output files (checkpoints).
    OutputSeries &
    output_series() override
    {
      return output_records;
    }

    const std::deque<ContactPairParameters> &pairs;

  private:
    friend class SemiSmoothNewton;
    friend class AugmentedLagrangian;

    /// Multiplier updates (augment()) since the last begin_step().
    unsigned int outer_updates = 0;

    using Pair = ContactPair;

    /// One Enforcement per kind in use, which the pairs point to.
    std::map<ContactEnforcement, std::unique_ptr<Enforcement>> enforcements;

    /// The Enforcement of @p kind, made on first use.
    const Enforcement *
    enforcement_of(ContactEnforcement kind);

    /// @p constraints (which know the locally relevant DoFs only) plus the
    /// constraints of every contact-surface DoF, gathered from the ranks
    /// that own them: a contact row of this rank may couple to master DoFs
    /// that are neither owned nor ghosted here, and a Dirichlet condition
    /// on them (a symmetry plane crossing the surface) must still be
    /// applied.
    void
    extend_constraints(const dealii::AffineConstraints<double> &constraints,
                       dealii::AffineConstraints<double>       &extended) const;

    using CellFilter = std::function<bool(
      const dealii::DoFHandler<dim>::active_cell_iterator &)>;
    using RowVisitor =
      std::function<void(const dealii::types::global_dof_index,
                         const std::vector<dealii::types::global_dof_index> &)>;
    /// Calls @p visit(row, the cell's DoFs) for every row that an active
    /// cell accepted by @p take writes into: its DoFs, and for a DoF with a
    /// hanging-node constraint the parents instead.
    void
    for_each_cell_row(const CellFilter &take, const RowVisitor &visit) const;

    /// Whether, on every rank, only its own cells add to the rows of the
    /// slave nodes it condenses (no ghost cell touches them). Collective.
    bool
    slave_rows_complete_here() const;

    /// The master faces of @p pair whose current bounding boxes meet each
    /// slave face's enlarged by @p radius, sorted, by slave face: the
    /// candidates of a step (radius search_radius()) or the faces within
    /// reach() of an assembly.
    static std::vector<std::vector<unsigned int>>
    search(const Pair &pair, const double radius);

    /// How far the box of a slave face reaches for master faces whose
    /// overlap counts: half the smallest slave face size (an open gap
    /// wider than that is not in contact in any case) [m].
    static double
    reach(const Pair &pair)
    {
      return 0.5 * pair.face_size;
    }

    /// The search radius of the step that starts at the current geometry
    /// (the predicted one): Contact pair/Search radius, or reach() plus a
    /// margin for the motion within the step, twice the largest predicted
    /// motion of a slave node plus that of a master node since the last
    /// accepted step and at least a quarter of the smallest slave face;
    /// times the pair's widening.
    static double
    search_radius(const Pair &pair);

    /// The face pairs of @p pair to integrate, by slave face: every
    /// candidate of each slave face that has a candidate among @p near
    /// (search() with reach() on the current geometry), so that a slave
    /// face is integrated whole or not at all.
    static std::vector<std::pair<unsigned int, unsigned int>>
    close_face_pairs(const Pair                                   &pair,
                     const std::vector<std::vector<unsigned int>> &near);

    /// A face pair of @p pair among @p near whose faces may overlap but
    /// which is no candidate of the step: its description, or "" when
    /// there is none.
    static std::string
    missed_pair(const Pair                                   &pair,
                const std::vector<std::vector<unsigned int>> &near);

    /// D, M, normals and aggregates of @p pair on its current geometry.
    /// Every rank integrates a share of the face pairs (share(); with
    /// @p derivatives it keeps their dD and dM for linearise_operators())
    /// and all gather the operators. Collective.
    void
    integrate(Pair &pair, const bool derivatives);

    /// integrate(): this rank's share of the @p close face pairs of
    /// @p pair, with their derivatives kept in pair.linearised_operators if
    /// @p derivatives; returns per overlapping pair the record f, c, D
    /// (its row sums with SlaveWeights::lumped), M.
    std::vector<double>
    integrate_share(Pair                                              &pair,
                    std::vector<std::pair<unsigned int, unsigned int>> close,
                    const bool derivatives) const;

    /// integrate(): gathers the records of integrate_share() from all
    /// ranks, in rank order, into pair.overlaps, D and M.
    void
    add_operators(Pair &pair, const std::vector<double> &mine) const;

    /// This rank's contiguous, equal share [first, second) of @p n_items
    /// face pairs.
    static std::pair<std::size_t, std::size_t>
    share(const std::size_t n_items, const MPI_Comm comm);

    /// This rank's share of the overlapping face pairs whose slave face has
    /// a node in @p any, as [first, second) in pair.overlaps.
    static std::pair<std::size_t, std::size_t>
    face_pair_share(const Pair              &pair,
                    const std::vector<bool> &any,
                    const MPI_Comm           comm);

    /**
     * Semi-smooth Newton with hanging nodes on the slave surface: the
     * multipliers live on the nodes with rows of their own. A hanging node
     * h (u_h = sum_p w_p u_p) hands its area, weighted gap and slip
     * aggregates and its master weights, times w_p, to its parents p and
     * carries no contact itself; its traction is the interpolation
     * sum_p w_p f_p. That is the dual multiplier space restricted to the
     * constrained trace space, with D lumped: a uniform traction still
     * gives the consistent nodal forces on both sides, and the forces on
     * the two bodies still balance.
     */
    void
    fold_hanging_nodes(Pair &pair) const;

    /// summaries[pair.index] from pair.nodal and the aggregates.
    void
    summarise(Pair &pair);

    /// Where linearise_operators() leaves the derivatives of D and M.
    enum class GradientShare
    {
      /// Summed on the ranks that own the nodes of `needed`.
      complete,
      /// Each rank's share where it was made.
      partial
    };

    /// d(aggregates of node j)/dx, for the nodes j in @p needed, from the
    /// derivatives of D and M (overlapping face pairs with a node in @p
    /// needed) and adds the dD f_j (if @p slave_rows), dM f_j part of the
    /// tangent to @p targets (@p forces: f_j of the needed nodes). Keys of
    /// @p gradients: 3 node + c, master nodes after the slave nodes.
    /// On several ranks the face pairs that any rank needs are split into
    /// shares, integrated where they fall, and the partial gradients sent
    /// to the ranks that need them: the slave nodes of a surface are
    /// mostly owned by one rank, which would otherwise do all of the work.
    /// The derivatives integrate() kept are used where it made them. With
    /// @p kept = GradientShare::partial the gradients stay where they were
    /// made.
    /// Returns the nodes whose gradients this rank holds (all of them, or
    /// its share), i.e. @p needed or the union of every rank's.
    std::vector<bool>
    linearise_operators(
      const Pair                                                  &pair,
      const std::vector<bool>                                     &needed,
      const std::vector<dealii::Tensor<1, dim>>                   &forces,
      const bool                                                   slave_rows,
      const GradientShare                                          kept,
      const dealii::AffineConstraints<double>                     &constraints,
      const AssemblyTargets                                       &targets,
      std::vector<std::map<unsigned int, std::array<double, 10>>> &gradients)
      const;

    /// The work of linearise_operators() on this rank: the face pairs
    /// pair.overlaps[@p range.first, @p range.second) that touch a node of
    /// @p needed, whose forces @p forces are complete.
    void
    integrate_face_pairs(
      const Pair                                                  &pair,
      const std::vector<bool>                                     &needed,
      const std::vector<dealii::Tensor<1, dim>>                   &forces,
      const bool                                                   slave_rows,
      const std::pair<std::size_t, std::size_t>                   &range,
      const dealii::AffineConstraints<double>                     &constraints,
      const AssemblyTargets                                       &targets,
      std::vector<std::map<unsigned int, std::array<double, 10>>> &gradients)
      const;

    /// The part of linearise_operators() of face pair
    /// pair.overlaps[@p overlap] with its @p operators: the gradients of
    /// the nodes of @p needed and the dD f_j (if @p slave_rows), dM f_j
    /// terms.
    void
    add_face_pair_terms(
      const Pair                                                  &pair,
      const std::size_t                                            overlap,
      const FacePairOperators                                     &operators,
      const std::vector<bool>                                     &needed,
      const std::vector<dealii::Tensor<1, dim>>                   &forces,
      const bool                                                   slave_rows,
      const dealii::AffineConstraints<double>                     &constraints,
      const AssemblyTargets                                       &targets,
      std::vector<std::map<unsigned int, std::array<double, 10>>> &gradients)
      const;

    /// Adds to @p g the derivatives of the aggregates of node @p j with
    /// D and M held (G, H through the positions) and, if @p normal, of its
    /// normal.
    static void
    add_direct_gradients(const Pair                                     &pair,
                         const unsigned int                              j,
                         std::map<unsigned int, std::array<double, 10>> &g,
                         const bool normal = true);

    /// The local numbering of the contact system of slave node @p j: the
    /// coordinate keys of the slave nodes @p slave_rows, of the master nodes
    /// of M_j and of the columns in @p g get their positions in @p local;
    /// returns their DoFs in that order.
    static std::vector<dealii::types::global_dof_index>
    local_numbering(const Pair                      &pair,
                    const unsigned int               j,
                    const std::vector<unsigned int> &slave_rows,
                    const std::map<unsigned int, std::array<double, 10>> &g,
                    std::map<unsigned int, unsigned int> &local);

    /// The DoF of coordinate @p key = 3 node + c (master nodes numbered
    /// after the slave nodes), the keys of linearise_operators().
    static dealii::types::global_dof_index
    coordinate_dof(const Pair &pair, const unsigned int key);

    /// The slave and master nodes that node @p j couples to.
    void
    coupled_nodes(const Pair                &pair,
                  const unsigned int         j,
                  std::vector<unsigned int> &slave_nodes,
                  std::vector<unsigned int> &master_nodes) const;

    const Discretisation &discretisation;
    const std::map<dealii::types::material_id, const BodyParameters *> bodies;
    std::vector<Pair>                                                  data;
    /// The pairs before a mesh change (keep_committed_state()).
    std::vector<Pair>               kept;
    std::vector<ContactPairSummary> summaries;
    /// DoFs of all contact surfaces.
    dealii::IndexSet surface;
    /// slave_rows_complete_here() of the current mesh.
    bool bulk_rows_here = false;
    /// (time, file) of the surface outputs written, per pair.
    std::vector<std::vector<std::pair<double, std::string>>> output_records;
  };
} // namespace DuctileContact
