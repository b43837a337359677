#pragma once

#include <deal.II/base/point.h>

#include <ductile_contact/contact/quad9.h>

#include <vector>

namespace DuctileContact
{
  /// One integration point of a slave/master face pair.
  struct MortarPoint
  {
    dealii::Point<2> slave;  ///< parameter point on the slave face
    dealii::Point<2> master; ///< parameter point on the master face
    double           weight; ///< area weight [m^2]
  };

  /**
   * Segment-based mortar integration of one slave/master face pair
   * (contact.md, Puso & Laursen 2004): both quad9 faces are split into their
   * four flat sub-quads; for each slave sub-quad an auxiliary plane through
   * its centre, normal n0 = the sub-quad normal; the vertices of every master
   * sub-quad that faces it (n0 . n_m < 0) are projected onto the plane, the
   * two convex polygons are clipped (Sutherland-Hodgman), the overlap is
   * split into triangles (fan from its centroid) with a 7-point Gauss rule
   * of degree 5 each, and every Gauss point is projected back along n0 onto
   * the curved slave and master faces (parameter points clamped to the
   * face). The weights are areas on the plane, so that a uniform field is
   * integrated over the same overlap on both sides: this is what makes the
   * patch test pass.
   *
   * A pure function of the two current face geometries.
   */
  std::vector<MortarPoint>
  mortar_points(const Quad9 &slave, const Quad9 &master);

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
