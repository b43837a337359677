#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <ductile_contact/core/option.h>
#include <ductile_contact/core/types.h>
#include <ductile_contact/materials/material_defaults.h>
#include <ductile_contact/materials/material_response.h>

#include <optional>
#include <utility>

namespace DuctileContact
{
  /// Plasticity/Flow integration: how the flow of a step updates
  /// (C^p)^{-1} (doc/model.md section 3, step 2).
  enum class FlowIntegration
  {
    /// b^e = exp(-2 dt lambda_p n_tr) b_tr: the flow d^p = lambda_p n
    /// integrated exactly along the trial direction (the exponential map);
    /// the plastic work of the step is then sqrt(3/2) n : tau_dev dalpha.
    exponential,
    /// (37) of the paper, its first-order truncation: b^e = b_tr - 2/3 dt
    /// lambda_p tr[b_tr] n_tr; its flow differs from lambda_p n by the
    /// elastic strain, and so does its plastic work from int yhat dalpha.
    linear
  };

  inline const NameTable<FlowIntegration> &
  flow_integration_names()
  {
    static const NameTable<FlowIntegration> t{
      {FlowIntegration::exponential, "exponential map"},
      {FlowIntegration::linear, "linear"}};
    return t;
  }

  /// Plasticity/Loading condition: where a point flows and how alpha is
  /// kept from falling (doc/model.md sections 3.1 and 3.2).
  enum class LoadingCondition
  {
    /// The paper's (50): the yield test chi_p at each quadrature point;
    /// where it fails, alpha is held at alpha_n by a stiff penalty against
    /// the force r_n that held it there (plastic_update()).
    pointwise_switch,
    /// Every point follows the same Perzyna law, r = eta_p dalpha/dt +
    /// yhat(alpha) - sqrt(3/2) n : tau_dev, and alpha >= alpha_n is a bound
    /// on the alpha DoFs (FieldBound): the weak form of the variational
    /// inequality of rate-dependent gradient plasticity, whose elastic
    /// region is the bound's active set. Its local plastic dissipation
    /// is >= 0 up to the time rule's third-order term.
    bound
  };

  inline const NameTable<LoadingCondition> &
  loading_condition_names()
  {
    static const NameTable<LoadingCondition> t{
      {LoadingCondition::pointwise_switch, "pointwise switch"},
      {LoadingCondition::bound, "bound"}};
    return t;
  }

  /**
   * Material parameters of the finite-strain visco-plastic J2 model with
   * saturation hardening and crack degradation (doc/model.md sections 2-3).
   * Stresses and moduli in Pa, viscosity eta_p in Pa times pseudo time.
   */
  struct PlasticityParameters
  {
    double shear_modulus    = MaterialDefaults::shear_modulus;    ///< mu
    double bulk_modulus     = MaterialDefaults::bulk_modulus;     ///< kappa
    double initial_yield    = MaterialDefaults::initial_yield;    ///< y_0
    double saturation_yield = MaterialDefaults::saturation_yield; ///< y_inf
    /// eta in (21)
    double saturation_exponent = MaterialDefaults::saturation_exponent;
    double linear_hardening = MaterialDefaults::linear_hardening; ///< h in (21)
    double viscosity = MaterialDefaults::plastic_viscosity; ///< eta_p in (34)
    double degradation_a = MaterialDefaults::degradation_a; ///< a_g in g(s)
    /// k in g_k(s)
    double residual_stiffness = MaterialDefaults::residual_stiffness;
    /// delta of the smoothed switch of (17); 0: sharp (see plastic_update)
    double volumetric_switch_width = MaterialDefaults::volumetric_switch_width;
    /// How the flow updates (C^p)^{-1}.
    FlowIntegration flow_integration = FlowIntegration::exponential;
    /// Where a point flows and how alpha is kept from falling.
    LoadingCondition loading_condition = LoadingCondition::pointwise_switch;
    /// The hold of alpha at points that do not yield, c (alpha - alpha_n),
    /// has c = this factor times the yielding branch's slope (doc/model.md
    /// section 3.1, choice 3) [-].
    double hold_stiffness_factor = 1.;
    /// Whether the plastic energy is degraded by the phase field
    /// (plastic_energy_density(); the crack driver 'elastic and plastic
    /// energy').
    bool degrade_plastic_energy = false;
    /// w_c [J/m^3]: the part of W_p(alpha) above it is degraded.
    double critical_work_density = 0.;
  };

