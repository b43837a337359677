#pragma once
// The check of a coarse tearing scene, shared by
// block_on_plate_tearing_bernstein.cc (3-D, the shipped scene's Bernstein
// phase field and loading condition 'bound'), two_d/block_on_strip_tearing.cc
// (plane strain, the Lagrange phase field, the pointwise switch) and
// two_d/block_on_strip_tearing_bound.cc (plane strain, the bound, Bernstein
// alpha and s): see their headers. two_d/impact_release.cc takes the tearing
// scene's plasticity entries from here too.
#include "tests.h"

#include <algorithm>

namespace Testing
{
  /// A coarse tearing run and what "torn" means for it.
  struct TearingScene
  {
    /// The whole input.
    std::string prm;
    /// Folder of the run.
    std::string run_name;
    /// Statistics column of the reaction on the block's top.
    std::string reaction;
    /// Extent of the plate across the tear (along y) [m]: the set s >= 0.95
    /// must come within @p edge of both of its faces.
    double width;
    double edge;
    /// The first steps, in which the block starts to touch and W_ext is
    /// small: there |energy residual| <= @p onset_bound, after them 1 % of
    /// W_ext.
    unsigned int onset_steps;
    double       onset_bound;
    /// "" in 3-D, "/m" in plane strain (per unit thickness).
    std::string per;
    /// Phase field in the Bernstein basis: s <= 1 at the quadrature points
    /// is checked too.
    bool bernstein;
    /// Plasticity/Loading condition = bound: the local plastic dissipation
    /// of every point and step is checked to be >= 0 (to the round-off of
    /// the elastic energy, 1e-14 mu).
    bool plastic_bound = false;
    /// With the bound, alpha in the Bernstein basis: alpha >= 0 at the
    /// quadrature points is checked too.
    bool alpha_bernstein = false;
  };

  /// The plasticity of prm/block_on_plate_tearing.prm for body 0:
  /// Loading condition = bound, alpha in the Bernstein basis.
  inline const std::string plastic_bound_entries = R"(
subsection Finite elements
  set Hardening basis = Bernstein
end
subsection Body 0
  subsection Plasticity
    set Loading condition = bound
  end
end
)";

  /// The round-off of the local plastic dissipation [J/m^3]: that of the
  /// elastic energy, 1e-14 mu of the plates of these scenes (mu = 26.455
  /// GPa).
  constexpr double local_dissipation_round_off = 1e-14 * 26.455e9;

  /**
   * The plane-strain tear of the two_d tests: prm/block_on_strip_2d.prm
   * (19 x 2 Q2 cells in the strip) with the variational crack driver
   * 'elastic and plastic energy', g_c = 30 kJ/m^2, w_c = 0, the
   * irreversibility by the bound alone, Maximum phase-field increment =
   * 0.1, steps of @p time_step to t = 160 (24 mm), no output, then
   * @p extra (the plasticity's and the bases' entries); the checks' data
   * for the strip. @p run_name names its folder.
   */
  inline TearingScene
  strip_tearing_scene(const std::string &extra,
                      const double       time_step,
                      const std::string &run_name)
  {
    TearingScene scene;
    scene.prm = shipped_scene("block_on_strip_2d.prm") + R"(
subsection Body 0
  subsection Fracture
    set Crack driver                 = elastic and plastic energy
    set Critical energy release rate = 30e3
    set Critical work density        = 0
  end
end
subsection Coupling
  set Irreversibility = bound
end
subsection Load stepping
  set End time                      = 160
  set Time step                     = )" +
                std::to_string(time_step) + R"(
  set Maximum phase-field increment = 0.1
end
subsection Output
  set Interval = 0
