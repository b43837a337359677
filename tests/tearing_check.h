#pragma once
// The check of the coarse tearing scene, shared by
// block_on_plate_tearing.cc (Lagrange phase field) and
// block_on_plate_tearing_bernstein.cc: see the first one's header.
#include "tests.h"

#include <algorithm>

namespace Testing
{
  /// Runs the coarse tearing scene with @p extra appended to its input (in
  /// the folder @p run_name) and writes its checks and quantities to
  /// @p out; @p bernstein adds the check that s <= 1 at the quadrature
  /// points.
  inline void
  check_coarse_tearing(std::ostream      &out,
                       const std::string &extra,
                       const std::string &run_name,
                       const bool         bernstein)
  {
    const Testing::Table t = Testing::run_scene(
      Testing::coarse_block_on_plate_prm(R"(
  subsection Body 0
    subsection Fracture
      set Critical energy release rate = 30e3
      set Critical work density        = 0
    end
  end
  subsection Load stepping
    set End time = 320
  end
  )" + extra,
                                         "block_on_plate_tearing.prm"),
      run_name);
    const std::size_t n   = t.at("time").size();
    const auto        col = [&](const std::string &name, const std::size_t k) {
      return t.at(name)[k];
    };
    double worst_balance = 0., worst_increment = 0., peak = 0., max_s = 0.,
           max_s_points = 0., min_s_change = 0., history = 0., worst_onset = 0.;
    for (std::size_t k = 1; k < n; ++k)
      {
        if (k <= 2)
          worst_onset =
            std::max(worst_onset, std::abs(col("energy_residual", k)));
        else
          worst_balance = std::max(worst_balance,
                                   std::abs(col("energy_residual", k)) /
                                     col("external_work", k));
        for (const char *c : {"fracture_viscous_work",
                              "contact1_dissipation",
                              "plastic_energy_released"})
          worst_increment =
            std::min(worst_increment, col(c, k) - col(c, k - 1));
        peak         = std::max(peak, std::abs(col("F2_z", k)));
        max_s        = std::max(max_s, col("max_s", k));
        max_s_points = std::max(max_s_points, col("max_s_points", k));
        min_s_change = std::min(min_s_change, col("min_s_change", k));
        history = std::max(history, std::abs(col("history_driving_work", k)));
      }
    const std::size_t last = n - 1;
    // The plate is 0.2 m wide in y, five cells across.
    const double plate_cell = 0.04;
    out << "energy balance within 1 % of W_ext at every step from the third, "
           "0.02 J in the first two: "
        << Testing::yes_no(worst_balance < 0.01 && worst_onset < 0.02) << "\n"
        << "no history driving work: " << Testing::yes_no(history == 0.) << "\n"
        << "D_f, D_c and R_p never decrease (1e-9 J): "
        << Testing::yes_no(worst_increment > -1e-9) << "\n"
        << "s in [0, 1] at the nodes and never decreasing (1e-8): "
        << Testing::yes_no(max_s <= 1. + 1e-12 && min_s_change > -1e-8) << "\n"
        << (bernstein ? std::string("s <= 1 at the quadrature points too "
                                    "(Bernstein coefficients bound the "
                                    "field): ") +
                          Testing::yes_no(max_s_points <= 1. + 1e-12) + "\n"
                      : std::string())
        << "the plate tears (s >= 0.95 across its width at the clamp, "
           "max s = 1, end reaction < 10 % of the peak): "
        << Testing::yes_no(col("cracked_min_y", last) < plate_cell &&
                           col("cracked_max_y", last) > 0.2 - plate_cell &&
                           max_s > 1. - 1e-6 &&
                           std::abs(col("F2_z", last)) < 0.1 * peak)
        << "\n"
        << std::setprecision(5) << "largest s at a quadrature point "
        << max_s_points << "\n"
        << "peak reaction " << peak << " N, end reaction " << col("F2_z", last)
        << " N\n"
        << "W_ext " << col("external_work", last) << " J, W_p "
        << col("plastic_work", last) << " J, Psi^p "
        << col("hardening_energy", last) << " J, R_p "
        << col("plastic_energy_released", last) << " J, D_p "
        << col("plastic_dissipation", last) << " J\n"
        << "crack energy " << col("fracture_energy", last) << " J, friction "
        << col("contact1_dissipation", last) << " J\n";
    std::cout << "worst balance " << worst_balance << ", worst increment "
              << worst_increment << ", steps " << last << std::endl;
  }
} // namespace Testing
