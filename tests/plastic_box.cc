// Homogeneous box (2x2x2 Q2 cells, unit cube) in uniaxial tension
// with the visco-plastic J2 model and the hardening field alpha solved
// globally by (50) with u, against the material-point driver
// (Testing::uniaxial_plastic_step) stepped with the same load steps:
//  - the nominal stress (reaction on x = 1) and the hardening energy
//    int_0^alpha yhat equal the driver's to 1e-6 at every step;
//  - the energy balance W_ext - Psi^e - W_p closes as dt -> 0, at first
//    order (W_p: the elastic energy released by the flow, see
//    plastic_work_of_step()): halving dt halves it or better. Its error
//    is made in the step in which the box starts to yield: there W_p
//    counts the flow from the yield onset on, while the trapezoidal
//    external work is taken across the kink of the force curve;
//  - the plastic work equals the hardening energy up to the viscous part
//    (eta_p is small here): within 1 % (with the exponential map the
//    plastic work is the work of the flow resistance, doc/model.md
//    section 3);
//  - a rejected step leaves no trace: steps that fail (at most 3 Newton
//    iterations) are cut back, and the accepted ones still match the
//    driver stepped with them alone.
// - graphical output is written on every rank count (one .vtu piece per
//   rank in the last step's record).
// Run on 1 and 2 MPI ranks with identical output.
#include "tests.h"

#include <iterator>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  std::string
  box_prm(const double dt, const unsigned int max_newton_iterations = 15)
  {
    return Testing::unit_cube_prm(R"(  set Plasticity    = true
  subsection Plasticity
    set Initial yield stress    = 0.005
    set Saturation yield stress = 0.006
    set Saturation exponent     = 25
    set Viscosity               = 1e-6
  end
)") + Testing::uniaxial_pull_prm("0.02*t") +
           R"(
subsection Load stepping
  set End time  = 1
  set Time step = )" +
           std::to_string(dt) + R"(
end
subsection Newton
  set Relative tolerance = 1e-11
  set Maximum iterations = )" +
           std::to_string(max_newton_iterations) + R"(
end
subsection Output
  set Interval = 5
end
)";
  }

  /// int_0^alpha yhat(a) da of (21) for h = 0.
  double
  hardening_energy(const double alpha, const PlasticityParameters &p)
  {
    const double eta = p.saturation_exponent;
    return p.initial_yield * alpha +
           (p.saturation_yield - p.initial_yield) *
             (alpha - (1. - std::exp(-eta * alpha)) / eta);
  }

  /// Largest relative differences of the reaction on x = 1 and of the
  /// hardening energy from the driver's, the driver stepped with the
  /// accepted steps of the run.
  struct DriverErrors
  {
    double force = 0., energy = 0.;
  };
  DriverErrors
  compare_with_driver(const Testing::Table       &stats,
                      const PlasticityParameters &p)
  {
    PlasticHistory h;
    DriverErrors   worst;
    for (unsigned int n = 1; n < stats.at("time").size(); ++n)
      {
        const double           lambda = 1. + 0.02 * stats.at("time")[n];
        const MaterialResponse r =
          Testing::uniaxial_plastic_step(lambda, h, stats.at("dt")[n], p);
        h                   = r.updated;
        const double P_xx   = r.tau[0][0] / lambda;
        const double energy = hardening_energy(h.alpha, p);
        worst.force =
          std::max(worst.force,
                   std::abs(stats.at("F1_x")[n] - P_xx) / std::abs(P_xx));
        if (energy > 0.)
          worst.energy =
            std::max(worst.energy,
                     std::abs(stats.at("hardening_energy")[n] - energy) /
                       energy);
      }
    return worst;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  PlasticityParameters p = Testing::unit_plasticity();
  p.viscosity            = 1e-6;

  double residual[2] = {0., 0.};
  for (const unsigned int k : {0u, 1u})
    {
      const double dt = (k == 0) ? 0.1 : 0.05;
      const auto   stats =
        Testing::run_scene(box_prm(dt), "plastic_box_" + std::to_string(k));

      const DriverErrors worst = compare_with_driver(stats, p);
      const std::size_t  last  = stats.at("time").size() - 1;
      residual[k]              = stats.at("energy_residual")[last];
      const double W_p         = stats.at("plastic_work")[last];
      const double Psi_p       = stats.at("hardening_energy")[last];
      out << "dt = " << dt << ": reaction equals the driver's P_xx (1e-6): "
          << Testing::yes_no(worst.force < 1e-6) << std::endl
          << "  hardening energy equals the driver's (1e-6): "
          << Testing::yes_no(worst.energy < 1e-6) << std::endl
          << "  plastic work = hardening energy (1 %): "
          << Testing::yes_no(std::abs(W_p - Psi_p) < 0.01 * Psi_p) << std::endl
          << std::setprecision(5) << "  end reaction " << stats.at("F1_x")[last]
          << ", W_p " << W_p << ", Psi^p " << Psi_p << std::setprecision(6)
          << std::endl;
      std::cout << "dt " << dt << " worst force " << worst.force
                << " worst energy " << worst.energy << " W_p " << W_p
                << " Psi_p " << Psi_p << " residual " << residual[k]
                << " W_ext " << stats.at("external_work")[last] << std::endl;
    }
  // Graphical output of a scene with an alpha block, on every rank count
  // (this hung on 2 ranks once): the last step's record names one piece per
  // rank and every piece exists.
  {
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    std::ifstream     record("plastic_box_1/solution_00020.pvtu");
    const std::string text((std::istreambuf_iterator<char>(record)),
                           std::istreambuf_iterator<char>());
    unsigned int      pieces = 0, present = 0;
    for (std::size_t at = text.find("<Piece Source=\"");
         at != std::string::npos;
         at = text.find("<Piece Source=\"", at + 1))
      {
        ++pieces;
        const std::size_t begin = at + 15, end = text.find('"', begin);
        present +=
          std::ifstream("plastic_box_1/" + text.substr(begin, end - begin))
            .good();
      }
    out << "output of the last step: one piece per rank, all written: "
        << Testing::yes_no(pieces == n_ranks && present == n_ranks)
        << std::endl;
  }
  // A rejected step leaves no trace: with at most 3 Newton iterations the
  // first plastic steps of dt = 0.25 fail and are cut back; the accepted
  // steps still match the driver stepped with them alone (the history is
  // committed only when a step is accepted).
  {
    const auto stats = Testing::run_scene(box_prm(0.25, 3), "plastic_cutback");
    double     cutbacks = 0;
    for (const double c : stats.at("cutbacks"))
      cutbacks += c;
    const double worst = compare_with_driver(stats, p).force;
    std::cout << "cut-back run: " << cutbacks << " cut-backs, "
              << stats.at("time").size() - 1 << " steps, worst force " << worst
              << std::endl;
    out << "steps cut back: " << Testing::yes_no(cutbacks > 0)
        << "; the accepted steps match the driver stepped with them alone "
           "(1e-6): "
        << Testing::yes_no(worst < 1e-6) << std::endl;
  }
  const double ratio = residual[0] / residual[1];
  out << "energy residual shrinks at first order or better (ratio > 1.8): "
      << Testing::yes_no(ratio > 1.8) << std::endl;
  std::cout << "energy residual ratio " << ratio << std::endl;
}