  /// Saturation hardening yhat(alpha), doc/model.md (21).
  double
  hardening_stress(const double alpha, const PlasticityParameters &p);

  /// Plastic work density W_p(alpha) = int_0^alpha yhat(a) da [J/m^3] of
  /// the saturation law (21): the local part of Psi^p in (20), and the
  /// work the flow does per unit volume in the rate-independent limit
  /// (tau : d^p = sqrt(2/3) |tau_dev| lambda_p = yhat alpha-dot on the yield
  /// surface).
  double
  plastic_work_density(const double alpha, const PlasticityParameters &p);

  /// The degradable part phi(W_p) of the plastic energy [J/m^3] and its
  /// slope phi'(W_p): W_p above the critical work density w_c =
  /// p.critical_work_density, with the bracket rounded over a width w_r =
  /// max(w_c/10, y_0/100) so that its slope is continuous (phi = (W_p -
  /// w_c)^2/(2 w_r) below w_c + w_r, W_p - w_c - w_r/2 beyond). The floor
  /// y_0/100, the work of 1 % plastic strain, keeps the softening of the
  /// flow resistance, (1 - g_k) yhat over w_r, from turning abrupt for
  /// small w_c (with w_r = w_c/10 alone a coarse paper scene with w_c =
  /// 0.05 MJ/m^3 stalled at the first yield).
  std::pair<double, double>
  degradable_plastic_energy(const double work, const PlasticityParameters &p);

  /**
   * Local part of the plastic stored energy [J/m^3] (doc/model.md (20) and
   * section 4.3): Psi^p_loc(alpha, s) = W_p(alpha), or, where the plastic
   * energy is degraded,
   *   Psi^p_loc = W_p(alpha) - (1 - g_k(s)) phi(W_p(alpha)),
   * so that the flow resistance dPsi^p_loc/dalpha = yhat (1 - (1 - g_k)
   * phi') falls with the phase field and -dPsi^p_loc/ds = -g_k'(s)
   * phi(W_p) is the plastic energy the crack releases.
   */
  double
  plastic_energy_density(const double                alpha,
                         const double                s,
                         const PlasticityParameters &p);



  /**
   * Degraded elastic energy Psi^e (16) of the state (F, (C^p)^{-1}, s):
   * b^e = F (C^p)^{-1} F^T, with the split (17).
   */
  double
  elastic_energy(const dealii::Tensor<2, material_dim>          &F,
                 const dealii::SymmetricTensor<2, material_dim> &Cp_inv,
                 const double                                    s,
                 const PlasticityParameters                     &p);

  /**
   * The work of a step's flow at the deformation @p G [J/m^3]: the
   * elastic energy the flow (C^p_n)^{-1} -> @p Cp_inv releases there,
   *   w(G) = Psi^e(G, (C^p_n)^{-1}, s) - Psi^e(G, (C^p)^{-1}, s).
   * At G = F, the step's end, the backward Euler work w_BE of the local
   * plastic dissipation (doc/model.md section 3.2).
   */
  double
  flow_work(const dealii::Tensor<2, material_dim>          &G,
            const PlasticHistory                           &history_n,
            const dealii::SymmetricTensor<2, material_dim> &Cp_inv,
            const double                                    s,
            const PlasticityParameters                     &p);

