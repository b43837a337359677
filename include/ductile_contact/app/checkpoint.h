#pragma once

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/core/types.h>

#include <string>
#include <vector>

namespace DuctileContact
{
  /**
   * The checkpoints of a run, in Output/Directory/checkpoints (doc/output.md,
   * "Checkpoints and resume"). Each is a folder step_NNNNNN holding
   *  - mesh*: the refined mesh (p4est; any number of ranks can load it) with
   *    the solution vectors and the quadrature-point history attached to its
   *    cells (partition-independent);
   *  - state.bin: what is not on the mesh (time, step, step controller,
   *    energy account, statistics, output series, contact state), written
   *    by rank 0;
   *  - parameters.prm: every entry of the run that wrote it.
   * Writing is atomic: the folder is written as .writing, all ranks meet,
   * rank 0 renames it and then replaces the marker file 'last' (written
   * beside it and renamed) that names the newest complete checkpoint. A run
   * killed while writing leaves the previous checkpoint and marker intact.
   * Older checkpoints beyond Checkpoint/Keep are deleted.
   *
   * Loading follows the order of writing: load_mesh() onto the coarse mesh,
   * then (after the DoFs are distributed on it) load_data().
   */
  /**
   * Compares the parameters a checkpoint was made with (@p saved) with
   * those of the run that resumes from it (@p current), both as written by
   * ParameterHandler::print_parameters() in PRM style. Throws InputError
   * naming the first changed entry that invalidates the checkpoint: one in
   * Mesh, Finite elements, Bodies, Body <id>, Boundary conditions (the id
   * list), Contact or Contact pair <n> (the mesh, the fields, the material
   * laws and their history, the contact surfaces). Returns the other
   * changes as "entry: old -> new" (load stepping, Newton, coupling, linear
   * solver, output, checkpoint, and the boundary conditions' values),
   * which the resumed run takes.
   */
  std::vector<std::string>
  compare_parameters(const std::string &saved, const std::string &current);

  class Checkpoint
  {
  public:
    /// Quadrature-point history: one flat vector per active cell (by
    /// active cell index), empty for cells this rank does not own.
    using CellData = std::vector<std::vector<double>>;

    Checkpoint(const std::string &output_directory,
               const unsigned int keep,
               const MPI_Comm     comm);

    /// Writes the checkpoint of accepted step @p step (collective).
    /// @p ghosted: vectors with ghost entries on @p dof_handler; @p state
    /// and @p parameters: the contents of state.bin and parameters.prm
    /// (used on rank 0).
    void
    write(const unsigned int             step,
          const dealii::DoFHandler<dim> &dof_handler,
          const std::vector<const dealii::TrilinosWrappers::MPI::BlockVector *>
                            &ghosted,
          const CellData    &cell_data,
          const std::string &state,
          const std::string &parameters) const;

    /// The folder of the newest complete checkpoint, "" if there is none
    /// (collective).
    std::string
    newest() const;

    /// A file of checkpoint @p folder, read on rank 0 and broadcast;
    /// throws InputError if it cannot be read.
    std::string
    read(const std::string &folder, const std::string &file) const;

    /// Loads the refined mesh of @p folder onto @p tria, which holds the
    /// coarse mesh the checkpoint was made on.
    static void
    load_mesh(const std::string                                 &folder,
              dealii::parallel::distributed::Triangulation<dim> &tria);

    /// Restores the vectors (without ghosts, in the order written) and
    /// the cell data, after load_mesh() and the DoF distribution.
    static void
    load_data(
      const dealii::DoFHandler<dim> &dof_handler,
      const std::vector<dealii::TrilinosWrappers::MPI::BlockVector *> &owned,
      CellData &cell_data);

    /// The folder name of step @p step.
    static std::string
    folder_name(const unsigned int step);

    /// A number that identifies the coarse mesh (cells and vertices), to
    /// check that a checkpoint is loaded onto the mesh it was made on.
    static std::string
    coarse_mesh_fingerprint(
      const dealii::parallel::distributed::Triangulation<dim> &tria);

  private:
    /// Deletes all but the newest @p keep complete checkpoints (rank 0).
    void
    prune() const;

    const std::string  root;
    const unsigned int keep;
    const MPI_Comm     comm;
  };
} // namespace DuctileContact
