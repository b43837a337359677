// Validation rung 11: Hertz line contact, coarse. A cylinder
// (R = 1 m) pressed onto a flat foundation of the same material (E = 1 GPa,
// nu = 0.3), plane strain slab, half model (tests/meshes/hertz_h<r>.msh from
// `make_hertz.py 1 0.01 <r> 0.3`: h = a/r at the contact, a = 0.01 m the
// design half-width), the indenter's top pushed down by 2e-4 m in one
// step, frictionless, dual multipliers. From the carried load P per unit
// length (twice the half model's), Hertz gives a = sqrt(4 P R/(pi E*)) and
// p0 = 2 P/(pi a); the run's a and p0 come from a least-squares fit of
// p^2 = p0^2 (1 - x^2/a^2) to the nodal pressures at x <= 0.8 a (Hertz).
// Checked at h = a/4: a within 8 % and p0 within 5 % of Hertz
// (benchmarks/contact/hertz has the converged study: 1.5 % at a/8); the contact
// force balances the reaction on the top face; the penetration is below the
// tolerance; the contact tangent (Newton/Check tangent) matches central
// differences of the residual. On 1 and 2 MPI ranks, the slave surface then
// spanning both (its symmetry-plane and slab-face DoFs carry Dirichlet
// conditions that a rank must know for master rows it does not own): identical
// output.
#include "tests.h"

#include <cmath>

using namespace dealii;

namespace
{
  std::string
  hertz_prm(const unsigned int ratio)
  {
    return Testing::hertz_line_prm(ratio) + R"(
subsection Output
  set Interval = 1
end
subsection Newton
  set Check tangent = true
end
)";
  }

  struct Result
  {
    double a_error, p0_error, balance, penetration, tangent_error;
    /// Load per unit length, half-width and peak pressure of the fit.
    double P, a, p0;
  };

  Result
  run(const unsigned int ratio)
  {
    const std::string dir   = "hertz_h" + std::to_string(ratio);
    const auto        stats = Testing::run_scene(hertz_prm(ratio), dir);
    const auto nodes = Testing::read_statistics(dir + "/contact1_00001.txt");

    double thickness = 0;
    for (const double z : nodes.at("Z"))
      thickness = std::max(thickness, z);
    const Testing::HertzLine h = Testing::hertz_line(stats, nodes, thickness);
    const double             F = stats.at("F2_y").back();
    std::cout << "h = a/" << ratio << ": P " << h.P << ", a " << h.a
              << " (Hertz " << h.a_hertz << "), p0 " << h.p0 << " (Hertz "
              << h.p0_hertz << ")" << std::endl;
    return {std::abs(h.a / h.a_hertz - 1.),
            std::abs(h.p0 / h.p0_hertz - 1.),
            // contact1_force: what the slave (indenter) exerts on the
            // master; the top face's reaction F balances its opposite.
            std::abs(F - stats.at("contact1_force_y").back()) / std::abs(F),
            stats.at("contact1_max_penetration").back(),
            stats.at("tangent_error").back(),
            h.P,
            h.a,
            h.p0};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const Result fine = run(4);
  out << "h = a/4: a within 8 % of Hertz: "
      << Testing::yes_no(fine.a_error < 0.08) << " (" << std::setprecision(1)
      << 100 * fine.a_error << " %)" << std::endl
      << "h = a/4: p0 within 5 % of Hertz: "
      << Testing::yes_no(fine.p0_error < 0.05) << " (" << std::setprecision(1)
      << 100 * fine.p0_error << " %)" << std::endl
      << "contact force balances the reaction (1e-6, Newton tolerance): "
      << Testing::yes_no(fine.balance < 1e-6) << std::endl
      << "penetration below 1e-6 h: "
      << Testing::yes_no(fine.penetration < 1e-6 * 0.0025) << std::endl
      << "consistent tangent (K d against central differences of R along the "
         "last Newton update, 1e-6): "
      << Testing::yes_no(fine.tangent_error < 1e-6) << std::endl
      << std::setprecision(5) << "h = a/4: P " << fine.P << " N/m, a " << fine.a
      << " m, p0 " << fine.p0 << " Pa" << std::endl;
}
