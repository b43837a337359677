#include <deal.II/differentiation/ad.h>

#include <ductile_contact/core/ad_value.h>
#include <ductile_contact/core/sacado_sfad.h>
#include <ductile_contact/materials/degradation.h>
#include <ductile_contact/materials/plasticity.h>

#include <algorithm>
#include <utility>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    // Derivatives with respect to F (9), alpha and s on the stack
    // (core/sacado_sfad.h makes deal.II's tensors accept SFad).
    using ADNumber = Sacado::Fad::SFad<double, 11>;

    /// eps / y_0 of the flow direction at points that do not yield (see
    /// plastic_update()).
    constexpr double elastic_direction_floor = 0.1;

    /// Stress scale / y_0 over which the floor of the bound's flow
    /// direction fades (see direction_floor_squared()).
    constexpr double direction_floor_fade = 0.25;

    /// eps^2 of the flow direction tau_tr / sqrt(|tau_tr|^2 + eps^2).
    /// pointwise switch: eps = 0.1 y_0 where chi_p = 0, 0 where it is 1
    /// (see plastic_update()). bound: no switch, so the floor fades
    /// smoothly with the trial stress, eps^2 = (0.1 y_0)^2 exp(-2
    /// (|tau_tr| / (0.25 y_0))^2): 0.1 y_0 where the deviator vanishes
    /// (a crack's unloading flank, where the unit direction turns at a rate
    /// 1/|tau_tr|), 2.3e-6 y_0 at the yield surface |tau_tr| = sqrt(2/3)
    /// y_0, so that the yielding points flow along n_tr to 1e-11.
    template <typename Number>
    Number
    direction_floor_squared(const Number               &norm_tr,
                            const bool                  yielding,
                            const PlasticityParameters &p)
    {
      const double floor = elastic_direction_floor * p.initial_yield;
      if (p.loading_condition == LoadingCondition::bound)
        {
          const Number x = norm_tr / (direction_floor_fade * p.initial_yield);
          return floor * floor * std::exp(-2. * x * x);
        }
      return Number(yielding ? 0. : floor * floor);
    }

    template <typename Number>
    Number
    degradation_of(const Number &s, const PlasticityParameters &p)
    {
      return degradation_value(s,
                               DegradationParameters{p.degradation_a,
                                                     p.residual_stiffness});
    }

    template <typename Number>
    Number
    hardening_of(const Number &alpha, const PlasticityParameters &p)
    {
      return p.initial_yield +
             (p.saturation_yield - p.initial_yield) *
               (1. - std::exp(-p.saturation_exponent * alpha)) +
             p.linear_hardening * alpha;
    }

    /// W_p(alpha) = int_0^alpha yhat(a) da of (21).
    template <typename Number>
    Number
    plastic_work_of(const Number &alpha, const PlasticityParameters &p)
    {
      const double eta = p.saturation_exponent;
      const Number saturation =
        eta > 0. ? Number(alpha - (1. - std::exp(-eta * alpha)) / eta)
                 : Number(0.);
      return p.initial_yield * alpha +
             (p.saturation_yield - p.initial_yield) * saturation +
             0.5 * p.linear_hardening * alpha * alpha;
    }

    /// Width w_r of the rounded bracket phi: w_c/10, at least the work
    /// y_0/100 of 1 % plastic strain at the initial yield stress.
    double
    rounding_width(const PlasticityParameters &p)
    {
      return std::max(0.1 * p.critical_work_density, 0.01 * p.initial_yield);
    }

    /// phi(W) and phi'(W) of degradable_plastic_energy().
    template <typename Number>
    std::pair<Number, Number>
    degradable_part(const Number &work, const PlasticityParameters &p)
    {
      using Pair         = std::pair<Number, Number>;
      const double w_c   = p.critical_work_density;
      const double width = rounding_width(p);
      const Number x     = work - w_c;
      if (value_of(x) <= 0.)
        return Pair(Number(0.), Number(0.));
      if (value_of(x) >= width)
        return Pair(Number(x - 0.5 * width), Number(1.));
      return Pair(Number(x * x / (2. * width)), Number(x / width));
    }

    /// The flow resistance dPsi^p_loc/dalpha: yhat(alpha), times (1 - (1 -
    /// g_k(s)) phi'(W_p)) where the plastic energy is degraded.
    template <typename Number>
    Number
    flow_resistance_of(const Number               &alpha,
                       const Number               &s,
                       const PlasticityParameters &p)
    {
      const Number y = hardening_of(alpha, p);
      if (!p.degrade_plastic_energy)
        return y;
      const Number slope = degradable_part(plastic_work_of(alpha, p), p).second;
      return y * (1. - (1. - degradation_of(s, p)) * slope);
    }

    /// Psi^p_loc(alpha, s) of plastic_energy_density().
    template <typename Number>
    Number
    plastic_energy_of(const Number               &alpha,
                      const Number               &s,
                      const PlasticityParameters &p)
    {
      const Number work = plastic_work_of(alpha, p);
      if (!p.degrade_plastic_energy)
        return work;
      return work -
             (1. - degradation_of(s, p)) * degradable_part(work, p).first;
    }

    /// |alpha - alpha_n| below which step_flow_resistance() takes the
    /// derivative at the midpoint instead of the difference quotient (whose
    /// cancellation error would grow as 1e-16 alpha / |alpha - alpha_n|).
    constexpr double discrete_gradient_floor = 1e-6;

    /**
     * The flow resistance of a step from alpha_n to alpha in the local
     * equation r: dPsi^p_loc/dalpha at alpha (backward Euler), or with
     * LoadingCondition::bound and a degraded plastic energy the discrete
     * gradient (Psi^p_loc(alpha, s) - Psi^p_loc(alpha_n, s)) / (alpha -
     * alpha_n) (the derivative at the midpoint when |alpha - alpha_n| <
     * 1e-6: the two differ there by the third derivative times
     * dalpha^2/24). Psi^p_loc is convex in alpha unless the plastic energy
     * is degraded, where the rounded bracket phi makes it soften: the
     * backward Euler step then stores more than its flow resistance times
     * dalpha, a negative local dissipation of the order of the second
     * derivative times dalpha^2; the discrete gradient stores exactly the
     * work of the flow resistance (doc/model.md section 3.2).
     */
    template <typename Number>
    Number
    step_flow_resistance(const Number               &alpha,
                         const double                alpha_n,
                         const Number               &s,
                         const PlasticityParameters &p)
    {
      if (p.loading_condition != LoadingCondition::bound ||
          !p.degrade_plastic_energy)
        return flow_resistance_of(alpha, s, p);
      const Number step = alpha - alpha_n;
      if (std::abs(value_of(step)) < discrete_gradient_floor)
        return flow_resistance_of(Number(0.5 * (alpha + alpha_n)), s, p);
      return (plastic_energy_of(alpha, s, p) -
              plastic_energy_of(Number(alpha_n), s, p)) /
             step;
    }

    /**
     * Tension part q(t) of the volumetric energy, t = J - 1, and q'(t):
     * psi_vol^+ = kappa/2 q(t), psi_vol^- = kappa/2 (t^2 - q(t)), so that
     * g psi_vol^+ + psi_vol^- = kappa/2 (t^2 - (1 - g) q(t)). Sharp (delta
     * = 0): q = t^2 for t > 0, else 0 (doc/model.md (17)). Blended: q'' = 2 w
     * with the C2 step w(x) = 6x^5 - 15x^4 + 10x^3, x = (t + delta)/(2
     * delta) in [0, 1]; integrated twice from q(-delta) = q'(-delta) = 0:
     *   q  = 8 delta^2 x^5 (x^2/7 - x/2 + 1/2),
     *   q' = 4 delta x^4 (x^2 - 3x + 5/2),
     * and q = t^2 + delta^2/7, q' = 2t for t >= delta (w is symmetric about
     * t = 0, so the stress beyond the blend is exactly the sharp one).
     * Both q and t^2 - q are convex (q'' = 2w, 2 - q'' = 2(1 - w)), so the
     * volumetric energy is convex in J for every g in [0, 1]. (Blending the
     * weight instead, (1 - w(J)(1 - g)) kappa/2 t^2, is not: at g = 0 its
     * curvature falls to about -kappa/4 near t = delta/2, a negative bulk
     * modulus in the damaged points that sit at J ~ 1.)
     */
    template <typename Number>
    std::pair<Number, Number>
    tension_part(const Number &J, const double delta)
    {
      using Pair     = std::pair<Number, Number>;
      const Number t = J - 1.;
      if (value_of(t) <= -delta || (delta == 0. && value_of(t) <= 0.))
        return Pair(Number(0.), Number(0.));
      if (value_of(t) >= delta)
        return Pair(Number(t * t + delta * delta / 7.), Number(2. * t));
      const Number x  = (t + delta) / (2. * delta);
      const Number x4 = x * x * x * x;
      return Pair(Number(8. * delta * delta * x4 * x *
                         (x * x / 7. - 0.5 * x + 0.5)),
                  Number(4. * delta * x4 * (x * x - 3. * x + 2.5)));
    }

    /// yhat'(alpha) of (21).
    double
    hardening_slope_of(const double alpha, const PlasticityParameters &p)
    {
      return (p.saturation_yield - p.initial_yield) * p.saturation_exponent *
               std::exp(-p.saturation_exponent * alpha) +
             p.linear_hardening;
    }

    /**
     * exp(A) of a symmetric tensor by scaling and squaring of its Taylor
     * series: A is halved until |A| <= 1/2, the series summed until a term
     * falls below 1e-17 (at most 20 terms), the result squared back. The
     * number of terms and squarings depends on the values only, so the
     * derivatives of AD numbers are those of the same polynomial.
     */
    template <typename Number>
    Tensor<2, material_dim, Number>
    exponential(const SymmetricTensor<2, material_dim, Number> &A)
    {
      const auto value_norm = [](const Tensor<2, material_dim, Number> &T) {
        double sum = 0.;
        for (unsigned int i = 0; i < material_dim; ++i)
          for (unsigned int j = 0; j < material_dim; ++j)
            sum += value_of(T[i][j]) * value_of(T[i][j]);
        return std::sqrt(sum);
      };
      Tensor<2, material_dim, Number> X(A);
      unsigned int                    squarings = 0;
      // (A non-finite A keeps its norm: at most 64 halvings, the NaN or
      // Inf then reaches the residual, which reports it.)
      for (double norm = value_norm(X); norm > 0.5 && squarings < 64;
           norm *= 0.5)
        ++squarings;
      X *= std::ldexp(1., -static_cast<int>(squarings));
      Tensor<2, material_dim, Number> result(
        unit_symmetric_tensor<material_dim, Number>());
      Tensor<2, material_dim, Number> term = result;
      for (unsigned int k = 1; k <= 20; ++k)
        {
          term = term * X;
          term /= static_cast<double>(k);
          result += term;
          if (value_norm(term) < 1e-17)
            break;
        }
      for (unsigned int i = 0; i < squarings; ++i)
        result = result * result;
      return result;
    }

    template <typename Number>
    struct Evaluation
    {
      Number                                   J, psi_elastic, psi_plus, r;
      SymmetricTensor<2, material_dim, Number> tau, Cp_inv;
      Tensor<2, material_dim, Number>          P;
      bool                                     yielding, trial_yielding;
    };

    template <typename Number>
    SymmetricTensor<2, material_dim, Number>
    push_forward(const Tensor<2, material_dim, Number>          &F,
                 const SymmetricTensor<2, material_dim, Number> &C)
    {
      return symmetrize(F * Tensor<2, material_dim, Number>(C) * transpose(F));
    }

    template <typename Number>
    Evaluation<Number>
    evaluate(const Tensor<2, material_dim, Number> &F,
             const PlasticHistory                  &history_n,
             const Number                          &alpha,
             const Number                          &s,
             const double                           dt,
             const PlasticityParameters            &p,
             const std::optional<bool>             &frozen_yielding)
    {
      const double       mu = p.shear_modulus, kappa = p.bulk_modulus;
      Evaluation<Number> e;
      e.J                = determinant(F);
      const Number J23   = std::pow(e.J, -2. / 3.);
      const Number g_dev = degradation_of(s, p);
      const auto [q, dq] = tension_part(e.J, p.volumetric_switch_width);

      // 1. Trial state and yield check (chi_p from values only).
      const SymmetricTensor<2, material_dim, Number> Cp_inv_n(history_n.Cp_inv);
      const SymmetricTensor<2, material_dim, Number> b_tr =
        push_forward(F, Cp_inv_n);
      const Number                                   mu_g     = mu * g_dev;
      const SymmetricTensor<2, material_dim, Number> b_bar_tr = J23 * b_tr;
      const SymmetricTensor<2, material_dim, Number> tau_dev_tr =
        mu_g * deviator(b_bar_tr);
      const Number norm_tr = std::sqrt(tau_dev_tr * tau_dev_tr);
      // The yielding branch of r at alpha_n against the non-yielding one,
      // r_n: the point yields where the force of the rest of the field,
      // r_n, exceeds what the trial state leaves (see the header).
      e.trial_yielding = std::sqrt(1.5) * value_of(norm_tr) -
                           flow_resistance_of(history_n.alpha, value_of(s), p) +
                           history_n.r >
                         0.;
      e.yielding = frozen_yielding ? *frozen_yielding : e.trial_yielding;
      // With the bound nothing depends on chi_p: it only labels the point
      // (statistics), and a frozen switch is no branch to keep.
      if (p.loading_condition == LoadingCondition::bound)
        e.trial_yielding = e.yielding;

      // 2. Plastic flow from the current alpha of the global field, at
      // every point and not clamped at alpha < alpha_n (see the header).
      e.Cp_inv = Cp_inv_n;
      SymmetricTensor<2, material_dim, Number> n_tr;
      if (value_of(norm_tr) > 0.)
        {
          const Number lambda = std::sqrt(1.5) * (alpha - history_n.alpha) / dt;
          const Tensor<2, material_dim, Number> F_inv = invert(F);
          // The direction tau_tr / sqrt(|tau_tr|^2 + eps^2) (see the
          // header).
          const Number inverse_norm =
            1. / std::sqrt(norm_tr * norm_tr +
                           direction_floor_squared(norm_tr, e.yielding, p));
          n_tr = inverse_norm * tau_dev_tr;
          if (p.flow_integration == FlowIntegration::linear)
            {
              const Number factor = (2. / 3.) * dt * lambda * trace(b_tr);
              e.Cp_inv -=
                factor *
                symmetrize(F_inv * Tensor<2, material_dim, Number>(n_tr) *
                           transpose(F_inv));
            }
          else
            // b^e = exp(-2 dt lambda n) b_tr: n and b_tr commute.
            e.Cp_inv = symmetrize(
              F_inv * exponential(Number(-2. * dt * lambda) * n_tr) *
              Tensor<2, material_dim, Number>(b_tr) * transpose(F_inv));
          // Plastic incompressibility: det (C^p)^{-1} = 1.
          const Number rescale = std::pow(determinant(e.Cp_inv), -1. / 3.);
          e.Cp_inv             = rescale * e.Cp_inv;
        }

      // 3. Stress and energies from bbar^e.
      const SymmetricTensor<2, material_dim, Number> b_bar =
        J23 * push_forward(F, e.Cp_inv);
      const Number                                   tr_b = trace(b_bar);
      const SymmetricTensor<2, material_dim, Number> tau_dev =
        mu_g * deviator(b_bar);
      // J dPsi^e/dJ of kappa/2 ((J - 1)^2 - (1 - g) q(J - 1)).
      const Number pressure_part =
        kappa * e.J * ((e.J - 1.) - 0.5 * (1. - g_dev) * dq);
      e.tau =
        pressure_part * unit_symmetric_tensor<material_dim, Number>() + tau_dev;
      e.P = Tensor<2, material_dim, Number>(e.tau) * transpose(invert(F));
      const Number vol_plus = 0.5 * kappa * q;
      const Number vol      = 0.5 * kappa * (e.J - 1.) * (e.J - 1.);
      const Number dev      = 0.5 * mu * (tr_b - 3.);
      e.psi_elastic         = vol - (1. - g_dev) * vol_plus + g_dev * dev;
      e.psi_plus            = vol_plus + dev;

      // Local part of (50).
      e.r = p.viscosity * (alpha - history_n.alpha) / dt;
      if (e.yielding || p.loading_condition == LoadingCondition::bound)
        // The stress along the trial direction n_tr (tau_dev stays parallel
        // to it), not |tau_dev|: sqrt(3/2) |tau_dev| = yhat(alpha) has a
        // second root where the flow overshoots and reverses tau_dev, a
        // spurious equilibrium that Newton found in the late neck of the
        // necking bar (force drop within one step while alpha stood still).
        e.r += step_flow_resistance(alpha, history_n.alpha, s, p) -
               std::sqrt(1.5) * (n_tr * tau_dev);
      else
        {
          // Hold alpha at alpha_n with the yielding branch's slope, against
          // the force r_n that held it there at the last accepted step.
          e.r += p.hold_stiffness_factor *
                   (mu_g * trace(b_bar_tr) +
                    hardening_slope_of(history_n.alpha, p)) *
                   (alpha - history_n.alpha) +
                 history_n.r;
        }
      return e;
    }
  } // namespace



  double
  hardening_stress(const double alpha, const PlasticityParameters &p)
  {
    return hardening_of(alpha, p);
  }



  double
  plastic_work_density(const double alpha, const PlasticityParameters &p)
  {
    return plastic_work_of(alpha, p);
  }



  std::pair<double, double>
  degradable_plastic_energy(const double work, const PlasticityParameters &p)
  {
    return degradable_part(work, p);
  }



  double
  plastic_energy_density(const double                alpha,
                         const double                s,
                         const PlasticityParameters &p)
  {
    return plastic_energy_of(alpha, s, p);
  }



  double
  elastic_energy(const Tensor<2, material_dim>          &F,
                 const SymmetricTensor<2, material_dim> &Cp_inv,
                 const double                            s,
                 const PlasticityParameters             &p)
  {
    const double J     = determinant(F);
    const double g_dev = degradation_of(s, p);
    const double q     = tension_part(J, p.volumetric_switch_width).first;
    const double tr_b  = std::pow(J, -2. / 3.) * trace(push_forward(F, Cp_inv));
    return 0.5 * p.bulk_modulus * ((J - 1.) * (J - 1.) - (1. - g_dev) * q) +
           g_dev * 0.5 * p.shear_modulus * (tr_b - 3.);
  }



  double
  flow_work(const Tensor<2, material_dim>          &G,
            const PlasticHistory                   &history_n,
            const SymmetricTensor<2, material_dim> &Cp_inv,
            const double                            s,
            const PlasticityParameters             &p)
  {
    return elastic_energy(G, history_n.Cp_inv, s, p) -
           elastic_energy(G, Cp_inv, s, p);
  }



  double
  plastic_work_of_step(const Tensor<2, material_dim>          &F_n,
                       const Tensor<2, material_dim>          &F,
                       const PlasticHistory                   &history_n,
                       const SymmetricTensor<2, material_dim> &Cp_inv,
                       const double                            s_n,
                       const double                            s,
                       const PlasticityParameters             &p)
  {
    const SymmetricTensor<2, material_dim> &C_n = history_n.Cp_inv;
    const auto release = [&](const Tensor<2, material_dim> &G) {
      return flow_work(G, history_n, Cp_inv, s, p);
    };
    // The trial yield function of evaluate() at G with the phase field
    // @p phase.
    const auto trial = [&](const Tensor<2, material_dim> &G,
                           const double                   phase) {
      const SymmetricTensor<2, material_dim> b_bar =
        std::pow(determinant(G), -2. / 3.) * push_forward(G, C_n);
      const SymmetricTensor<2, material_dim> tau_dev =
        p.shear_modulus * degradation_of(phase, p) * deviator(b_bar);
      return std::sqrt(1.5) * tau_dev.norm() -
             flow_resistance_of(history_n.alpha, phase, p) + history_n.r;
    };
    // At the start of the step with its phase field, at its end with the
    // new one.
    const double f_n = trial(F_n, s_n), f = trial(F, s);
    double       theta = 0.;
    if (f_n < 0. && f > 0.)
      theta = f_n / (f_n - f);
    return 0.5 * (release(F_n + theta * (F - F_n)) + release(F));
  }



  MaterialResponse
  plastic_update(const Tensor<2, material_dim> &F,
                 const PlasticHistory          &history_n,
                 const double                   alpha,
                 const double                   s,
                 const double                   dt,
                 const PlasticityParameters    &parameters,
                 const bool                     with_tangent,
                 const std::optional<bool>     &frozen_yielding)
  {
    MaterialResponse response;
    if (!with_tangent)
      {
        const Evaluation<double> e = evaluate<double>(
          F, history_n, alpha, s, dt, parameters, frozen_yielding);
        response.J              = e.J;
        response.psi_elastic    = e.psi_elastic;
        response.psi_plus       = e.psi_plus;
        response.tau            = e.tau;
        response.P              = e.P;
        response.r              = e.r;
        response.yielding       = e.yielding;
        response.trial_yielding = e.trial_yielding;
        response.updated        = {e.Cp_inv, alpha, e.r};
        return response;
      }

    // Directions: F_cD -> 3c + D, alpha -> 9, s -> 10.
    Tensor<2, material_dim, ADNumber> F_ad;
    for (unsigned int c = 0; c < material_dim; ++c)
      for (unsigned int D = 0; D < material_dim; ++D)
        F_ad[c][D] = ADNumber(11, material_dim * c + D, F[c][D]);
    const ADNumber             alpha_ad(11, 9, alpha), s_ad(11, 10, s);
    const Evaluation<ADNumber> e = evaluate<ADNumber>(
      F_ad, history_n, alpha_ad, s_ad, dt, parameters, frozen_yielding);

    response.J              = e.J.val();
    response.psi_elastic    = e.psi_elastic.val();
    response.psi_plus       = e.psi_plus.val();
    response.r              = e.r.val();
    response.yielding       = e.yielding;
    response.trial_yielding = e.trial_yielding;
    response.updated.alpha  = alpha;
    response.updated.r      = e.r.val();
    for (unsigned int a = 0; a < material_dim; ++a)
      for (unsigned int b = a; b < material_dim; ++b)
        {
          response.tau[a][b]            = e.tau[a][b].val();
          response.updated.Cp_inv[a][b] = e.Cp_inv[a][b].val();
        }
    for (unsigned int a = 0; a < material_dim; ++a)
      for (unsigned int B = 0; B < material_dim; ++B)
        {
          response.P[a][B] = e.P[a][B].val();
          for (unsigned int c = 0; c < material_dim; ++c)
            for (unsigned int D = 0; D < material_dim; ++D)
              response.dP_dF[a][B][c][D] = e.P[a][B].dx(material_dim * c + D);
          response.dP_dalpha[a][B]    = e.P[a][B].dx(9);
          response.dP_ds[a][B]        = e.P[a][B].dx(10);
          response.dr_dF[a][B]        = e.r.dx(material_dim * a + B);
          response.dpsi_plus_dF[a][B] = e.psi_plus.dx(material_dim * a + B);
        }
    response.dpsi_plus_dalpha = e.psi_plus.dx(9);
    response.dpsi_plus_ds     = e.psi_plus.dx(10);
    response.dr_dalpha        = e.r.dx(9);
    response.dr_ds            = e.r.dx(10);
    return response;
  }
} // namespace DuctileContact
