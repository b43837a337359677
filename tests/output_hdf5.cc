// Output/Format = hdf5: parallel HDF5 files with an XDMF
// time series, checked against closed forms (a stronger check than against
// the .vtu values, which hold the same patches):
//  1. the unit cube stretched homogeneously by 10 % along x (uniaxial
//     stress, 2 load steps): in the last step's file, at every node of the
//     mesh file, u_x = 0.1 x and u_y/y = u_z/z = the lateral contraction
//     (one value), to the single precision DataOut stores its patches in
//     (1e-7 of the displacement); the vtu run gives the same reaction
//     (1e-12); the mesh is written once (one mesh file),
//     the .xdmf lists the 3 output steps with their times and refers to
//     files that exist; the cell tensors (six components each in HDF5) are
//     those of the homogeneous state at every node: log_strain =
//     diag(ln 1.1, ln(1 + e), ln(1 + e))
//     with e the lateral contraction, cauchy_stress uniaxial (sigma_yy,
//     sigma_zz, shears below 1e-5 sigma_xx) with sigma_xx times the current
//     area = the reaction (1e-5), triaxiality 1/3 (1e-5), plastic_strain 0;
//  2. two bodies touching (the plate and a block whose bottom nodes sit
//     on plate nodes): the nodes are not merged: 27 per cell, and every
//     node of the block's bottom face has a twin of the plate at the same
//     coordinates with the other body id.
// 1 and 2 ranks, the same output.
#include <deal.II/base/hdf5.h>

#include "tests.h"

#include <filesystem>
#include <map>
#include <regex>

using namespace dealii;

namespace
{
  /// A dataset of @p file as rows of @p columns.
  std::vector<std::vector<double>>
  read_rows(const std::string &file, const std::string &name)
  {
    HDF5::File                       h5(file, HDF5::File::FileAccessMode::open);
    auto                             data    = h5.open_dataset(name);
    const auto                       dims    = data.get_dimensions();
    std::vector<double>              flat    = data.read<std::vector<double>>();
    const std::size_t                columns = dims.size() > 1 ? dims[1] : 1;
    std::vector<std::vector<double>> rows(dims[0]);
    for (std::size_t i = 0; i < dims[0]; ++i)
      rows[i].assign(flat.begin() + i * columns,
                     flat.begin() + (i + 1) * columns);
    return rows;
  }

  std::string
  files_in(const std::string &directory, const std::string &prefix)
  {
    std::vector<std::string> names;
    for (const auto &f : std::filesystem::directory_iterator(directory))
      if (f.path().filename().string().rfind(prefix, 0) == 0)
        names.push_back(f.path().filename().string());
    std::sort(names.begin(), names.end());
    std::string all;
    for (const auto &n : names)
      all += n + " ";
    return all;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  // 1. Homogeneous stretch.
  const std::string stretch =
    Testing::unit_cube_prm() + Testing::uniaxial_pull_prm("0.1*t") + R"(
subsection Load stepping
  set End time  = 1
  set Time step = 0.5
end
subsection Output
  set Interval = 1
)";
  const Testing::Table h5_run =
    Testing::run_scene(stretch + "  set Format = hdf5\nend\n", "stretch_h5");
  const Testing::Table vtu_run =
    Testing::run_scene(stretch + "  set Format = vtu\nend\n", "stretch_vtu");
  if (root)
    {
      const auto nodes = read_rows("stretch_h5/mesh_00000.h5", "nodes");
      const auto u = read_rows("stretch_h5/solution_00002.h5", "displacement");
      double     worst_x = 0., lo = 1e300, hi = -1e300;
      for (std::size_t i = 0; i < nodes.size(); ++i)
        {
          worst_x = std::max(worst_x, std::abs(u[i][0] - 0.1 * nodes[i][0]));
          for (const unsigned int d : {1u, 2u})
            if (nodes[i][d] > 0.1)
              {
                lo = std::min(lo, u[i][d] / nodes[i][d]);
                hi = std::max(hi, u[i][d] / nodes[i][d]);
              }
        }
      const std::string xdmf = Testing::file_text("stretch_h5/solution.xdmf");
      std::vector<std::string> times, referenced;
      const std::regex         time_pattern("<Time Value=\"([^\"]*)\"");
      for (std::sregex_iterator it(xdmf.begin(), xdmf.end(), time_pattern);
           it != std::sregex_iterator();
           ++it)
        times.push_back((*it)[1]);
      const std::regex file_pattern("([A-Za-z_0-9]+\\.h5):/");
      bool             files_exist = true;
      for (std::sregex_iterator it(xdmf.begin(), xdmf.end(), file_pattern);
           it != std::sregex_iterator();
           ++it)
        files_exist = files_exist &&
                      std::filesystem::exists("stretch_h5/" + (*it)[1].str());
      const double F_h5  = h5_run.at("F1_x").back(),
                   F_vtu = vtu_run.at("F1_x").back();
      // The tensors (in HDF5 their six components) and triaxiality.
      const std::string last = "stretch_h5/solution_00002.h5";
      const auto        eta  = read_rows(last, "triaxiality");
      const double      e_y  = std::log(1. + lo),
                   s_xx      = read_rows(last, "cauchy_stress_xx")[0][0];
      double worst_strain = 0., worst_stress = 0., worst_eta = 0.,
             worst_plastic = 0.;
      for (const auto &[component, strain_value, stress_value] :
           {std::tuple{"xx", std::log(1.1), s_xx},
            std::tuple{"yy", e_y, 0.},
            std::tuple{"zz", e_y, 0.},
            std::tuple{"xy", 0., 0.},
            std::tuple{"xz", 0., 0.},
            std::tuple{"yz", 0., 0.}})
        {
          const std::string c       = component;
          const auto        strain  = read_rows(last, "log_strain_" + c);
          const auto        sigma   = read_rows(last, "cauchy_stress_" + c);
          const auto        plastic = read_rows(last, "plastic_strain_" + c);
          for (std::size_t i = 0; i < strain.size(); ++i)
            {
              worst_strain =
                std::max(worst_strain, std::abs(strain[i][0] - strain_value));
              worst_stress =
                std::max(worst_stress, std::abs(sigma[i][0] - stress_value));
              worst_plastic = std::max(worst_plastic, std::abs(plastic[i][0]));
            }
        }
      for (const auto &row : eta)
        worst_eta = std::max(worst_eta, std::abs(row[0] - 1. / 3.));
      // The reaction on x = 0 against sigma_xx on the current cross-section.
      const double area = (1. + lo) * (1. + lo);
      out << "u_x = 0.1 x at every node (float precision, 1e-8): "
          << Testing::yes_no(worst_x < 1e-8 && !nodes.empty()) << "\n"
          << "u_y/y = u_z/z, one lateral contraction (1e-6 of it): "
          << Testing::yes_no(hi - lo < 1e-6 * std::abs(lo) && lo < 0.) << "\n"
          << "same reaction as the vtu run (1e-12): "
          << Testing::yes_no(std::abs(F_h5 - F_vtu) <= 1e-12 * std::abs(F_vtu))
          << "\n"
          << "files: " << files_in("stretch_h5", "mesh")
          << files_in("stretch_h5", "solution") << "\n"
          << "xdmf times: " << times.size() << " (" << times.front() << " ... "
          << times.back()
          << "), referenced files exist: " << Testing::yes_no(files_exist)
          << "\n"
          << "log_strain = diag(ln 1.1, ln(1 + e), ln(1 + e)) at every node "
             "(1e-6): "
          << Testing::yes_no(worst_strain < 1e-6 && !eta.empty()) << "\n"
          << "cauchy_stress uniaxial (1e-5 sigma_xx), sigma_xx x current area "
             "= the reaction (1e-5): "
          << Testing::yes_no(worst_stress < 1e-5 * std::abs(s_xx) &&
                             std::abs(std::abs(s_xx) * area - std::abs(F_h5)) <
                               1e-5 * std::abs(F_h5))
          << "\n"
          << "triaxiality 1/3 (1e-5), plastic_strain 0: "
          << Testing::yes_no(worst_eta < 1e-5 && worst_plastic == 0.) << "\n"
          << "sigma_xx = " << std::setprecision(5) << s_xx << " Pa\n";
      std::cout << "worst u_x " << worst_x << ", lateral " << lo << " .. " << hi
                << ", F1_x " << F_h5 << " / " << F_vtu << "; tensors: strain "
                << worst_strain << ", stress " << worst_stress << ", eta "
                << worst_eta << ", |sigma_xx| A - |F| "
                << std::abs(s_xx) * area - std::abs(F_h5) << std::endl;
    }

