#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/mesh/mesh_parameters.h>

#include <functional>
#include <vector>

namespace DuctileContact
{
  /**
   * Refinement of the mesh during a run (Mesh/Adaptive refinement,
   * doc/input.md): the predictor-corrector scheme of Heister, Wheeler and
   * Wick (2015) needs two things from it, which cells to refine after a
   * converged load step and how the state of the last accepted step moves
   * to the refined mesh.
   *
   * Flagging: a cell below Maximum level is flagged where its indicator
   *
   *   eta_K = max( max_i s_i / s_thr , max_i alpha_i / alpha_thr ) > 1
   *
   * (the maxima over the cell's DoFs; a term is left out when its threshold
   * is 0). When refining all of them would make more than Maximum cells
   * cells (7 more per flagged cell, before the 2:1 balance), only those
   * with the largest eta_K are refined. Cells are never coarsened.
   *
   * Transfer:
   *  - finite-element vectors by interpolation
   *    (parallel::distributed::SolutionTransfer, hp with FE_Nothing
   *    bodies); on refinement the new space contains the old one, so the
   *    fields are carried exactly, and the hanging-node constraints hold;
   *  - per-cell quadrature data (records of a fixed size per point) by
   *    injection: each point of a child takes the record of the parent's
   *    point nearest to it in the parent's reference cell. A child's state
   *    is thus one the parent had: det (C^p)^{-1} = 1, alpha_n >= 0 and the
   *    history of psi^+ never below the parent's value there, which an
   *    L2 projection would not keep.
   */
  class MeshAdaptation
  {
  public:
    /// One flat vector per active cell (by active cell index), empty for
    /// cells this rank does not own.
    using CellData = std::vector<std::vector<double>>;
    using Vector   = dealii::TrilinosWrappers::MPI::BlockVector;

    MeshAdaptation(const MeshParameters::AdaptiveRefinement &parameters,
                   dealii::parallel::distributed::Triangulation<dim> &tria,
                   const Discretisation                              &d);

    /// What flag() did.
    struct Flags
    {
      /// Cells flagged on all ranks (0: the mesh stays).
      unsigned int flagged = 0;
      /// Cells above the thresholds that Maximum cells left unrefined.
      unsigned int held_back = 0;
    };

    /// Flags the cells to refine by the fields of @p u (with ghosts).
    Flags
    flag(const Vector &u);

    /**
     * Refines the flagged cells. @p ghosted: vectors (with ghosts) on the
     * current DoFs; @p cell_data: records of @p record_size doubles per
     * quadrature point of @p quadrature. @p redistribute is called once the
     * mesh has changed: it distributes the DoFs and resizes everything that
     * depends on them, among them the vectors @p owned (one per @p ghosted,
     * without ghosts), which then receive the carried fields; @p cell_data
     * then holds the carried records.
     */
    void
    refine(const std::vector<const Vector *> &ghosted,
           CellData                          &cell_data,
           const unsigned int                 record_size,
           const dealii::Quadrature<dim>     &quadrature,
           const std::function<void()>       &redistribute,
           const std::vector<Vector *>       &owned);

  private:
    /// eta_K of a locally owned cell (see the class documentation).
    double
    indicator(const dealii::DoFHandler<dim>::active_cell_iterator &cell,
              const Vector                                        &u) const;

    const MeshParameters::AdaptiveRefinement           parameters;
    dealii::parallel::distributed::Triangulation<dim> &tria;
    const Discretisation                              &discretisation;
  };

  /**
   * For each child c of a hexahedron and each point q of @p quadrature,
   * the point of @p quadrature in the parent nearest to q's position in
   * the parent's reference cell: result[c][q].
   */
  std::vector<std::vector<unsigned int>>
  nearest_parent_points(const dealii::Quadrature<dim> &quadrature);
} // namespace DuctileContact
