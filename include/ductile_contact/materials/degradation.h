#pragma once

namespace DuctileContact
{
  /**
   * Parameters of the crack degradation function of doc/model.md section 2,
   * after (17):
   *
   *   g(s)   = a_g ((1 - s)^3 - (1 - s)^2) - 2 (1 - s)^3 + 3 (1 - s)^2,
   *   g_k(s) = (1 - k) g(s) + k.
   *
   * Both are dimensionless. Beyond s = 1 we take g = 0 (g_k = k): the
   * discrete phase field overshoots 1 by a few per cent beside a crack
   * (the C0IP solution of the fourth-order equation is not bounded by its
   * data), and the polynomial would let the broken band regain stiffness
   * there ((1 - s)^2 = 2.5e-3 at s = 1.05), which the irreversibility
   * bound would then keep. Since g(1) = g'(1) = 0 the continuation is C1;
   * g'' jumps from 2 (3 - a_g) (1 - k) to 0 at s = 1.
   */
  struct DegradationParameters
  {
    /**
     * a_g >= 0 in g(s), doc/model.md section 2: the slope -g'(0) = a_g (1 - k)
     * at the intact state; a_g = 2 gives the quadratic degradation
     * g(s) = (1 - s)^2.
     */
    double a = 2.;

    /**
     * Residual stiffness k in g_k(s) = (1 - k) g(s) + k, doc/model.md section
     * 2: the fraction of the stiffness a fully broken point (s = 1) keeps, so
     * that the tangent stays invertible.
     */
    double residual_stiffness = 1e-8;
  };



  /**
   * The degradation g_k(s) = (1 - k) g(s) + k of doc/model.md section 2 (used
   * in (16)-(17)), written with x = 1 - s as g = (a_g - 2) x^3 + (3 - a_g) x^2.
   * A template so that automatic-differentiation numbers (Sacado) can use
   * it; g_k(0) = 1, g_k(s) = k for s >= 1.
   */
  template <typename Number>
  inline Number
  degradation_value(const Number &s, const DegradationParameters &p)
  {
    if (s > 1.)
      return Number(p.residual_stiffness);
    const Number x = 1. - s;
    const Number g = (p.a - 2.) * x * x * x + (3. - p.a) * x * x;
    return (1. - p.residual_stiffness) * g + p.residual_stiffness;
  }



  /**
   * g_k'(s) = -(1 - k) (3 (a_g - 2) x^2 + 2 (3 - a_g) x), x = 1 - s: the
   * derivative of degradation_value(); g_k'(0) = -a_g (1 - k), g_k'(s) = 0
   * for s >= 1. It enters the crack driving force H = -g_k'(s) psi^+ of
   * doc/model.md (27).
   */
  inline double
  degradation_derivative(const double s, const DegradationParameters &p)
  {
    if (s > 1.)
      return 0.;
    const double x = 1. - s;
    return -(1. - p.residual_stiffness) *
           (3. * (p.a - 2.) * x * x + 2. * (3. - p.a) * x);
  }



  /**
   * g_k''(s) = (1 - k) (6 (a_g - 2) x + 2 (3 - a_g)), x = 1 - s: the second
   * derivative of degradation_value(), needed for the tangent of doc/model.md
   * (51) with respect to s; 0 for s > 1 (at s = 1 the left limit).
   */
  inline double
  degradation_second_derivative(const double s, const DegradationParameters &p)
  {
    if (s > 1.)
      return 0.;
    const double x = 1. - s;
    return (1. - p.residual_stiffness) *
           (6. * (p.a - 2.) * x + 2. * (3. - p.a));
  }
} // namespace DuctileContact