  // 2. Two touching bodies: no merged nodes.
  const std::string bodies = R"(
subsection Mesh
  set Scene = two bodies
  subsection Two bodies
    set Plate subdivisions = 15, 10, 1
    set Block subdivisions = 2, 2, 2
    set Block centre       = 0.04, 0.1
  end
end
subsection Bodies
  set Material ids = 0, 1
end
subsection Body 1
  set Shear modulus = 35e6
  set Bulk modulus  = 333e6
end
subsection Boundary conditions
  set Boundary ids = 1, 2
end
subsection Boundary 1
  set Constrained components = x, y, z
end
subsection Boundary 2
  set Constrained components = x, y, z
end
subsection Load stepping
  set End time  = 1
  set Time step = 1
end
subsection Output
  set Format   = hdf5
  set Interval = 1
end
)";
  Testing::run_scene(bodies, "bodies_h5");
  if (root)
    {
      const auto nodes = read_rows("bodies_h5/mesh_00000.h5", "nodes");
      const auto body  = read_rows("bodies_h5/solution_00001.h5", "body");
      const unsigned int n_cells = 15 * 10 * 1 + 2 * 2 * 2;
      // The block's bottom face z = 0.02: 5 x 5 nodes of Q2 in each of
      // its 4 cells' patches there, each with a plate twin.
      std::map<std::array<long, 3>, std::set<int>> bodies_at;
      unsigned int                                 block_bottom = 0;
      // A node's position in micrometres, as integers.
      const auto key_of = [&nodes](const std::size_t i) {
        return std::array<long, 3>{{std::lround(nodes[i][0] * 1e6),
                                    std::lround(nodes[i][1] * 1e6),
                                    std::lround(nodes[i][2] * 1e6)}};
      };
      for (std::size_t i = 0; i < nodes.size(); ++i)
        bodies_at[key_of(i)].insert(static_cast<int>(std::lround(body[i][0])));
      bool twins = true;
      for (std::size_t i = 0; i < nodes.size(); ++i)
        if (std::lround(body[i][0]) == 1 && std::abs(nodes[i][2] - 0.02) < 1e-9)
          {
            ++block_bottom;
            twins = twins && bodies_at[key_of(i)].count(0) == 1;
          }
      out << "27 nodes per cell (no merging): "
          << Testing::yes_no(nodes.size() == 27 * n_cells) << "\n"
          << "block bottom nodes with a plate twin: "
          << Testing::yes_no(twins && block_bottom == 4 * 9) << "\n";
      std::cout << nodes.size() << " nodes, " << block_bottom
                << " on the block's bottom" << std::endl;
    }
}
