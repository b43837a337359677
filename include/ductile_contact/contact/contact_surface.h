#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/contact/contact_face.h>
#include <ductile_contact/discretisation/discretisation.h>

#include <array>
#include <utility>
#include <vector>

namespace DuctileContact
{
  /**
   * The faces of one boundary id, replicated on every MPI rank: quad9 faces
   * in 3-D, line3 faces in plane strain (FE_Q(2) displacement;
   * ContactFace), with their nodes' global DoF indices, reference and
   * current positions.
   *
   * How the data moves: gather() all-gathers the faces of the locally owned
   * cells once per DoF distribution (connectivity, DoF indices, reference
   * positions); update() then sums the current positions of the nodes each
   * rank owns into one array of dim x (number of surface nodes) doubles with
   * an all-reduce, once per Newton iteration. Memory and traffic per rank
   * grow with the size of the contact surface, not with the mesh, which is
   * fine while surfaces have up to some 10^5 faces; beyond that the
   * replicated surface should be replaced by a some-to-some exchange of
   * the faces near each rank's slave faces.
   */
  struct ContactSurface
  {
    struct Node
    {
      std::array<dealii::types::global_dof_index, dim> dofs;
      dealii::Point<dim>                               reference;
      dealii::Point<dim>                               current;
      /// A hanging node (its DoFs constrained by hanging-node constraints):
      /// the nodes it is constrained to and their weights, u = sum w_p u_p
      /// (the same for each component); a parent that is not a node of this
      /// surface is numbers::invalid_unsigned_int. Empty otherwise.
      std::vector<std::pair<unsigned int, double>> parents;
    };
    struct Face
    {
      std::array<unsigned int, face_nodes> nodes; ///< ContactFace order,
                                                  ///< outward normal
      dealii::types::material_id material_id;
    };

    dealii::types::boundary_id boundary_id = 0;
    std::vector<Node>          nodes;
    std::vector<Face>          faces;
    /// Faces that contain each node.
    std::vector<std::vector<unsigned int>> node_faces;
    /// The hanging nodes constrained to each node (Node::parents reversed):
    /// (hanging node, weight).
    std::vector<std::vector<std::pair<unsigned int, double>>> children;

    /// Whether any node hangs.
    bool
    has_hanging_nodes() const;

    /// Collects the boundary faces with @p id from every rank. Requires
    /// FE_Q(2) for the displacement (throws InputError otherwise).
    void
    gather(const Discretisation &discretisation, dealii::types::boundary_id id);

    /// Current positions x = X + u from @p u (ghosted).
    void
    update(const dealii::TrilinosWrappers::MPI::BlockVector &u,
           const Discretisation                             &discretisation);

    ContactFace
    current_face(const unsigned int f) const;

    /// Smallest distance between two nodes of a face (reference) [m].
    double
    smallest_face_size() const;
    /// Largest face diameter (reference) [m].
    double
    largest_face_size() const;
  };
} // namespace DuctileContact
