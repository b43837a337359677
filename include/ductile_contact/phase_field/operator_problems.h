#pragma once

#include <deal.II/base/mpi.h>

#include <ductile_contact/phase_field/c0ip.h>

#include <string>

namespace DuctileContact
{
  /**
   * Validation problems for the C0IP crack operator alone (no mechanics),
   * shared by the tests and benchmarks/phase_field. Both run on a
   * distributed mesh with a scalar FE_Q(degree) and solve a(s, v) = l(v)
   * with Trilinos: `solver` is "direct" (Amesos MUMPS) or "cg-amg" (CG with
   * ML AMG, tolerance 1e-12 relative).
   */
  struct OperatorSolveInfo
  {
    unsigned long n_dofs            = 0;
    unsigned int  linear_iterations = 0;
    double        setup_seconds     = 0.;
    double        assembly_seconds  = 0.;
    double        solve_seconds     = 0.;
  };

  /// Errors of the manufactured solution (validation rung 5).
  struct ManufacturedErrors
  {
    double            h  = 0.;
    double            l2 = 0.; ///< ||s - s_h||_L2
    double            h1 = 0.; ///< |s - s_h|_H1
    double            h2 = 0.; ///< broken |s - s_h|_H2 (cellwise Hessians)
    OperatorSolveInfo info;
  };

  /**
   * Manufactured solution on the unit cube: s = cos(pi x) cos(pi y)
   * cos(pi z) (the unit square and cos(pi x) cos(pi y) in 2-D), for which d_n s
   * = d_n Lap s = 0 on the boundary, so that L s = mass s - gradient Lap s +
   * bilaplacian Lap^2 s = f holds with l(v) = int f v dV + int_dB bilaplacian
   * Lap s d_n v dA (the natural conditions of a with the boundary data of s).
   */
  ManufacturedErrors
  solve_manufactured_c0ip(const unsigned int      degree,
                          const unsigned int      refinements,
                          const C0IPCoefficients &coefficients,
                          const std::string      &solver,
                          const MPI_Comm          comm);

  /// Result of the crack-energy strip (validation rung 6).
  struct StripResult
  {
    /// int gamma dV / cross-section area, i.e. Gamma(L) of doc/model.md
    /// section 4.
    double            gamma = 0.;
    OperatorSolveInfo info;
  };

  /**
   * A bar [-L, L] x [0, h] x [0, h], one cell across and periodic in y and
   * z (an infinite plate; natural conditions at x = +-L), with s = 1
   * imposed on the plane x = 0 and no load: the minimiser of int gamma.
   * Returns int gamma / h^2 evaluated as a(s, s)/2
   * with the C0IP form, i.e. with the discrete Laplacian consistent with
   * the face terms.
   *
   * @param half_length   L in units of l_f
   * @param cells_per_lf  l_f / h
   */
  StripResult
  solve_crack_strip(const unsigned int degree,
                    const double       half_length,
                    const unsigned int cells_per_lf,
                    const std::string &solver,
                    const MPI_Comm     comm);
} // namespace DuctileContact
