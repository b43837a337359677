// Validation rung 11: Hertz point contact, coarse. A sphere
// (R = 1 m) pressed onto a flat foundation of the same material (E = 1 GPa,
// nu = 0.3), frictionless, quarter model (tests/meshes/hertz_sphere_h2.msh
// from `make_hertz_sphere.py 1 0.01 2 0.1 1.5`: h = a/2 at the contact for
// the design contact radius a = 0.01 m, bodies 10 a wide and deep), the
// indenter's top pushed down by 1e-4 m in one step, dual multipliers,
// GMRES-AMG. From the carried load P (four times the quarter model's),
// Hertz gives a = (3 P R / (4 E*))^(1/3) and p0 = 3 P / (2 pi a^2); the run's
// a and p0 come from a least-squares fit of p^2 = p0^2 (1 - r^2/a^2) to the
// nodal pressures at r <= 0.8 a. Force-approach: two probes on the axis at
// depth d = 2 a below and height 2 a above the contact point; the surface
// points between them coincide, so their approach is the compression of the
// two columns, 2 integral_0^d -eps_z dz with the Hertz axis stresses
// (Johnson 1985, eq. 3.45). The indenter's surface is given as the sphere
// (Mesh/Gmsh/Curved boundaries), so that its faces' mid-side and centre
// nodes lie on it. Checked at h = a/2 (benchmarks/contact/hertz_sphere has
// the errors per mesh): approach within 1.5 % (0.59 % measured), a within
// 1 % (0.18 %), p0 within 4 % (2.0 %); with the sphere as the polyhedron of
// the mesh vertices the errors were 6, 4 and 18 %; the contact force
// balances the reaction on the top face; the penetration is below the
// tolerance.
#include <deal.II/base/quadrature_lib.h>

#include "tests.h"

#include <cmath>

using namespace dealii;

namespace
{
  const double E = 1e9, nu = 0.3, R = 1., depth = 0.02;

  /// integral_0^{d/a} -E eps_z / p0 d(z/a) along the axis of the Hertz
  /// field of a half-space, eps_z = (sigma_z - 2 nu sigma_r)/E, by Gauss in
  /// t = atan(z/a) (the integrand decays like 1/z^2).
  double
  axial_compression(const double d_over_a)
  {
    const QGauss<1> gauss(200);
    const double    top = std::atan(d_over_a);
    double          sum = 0;
    for (unsigned int q = 0; q < gauss.size(); ++q)
      {
        const double t  = top * gauss.point(q)[0];
        const double z  = std::tan(t);
        const double sz = -1. / (1. + z * z);
        const double sr =
          -(1. + nu) * (1. - z * std::atan(1. / z)) + 0.5 / (1. + z * z);
        sum += -(sz - 2. * nu * sr) / std::pow(std::cos(t), 2) *
               gauss.weight(q) * top;
      }
    return sum;
  }

  std::string
  hertz_prm()
  {
    return Testing::two_body_contact_prm("hertz_sphere_h2.msh",
                                         "3.846153846153846e8",
                                         "8.333333333333334e8",
                                         4,
                                         3) +
           R"(
subsection Boundary conditions
  set Boundary ids = 1, 2, 5, 6
end
subsection Boundary 1
  set Constrained components = z
end
subsection Boundary 2
  set Constrained components = z
  set Displacement           = 0; 0; -1e-4*t
end
subsection Boundary 5
  set Constrained components = x
end
subsection Boundary 6
  set Constrained components = y
end
subsection Load stepping
  set End time  = 1
  set Time step = 1
end
subsection Linear solver
  set Type = gmres-amg
end
subsection Output
  set Interval     = 1
  set Probe points = 0, 0, -0.02; 0, 0, 0.02
end
subsection Mesh
  subsection Gmsh
    set Curved boundaries = 4 : 0, 0, 1
  end
end
)";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  // The half-space integral against its closed limit: the compression of
  // the whole axis is the surface displacement pi a p0 (1 - nu^2)/(2 E).
  out << "axis integral to z = 1e6 a equals pi (1 - nu^2)/2 (1e-5): "
      << Testing::yes_no(
           std::abs(axial_compression(1e6) / (M_PI * (1. - nu * nu) / 2.) -
                    1.) < 1e-5)
      << std::endl;

  const std::string dir   = "hertz_sphere";
  const auto        stats = Testing::run_scene(hertz_prm(), dir);
  const auto nodes = Testing::read_statistics(dir + "/contact1_00001.txt");

  const double F      = stats.at("F2_z").back();
  const double P      = 4. * std::abs(F);
  const double E_star = E / (2. * (1. - nu * nu));
  const double a_h    = std::cbrt(3. * P * R / (4. * E_star));
  const double p0_h   = 3. * P / (2. * M_PI * a_h * a_h);
  const double approach_h =
    2. * p0_h * a_h / E * axial_compression(depth / a_h);
  const double approach =
    stats.at("probe1_u_z").back() - stats.at("probe2_u_z").back();

  const auto         &x = nodes.at("x"), &y = nodes.at("y");
  std::vector<double> r2(x.size());
  for (unsigned int i = 0; i < x.size(); ++i)
    r2[i] = x[i] * x[i] + y[i] * y[i];
  const auto [a, p0] = Testing::fit_hertz_pressure(r2,
                                                   nodes.at("pressure"),
                                                   std::pow(0.8 * a_h, 2));
  out << std::setprecision(5) << "P " << P << " N, a " << a << " m, p0 " << p0
      << " Pa, approach " << approach << " m" << std::setprecision(6)
      << std::endl;
  std::cout << "P " << P << ", a " << a << " (Hertz " << a_h << "), p0 " << p0
            << " (Hertz " << p0_h << "), approach " << approach << " (Hertz "
            << approach_h << ")" << std::endl;

  const auto within =
    [&](const char *what, double value, double hertz, double limit) {
      const double error = std::abs(value / hertz - 1.);
      out << "h = a/2: " << what << " within " << 100 * limit
          << " % of Hertz: " << Testing::yes_no(error < limit) << std::endl;
    };
  within("approach of the axis probes at 2 a", approach, approach_h, 0.015);
  within("contact radius a", a, a_h, 0.01);
  within("peak pressure p0", p0, p0_h, 0.04);
  // contact1_force: what the slave (indenter) exerts on the master; the top
  // face's reaction balances its opposite.
  out << "contact force balances the reaction (1e-6, Newton tolerance): "
      << Testing::yes_no(std::abs(F - stats.at("contact1_force_z").back()) /
                           std::abs(F) <
                         1e-6)
      << std::endl
      << "penetration below 1e-6 h: "
      << Testing::yes_no(stats.at("contact1_max_penetration").back() <
                         1e-6 * 0.005)
      << std::endl;
}