  /**
   * The plastic work of a step at a material point [J/m^3]: the elastic
   * energy the flow (C^p_n)^{-1} -> @p Cp_inv releases at fixed
   * deformation,
   *   w(G) = Psi^e(G, (C^p_n)^{-1}, s) - Psi^e(G, (C^p)^{-1}, s),
   * averaged over the deformations at which the flow starts and ends: F_n
   * and F (the trapezoidal rule; with the trapezoidal external work the
   * energy balance closes at second order in dt along a plastic path), or,
   * in the step in which the point starts to yield, F_theta = F_n +
   * theta (F - F_n) and F, where theta is the zero of the trial yield
   * function sqrt(3/2) |tau_dev,tr| - dPsi^p_loc/dalpha(alpha_n, .) + r_n
   * (at F_n with the phase field @p s_n of the step's start, at F with the
   * new @p s) interpolated linearly between F_n and F. The trapezoidal rule
   * over the whole step gives a point that yields only in the last part of its
   * first plastic step half of the work it does there, and a local
   * plastic dissipation w - Delta Psi^p below zero.
   */
  double
  plastic_work_of_step(const dealii::Tensor<2, material_dim> &F_n,
                       const dealii::Tensor<2, material_dim> &F,
                       const PlasticHistory                  &history_n,
                       const dealii::SymmetricTensor<2, material_dim> &Cp_inv,
                       const double                                    s_n,
                       const double                                    s,
                       const PlasticityParameters                     &p);

