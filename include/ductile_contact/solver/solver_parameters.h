#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <ductile_contact/core/option.h>

#include <string>

namespace DuctileContact
{
  /// Load stepping/Time integration.
  enum class TimeIntegration
  {
    quasi_static,
    bossak
  };

  inline const NameTable<TimeIntegration> &
  time_integration_names()
  {
    static const NameTable<TimeIntegration> t{
      {TimeIntegration::quasi_static, "quasi-static"},
      {TimeIntegration::bossak, "Bossak"}};
    return t;
  }

  /// Load stepping/Contact surface mass.
  enum class ContactSurfaceMass
  {
    redistributed,
    consistent
  };

  inline const NameTable<ContactSurfaceMass> &
  contact_surface_mass_names()
  {
    static const NameTable<ContactSurfaceMass> t{
      {ContactSurfaceMass::redistributed, "redistributed"},
      {ContactSurfaceMass::consistent, "consistent"}};
    return t;
  }

  /**
   * Subsection `Load stepping`: quasi-static pseudo time t in [0, End time];
   * all boundary data are functions of t. A step whose Newton iteration
   * fails is repeated with half the step (cut-back); after easy steps, or
   * after a run of accepted steps at the same increment, the step grows
   * again, never beyond `Time step`.
   */
  /// Load stepping/Predictor.
  enum class Predictor
  {
    constant,
    linear,
    linear_displacements,
    best_linear
  };

  inline const NameTable<Predictor> &
  predictor_names()
  {
    static const NameTable<Predictor> t{
      {Predictor::constant, "constant"},
      {Predictor::linear, "linear"},
      {Predictor::linear_displacements, "linear displacements"},
      {Predictor::best_linear, "best linear"}};
    return t;
  }

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
    /// Failed steps while t advances by less than 1e-3 Time step after
    /// which the run gives up (0: never; see declare()).
    unsigned int max_stalled_failures = 20;
    /// Largest rise of s at a DoF in one step; a step above it is cut back
    /// (1: no limit; see declare()).
    double max_phase_field_increment = 1.;
    /// constant | linear | linear displacements | best linear: first guess
    /// of a step (see declare()).
    Predictor predictor = Predictor::constant;
    /// quasi-static | Bossak (implicit dynamics; see declare()).
    TimeIntegration time_integration = TimeIntegration::quasi_static;
    /// rho_inf of the Bossak scheme, in [0, 1] (1: the trapezoidal rule).
    double spectral_radius = 1.;
    /// Largest relative local error estimate of a dynamic step (0: no
    /// control; see declare()).
    double local_error_tolerance = 0.;
    /// Whether the contact surfaces carry mass (see declare()).
    ContactSurfaceMass contact_surface_mass = ContactSurfaceMass::redistributed;

