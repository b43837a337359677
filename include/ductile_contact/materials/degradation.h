#pragma once

namespace DuctileContact
{
  /**
   * Parameters of the crack degradation function of model.md section 2,
   * after (17):
   *
   *   g(s)   = a_g ((1 - s)^3 - (1 - s)^2) - 2 (1 - s)^3 + 3 (1 - s)^2,
   *   g_k(s) = (1 - k) g(s) + k.
   *
   * Both are dimensionless.
   */
  struct DegradationParameters
  {
    /**
     * a_g >= 0 in g(s), model.md section 2: the slope -g'(0) = a_g (1 - k)
     * at the intact state; a_g = 2 gives the quadratic degradation
     * g(s) = (1 - s)^2.
     */
    double a = 2.;

    /**
     * Residual stiffness k in g_k(s) = (1 - k) g(s) + k, model.md section 2:
     * the fraction of the stiffness a fully broken point (s = 1) keeps, so
     * that the tangent stays invertible.
     */
    double residual_stiffness = 1e-8;
  };



  /**
   * The degradation g_k(s) = (1 - k) g(s) + k of model.md section 2 (used in
   * (16)-(17)), written with x = 1 - s as g = (a_g - 2) x^3 + (3 - a_g) x^2.
   * A template so that automatic-differentiation numbers (Sacado) can use
   * it; g_k(0) = 1, g_k(1) = k.
   */
  template <typename Number>
  inline Number
  degradation_value(const Number &s, const DegradationParameters &p)
  {
    const Number x = 1. - s;
    const Number g = (p.a - 2.) * x * x * x + (3. - p.a) * x * x;
    return (1. - p.residual_stiffness) * g + p.residual_stiffness;
  }



  /**
   * g_k'(s) = -(1 - k) (3 (a_g - 2) x^2 + 2 (3 - a_g) x), x = 1 - s: the
   * derivative of degradation_value(); g_k'(0) = -a_g (1 - k), g_k'(1) = 0.
   * It enters the crack driving force H = -g_k'(s) psi^+ of model.md (27).
   */
  inline double
  degradation_derivative(const double s, const DegradationParameters &p)
  {
    const double x = 1. - s;
    return -(1. - p.residual_stiffness) *
           (3. * (p.a - 2.) * x * x + 2. * (3. - p.a) * x);
  }



  /**
   * g_k''(s) = (1 - k) (6 (a_g - 2) x + 2 (3 - a_g)), x = 1 - s: the second
   * derivative of degradation_value(), needed for the tangent of model.md
   * (51) with respect to s.
   */
  inline double
  degradation_second_derivative(const double s, const DegradationParameters &p)
  {
    const double x = 1. - s;
    return (1. - p.residual_stiffness) *
           (6. * (p.a - 2.) * x + 2. * (3. - p.a));
  }
} // namespace DuctileContact