  /**
   * Material point update of doc/model.md section 3, steps 1-3, a pure
   * function: trial state b_tr = F (C^p_n)^{-1} F^T and yield switch chi_p
   * from the degraded trial stress; lambda_p = sqrt(3/2) (alpha -
   * alpha_n)/dt and, by the exponential map (FlowIntegration),
   *   (C^p)^{-1} = F^{-1} exp(-2 dt lambda_p n_tr) b_tr F^{-T},
   * or by the paper's (37),
   *   (C^p)^{-1} = (C^p_n)^{-1} - 2/3 dt lambda_p tr[b_tr] F^{-1} n_tr F^{-T},
   * rescaled to determinant 1 (plastic incompressibility to round-off);
   * finally tau = J dPsi^e/dJ I + mu g_dev(s) dev[bbar^e] with Psi^e of
   * (16)-(17): Psi^e = kappa/2 ((J - 1)^2 - (1 - g(s)) q(J - 1)) + g(s)
   * mu/2 (tr bbar^e - 3), where q(t) = t^2 for t > 0 and 0 below (the
   * sharp switch of (17): the volumetric part degrades in tension only),
   * or, with volumetric_switch_width delta > 0, a smooth convex q with
   * q'' = 2w, w the C2 step 6x^5 - 15x^4 + 10x^3 of x = (t + delta)/(2
   * delta) in [0, 1]: the tangent does not jump at J = 1, the energy stays
   * convex in J at every damage, and beyond |J - 1| >= delta the stress is
   * the sharp one (the energy differs by the constant kappa/14 delta^2
   * (1 - g) in tension); psi^+ = kappa/2 q(J - 1) + mu/2 (tr bbar^e - 3).
   * r is the local part of (50): eta_p (alpha - alpha_n)/dt + y(alpha, s) -
   * sqrt(3/2) n_tr : tau_dev where chi_p = 1, y = dPsi^p_loc/dalpha the
   * flow resistance (yhat(alpha) unless the plastic energy is degraded,
   * plastic_energy_density()), with n_tr = dev tau_tr /
   * |dev tau_tr|. The flow keeps tau_dev parallel to n_tr, so n_tr : tau_dev
   * is |tau_dev| as long as the flow does not overshoot; unlike |tau_dev| it
   * falls monotonically with alpha, so r has one root (with |tau_dev|
   * there is a second, spurious root at which tau_dev is reversed).
   *
   * Our choices where (50) and section 3 leave the discretisation open
   * (found on the necking bar, whose Newton iteration cycled or stalled at
   * the onset of the neck otherwise; doc/model.md section 3.1):
   *  - the flow formula is applied at every point with the alpha it is
   *    given, not only where chi_p = 1, and lambda_p is not clamped at
   *    alpha < alpha_n: tau is a smooth function of (F, alpha);
   *  - where chi_p = 0 the flow direction is tau_tr / sqrt(|tau_tr|^2 +
   *    eps^2), eps = 0.1 y_0, instead of n_tr: such points flow only as far
   *    as the gradient term pulls alpha away from alpha_n, and at points
   *    whose deviatoric trial stress passes near zero (common next to a
   *    crack, where the material unloads) n_tr turns with a derivative
   *    ~1/|tau_tr|; Newton's steps then met a curvature of the residual
   *    that no line search could follow (a coarse copy of the ductile
   *    notch stalled at its force peak with the time step cut to 1e-6;
   *    benchmarks/plasticity/ductile_notch). Near the yield surface,
   *    where chi_p switches, |tau_tr| ~ 0.8 y_0 and the direction differs
   *    from n_tr by under 1 %;
   *  - where chi_p = 0 the local part is eta_p (alpha - alpha_n)/dt + c
   *    (alpha - alpha_n) + r_n with c = f (mu g_dev tr[bbar_tr] +
   *    yhat'(alpha_n)), f the hold_stiffness_factor times about the slope
   *    the yielding branch has there (~3 mu + h; the undegraded hardening
   *    slope), and r_n the local part at the last accepted state
   *    (PlasticHistory::r): the continuum equation (alpha = alpha_n, no
   *    flow) is the same, but alpha is held at alpha_n as firmly as the
   *    yielding points hold theirs, and the force r_n with which the rest
   *    of the field (the gradient term, the Q2 interpolation shared by a
   *    cell's points) held it there stays balanced: an accepted state is
   *    a fixed point of the next step. Without r_n the hold relaxed to
   *    zero in every step and the pull moved alpha, and the flow with it,
   *    once more per step: the paper scene's force fell by 2 % per
   *    halving of the load step without converging;
   *  - chi_p = [sqrt(3/2) |tau_dev,tr| - yhat(alpha_n) + r_n > 0]: the
   *    switch at which both branches of r agree at alpha_n, so r is
   *    continuous to first order in alpha - alpha_n where chi_p switches.
   *    With r_n the pull of the gradient term, this is the gradient
   *    model's yield condition (a point pulled by yielding neighbours
   *    yields earlier);
   *  - the gradient term y_0 l_p^2 grad(alpha) . grad(delta alpha) acts
   *    everywhere (SystemAssembler), not only where chi_p = 1: with c, an
   *    elastic region holds alpha - alpha_n to a layer of width l_p
   *    sqrt(y_0 / c) (~0.04 l_p for steel) at its border.
   * At a converged state the yielding points have alpha >= alpha_n except
   * where the gradient term pulls alpha down (statistics
   * min_alpha_change_yielding).
   *
   * With LoadingCondition::bound none of the last four choices applies:
   * every point has the yielding branch's r, with the flow direction
   * tau_tr / sqrt(|tau_tr|^2 + eps^2) whose floor eps fades smoothly with
   * |tau_tr| (direction_floor_squared() in the source), and chi_p is a
   * label for the statistics only. alpha >= alpha_n is the bound on the
   * alpha DoFs that FieldBound enforces, and r_n is not used. Where r > 0
   * (below yield) a free DoF's row is balanced by its neighbours through
   * the gradient term; the local plastic dissipation of a step, w -
   * Delta Psi^p_loc + r Delta alpha (doc/model.md section 3.2), is then
   * eta_p Delta alpha^2/dt plus the return map's relaxation, >= 0.
   *
   * The tangents with respect to F, alpha and s are exact: forward-mode
   * automatic differentiation (Sacado SFad with 11 directions) of the same
   * code (the yield switch chi_p is fixed at its value, as in Newton's
   * method). @p frozen_yielding, if given, replaces the trial-state test
   * for chi_p (the Newton line search keeps the switch of the iterate it
   * starts from, so that the residual is smooth along the line).
   */
  MaterialResponse
  plastic_update(const dealii::Tensor<2, material_dim> &F,
                 const PlasticHistory                  &history_n,
                 const double                           alpha,
                 const double                           s,
                 const double                           dt,
                 const PlasticityParameters            &parameters,
                 const bool                             with_tangent,
                 const std::optional<bool>             &frozen_yielding = {});
} // namespace DuctileContact
