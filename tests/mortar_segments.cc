// The geometry of the segment-based mortar integration
// (contact/mortar_segments.h) on flat quad9 faces whose overlaps are known:
//  - identical faces: the weights sum to the face area and every point is
//    the same point of both faces;
//  - master shifted by (0.3, 0.2): the weights sum to the overlap 0.56;
//  - master rotated by 45 degrees about the common centre: the overlap is
//    the regular octagon, 2 (sqrt 2 - 1);
//  - a master that does not face the slave (same normal) gives no points;
//  - clip_polygon() of two squares, and the node order of a gathered face
//    (Quad9::normal points along x_xi x x_eta).
#include <deal.II/base/mpi.h>

#include <ductile_contact/contact/mortar_segments.h>

#include "tests.h"

#include <cmath>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  /// Flat square face [0, 1]^2 at height z, rotated by @p angle about its
  /// centre and shifted by (dx, dy); normal +z (up) or -z (down).
  Quad9
  square(const double z,
         const bool   up,
         const double angle = 0.,
         const double dx    = 0.,
         const double dy    = 0.)
  {
    Quad9 q;
    for (unsigned int i = 0; i < 9; ++i)
      {
        const Point<2> xi = Quad9::node_parameter(i);
        // downward faces: swap the parameters, so x_xi x x_eta = -e_z
        const double u = up ? xi[0] : xi[1], v = up ? xi[1] : xi[0];
        const double x = u - 0.5, y = v - 0.5;
        q.x[i] =
          Point<dim>(0.5 + dx + std::cos(angle) * x - std::sin(angle) * y,
                     0.5 + dy + std::sin(angle) * x + std::cos(angle) * y,
                     z);
      }
    return q;
  }

  double
  total_weight(const std::vector<MortarPoint> &points)
  {
    double w = 0;
    for (const auto &p : points)
      w += p.weight;
    return w;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const Quad9 slave = square(0., true);
  out << "normal of an upward face is +z: "
      << Testing::yes_no(
           (slave.normal(Point<2>(0.3, 0.7)) - Tensor<1, dim>({0., 0., 1.}))
             .norm() < 1e-15)
      << std::endl;

  {
    const auto points = mortar_points(slave, square(0., false));
    double     worst  = 0;
    for (const auto &p : points)
      // the downward face has its parameters swapped
      worst =
        std::max(worst, p.slave.distance(Point<2>(p.master[1], p.master[0])));
    out << "identical faces: area 1 (1e-13): "
        << Testing::yes_no(std::abs(total_weight(points) - 1.) < 1e-13)
        << ", same parameters on both faces (1e-12): "
        << Testing::yes_no(worst < 1e-12) << std::endl;
  }
  {
    const auto points = mortar_points(slave, square(1e-3, false, 0., 0.3, 0.2));
    out << "shifted master (0.3, 0.2), gap 1e-3: overlap 0.56 (1e-13): "
        << Testing::yes_no(std::abs(total_weight(points) - 0.56) < 1e-13)
        << std::endl;
  }
  {
    const auto   points  = mortar_points(slave, square(0., false, M_PI / 4));
    const double octagon = 2. * (std::sqrt(2.) - 1.);
    out << "master rotated by 45 degrees: octagon area (1e-13): "
        << Testing::yes_no(std::abs(total_weight(points) - octagon) < 1e-13)
        << std::endl;
    std::cout << "octagon " << total_weight(points) << " vs " << octagon
              << std::endl;
  }
  out << "master not facing the slave: no points: "
      << Testing::yes_no(mortar_points(slave, square(0., true)).empty())
      << std::endl;
  {
    const std::vector<Point<2>> a{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    const std::vector<Point<2>> b{{1, 1}, {3, 1}, {3, 3}, {1, 3}};
    out << "clip of two squares: area 1: "
        << Testing::yes_no(std::abs(polygon_area(clip_polygon(a, b)) - 1.) <
                           1e-15)
        << std::endl;
  }
}
