// Helpers shared by the ctest programs. Each test writes only converged,
// O(1)-scaled quantities to the file 'output' (compared with numdiff); the
// screen output of the runs goes to the harness' stdout, which is not
// compared.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <ductile_contact/app/run_parameters.h>
#include <ductile_contact/app/simulation.h>
#include <ductile_contact/materials/neo_hooke.h>
#include <ductile_contact/materials/plasticity.h>
#include <ductile_contact/output/tee_stream.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace Testing
{
  /// Dimensionless material-point parameters of the unit tests (mu = 1,
  /// kappa = 2.5, y_0 = 0.005, y_inf = 0.006, eta = 25, h = 0, eta_p =
  /// 1e-3, a_g = 2, k = 1e-8, sharp switch), not the program's defaults.
  inline DuctileContact::PlasticityParameters
  unit_plasticity()
  {
    DuctileContact::PlasticityParameters p;
    p.shear_modulus           = 1.;
    p.bulk_modulus            = 2.5;
    p.initial_yield           = 0.005;
    p.saturation_yield        = 0.006;
    p.saturation_exponent     = 25.;
    p.linear_hardening        = 0.;
    p.viscosity               = 1e-3;
    p.degradation_a           = 2.;
    p.residual_stiffness      = 1e-8;
    p.volumetric_switch_width = 0.;
    return p;
  }

  /// Columns of a statistics table.
  using Table = std::map<std::string, std::vector<double>>;

  inline Table
  read_statistics(const std::string &file_name)
  {
    std::ifstream in(file_name);
    std::string   line;
    std::getline(in, line);
    std::istringstream       header(line);
    std::vector<std::string> names;
    for (std::string n; header >> n;)
      names.push_back(n);
    Table table;
    while (std::getline(in, line))
      {
        std::istringstream row(line);
        for (const auto &n : names)
          {
            std::string value;
            row >> value;
            table[n].push_back(std::stod(value));
          }
      }
    return table;
  }

  /// Text of the file @p path; throws if it cannot be read.
  inline std::string
  file_text(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      throw std::runtime_error("cannot read " + path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /// The largest positive value of column @p force of @p t and the value
  /// of column @p at in the same row (0, 0 when no value is positive).
  inline std::pair<double, double>
  peak(const Table &t, const std::string &force, const std::string &at)
  {
    std::pair<double, double> p{0., 0.};
    for (unsigned int n = 0; n < t.at(force).size(); ++n)
      if (t.at(force)[n] > p.first)
        p = {t.at(force)[n], t.at(at)[n]};
    return p;
  }

  /// Text of the shipped scene prm/@p name (tests append overrides).
  inline std::string
  shipped_scene(const std::string &name)
  {
    return file_text(SOURCE_DIR "/../prm/" + name);
  }

  /**
   * Runs the scene in @p prm (text of a .prm file) with its results in
   * folder @p directory and returns the statistics table; its screen goes
   * to @p screen. Throws if the run does not reach its end time.
   */
  inline Table
  run_scene(const std::string &prm,
            const std::string &directory,
            std::ostream      &screen = std::cout)
  {
    const MPI_Comm                comm = MPI_COMM_WORLD;
    DuctileContact::RunParameters parameters;
    parameters.parse_string(
      prm + "\nsubsection Output\n  set Directory = " + directory + "\nend\n");
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      std::filesystem::create_directories(directory);
    MPI_Barrier(comm);
    int code = 0;
    {
      DuctileContact::TeeStream  log(screen);
      DuctileContact::Simulation simulation(parameters, comm, log);
      code = simulation.run();
    }
    MPI_Barrier(comm);
    if (code != 0)
      throw std::runtime_error("run in " + directory + " failed");
    return read_statistics(directory + "/statistics");
  }

  /**
   * .prm text of the unit cube as 2x2x2 cells of one body (id 0) with
   * mu = 1, kappa = 2.5; @p body_entries adds entries or subsections to
   * subsection Body 0 (e.g. Plasticity or Fracture).
   */
  inline std::string
  unit_cube_prm(const std::string &body_entries = "")
  {
    return R"(
subsection Mesh
  set Scene = box
  subsection Box
    set Subdivisions = 2, 2, 2
  end
end
subsection Body 0
  set Shear modulus = 1
  set Bulk modulus  = 2.5
)" + body_entries +
           "end\n";
  }

  /**
   * .prm text of a contact scene on the Gmsh mesh tests/meshes/@p mesh:
   * bodies 1 and 2 of the same neo-Hooke material (@p shear_modulus,
   * @p bulk_modulus [Pa]) and contact pair 1 from boundary @p slave to
   * @p master; @p pair_entries adds entries to the pair's subsection.
   */
  inline std::string
  two_body_contact_prm(const std::string &mesh,
                       const std::string &shear_modulus,
                       const std::string &bulk_modulus,
                       const unsigned int slave,
                       const unsigned int master,
                       const std::string &pair_entries = "")
  {
    const std::string material = "\n  set Shear modulus = " + shear_modulus +
                                 "\n  set Bulk modulus  = " + bulk_modulus +
                                 "\nend\n";
    return R"(
subsection Mesh
  set Scene = gmsh
  subsection Gmsh
    set File name = )" SOURCE_DIR R"(/meshes/)" +
           mesh + R"(
  end
end
subsection Bodies
  set Material ids = 1, 2
end
subsection Body 1)" +
           material + "subsection Body 2" + material + R"(subsection Contact
  set Pairs = 1
end
subsection Contact pair 1
  set Slave boundary id  = )" +
           std::to_string(slave) +
           "\n  set Master boundary id = " + std::to_string(master) + "\n" +
           pair_entries + "end\n";
  }

  /**
   * .prm text of the single 1 x 1 x 2 block of the contact patch test
   * (contact_patch, contact_semi_smooth): the state both cubes must reach,
   * symmetry planes x = 0, y = 0, u_z = 0 at the bottom, 1 MPa on top.
   */
  inline std::string
  contact_patch_single_block_prm()
  {
    return R"(
subsection Mesh
  set Scene = box
  subsection Box
    set Upper corner = 1, 1, 2
    set Subdivisions = 2, 2, 4
  end
end
subsection Body 0
  set Shear modulus = 1e9
  set Bulk modulus  = 2e9
end
subsection Boundary conditions
  set Boundary ids = 0, 2, 4, 5
end
subsection Boundary 0
  set Constrained components = x
end
subsection Boundary 2
  set Constrained components = y
end
subsection Boundary 4
  set Constrained components = z
end
subsection Boundary 5
  set Traction = 0; 0; -1e6*t
end
subsection Load stepping
  set End time  = 1
  set Time step = 0.5
end
subsection Newton
  set Relative tolerance = 1e-11
end
)";
  }

  /**
   * .prm text of the contact patch test (contact_patch,
   * contact_semi_smooth): the two swirled non-matching cubes of
   * tests/meshes/contact_patch.msh with symmetry planes through the contact
   * surface and 1 MPa on top, frictionless pair 1 from @p slave to @p
   * master; @p pair_entries adds entries to the pair's subsection.
   */
  inline std::string
  contact_patch_prm(const unsigned int slave,
                    const unsigned int master,
                    const std::string &pair_entries = "")
  {
    return two_body_contact_prm(
             "contact_patch.msh", "1e9", "2e9", slave, master, pair_entries) +
           R"(
subsection Boundary conditions
  set Boundary ids = 1, 2, 5, 6, 8, 9
end
subsection Boundary 1
  set Constrained components = z
end
subsection Boundary 2
  set Traction = 0; 0; -1e6*t
end
subsection Boundary 5
  set Constrained components = x
end
subsection Boundary 6
  set Constrained components = y
end
subsection Boundary 8
  set Constrained components = x
end
subsection Boundary 9
  set Constrained components = y
end
subsection Load stepping
  set End time  = 1
  set Time step = 0.5
end
subsection Newton
  set Relative tolerance = 1e-11
end
)";
  }


  /**
   * .prm text of the sliding patch (contact_friction, contact_semi_smooth):
   * the patch cubes, the lower one clamped, the upper one's top pressed by
   * 1 MPa for t <= 1 and then moved along x by 1e-2 m x (t - 1), Coulomb
   * friction @p mu, load steps 0.125 up to @p end_time; @p pair_entries
   * adds entries to the pair's subsection.
   */
  inline std::string
  patch_sliding_prm(const double       mu,
                    const std::string &end_time,
                    const std::string &pair_entries = "")
  {
    return two_body_contact_prm("contact_patch.msh",
                                "1e9",
                                "2e9",
                                4,
                                3,
                                "  set Friction coefficient = " +
                                  std::to_string(mu) + "\n" + pair_entries) +
           R"(
subsection Boundary conditions
  set Boundary ids = 1, 2
end
subsection Boundary 1
  set Constrained components = x, y, z
end
subsection Boundary 2
  set Constrained components = x, y
  set Displacement           = 1e-2*max(t-1,0); 0; 0
  set Traction               = 0; 0; -1e6*min(t,1)
end
subsection Load stepping
  set End time  = )" +
           end_time + R"(
  set Time step = 0.125