end
)" + extra;
    scene.run_name    = run_name;
    scene.reaction    = "F2_y";
    scene.width       = 0.02; // the strip's thickness
    scene.edge        = 0.002;
    scene.onset_steps = 3;
    scene.onset_bound = 0.08;
    scene.per         = "/m";
    scene.bernstein   = false;
    return scene;
  }

  /// Input of the coarse copy of prm/block_on_plate_tearing.prm (plate
  /// 8 x 5 x 1, block 2 x 2 x 2 Q2 cells, 0.6 mm steps) with g_c = 30
  /// kJ/m^2 and w_c = 0, to 48 mm.
  inline std::string
  coarse_tearing_prm()
  {
    return coarse_block_on_plate_prm(R"(
  subsection Body 0
    subsection Fracture
      set Critical energy release rate = 30e3
      set Critical work density        = 0
    end
  end
  subsection Load stepping
    set End time = 320
  end
  )",
                                     "block_on_plate_tearing.prm");
  }

  /// Runs @p scene and writes its checks and quantities of interest (5
  /// significant digits) to @p out; returns the run's statistics.
  inline Testing::Table
  check_tearing(std::ostream &out, const TearingScene &scene)
  {
    const Testing::Table t = Testing::run_scene(scene.prm, scene.run_name);
    const std::size_t    n = t.at("time").size();
    const auto col         = [&](const std::string &name, const std::size_t k) {
      return t.at(name)[k];
    };
    double worst_balance = 0., worst_increment = 0., peak = 0., max_s = 0.,
           max_s_points = 0., min_s_change = 0., history = 0., worst_onset = 0.,
           min_alpha = 0., min_local_dissipation = 0.;
    for (std::size_t k = 1; k < n; ++k)
      {
        if (k <= scene.onset_steps)
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
        peak         = std::max(peak, std::abs(col(scene.reaction, k)));
        max_s        = std::max(max_s, col("max_s", k));
        max_s_points = std::max(max_s_points, col("max_s_points", k));
        min_s_change = std::min(min_s_change, col("min_s_change", k));
        min_alpha    = std::min(min_alpha, col("min_alpha", k));
        min_local_dissipation =
          std::min(min_local_dissipation, col("min_plastic_dissipation", k));
        history = std::max(history, std::abs(col("history_driving_work", k)));
      }
    const std::size_t last = n - 1;
    const std::string J = " J" + scene.per, N = " N" + scene.per;
    out << "energy balance within 1 % of W_ext at every step after the first "
        << scene.onset_steps << ", " << scene.onset_bound << J << " in those: "
        << Testing::yes_no(worst_balance < 0.01 &&
                           worst_onset < scene.onset_bound)
        << "\n"
        << "no history driving work: " << Testing::yes_no(history == 0.) << "\n"
        << "D_f, D_c and R_p never decrease (1e-9" << J
        << "): " << Testing::yes_no(worst_increment > -1e-9) << "\n"
        << "s in [0, 1] at the nodes and never decreasing (1e-8): "
        << Testing::yes_no(max_s <= 1. + 1e-12 && min_s_change > -1e-8) << "\n"
        << (scene.bernstein
              ? std::string("s <= 1 at the quadrature points too "
                            "(Bernstein coefficients bound the "
                            "field): ") +
                  Testing::yes_no(max_s_points <= 1. + 1e-12) + "\n"
              : std::string())
        << (scene.plastic_bound
              ? std::string("local plastic dissipation >= 0 at every point "
                            "and step (1e-14 mu): ") +
                  Testing::yes_no(min_local_dissipation >=
                                  -local_dissipation_round_off) +
                  "\n"
              : std::string())
        << (scene.alpha_bernstein
              ? std::string("alpha >= 0 at the quadrature points (the bound "
                            "alpha_n <= alpha on Bernstein coefficients): ") +
                  Testing::yes_no(min_alpha >= 0.) + "\n"
              : std::string())
        << "the plate tears (s >= 0.95 across it at the clamp, "
           "max s = 1, end reaction < 10 % of the peak): "
        << Testing::yes_no(col("cracked_min_y", last) < scene.edge &&
                           col("cracked_max_y", last) >
                             scene.width - scene.edge &&
                           max_s > 1. - 1e-6 &&
                           std::abs(col(scene.reaction, last)) < 0.1 * peak)
        << "\n"
        << std::setprecision(5) << "largest s at a quadrature point "
        << max_s_points << "\n"
        << "peak reaction " << peak << N << ", end reaction "
        << col(scene.reaction, last) << N << "\n"
        << "W_ext " << col("external_work", last) << J << ", W_p "
        << col("plastic_work", last) << J << ", Psi^p "
        << col("hardening_energy", last) << J << ", R_p "
        << col("plastic_energy_released", last) << J << ", D_p "
        << col("plastic_dissipation", last) << J << "\n"
        << "crack energy " << col("fracture_energy", last) << J << ", friction "
        << col("contact1_dissipation", last) << J << "\n";
    std::cout << "worst balance " << worst_balance << ", onset " << worst_onset
              << ", worst increment " << worst_increment << ", steps " << last
              << ", min alpha " << min_alpha << ", min local D_p "
              << min_local_dissipation << std::endl;
    return t;
  }
} // namespace Testing
