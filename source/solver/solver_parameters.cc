#include <deal.II/base/utilities.h>

#include <ductile_contact/core/input_error.h>
#include <ductile_contact/solver/solver_parameters.h>

namespace DuctileContact
{
  using namespace dealii;

  void
  LoadSteppingParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Load stepping");
    prm.add_parameter("End time",
                      end_time,
                      "Final value of the load-step time t [-]; boundary "
                      "data are functions of t.",
                      Patterns::Double(0.));
    prm.add_parameter("Time step",
                      time_step,
                      "Nominal (and largest) load-step increment of t "
                      "[-].",
                      Patterns::Double(0.));
    prm.add_parameter("Minimum time step",
                      minimum_time_step,
                      "The run gives up when a failing step would need a "
                      "smaller increment than this [-].",
                      Patterns::Double(0.));
    prm.add_parameter("Growth factor",
                      growth_factor,
                      "After an easy step (see below), the increment grows by "
                      "this factor, up to the nominal time step [-].",
                      Patterns::Double(1.));
    prm.add_parameter("Easy step Newton iterations",
                      easy_newton_steps,
                      "A step that converged in at most this many Newton "
                      "iterations counts as easy.",
                      Patterns::Integer(1));
    prm.add_parameter(
      "Growth after accepted steps",
      steps_before_growth,
      "The increment also grows (by the growth factor) after this many "
      "steps in a row were accepted at it, however many Newton iterations "
      "they took: a phase where every step needs more than the easy count "
      "(a running crack, a cut-back deep into a hard stretch) would "
      "otherwise keep the small increment to the end. A step that then "
      "fails is cut back as usual. 0: only easy steps grow the increment.",
      Patterns::Integer(0));
    prm.add_parameter(
      "Maximum failures without progress",
      max_stalled_failures,
      "The run gives up (exit code 2) after this many failed steps while t "
      "advanced by less than 1e-3 of the Time step since the first of them: "
      "a state from which no increment above a tiny one converges (elements "
      "about to invert, a limit point) would otherwise alternate failed "
      "steps with accepted tiny ones for ever, each above the Minimum time "
      "step. Counted over the whole run, not per step. 0: never.",
      Patterns::Integer(0));
    prm.add_parameter(
      "Maximum phase-field increment",
      max_phase_field_increment,
      "A converged step in which s rose by more than this at some DoF is cut "
      "back like a failed one [-]: the crack's path and the energy balance "
      "are first order in the step, and a crack that runs through a few "
      "elements in one step leaves an error of the size of that step in "
      "both. With a crack viscosity the rise shrinks with the step; the "
      "limit is not applied below 1e-3 of the Time step. 1: no limit.",
      Patterns::Double(0., 1.));
    add_option(
      prm,
      "Predictor",
      predictor,
      predictor_names(),
      "First guess of every unknown (u, alpha, s) at the start of a step. "
      "'constant': the last converged state (Newton's first iteration then "
      "applies the new boundary data with the tangent of that state; in a "
      "plastic body this is an elastic predictor whose stresses may "
      "overshoot the yield stress by a whole step's strain). 'linear': the "
      "last converged state plus the last step's increment scaled by the "
      "ratio of the step sizes (from the second step on; for monotonic "
      "loading the first residual is then of second order in the step, and "
      "the notched and necking scenes of prm/ use it). Not for load paths "
      "with a kink or long frictional sliding: prm/ironing.prm, pressed "
      "and then dragged, needs 14-17 iterations per sliding step with it "
      "and stalls. 'linear displacements': u extrapolated so, alpha and s "
      "kept at their last values (internal fields that grow one way only "
      "and may stop or jump, as s does when a crack runs). 'best linear': "
      "of these two first guesses the one with the smaller residual (the "
      "merit of Newton's line search; two residual assemblies more per "
      "step), so that a step where the internal fields' last increment "
      "misleads starts without it.");
    add_option(
      prm,
      "Time integration",
      time_integration,
      time_integration_names(),
      "'quasi-static': no inertia; t is a load parameter. 'Bossak': "
      "implicit dynamics, t in seconds, the inertia of the bodies with a "
      "Density > 0 in the momentum balance, integrated by the Bossak-alpha "
      "scheme (Wood, Bossak & Zienkiewicz 1980; Newmark's update with the "
      "inertia at (1 - a_B) a_n+1 + a_B a_n), second-order accurate; alpha "
      "and s keep their first-order (viscous) evolution "
      "(doc/model.md section 6.5).");
    prm.add_parameter(
      "High-frequency spectral radius",
      spectral_radius,
      "rho_inf of the Bossak scheme [-]: the amplification of the modes "
      "that the step does not resolve (omega dt -> infinity). 1: no "
      "numerical dissipation, the trapezoidal rule (Newmark beta = 1/4, "
      "gamma = 1/2); smaller values damp those modes (0: in one step), at "
      "the cost of a dissipation of second order in dt for the resolved "
      "ones (statistics column numerical_dissipation). a_B = (rho_inf - "
      "1)/(rho_inf + 1), gamma = 1/2 - a_B, beta = (1 - a_B)^2/4.",
      Patterns::Double(0., 1.));
    prm.add_parameter(
      "Local error tolerance",
      local_error_tolerance,
      "Dynamic runs: the step size follows the local error estimate of "
      "Zienkiewicz & Xie (1991), e = (beta - 1/6) dt^2 (a_n+1 - a_n) per "
      "DoF, measured as the largest |e| over the largest displacement "
      "increment of the step, both over the DoFs that carry mass and are not "
      "prescribed (statistics column local_error) [-]. A converged step "
      "whose estimate exceeds this is cut back to 0.9 (tolerance/estimate)^"
      "(1/3) of its size (at least by half, at most to a fifth), and the next "
      "increment is at most that factor times the last one (and never above "
      "Time step): the steps shrink where the accelerations change fast, "
      "at an impact and a release, and grow back in free motion. Steps "
      "within twice the Minimum time step are accepted whatever their "
      "estimate. 0: no control (the step is cut back only when Newton "
      "fails).",
      Patterns::Double(0.));
    add_option(
      prm,
      "Contact surface mass",
      contact_surface_mass,
      contact_surface_mass_names(),
      "Dynamic runs with contact pairs: 'redistributed' takes the mass off "
      "the nodes of the contact surfaces (slave and master) and gives it to "
      "the next layer of nodes of the same cells, keeping each cell's mass "
      "and centre of mass (the singular mass of Khenous, Laborde & Renard "
      "2008): the contact constraints then act on nodes without inertia, "
      "and implicit contact neither chatters nor creates energy. "
      "'consistent': the consistent mass everywhere, with which an elastic "
      "impact gains energy at every contact and release "
      "(doc/model.md section 6.5).");
    prm.leave_subsection();
  }



  void
  LoadSteppingParameters::check() const
  {
    check_input(end_time > 0.,
                "Load stepping/End time",
                Utilities::to_string(end_time),
                "it must be positive");
    check_input(time_step > 0.,
                "Load stepping/Time step",
                Utilities::to_string(time_step),
                "it must be positive");
    check_input(max_phase_field_increment > 0.,
                "Load stepping/Maximum phase-field increment",
                Utilities::to_string(max_phase_field_increment),
                "it must be positive (1: no limit)");
    check_input(local_error_tolerance == 0. ||
                  time_integration != TimeIntegration::quasi_static,
                "Load stepping/Local error tolerance",
                Utilities::to_string(local_error_tolerance),
                "it needs Time integration = Bossak, and this run is "
                "quasi-static (0: no local error control)");
    check_input(minimum_time_step > 0. && minimum_time_step <= time_step,
                "Load stepping/Minimum time step",
                Utilities::to_string(minimum_time_step),
                "it must be positive and not larger than Time step (" +
                  Utilities::to_string(time_step) + ")");
  }



  void
  NewtonParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    prm.add_parameter("Maximum iterations",
                      max_iterations,
                      "Newton iterations per load step before the step is "
                      "cut back.",
                      Patterns::Integer(1, 200));
    prm.add_parameter(
      "Relative tolerance",
      relative_tolerance,
      "Converged when the residual norm on free DoFs is below this times "
      "the norm of the internal force vector (which includes reactions) "
      "[-].",
      Patterns::Double(0., 1.));
    prm.add_parameter(
      "Absolute tolerance",
      absolute_tolerance,
      "Also converged when the residual norm is below this times mu_max * "
      "diameter^2 (largest shear modulus times squared domain diameter, a "
      "force scale) [-]; guards unloaded steps.",
      Patterns::Double(0., 1.));
    prm.add_parameter("Line search",
                      line_search,
                      "Backtracking line search on the residual norm; a step "
                      "that inverts an element (J <= 0) is always shortened.");
    prm.add_parameter("Maximum line search steps",
                      max_line_search_steps,
                      "Halvings of the Newton update before the step counts "
                      "as failed.",
                      Patterns::Integer(0, 30));
    prm.add_parameter(
      "Line search memory",
      line_search_memory,
      "The line search accepts an update once the residual, in units of its "
      "tolerances, falls below (1 - 1e-4 l) times the largest at the start "
      "of the last this-many Newton iterations of the load step (l the step "
      "length; a non-monotone line search, Grippo, Lampariello and Lucidi "
      "1986); 1: below the current one. While a crack runs, a full Newton "
      "update often raises the residual for an iteration on the way to the "
      "solution, and backtracking to a strict decrease crawls and fails: "
      "prm/sent_coarse.prm sets 5 (benchmarks/performance/results.md). It "
      "changes the iterates, and so where a step fails and is cut back: "
      "after a crack has run, the state of a rate-dependent scene can "
      "differ by more than its tolerances (with 5, tests/ductile_notch's "
      "adaptive and graded runs end 2.4 % apart in plastic work, 0.2 % with "
      "1).",
      Patterns::Integer(1, 20));
    prm.add_parameter(
      "Check tangent",
      check_tangent,
      "For developers of materials and contact terms: compare the tangent "
      "with central finite differences of the residual along every Newton "
      "update d, |K d - dR/de| / |K d| on the free DoFs, printed with "
      "Verbosity = 2; the value of the last update of each step, the one "
      "nearest the solution, goes to the statistics column tangent_error. "
      "The quotients of second and fourth order are taken with steps e d of "
      "1e-6, 1e-5, ... of |x| until the residual's round-off (eps times the "
      "terms summed into it) is below 1e-5 of e |K d|, at most 1e-3 of |x| "
      "(up to 16 extra residual assemblies per iteration), and the smallest "
      "error counts: near convergence |K d| is many orders below those terms, "
      "so a short step measures round-off, a long one meets the residual's "
      "curvature and kinks. Expect 1e-5 or less except where the residual has "
      "a kink within every step (a node just touching, flush edges). The "
      "screen shows the ratio per block (u, alpha, s) as well: the alpha and "
      "s rows are small next to those of u, so their errors hide in the "
      "global ratio, and their own round-off can reach 1e-4.");
    add_option(
      prm,
      "Tangent update",
      tangent_update,
      tangent_update_names(),
      "'every iteration': Newton's method, the tangent assembled at every "
      "iterate. 'chord after a quadratic step': after a full Newton update "
      "(step length 1, boundary data reached by it) that brought the residual, "
      "in "
      "units of its tolerances, down by 100 or more, the next iteration keeps "
      "the matrix of the linear system (and so the factors of the direct "
      "solver) and assembles the residual only, with the branches of the new "
      "iterate (a chord step); chord steps go on while each brings the "
      "residual down by 10 or more, else (and where a chord step's line search "
      "finds no admissible step) a full iteration follows. "
      "The converged state is the same (Newton's tolerances decide), the "
      "iteration is cheaper where the second iteration of a step only "
      "corrects small changes: in prm/block_on_plate.prm the crack driver's "
      "loading points that switch on during the first update "
      "(benchmarks/performance). Not while the phase-field bound s >= s_n "
      "holds DoFs (its rows follow the iterate); with the bound alpha >= "
      "alpha_n (Plasticity/Loading condition = bound) while its active set "
      "stays the one the kept tangent holds.");
    add_option(
      prm,
      "Linear solve accuracy",
      linear_accuracy,
      linear_accuracy_names(),
      "When the iterative linear solves of a Newton iteration stop (GMRES on "
      "the direct solver's factors, GMRES or CG with AMG). 'relative "
      "tolerance': when the residual norm of the linear system is below "
      "Linear solver/Relative tolerance times that of its right-hand side. "
      "'newton tolerances': in Newton's fast phase (the first iteration of a "
      "solve, and after a full update that cut the residual in units of the "
      "tolerances 10-fold), while the problem's rows do not follow the "
      "iterate (not while the phase-field bound holds DoFs, nor while the "
      "alpha bound's active set changes), also as soon as "
      "the linear residual r is far below "
      "Newton's tolerances, sqrt(sum_b (|r_b| / tol_b)^2) <= 0.1 over the "
      "blocks b = u, alpha, s (GMRES on factors measures its residual in that "
      "norm; the AMG solvers, which see the plain norm, stop at 0.1 min_b "
      "tol_b): the update's own error then adds at most a tenth of the "
      "tolerance to the next residual. After a damped or slow update, and "
      "with the bound's active set, the solves go to the relative tolerance: "
      "prm/sent_coarse.prm stalled in its crack phase when they stopped early "
      "there too. Saves the GMRES iterations of late "
      "Newton iterations and chord steps, whose right-hand side is already "
      "near the tolerances (benchmarks/performance); the converged state "
      "meets the same tolerances. Solves with exact factors are not changed. "
      "The observed order of convergence (statistics column newton_rate) "
      "then measures the linear solves' stop as well.");
    prm.leave_subsection();
  }



  void
  NewtonParameters::check() const
  {
    check_input(relative_tolerance > 0. || absolute_tolerance > 0.,
                "Newton/Relative tolerance",
                "0",
                "at least one of Relative tolerance and Absolute tolerance "
                "must be positive");
  }



  void
  LinearSolverParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    add_option(
      prm,
      "Type",
      type,
      linear_solver_type_names(),
      "automatic: direct up to Direct solver limit unknowns, gmres-amg "
      "above (decided at every solve, so a mesh that grows past the limit "
      "switches). direct: sparse factorisation (see Direct solver) of the "
      "whole system; cg-amg: CG preconditioned by Trilinos ML AMG with the six "
      "rigid-body modes; gmres-amg: GMRES with the same AMG (for "
      "non-symmetric tangents). With alpha or s unknowns the coupled tangent "
      "is not symmetric: cg-amg and gmres-amg then both run GMRES with a "
      "block lower-triangular (block Gauss-Seidel) preconditioner: this AMG "
      "on u, a scalar AMG on alpha, and on s the Phase-field preconditioner.");
    prm.add_parameter(
      "Direct solver limit",
      direct_limit,
      "Type = automatic: the largest number of unknowns (all fields, all "
      "ranks) solved by the direct solver; above it gmres-amg. The default "
      "depends on the dimension, from runs on 2 ranks of a 24 GB node "
      "(benchmarks/iterative_solver): 3-D 500000 (the direct solver was "
      "the faster one up to 444k unknowns, and at 1.03M its factors did "
      "not fit into the node); plane strain 1000000 (the direct solver "
      "was faster than the default gmres-amg at every size up to 520k, and "
      "its 8.9 kB per unknown fit into the node to about 2M; an elastic "
      "contact scene with Rigid-body modes = per body solves faster "
      "iteratively from about 260k). Elsewhere, measure.",
      Patterns::Integer(0));
    add_option(prm,
               "Direct solver",
               direct_solver,
               direct_solver_names(),
               "Type = direct: mumps: MUMPS analysed once per sparsity "
               "pattern and refactorised per Newton iteration (see Ordering "
               "and Factorisation); Amesos_Mumps: MUMPS through Trilinos "
               "Amesos, analysed again on every solve; Amesos_Klu: KLU through "
               "Amesos (one "
               "rank factorises).");
    add_option(prm,
               "Ordering",
               ordering,
               direct_ordering_names(),
               "Direct solver = mumps: fill-reducing ordering. metis: "
               "METIS nested dissection of the pattern, handed to MUMPS as "
               "its pivot order (rank 0 gathers the pattern, orders it, and "
               "MUMPS analyses it there); pt-scotch: PT-Scotch nested "
               "dissection in MUMPS's parallel analysis, on all ranks (no "
               "rank gathers the pattern; on one rank Scotch, sequential); "
               "automatic: MUMPS's choice for a sequential analysis among "
               "those it was built with (Debian: AMD, AMF, QAMD, PORD, "
               "Scotch); amd, pord: that one.");
    add_option(prm,
               "Factorisation",
               factorisation,
               factorisation_names(),
               "Direct solver = mumps: lu (any tangent) or ldlt (the upper "
               "triangle only: about half the time and memory, exact only "
               "for a symmetric tangent; with an unsymmetric one Newton "
               "converges more slowly).");
    add_option(prm,
               "Factorisation precision",
               precision,
               factor_precision_names(),
               "Direct solver = mumps: single-precision factors (half the "
               "memory traffic and about half the factorisation time of "
               "double ones) are used through GMRES to Relative tolerance "
               "like reused ones, so the answer is the same; a matrix they "
               "cannot precondition (condition number near 1e7 and above) "
               "is factorised again in double. double: exact solves with "
               "the factors of the current matrix.");
    prm.add_parameter(
      "Factorisation reuse",
      reuse_iterations,
      "Direct solver = mumps: a solve first tries GMRES preconditioned by "
      "the factors of an earlier matrix of the same pattern, to Relative "
      "tolerance; the matrix is factorised again when that fails within "
      "the iterations left (GMRES gives up as soon as the rate of its last "
      "5 iterations says it would need more than twice those), or once the "
      "factors have served this many "
      "GMRES iterations in all; it is factorised at once when fewer "
      "iterations are left than the last solve on these factors needed. When "
      "the factors of the previous matrix fail, the next 1, 2, 4, ... solves "
      "factorise directly. 0: factorise on every solve. The answer is the "
      "same "
      "(to Relative tolerance in each linear solve); 2-5x faster linear "
      "solves measured (benchmarks/linear_solver).",
      Patterns::Integer(0, 100));
    prm.add_parameter("Relative tolerance",
                      relative_tolerance,
                      "Iterative solvers stop when the residual is below "
                      "this times the right-hand side norm [-].",
                      Patterns::Double(0., 1.));
    prm.add_parameter("Maximum iterations",
                      max_iterations,
                      "Iteration limit of the iterative solvers.",
                      Patterns::Integer(1));
    prm.add_parameter("AMG aggregation threshold",
                      aggregation_threshold,
                      "ML aggregation threshold of the AMG on u and alpha "
                      "(1e-4 is best measured for Q2 elasticity, see docs); "
                      "the AMG on s uses 0.02, best measured for its C0IP "
                      "block [-].",
                      Patterns::Double(0., 1.));
    prm.add_parameter("AMG smoother sweeps",
                      smoother_sweeps,
                      "Smoother sweeps per AMG level (Chebyshev: its "
                      "polynomial degree).",
                      Patterns::Integer(1, 10));
    add_option(
      prm,
      "AMG smoother",
      smoother,
      amg_smoother_names(),
      "Smoother of every AMG level (u, alpha and s). Chebyshev: a "
      "polynomial in the diagonally scaled matrix, the same on any number "
      "of ranks. symmetric Gauss-Seidel: a forward and a backward sweep, "
      "within each rank's rows (across ranks it is Jacobi-like, so its "
      "iterations grow with the ranks). On one rank and with contact "
      "rows it needs a quarter to a half fewer Krylov iterations than "
      "Chebyshev, each 2-3x dearer: faster only where Chebyshev breaks "
      "down (contact on curved surfaces; benchmarks/iterative_solver).");
    prm.add_parameter("GMRES restart",
                      gmres_restart,
                      "Krylov vectors the GMRES of the AMG solvers keeps "
                      "before it restarts (memory: this many vectors of the "
                      "system's size per rank).",
                      Patterns::Integer(10, 2000));
    add_option(
      prm,
      "Phase-field preconditioner",
      phase_field_preconditioner,
      phase_field_preconditioner_names(),
      "Iterative types with s unknowns: how the s-s diagonal block is "
      "inverted inside the block preconditioner. amg: one ML AMG V-cycle "
      "whose near-null space is the constant and the coordinates (the "
      "linear functions cost the C0IP operator's fourth-order part "
      "nothing); its iterations still grow with l_f/h; direct: a sparse LU of "
      "that block "
      "with the Direct solver package, factorised once per linear solve.");
    add_option(
      prm,
      "Constrained rows",
      constrained_rows,
      constrained_rows_names(),
      "Iterative types: what the displacement block's AMG sees of the rows "
      "of active contact nodes (semi-smooth Newton), which hold the "
      "complementarity function and no bulk stiffness of the node. keep: "
      "the AMG coarsens the block as assembled. eliminate: the constrained "
      "components (normal; tangential where a node sticks) are taken out "
      "in each node's frame, and the AMG sees the Schur complement, the "
      "stiffness of the bodies tied through the mortar projection; the "
      "answer is the same.");
    add_option(
      prm,
      "Rigid-body modes",
      rigid_body_modes,
      rigid_body_modes_names(),
      "Iterative types: the near-null space of the displacement block's "
      "AMG. whole mesh: the dim translations and dim(dim-1)/2 rotations of "
      "the whole mesh. per body: a set of them for each body, zero off it, "
      "so that coarse levels can also move bodies that touch through "
      "contact rigidly against each other. Measured "
      "(benchmarks/iterative_solver): per body keeps the Krylov iterations "
      "of the plane-strain block on a clamped strip flat under refinement "
      "(40 per solve at 131k unknowns against 326); in the 3-D two bodies "
      "refined once it needs about a third fewer in most solves but 1789 in "
      "the first.");
    prm.leave_subsection();
  }



  void
  LinearSolverParameters::check() const
  {
    check_input(type == LinearSolverType::direct || relative_tolerance > 0.,
                "Linear solver/Relative tolerance",
                Utilities::to_string(relative_tolerance),
                "an iterative solver needs a positive tolerance");
  }



  LinearSolverType
  LinearSolverParameters::resolved_type(
    const types::global_dof_index n_unknowns) const
  {
    if (type != LinearSolverType::automatic)
      return type;
    return n_unknowns <= direct_limit ? LinearSolverType::direct
                                      : LinearSolverType::gmres_amg;
  }



  unsigned int
  LinearSolverParameters::default_direct_limit(const unsigned int dim)
  {
    return dim == 2 ? 1000000 : 500000;
  }
} // namespace DuctileContact
