#pragma once

#include <deal.II/base/point.h>

#include <ductile_contact/core/types.h>

#if DUCTILE_CONTACT_DIM == 3
#include <ductile_contact/contact/quad9.h>
#else
#include <ductile_contact/contact/line3.h>
#endif

namespace DuctileContact
{
  /**
   * The face type of the contact surfaces of this build: the 9-node quad9
   * of an FE_Q(2) hexahedron in 3-D, the 3-node line3 of an FE_Q(2)
   * quadrilateral in plane strain. Both have the same members, with the
   * parameter point FaceParameter = Point<dim - 1>.
   */
#if DUCTILE_CONTACT_DIM == 3
  using ContactFace = Quad9;
#else
  using ContactFace = Line3;
#endif

  /// Number of nodes of a face (9 | 3).
  constexpr unsigned int face_nodes = ContactFace::n_nodes;

  /// Parameter point of a face: (xi, eta) in 3-D, xi in 2-D.
  using FaceParameter = dealii::Point<dim - 1>;

  /// Number of current coordinates of one face (27 | 6): node i, component
  /// c is coordinate dim i + c.
  constexpr unsigned int face_coordinates = face_nodes * dim;

  /// Number of derivative directions of a slave/master face pair (54 | 12):
  /// slave node i, component c is direction dim i + c, master node i,
  /// component c is direction face_coordinates + dim i + c.
  constexpr unsigned int face_pair_coordinates = 2 * face_coordinates;
} // namespace DuctileContact