    void
    declare(dealii::ParameterHandler &prm);
    void
    check() const;
  };

  /// Newton/Tangent update.
  enum class TangentUpdate
  {
    every_iteration,
    chord
  };

  inline const NameTable<TangentUpdate> &
  tangent_update_names()
  {
    static const NameTable<TangentUpdate> t{
      {TangentUpdate::every_iteration, "every iteration"},
      {TangentUpdate::chord, "chord after a quadratic step"}};
    return t;
  }

  /// Newton/Linear solve accuracy.
  enum class LinearAccuracy
  {
    relative_tolerance,
    newton_tolerances
  };

  inline const NameTable<LinearAccuracy> &
  linear_accuracy_names()
  {
    static const NameTable<LinearAccuracy> t{
      {LinearAccuracy::relative_tolerance, "relative tolerance"},
      {LinearAccuracy::newton_tolerances, "newton tolerances"}};
    return t;
  }

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
    /// Newton iterations whose merit the line search compares with (1:
    /// monotone; see declare()).
    unsigned int line_search_memory = 1;
    /// Compare K delta with central differences of R along delta.
    bool check_tangent = false;
    /// every iteration | chord after a quadratic step (see declare()).
    TangentUpdate tangent_update = TangentUpdate::every_iteration;
    /// relative tolerance | newton tolerances (see declare()).
    LinearAccuracy linear_accuracy = LinearAccuracy::relative_tolerance;

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
  /// Linear solver/Type.
  enum class LinearSolverType
  {
    /// direct up to Direct solver limit unknowns, gmres_amg above.
    automatic,
    direct,
    cg_amg,
    gmres_amg
  };

  inline const NameTable<LinearSolverType> &
  linear_solver_type_names()
  {
    static const NameTable<LinearSolverType> t{
      {LinearSolverType::automatic, "automatic"},
      {LinearSolverType::direct, "direct"},
      {LinearSolverType::cg_amg, "cg-amg"},
      {LinearSolverType::gmres_amg, "gmres-amg"}};
    return t;
  }

  /// Linear solver/Direct solver.
  enum class DirectSolver
  {
    /// MUMPS through its own interface (MumpsSolver): analysis once per
    /// sparsity pattern, Ordering and Factorisation as set.
    mumps,
    /// MUMPS through Trilinos Amesos: a new analysis on every solve.
    amesos_mumps,
    /// KLU through Trilinos Amesos.
    amesos_klu
  };

  inline const NameTable<DirectSolver> &
  direct_solver_names()
  {
    static const NameTable<DirectSolver> t{
      {DirectSolver::mumps, "mumps"},
      {DirectSolver::amesos_mumps, "Amesos_Mumps"},
      {DirectSolver::amesos_klu, "Amesos_Klu"}};
    return t;
  }

  /// Linear solver/Ordering: the fill-reducing order of the direct solver.
  enum class DirectOrdering
  {
    /// METIS nested dissection of the symmetrised graph, computed by us
    /// and handed to MUMPS as its pivot order (Debian's MUMPS has no METIS).
    metis,
    /// MUMPS's own choice among the orderings it was built with.
    automatic,
    amd,
    pord,
    /// PT-Scotch nested dissection computed by MUMPS on all ranks (its
    /// parallel analysis: no rank gathers the pattern; on one rank Scotch).
    pt_scotch
  };

  /// Linear solver/Factorisation: how the matrix is factorised.
  enum class Factorisation
  {
    /// K = L U (any matrix).
    lu,
    /// K = L D L^T from the upper triangle: half the work and memory, for a
    /// symmetric tangent only (an unsymmetric one is solved inexactly).
    ldlt
  };

  inline const NameTable<DirectOrdering> &
  direct_ordering_names()
  {
    static const NameTable<DirectOrdering> t{
      {DirectOrdering::metis, "metis"},
      {DirectOrdering::automatic, "automatic"},
      {DirectOrdering::amd, "amd"},
      {DirectOrdering::pord, "pord"},
      {DirectOrdering::pt_scotch, "pt-scotch"}};
    return t;
  }

  inline const NameTable<Factorisation> &
  factorisation_names()
  {
    static const NameTable<Factorisation> t{{Factorisation::lu, "lu"},
                                            {Factorisation::ldlt, "ldlt"}};
    return t;
  }

  /// Linear solver/Factorisation precision: the arithmetic of the factors.
  enum class FactorPrecision
  {
    double_precision,
    single_precision
  };

  inline const NameTable<FactorPrecision> &
  factor_precision_names()
  {
    static const NameTable<FactorPrecision> t{
      {FactorPrecision::double_precision, "double"},
      {FactorPrecision::single_precision, "single"}};
    return t;
  }

  /// Linear solver/Phase-field preconditioner.
  enum class PhaseFieldPreconditioner
  {
    amg,
    direct
  };

  inline const NameTable<PhaseFieldPreconditioner> &
  phase_field_preconditioner_names()
  {
    static const NameTable<PhaseFieldPreconditioner> t{
      {PhaseFieldPreconditioner::amg, "amg"},
      {PhaseFieldPreconditioner::direct, "direct"}};
    return t;
  }

  /// Linear solver/AMG smoother; the names are those of ML's smoothers
  /// that TrilinosWrappers::PreconditionAMG takes.
  enum class AmgSmoother
  {
    chebyshev,
    symmetric_gauss_seidel
  };

  inline const NameTable<AmgSmoother> &
  amg_smoother_names()
  {
    static const NameTable<AmgSmoother> t{{AmgSmoother::chebyshev, "Chebyshev"},
                                          {AmgSmoother::symmetric_gauss_seidel,
                                           "symmetric Gauss-Seidel"}};
    return t;
  }

  /// Linear solver/Constrained rows: what the displacement AMG sees of the
  /// rows that hold constraints (DisplacementPreconditioner).
  enum class ConstrainedRows
  {
    keep,
    eliminate
  };

  inline const NameTable<ConstrainedRows> &
  constrained_rows_names()
  {
    static const NameTable<ConstrainedRows> t{{ConstrainedRows::keep, "keep"},
                                              {ConstrainedRows::eliminate,
                                               "eliminate"}};
    return t;
  }

  /// Linear solver/Rigid-body modes: the displacement AMG's near-null
  /// space.
  enum class RigidBodyModes
  {
    whole_mesh,
    per_body
  };

  inline const NameTable<RigidBodyModes> &
  rigid_body_modes_names()
  {
    static const NameTable<RigidBodyModes> t{
      {RigidBodyModes::whole_mesh, "whole mesh"},
      {RigidBodyModes::per_body, "per body"}};
    return t;
  }

  struct LinearSolverParameters
  {
    /// The defaults of a scene in @p dim dimensions.
    explicit LinearSolverParameters(unsigned int dim = 3)
        : direct_limit(default_direct_limit(dim))
    {
    }

    LinearSolverType type = LinearSolverType::automatic;
    /// Type = automatic: the most unknowns solved by the direct solver
    /// (see declare()).
    unsigned int   direct_limit;
    DirectSolver   direct_solver = DirectSolver::mumps;
    DirectOrdering ordering      = DirectOrdering::metis;
    Factorisation  factorisation = Factorisation::lu;
    /// Single-precision factors: as fast or faster in every shipped scene
    /// on the direct solver (sent_coarse -17 %, two_bodies -10 %; the same
    /// Newton iterations and answers, benchmarks/performance/results.md).
    FactorPrecision precision = FactorPrecision::single_precision;
    /// Direct solver = mumps: GMRES iterations preconditioned by the last
    /// factors before the matrix is factorised again (0: every solve;
    /// 60 measured best of 20, 40, 60, 100, benchmarks/linear_solver).
    unsigned int reuse_iterations      = 60;
    double       relative_tolerance    = 1.e-8;
    unsigned int max_iterations        = 2000;
    double       aggregation_threshold = 1.e-4;
    unsigned int smoother_sweeps       = 2;
    AmgSmoother  smoother              = AmgSmoother::chebyshev;
    /// Krylov vectors of the AMG solvers' GMRES before it restarts.
    unsigned int gmres_restart = 100;
    /// amg | direct: approximate inverse of the s-s block (coupled systems).
    PhaseFieldPreconditioner phase_field_preconditioner =
      PhaseFieldPreconditioner::amg;
    /// keep | eliminate: the contact rows in the displacement AMG.
    ConstrainedRows constrained_rows = ConstrainedRows::keep;
    /// whole mesh | per body: the displacement AMG's near-null space.
    RigidBodyModes rigid_body_modes = RigidBodyModes::whole_mesh;

    /// The type that solves a system of @p n_unknowns: @p type itself
    /// unless it is automatic.
    LinearSolverType
    resolved_type(dealii::types::global_dof_index n_unknowns) const;

    /// Direct solver limit's default in @p dim dimensions: the size above
    /// which the iterative solver is measured faster on this project's
    /// scenes, or the direct solver's factors outgrow a 24 GB node
    /// (benchmarks/iterative_solver).
    static unsigned int
    default_direct_limit(unsigned int dim);

    void
    declare(dealii::ParameterHandler &prm);
    void
    check() const;
  };
} // namespace DuctileContact
