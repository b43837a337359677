// Validation rung 1: homogeneous finite-strain states of a unit cube (2x2x2
// Q2 cells) with the neo-Hooke law (16)/(19), mu = 1, kappa = 2.5, in two
// load steps, against closed forms:
//  - uniaxial stretch lambda = 1.5 with symmetry planes and free lateral
//    faces: nominal stress P_xx (reaction on x+) and the lateral stretch
//    (solved from tau_yy = 0 by bisection);
//  - simple shear gamma = 0.5 (all faces prescribed): P_xy and P_yy from the
//    reaction on y+, and the displacement at two probe points (Output/Probe
//    points: inside a cell and at a vertex of 8 cells);
//  - volumetric expansion lambda = 1.2: P_xx from the reaction on x+;
// and the stored energy Psi(F) V in each case. Agreement to 1e-8 relative.
// Run on 1 and 2 MPI ranks with identical output.
#include <deal.II/base/tensor.h>

#include <ductile_contact/materials/neo_hooke.h>

#include "tests.h"

using namespace dealii;
using namespace DuctileContact;

namespace
{
  const double mu = 1., kappa = 2.5;

  std::string
  cube_prm(const std::string &boundaries, const std::string &solver)
  {
    return Testing::unit_cube_prm() + R"(
subsection Load stepping
  set End time  = 1
  set Time step = 0.5
end
subsection Newton
  set Relative tolerance = 1e-12
end
subsection Linear solver
  set Type = )" +
           solver + R"(
  set Relative tolerance = 1e-12
end
subsection Output
  set Interval = 0
end
)" + boundaries;
  }

  std::string
  boundary(const unsigned int id,
           const std::string &components,
           const std::string &displacement)
  {
    return "subsection Boundary " + std::to_string(id) +
           "\n  set Constrained components = " + components +
           "\n  set Displacement = " + displacement + "\nend\n";
  }

  std::string
  all_faces(const std::string &displacement)
  {
    std::string text = "subsection Boundary conditions\n  set Boundary ids = "
                       "0, 1, 2, 3, 4, 5\nend\n";
    for (unsigned int id = 0; id < 6; ++id)
      text += boundary(id, "x, y, z", displacement);
    return text;
  }

  void
  report(std::ostream      &out,
         const std::string &name,
         const double       value,
         const double       exact,
         bool              &all_ok)
  {
    const bool ok = Testing::relative_error(value, exact, mu) < 1e-8;
    all_ok        = all_ok && ok;
    out << "  " << name << " = " << value << " (closed form " << exact << ")"
        << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  // Uniaxial stretch.
  {
    const double           lambda = 1.5;
    double                 lt     = 1.;
    const MaterialResponse m =
      Testing::uniaxial_stress_state(lambda, mu, kappa, lt);

    const std::string bcs =
      "subsection Boundary conditions\n  set Boundary ids = 0, 1, 2, 3, "
      "4\nend\n" +
      boundary(0, "x", "0; 0; 0") + boundary(1, "x", "0.5*t; 0; 0") +
      boundary(2, "y", "0; 0; 0") + boundary(3, "", "0; 0; 0") +
      boundary(4, "z", "0; 0; 0");
    const auto t  = Testing::run_scene(cube_prm(bcs, "cg-amg"), "uniaxial");
    bool       ok = true;
    out << "uniaxial stretch lambda = 1.5:" << std::endl;
    report(out, "P_xx / mu", t.at("F1_x").back(), m.P[0][0], ok);
    report(out, "lateral stretch", 1. + t.at("u3_y").back(), lt, ok);
    report(out,
           "stored energy / mu",
           t.at("stored_energy").back(),
           m.psi_elastic,
           ok);
    out << "  matches (1e-8): " << Testing::yes_no(ok) << std::endl;
  }

  // Simple shear.
  {
    const double   gamma     = 0.5;
    Tensor<2, dim> F         = unit_symmetric_tensor<dim>();
    F[0][1]                  = gamma;
    const MaterialResponse m = neo_hooke(F, mu, kappa, false);
    const auto t = Testing::run_scene(cube_prm(all_faces("0.5*t*y; 0; 0") + R"(
subsection Output
  set Probe points = 0.3, 0.7, 0.45; 0.5, 0.5, 0.5
end
)",
                                               "direct"),
                                      "simple_shear");
    bool       ok = true;
    out << "simple shear gamma = 0.5:" << std::endl;
    report(out, "P_xy / mu", t.at("F3_x").back(), m.P[0][1], ok);
    report(out, "P_yy / mu", t.at("F3_y").back(), m.P[1][1], ok);
    report(out,
           "stored energy / mu",
           t.at("stored_energy").back(),
           m.psi_elastic,
           ok);
    report(out,
           "u_x at probe (0.3, 0.7, 0.45)",
           t.at("probe1_u_x").back(),
           0.35,
           ok);
    report(out,
           "u_x at probe (0.5, 0.5, 0.5), a vertex of 8 cells",
           t.at("probe2_u_x").back(),
           0.25,
           ok);
    ok = ok && std::abs(t.at("probe1_u_y").back()) < 1e-10 &&
         std::abs(t.at("probe2_u_z").back()) < 1e-10;
    out << "  matches (1e-8): " << Testing::yes_no(ok) << std::endl;
  }

  // Volumetric expansion.
  {
    const double           lambda = 1.2;
    const MaterialResponse m =
      neo_hooke(lambda * unit_symmetric_tensor<dim>(), mu, kappa, false);
    const auto t = Testing::run_scene(
      cube_prm(all_faces("0.2*t*x; 0.2*t*y; 0.2*t*z"), "direct"), "volumetric");
    bool ok = true;
    out << "volumetric expansion lambda = 1.2:" << std::endl;
    report(out, "P_xx / mu", t.at("F1_x").back(), m.P[0][0], ok);
    report(out,
           "stored energy / mu",
           t.at("stored_energy").back(),
           m.psi_elastic,
           ok);
    out << "  matches (1e-8): " << Testing::yes_no(ok) << std::endl;
  }
}