end
subsection Linear solver
  set Type = direct
end
)";
  }

  /**
   * .prm text of the Hertz line contact of contact_hertz (a cylinder, R =
   * 1 m, pressed onto a slab of the same material by 2e-4 m in one step,
   * frictionless, half model on tests/meshes/hertz_h<@p ratio>.msh);
   * @p pair_entries adds entries to the pair's subsection.
   */
  inline std::string
  hertz_line_prm(const unsigned int ratio, const std::string &pair_entries = "")
  {
    return two_body_contact_prm("hertz_h" + std::to_string(ratio) + ".msh",
                                "3.846153846153846e8",
                                "8.333333333333334e8",
                                4,
                                3,
                                pair_entries) +
           R"(
subsection Boundary conditions
  set Boundary ids = 1, 2, 5, 6
end
subsection Boundary 1
  set Constrained components = y
end
subsection Boundary 2
  set Constrained components = y
  set Displacement           = 0; -2e-4*t; 0
end
subsection Boundary 5
  set Constrained components = x
end
subsection Boundary 6
  set Constrained components = z
end
subsection Load stepping
  set End time  = 1
  set Time step = 1
end
subsection Linear solver
  set Type = direct
end
)";
  }

  /**
   * Hertz fit of nodal contact pressures: least squares of
   * p^2 = p0^2 (1 - r^2/a^2) over the nodes with p > 0 and r^2 <= @p r2_max
   * (@p r2: squared distance of each node from the centre of the contact).
   * Returns {a, p0}.
   */
  inline std::pair<double, double>
  fit_hertz_pressure(const std::vector<double> &r2,
                     const std::vector<double> &p,
                     const double               r2_max)
  {
    double s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0;
    for (unsigned int i = 0; i < r2.size(); ++i)
      if (p[i] > 0. && r2[i] <= r2_max)
        {
          const double u = r2[i], v = p[i] * p[i];
          s0 += 1;
          s1 += u;
          s2 += u * u;
          t0 += v;
          t1 += u * v;
        }
    const double det = s0 * s2 - s1 * s1;
    const double c0  = (s2 * t0 - s1 * t1) / det;
    const double c1  = (s0 * t1 - s1 * t0) / det;
    return {std::sqrt(-c0 / c1), std::sqrt(c0)};
  }

  /// Hertz line contact of the meshes of prm/meshes/make_hertz.py (a
  /// cylinder R = 1 m on a flat foundation, E = 1 GPa and nu = 0.3 both, half
  /// model) from a run: the load per unit length P (twice the half model's
  /// reaction F2_y of @p stats, divided by @p thickness), Hertz's half-width
  /// a = sqrt(4 P R / (pi E*)) and peak pressure p0 = 2 P / (pi a) for it, and
  /// the a and p0 of fit_hertz_pressure() over the contact nodes @p nodes
  /// at x <= 0.8 a (Hertz).
  struct HertzLine
  {
    double P, a_hertz, p0_hertz, a, p0;
    /// The largest |p / p_Hertz(x) - 1| over the nodes at x <= a_hertz / 2
    /// (1 for a node out of contact there; NaN when there is none): the
    /// largest deviation of a nodal pressure from Hertz's.
    double alternation;
  };
  inline HertzLine
  hertz_line(const Table &stats, const Table &nodes, const double thickness)
  {
    const double E = 1e9, nu = 0.3, R = 1.;
    const double E_star = E / (2. * (1. - nu * nu));
    HertzLine    h;
    h.P        = 2. * std::abs(stats.at("F2_y").back()) / thickness;
    h.a_hertz  = std::sqrt(4. * h.P * R / (M_PI * E_star));
    h.p0_hertz = 2. * h.P / (M_PI * h.a_hertz);
    const std::vector<double> &x = nodes.at("x");
    std::vector<double>        x2(x.size());
    for (unsigned int i = 0; i < x.size(); ++i)
      x2[i] = x[i] * x[i];
    std::tie(h.a, h.p0) = fit_hertz_pressure(x2,
                                             nodes.at("pressure"),
                                             std::pow(0.8 * h.a_hertz, 2));
    h.alternation       = std::numeric_limits<double>::quiet_NaN();
    unsigned int n      = 0;
    for (unsigned int i = 0; i < x.size(); ++i)
      if (x[i] <= 0.5 * h.a_hertz)
        {
          const double p = nodes.at("pressure")[i];
          const double hertz =
            h.p0_hertz * std::sqrt(1. - x2[i] / (h.a_hertz * h.a_hertz));
          const double deviation = p > 0. ? std::abs(p / hertz - 1.) : 1.;
          h.alternation =
            n++ == 0 ? deviation : std::max(h.alternation, deviation);
        }
    return h;
  }

  /// Length of the vector statistics columns contact1_<what>_x/y/z in row
  /// @p n (what = force or friction).
  inline double
  contact_norm(const Table &s, const std::string &what, const std::size_t n)
  {
    double sum = 0;
    for (const char *c : {"_x", "_y", "_z"})
      sum += std::pow(s.at("contact1_" + what + c)[n], 2);
    return std::sqrt(sum);
  }

  /**
   * Largest difference of column @p name between the first @p rows rows
   * (all when omitted) of runs @p a and @p b, relative to the largest
   * magnitude in @p a's column over those rows; infinity when the runs'
   * times differ in those rows (different steps), or, comparing all rows,
   * when the runs have different numbers of rows.
   */
  inline double
  column_difference(const Table       &a,
                    const Table       &b,
                    const std::string &name,
                    std::size_t        rows = std::size_t(-1))
  {
    const bool all = rows == std::size_t(-1);
    rows           = std::min(rows, a.at("time").size());
    if ((all ? b.at("time").size() != rows : b.at("time").size() < rows) ||
        !std::equal(a.at("time").begin(),
                    a.at("time").begin() + rows,
                    b.at("time").begin()))
      return std::numeric_limits<double>::infinity();
    double scale = 0, worst = 0;
    for (std::size_t k = 0; k < rows; ++k)
      {
        scale = std::max(scale, std::abs(a.at(name)[k]));
        worst = std::max(worst, std::abs(a.at(name)[k] - b.at(name)[k]));
      }
    return scale > 0. ? worst / scale : worst;
  }

  /**
   * Largest difference of run @p t from run @p reference at every step
   * after the first: the column @p force relative to its own value at that
   * step, each column of @p energies relative to the reference's W_ext
   * there; 1 when the runs have different numbers of steps.
   */
  inline double
  stepwise_difference(const Table                    &t,
                      const Table                    &reference,
                      const std::string              &force,
                      const std::vector<std::string> &energies)
  {
    if (t.at("time").size() != reference.at("time").size())
      return 1.;
    double worst = 0.;
    for (std::size_t k = 1; k < reference.at("time").size(); ++k)
      {
        worst = std::max(worst,
                         std::abs(t.at(force)[k] - reference.at(force)[k]) /
                           std::abs(reference.at(force)[k]));
        for (const std::string &c : energies)
          worst = std::max(worst,
                           std::abs(t.at(c)[k] - reference.at(c)[k]) /
                             reference.at("external_work")[k]);
      }
    return worst;
  }

  /**
   * .prm text of the coarse copy of the paper's scene (@p scene, a file of
   * prm/, on plate 8 x 5 x 1 and block 2 x 2 x 2 cells, 16 steps of 0.6 mm
   * to 9.6 mm, no field output) used by block_on_plate,
   * block_on_plate_adaptive and tearing_check.h; @p extra is
   * appended (later entries win).
   */
  inline std::string
  coarse_block_on_plate_prm(const std::string &extra = "",
                            const std::string &scene = "block_on_plate.prm")
  {
    return shipped_scene(scene) + R"(
subsection Mesh
  subsection Two bodies
    set Plate subdivisions = 8, 5, 1
    set Block subdivisions = 2, 2, 2
  end
end
subsection Load stepping
  set Time step = 4
  set End time  = 64
end
subsection Output
  set Interval = 0
end
)" + extra;
  }

  /**
   * .prm text of uniaxial tension of the unit cube: symmetry planes x = 0
   * (id 0), y = 0 (id 2), z = 0 (id 4); the face x = 1 (id 1) moved along x
   * by @p displacement (an expression in t), free laterally.
   */
  inline std::string
  uniaxial_pull_prm(const std::string &displacement)
  {
    return R"(
subsection Boundary conditions
  set Boundary ids = 0, 1, 2, 4
end
subsection Boundary 0
  set Constrained components = x
end
subsection Boundary 2
  set Constrained components = y
end
subsection Boundary 4
  set Constrained components = z
end
subsection Boundary 1
  set Constrained components = x
  set Displacement           = )" +
           displacement + R"(; 0; 0
