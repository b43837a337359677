// Patch test on distorted elements, read from a Gmsh file: the unit cube as
// 3x3x3 hexahedra with displaced interior vertices
// (prm/meshes/distorted_cube.msh, material id 7, boundary ids 1..6 from
// physical tags). Every face gets u = (F - I) X for a general F (non-symmetric,
// J != 1). Q2 reproduces the homogeneous solution exactly, so the force on each
// face equals P(F) N A and the stored energy equals Psi(F) V to solver
// tolerance (1e-8 relative); any error in the assembly on distorted cells
// breaks this.
#include <ductile_contact/materials/neo_hooke.h>

#include "tests.h"

using namespace dealii;
using namespace DuctileContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  // F - I, applied in two load steps.
  const double H[3][3] = {{0.20, 0.10, -0.05},
                          {0.02, -0.10, 0.08},
                          {0.05, -0.03, 0.15}};
  std::string  u_text;
  for (unsigned int i = 0; i < 3; ++i)
    {
      u_text += std::string(i ? "; " : "") + "t*(" + std::to_string(H[i][0]) +
                "*x + " + std::to_string(H[i][1]) + "*y + " +
                std::to_string(H[i][2]) + "*z)";
    }
  std::string prm = std::string(R"(
subsection Mesh
  set Scene = gmsh
  subsection Gmsh
    set File name = )") +
                    SOURCE_DIR + R"(/../prm/meshes/distorted_cube.msh
  end
end
subsection Bodies
  set Material ids = 7
end
subsection Body 7
  set Shear modulus = 1
  set Bulk modulus  = 3
end
subsection Boundary conditions
  set Boundary ids = 1, 2, 3, 4, 5, 6
end
subsection Load stepping
  set Time step = 0.5
end
subsection Newton
  set Relative tolerance = 1e-12
end
subsection Linear solver
  set Type = gmres-amg
  set Relative tolerance = 1e-12
end
subsection Output
  set Interval = 0
end
)";
  for (unsigned int id = 1; id <= 6; ++id)
    prm += "subsection Boundary " + std::to_string(id) +
           "\n  set Constrained components = x, y, z\n  set Displacement = " +
           u_text + "\nend\n";

  const auto t = Testing::run_scene(prm, "patch");

  Tensor<2, dim> F = unit_symmetric_tensor<dim>();
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      F[i][j] += H[i][j];
  const MaterialResponse m = neo_hooke(F, 1., 3., false);

  // Outward unit normals of the faces with ids 1..6.
  const int normal[6][3] = {
    {-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  const char *xyz[3] = {"x", "y", "z"};
  double      worst  = 0;
  for (unsigned int id = 1; id <= 6; ++id)
    for (unsigned int a = 0; a < dim; ++a)
      {
        double exact = 0;
        for (unsigned int b = 0; b < dim; ++b)
          exact += m.P[a][b] * normal[id - 1][b];
        const double value =
          t.at("F" + std::to_string(id) + "_" + xyz[a]).back();
        worst = std::max(worst, Testing::relative_error(value, exact, 1.));
        out << "face " << id << " force " << xyz[a] << " = " << value
            << std::endl;
      }
  const double energy = t.at("stored_energy").back();
  worst = std::max(worst, Testing::relative_error(energy, m.psi_elastic, 1.));
  out << "stored energy = " << energy << std::endl;
  out << "forces and energy equal P(F) N A and Psi(F) V (1e-8): "
      << Testing::yes_no(worst < 1e-8) << std::endl;
}
