// Hertz line contact in plane strain (Dimension = 2, line3 contact faces):
// the scene of tests/contact_hertz (a cylinder, R = 1 m, pressed onto a
// flat foundation of the same material, E = 1 GPa, nu = 0.3, half model,
// the indenter's top pushed down by 2e-4 m in one step, frictionless, dual
// multipliers) on the 2-D mesh tests/meshes/hertz_h4_2d.msh
// (`make_hertz.py 1 0.01 4 0.3 hertz_h4_2d.msh 2d`: h = a/4 at the
// contact), with both enforcements:
//  - semi-smooth Newton (the default) and the augmented Lagrangian each
//    give a and p0 of the pressure fit (p^2 = p0^2 (1 - x^2/a^2) at
//    x <= 0.8 a) within 8 % and 5 % of Hertz for the carried load P per
//    unit length;
//  - the slab of tests/contact_hertz is this plane-strain problem (one
//    layer with u_z = 0 on both faces): P, a and p0 equal the slab's
//    39817 N/m, 0.0099828 m and 2.7273e6 Pa to 1e-4;
//  - the contact force balances the reaction on the top face, the
//    penetration is below 1e-6 h (augmented Lagrangian: its tolerance),
//    and the contact tangent (Newton/Check tangent) matches central
//    differences of the residual.
//  - with the indenter's surface given as the circle it is
//    (Mesh/Gmsh/Curved boundaries = 4 : 0, 1), its mid-side nodes lie on
//    the circle instead of on the chords, h^2/(8R) inside it: the nodal
//    pressures at x <= a/2 are within 1 % of Hertz's (0.47 % measured,
//    against 10.3 % on the polygon, which the first two runs print), and
//    a and p0 within 1 % and 0.3 % (measured 0.70 % and 0.062 %, against
//    3.9 % and 3.3 % on the polygon); the
//    contact tangent with the quadratic mapping matches central
//    differences (semi-smooth Newton).
// The compared output holds P, a, p0 and the alternation at 5 significant
// digits.
#include "../tests.h"

#include <cmath>

using namespace dealii;

namespace
{
  /// The indenter's surface as the circle around (0, R).
  const std::string curved = R"(
subsection Mesh
  subsection Gmsh
    set Curved boundaries = 4 : 0, 1
  end
end
)";

  std::string
  hertz_2d_prm(const std::string &enforcement)
  {
    return "set Dimension = 2\n" +
           Testing::two_body_contact_prm("hertz_h4_2d.msh",
                                         "3.846153846153846e8",
                                         "8.333333333333334e8",
                                         4,
                                         3,
                                         enforcement) +
           R"(
subsection Boundary conditions
  set Boundary ids = 1, 2, 5
end
subsection Boundary 1
  set Constrained components = y
end
subsection Boundary 2
  set Constrained components = y
  set Displacement           = 0; -2e-4*t
end
subsection Boundary 5
  set Constrained components = x
end
subsection Load stepping
  set End time  = 1
  set Time step = 1
end
subsection Linear solver
  set Type = direct
end
subsection Newton
  set Check tangent = true
end
subsection Output
  set Interval = 1
end
)";
  }

  struct Result
  {
    double a_error, p0_error, balance, penetration, tangent_error;
    /// Load per unit length, half-width and peak pressure of the fit, and
    /// the largest deviation of a nodal pressure from Hertz's at x <= a/2.
    double P, a, p0, alternation;
  };

  Result
  run(const std::string &name,
      const std::string &enforcement,
      const std::string &extra = "")
  {
    const auto stats =
      Testing::run_scene(hertz_2d_prm(enforcement) + extra, name);
    const auto nodes = Testing::read_statistics(name + "/contact1_00001.txt");
    // Forces are per unit thickness.
    const Testing::HertzLine h = Testing::hertz_line(stats, nodes, 1.);
    const double             F = stats.at("F2_y").back();
    std::cout << name << ": P " << h.P << ", a " << h.a << " (Hertz "
              << h.a_hertz << "), p0 " << h.p0 << " (Hertz " << h.p0_hertz
              << "), tangent error " << stats.at("tangent_error").back()
              << std::endl;
    return {std::abs(h.a / h.a_hertz - 1.),
            std::abs(h.p0 / h.p0_hertz - 1.),
            std::abs(F - stats.at("contact1_force_y").back()) / std::abs(F),
            stats.at("contact1_max_penetration").back(),
            stats.at("tangent_error").back(),
            h.P,
            h.a,
            h.p0,
            h.alternation};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const double slab_P = 39817, slab_a = 0.0099828, slab_p0 = 2.7273e6;
  for (const auto &[name, enforcement] :
       {std::pair<std::string, std::string>{"semi_smooth", ""},
        std::pair<std::string, std::string>{
          "augmented",
          "  set Enforcement = augmented Lagrangian\n"
          "  set Penetration tolerance = 1e-8\n"}})
    {
      const Result r = run("hertz_2d_" + name, enforcement);
      out << name
          << ": a within 8 % of Hertz: " << Testing::yes_no(r.a_error < 0.08)
          << std::endl
          << name
          << ": p0 within 5 % of Hertz: " << Testing::yes_no(r.p0_error < 0.05)
          << std::endl
          << name << ": P, a, p0 equal the slab's (1e-4): "
          << Testing::yes_no(std::abs(r.P / slab_P - 1.) < 1e-4 &&
                             std::abs(r.a / slab_a - 1.) < 1e-4 &&
                             std::abs(r.p0 / slab_p0 - 1.) < 1e-4)
          << std::endl
          << name << ": contact force balances the reaction (1e-6): "
          << Testing::yes_no(r.balance < 1e-6) << std::endl
          << name << ": penetration below 1e-6 h: "
          << Testing::yes_no(r.penetration < 1e-6 * 0.0025) << std::endl
          << name << ": consistent tangent (1e-6): "
          << Testing::yes_no(r.tangent_error < 1e-6) << std::endl
          << std::setprecision(5) << name << ": P " << r.P << " N/m, a " << r.a
          << " m, p0 " << r.p0 << " Pa, nodal pressures at x <= a/2 within "
          << r.alternation << " of Hertz" << std::endl;
    }

  const Result r = run("hertz_2d_curved", "", curved);
  out << "curved: nodal pressures at x <= a/2 within 1 % of Hertz: "
      << Testing::yes_no(r.alternation < 0.01) << std::endl
      << "curved: a within 1 % and p0 within 0.3 % of Hertz: "
      << Testing::yes_no(r.a_error < 0.01 && r.p0_error < 0.003) << std::endl
      << "curved: contact force balances the reaction (1e-6): "
      << Testing::yes_no(r.balance < 1e-6) << std::endl
      << "curved: consistent tangent (1e-6): "
      << Testing::yes_no(r.tangent_error < 1e-6) << std::endl
      << std::setprecision(5) << "curved: P " << r.P << " N/m, a " << r.a
      << " m, p0 " << r.p0 << " Pa, nodal pressures at x <= a/2 within "
      << r.alternation << " of Hertz" << std::endl;
}
