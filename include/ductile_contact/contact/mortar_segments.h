#pragma once

#include <deal.II/base/point.h>

#include <ductile_contact/contact/contact_face.h>

#include <array>
#include <vector>

namespace DuctileContact
{
  /// Current coordinates x_i[c] of the nodes of a face (node order of
  /// ContactFace), in a number type that may carry derivatives.
  template <typename Number>
  using FaceCoordinates = std::array<std::array<Number, dim>, face_nodes>;

  /// One integration point of a slave/master face pair.
  template <typename Number>
  struct MortarPointOf
  {
    std::array<Number, dim - 1> slave;  ///< parameter point on the slave face
    std::array<Number, dim - 1> master; ///< parameter point on the master face
    Number weight; ///< area weight [m^2] (length [m] in 2-D)
  };

  /**
   * Segment-based mortar integration of one slave/master face pair
   * (doc/contact.md, Puso & Laursen 2004): both quad9 faces are split into
   * their four flat sub-quads; for each slave sub-quad an auxiliary plane
   * through its centre, normal n0 = the sub-quad normal; the vertices of every
   * master sub-quad that faces it (n0 . n_m < 0) are projected onto the plane,
   * the two convex polygons are clipped (Sutherland-Hodgman), the overlap is
   * split into triangles (a fan from one vertex) with a 16-point symmetric
   * rule of degree 8 each, and every point is projected back along n0
   * onto the curved slave and master faces (parameter points clamped to the
   * face). The weights are areas on the plane, so that a uniform field is
   * integrated over the same overlap on both sides: this is what makes the
   * patch test pass.
   *
   * In plane strain the faces are line3: both are split into their two
   * straight sub-segments; for each slave sub-segment an auxiliary line
   * through its centre along its chord, normal n0 = the chord turned by -90
   * degrees; the ends of every master sub-segment that faces it are
   * projected onto the line, the two intervals intersected, and a 5-point
   * Gauss rule on the overlap projected back along n0. The weights are
   * lengths on the line.
   *
   * A pure function of the two current face geometries. With Number =
   * ContactAD (contact_ad.h) the points and weights carry their derivatives
   * with respect to the face coordinates (54 | 12): the branches (which
   * sub-quads face each other, which polygon vertices are clipped) are decided
   * on the values, the Newton back-projection runs on the values and one final
   * Newton correction in ContactAD gives the derivatives of the parameter
   * points by the implicit function theorem. With ContactAD the face
   * coordinates must be the independent variables themselves: slave[i][c]
   * direction dim i + c, master[i][c] direction face_coordinates + dim i + c
   * (as
   * MortarFace::integrate() seeds them). Instantiated for double and
   * ContactAD.
   */
  template <typename Number>
  std::vector<MortarPointOf<Number>>
  mortar_points(const FaceCoordinates<Number> &slave,
                const FaceCoordinates<Number> &master);

  /// The node coordinates of @p face as FaceCoordinates.
  FaceCoordinates<double>
  coordinates_of(const ContactFace &face);

  /// Whether some sub-quads of the two faces face each other and overlap
  /// in the plane (the clipping of mortar_points() without its
  /// quadrature): false means mortar_points() has no point.
  bool
  faces_may_overlap(const ContactFace &slave, const ContactFace &master);

  /// mortar_points() on plain faces.
  struct MortarPoint
  {
    FaceParameter slave;  ///< parameter point on the slave face
    FaceParameter master; ///< parameter point on the master face
    double        weight; ///< area weight [m^2] (length [m] in 2-D)
  };
  std::vector<MortarPoint>
  mortar_points(const ContactFace &slave, const ContactFace &master);

  /// Area of the overlap of a convex polygon pair in the plane (tested
  /// helper of mortar_points()): Sutherland-Hodgman clip of @p subject by
  /// the counter-clockwise convex @p clipper.
  std::vector<dealii::Point<2>>
  clip_polygon(const std::vector<dealii::Point<2>> &subject,
               const std::vector<dealii::Point<2>> &clipper);

  /// Signed area (positive counter-clockwise).
  double
  polygon_area(const std::vector<dealii::Point<2>> &polygon);
} // namespace DuctileContact
