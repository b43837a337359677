#include <ductile_contact/contact/nodal_complementarity.h>

#include <Sacado.hpp>
#include <cmath>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /**
     * The pressure of the Coulomb bound, lambda - w c_N g / A with w =
     * q^2 / (q^2 + (eps lambda)^2), q = c_N g / A. A node that has just
     * turned active (lambda <= 0, |q| >> eps lambda) sees the augmented
     * pressure lambda_aug (w ~ 1), so friction acts from its first
     * iteration; a settled node (g at solver accuracy, |q| << eps lambda)
     * sees lambda, because its gap enters only through the cube of
     * q / (eps lambda): c_N amplifies a gap at the linear solver's accuracy
     * to ~1e-3 lambda, which would otherwise move the bound of a node on
     * the edge of the Coulomb cone across the traction, and decide stick
     * or slip by that error (benchmarks/rank_invariance/README.md). Both
     * are lambda at a solution (g = 0 on the active set), and the
     * expression is smooth wherever (q, lambda) != 0.
     */
    template <typename Number>
    Number
    friction_pressure(const Number                 &lambda,
                      const Number                 &gap,
                      const Number                 &area,
                      const NodalContactParameters &p)
    {
      constexpr double eps = 1e-2;
      const Number     q   = p.penalty * gap / area;
      if (q.val() == 0.)
        return lambda;
      const Number q2 = q * q;
      return lambda - q * q2 / (q2 + eps * eps * lambda * lambda);
    }
  } // namespace

  NodalComplementarity
  nodal_complementarity(const NodalAggregates        &a,
                        const Tensor<1, dim>         &traction,
                        const NodalContactParameters &p)
  {
    constexpr unsigned int n_args = complementarity_arguments;
    using AD                      = Sacado::Fad::SFad<double, n_args>;
    using V                       = std::array<AD, dim>;
    const auto dot                = [](const V &x, const V &y) -> AD {
      if constexpr (dim == 3)
        return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
      else
        return x[0] * y[0] + x[1] * y[1];
    };

    const AD A(n_args, 0, a.area);
    V        G, H, n, f;
    for (unsigned int c = 0; c < dim; ++c)
      {
        G[c] = AD(n_args, 1 + c, a.G[c]);
        H[c] = AD(n_args, 4 + c, a.H[c]);
        n[c] = AD(n_args, 7 + c, a.normal[c]);
        f[c] = AD(n_args, 10 + c, traction[c]);
      }

    using std::sqrt;
    NodalComplementarity result;
    const AD             gap        = dot(n, G);
    const AD             lambda     = dot(n, f);
    const AD             lambda_aug = lambda - p.penalty * gap / A;
    const AD             Hn         = dot(n, H);
    V                    t, s;
    for (unsigned int c = 0; c < dim; ++c)
      {
        t[c] = f[c] - lambda * n[c];
        s[c] = (H[c] - Hn * n[c]) / A;
      }
    result.gap    = gap.val();
    result.active = lambda_aug.val() > -p.activation_threshold;
    for (unsigned int c = 0; c < dim; ++c)
      result.slip[c] = s[c].val();

    V C;
    if (!result.active)
      for (unsigned int c = 0; c < dim; ++c)
        C[c] = A * f[c];
    else
      {
        result.pressure = std::max(0., lambda.val());
        V        C_T    = t;
        const AD bound  = p.friction * friction_pressure(lambda, gap, A, p);
        if (p.friction > 0. && bound.val() > 0.)
          {
            V tau;
            for (unsigned int c = 0; c < dim; ++c)
              tau[c] = t[c] + p.tangential_penalty * s[c];
            const AD tau_norm = sqrt(dot(tau, tau));
            if (tau_norm.val() <= bound.val())
              {
                result.friction_state = 1;
                for (unsigned int c = 0; c < dim; ++c)
                  C_T[c] = -p.tangential_penalty * s[c];
              }
            else
              {
                result.friction_state = 2;
                for (unsigned int c = 0; c < dim; ++c)
                  C_T[c] = t[c] - bound * tau[c] / tau_norm;
              }
          }
        // Without friction t is zero at a solution: no traction is
        // reported (its round-off would show as a friction force).
        for (unsigned int c = 0; c < dim; ++c)
          {
            C[c] = p.penalty * gap * n[c] + A * C_T[c];
            if (p.friction > 0.)
              {
                result.traction[c] = t[c].val();
                result.dissipation += a.area * t[c].val() * s[c].val();
              }
          }
      }
    for (unsigned int c = 0; c < dim; ++c)
      {
        result.value[c] = C[c].val();
        for (unsigned int d = 0; d < n_args; ++d)
          result.jacobian[c][d] = C[c].fastAccessDx(d);
      }
    return result;
  }
} // namespace DuctileContact