end
)";
  }

  /**
   * The file 'output' that the harness compares, open on rank 0 only (other
   * ranks write into a closed stream, i.e. nowhere), 6 significant digits.
   */
  inline std::ofstream
  open_output()
  {
    std::ofstream out;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      out.open("output");
    out << std::setprecision(6);
    return out;
  }

  /**
   * Closed form of homogeneous uniaxial stress: the state F = diag(lambda,
   * lt, lt) with tau_yy = 0, lt found by bisection.
   */
  inline DuctileContact::MaterialResponse
  uniaxial_stress_state(const double lambda,
                        const double mu,
                        const double kappa,
                        double      &lateral_stretch)
  {
    const auto response = [&](const double lt) {
      dealii::Tensor<2, DuctileContact::material_dim> F;
      F[0][0] = lambda;
      F[1][1] = F[2][2] = lt;
      return DuctileContact::neo_hooke(F, mu, kappa, false);
    };
    double lo = 0.3, hi = 1.5;
    for (unsigned int i = 0; i < 200; ++i)
      ((response(0.5 * (lo + hi)).tau[1][1] > 0) ? hi : lo) = 0.5 * (lo + hi);
    lateral_stretch = 0.5 * (lo + hi);
    return response(lateral_stretch);
  }

  /// Relative difference, guarded for a zero reference.
  /**
   * One homogeneous uniaxial-stress step of the plasticity update: F =
   * diag(lambda, lt, lt) with tau_yy = 0 (lt by bisection) and alpha from
   * the local hardening equation r = 0 (Newton with dr/dalpha).
   */
  inline DuctileContact::MaterialResponse
  uniaxial_plastic_step(const double                                lambda,
                        const DuctileContact::PlasticHistory       &history,
                        const double                                dt,
                        const DuctileContact::PlasticityParameters &p)
  {
    const auto solve_alpha =
      [&](const dealii::Tensor<2, DuctileContact::material_dim> &F) {
        // Start just above alpha_n (the one-sided derivative of the flow).
        double                           alpha = history.alpha + 1e-12;
        DuctileContact::MaterialResponse r =
          DuctileContact::plastic_update(F, history, alpha, 0., dt, p, true);
        if (!r.yielding) // elastic: r = eta_p (alpha - alpha_n)/dt = 0
          return DuctileContact::plastic_update(
            F, history, history.alpha, 0., dt, p, true);
        for (unsigned int it = 0; it < 50 && r.yielding; ++it)
          {
            alpha = std::max(history.alpha + 1e-12, alpha - r.r / r.dr_dalpha);
            r     = DuctileContact::plastic_update(
              F, history, alpha, 0., dt, p, true);
            if (std::abs(r.r) < 1e-14)
              break;
          }
        return r;
      };
    double lo = 0.5, hi = 1.5;
    for (unsigned int i = 0; i < 60; ++i)
      {
        const double                                    mid = 0.5 * (lo + hi);
        dealii::Tensor<2, DuctileContact::material_dim> F;
        F[0][0] = lambda;
        F[1][1] = F[2][2]                        = mid;
        (solve_alpha(F).tau[1][1] > 0 ? hi : lo) = mid;
      }
    dealii::Tensor<2, DuctileContact::material_dim> F;
    F[0][0] = lambda;
    F[1][1] = F[2][2] = 0.5 * (lo + hi);
    return solve_alpha(F);
  }

  /// Norm-wise relative error of a set of entries, |approximation - exact|
  /// / |exact| over all of them (the absolute error if every exact entry is
  /// 0): the finite-difference checks of the material laws.
  class RelativeError
  {
  public:
    void
    add(const double approximation, const double exact)
    {
      diff += (approximation - exact) * (approximation - exact);
      norm += exact * exact;
    }

    double
    value() const
    {
      return norm > 0. ? std::sqrt(diff / norm) : std::sqrt(diff);
    }

  private:
    double diff = 0, norm = 0;
  };

  inline double
  relative_error(const double value, const double reference, const double scale)
  {
    return std::abs(value - reference) / std::max(std::abs(reference), scale);
  }

  /// f'(0) by fourth-order central differences from f(+-h), f(+-2h).
  template <typename Function>
  double
  derivative_4th_order(const Function &f, const double h)
  {
    return (8. * (f(h) - f(-h)) - (f(2. * h) - f(-2. * h))) / (12. * h);
  }

  /**
   * |D - G| / |G| over the 11 directions (F_cD, alpha, s) of a material
   * point's derivative: @p derivative(dF, dalpha, ds) the difference
   * quotient along a direction, G = (@p d_dF, @p d_dalpha, @p d_ds) the
   * exact gradient.
   */
  template <typename Derivative>
  double
  point_gradient_error(
    const Derivative                                      &derivative,
    const dealii::Tensor<2, DuctileContact::material_dim> &d_dF,
    const double                                           d_dalpha,
    const double                                           d_ds)
  {
    constexpr unsigned int dim  = DuctileContact::dim;
    double                 diff = 0., norm = 0.;
    const auto             add = [&](const double fd, const double exact) {
      diff += (fd - exact) * (fd - exact);
      norm += exact * exact;
    };
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int C = 0; C < dim; ++C)
        {
          dealii::Tensor<2, dim> dF;
          dF[c][C] = 1.;
          add(derivative(dF, 0., 0.), d_dF[c][C]);
        }
    add(derivative(dealii::Tensor<2, dim>(), 1., 0.), d_dalpha);
    add(derivative(dealii::Tensor<2, dim>(), 0., 1.), d_ds);
    return std::sqrt(diff / norm);
  }

  /// I + A with the entries of A drawn from @p d (by rows) times
  /// @p amplitude: a random deformation gradient near the identity.
  template <typename Generator, typename Distribution>
  dealii::Tensor<2, DuctileContact::material_dim>
  perturbed_identity(Generator &gen, Distribution &d, const double amplitude)
  {
    dealii::Tensor<2, DuctileContact::material_dim> F =
      dealii::unit_symmetric_tensor<DuctileContact::dim>();
    for (unsigned int i = 0; i < DuctileContact::dim; ++i)
      for (unsigned int j = 0; j < DuctileContact::dim; ++j)
        F[i][j] += amplitude * d(gen);
    return F;
  }

  /// A random isochoric plastic deformation F^p (perturbed_identity() with
  /// amplitude 0.01, scaled to det 1) and the history with its (C^p)^{-1}
  /// and @p alpha.
  template <typename Generator, typename Distribution>
  std::pair<dealii::Tensor<2, DuctileContact::material_dim>,
            DuctileContact::PlasticHistory>
  random_plastic_history(Generator &gen, Distribution &d, const double alpha)
  {
    dealii::Tensor<2, DuctileContact::material_dim> Fp =
      perturbed_identity(gen, d, 0.01);
    Fp /= std::cbrt(determinant(Fp));
    DuctileContact::PlasticHistory h;
    h.Cp_inv = symmetrize(invert(transpose(Fp) * Fp));
    h.alpha  = alpha;
    return {Fp, h};
  }

  /// "yes"/"no" for a condition: what the output file records.
  inline const char *
  yes_no(const bool condition)
  {
    return condition ? "yes" : "no";
  }
} // namespace Testing
