#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace DuctileContact
{
  /**
   * Subsection `Load stepping`: quasi-static pseudo time t in [0, End time];
   * all boundary data are functions of t. A step whose Newton iteration
   * fails is repeated with half the step (cut-back); after easy steps, or
   * after a run of accepted steps at the same increment, the step grows
   * again, never beyond `Time step`.
   */
  struct LoadSteppingParameters
  {
    double       end_time          = 1.;
    double       time_step         = 0.1;
    double       minimum_time_step = 1.e-6;
    double       growth_factor     = 1.5;
    unsigned int easy_newton_steps = 5;
    /// Accepted steps in a row at one increment after which it grows even
    /// if none was easy (0: never).
    unsigned int steps_before_growth = 4;
    /// constant | linear: first guess of a step (see declare()).
    std::string predictor = "constant";

    void
    declare(dealii::ParameterHandler &prm);
    void
    check() const;
  };

  /**
   * Subsection `Newton`: tolerances and globalisation of the Newton
   * iteration on the coupled residual.
   */
  struct NewtonParameters
  {
    unsigned int max_iterations        = 15;
    double       relative_tolerance    = 1.e-9;
    double       absolute_tolerance    = 1.e-12;
    bool         line_search           = true;
    unsigned int max_line_search_steps = 6;
    /// Compare K delta with central differences of R along delta.
    bool check_tangent = false;

    void
    declare(dealii::ParameterHandler &prm);
    void
    check() const;
  };

  /**
   * Subsection `Linear solver`. With alpha or s unknowns the iterative types
   * solve the coupled [u | alpha | s] system with GMRES and a block
   * lower-triangular preconditioner (see LinearSolver).
   */
  struct LinearSolverParameters
  {
    /// direct | cg-amg | gmres-amg
    std::string type = "direct";
    /// Amesos_Klu | Amesos_Mumps
    std::string  direct_solver         = "Amesos_Mumps";
    double       relative_tolerance    = 1.e-8;
    unsigned int max_iterations        = 2000;
    double       aggregation_threshold = 1.e-4;
    unsigned int smoother_sweeps       = 2;
    /// amg | direct: approximate inverse of the s-s block (coupled systems).
    std::string phase_field_preconditioner = "amg";

    void
    declare(dealii::ParameterHandler &prm);
    void
    check() const;
  };
} // namespace DuctileContact
