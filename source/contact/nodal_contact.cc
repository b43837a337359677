#include <ductile_contact/contact/nodal_contact.h>

#include <Sacado.hpp>
#include <cmath>

namespace DuctileContact
{
  using namespace dealii;

  NodalContactState
  nodal_contact(const NodalAggregates        &a,
                const double                  multiplier,
                const Tensor<1, dim>         &committed_traction,
                const NodalContactParameters &p)
  {
    using AD       = Sacado::Fad::SFad<double, 10>;
    using V        = std::array<AD, dim>;
    const auto dot = [](const V &x, const V &y) -> AD {
      if constexpr (dim == 3)
        return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
      else
        return x[0] * y[0] + x[1] * y[1];
    };

    const AD A(10, 0, a.area);
    V        G, H, n;
    for (unsigned int c = 0; c < dim; ++c)
      {
        G[c] = AD(10, 1 + c, a.G[c]);
        H[c] = AD(10, 4 + c, a.H[c]);
        n[c] = AD(10, 7 + c, a.normal[c]);
      }

    using std::sqrt;
    NodalContactState state;
    const AD          gap   = dot(n, G);
    const AD          trial = multiplier - p.penalty * gap / A;
    state.gap               = gap.val();
    state.pressure          = std::max(0., trial.val());
    state.active            = trial.val() > -p.activation_threshold;
    if (!state.active)
      return state;

    const double Hn = dot(n, H).val();
    for (unsigned int c = 0; c < dim; ++c)
      state.slip[c] = (a.H[c] - Hn * a.normal[c]) / a.area;

    // f = lambda n + t; lambda = trial on the active branch (its value is
    // clipped at 0 for a node that only touches).
    V f;
    for (unsigned int c = 0; c < dim; ++c)
      f[c] = trial * n[c];
    if (state.pressure > 0. && p.friction > 0.)
      {
        // T v = v - (n . v) n
        const auto tangential = [&](const V &v) -> V {
          const AD vn = dot(n, v);
          V        t;
          for (unsigned int c = 0; c < dim; ++c)
            t[c] = v[c] - vn * n[c];
          return t;
        };
        V committed;
        for (unsigned int c = 0; c < dim; ++c)
          committed[c] = committed_traction[c];
        V        old       = tangential(committed);
        const AD old_norm2 = dot(old, old);
        if (old_norm2.val() > 0.)
          {
            const AD scale = committed_traction.norm() / sqrt(old_norm2);
            for (auto &c : old)
              c *= scale;
          }
        const V slip = tangential(H);
        V       t_trial;
        for (unsigned int c = 0; c < dim; ++c)
          t_trial[c] = old[c] + p.tangential_penalty * slip[c] / A;
        const AD trial_norm  = sqrt(dot(t_trial, t_trial));
        const AD limit       = p.friction * trial;
        V        t           = t_trial;
        state.friction_state = 1;
        if (trial_norm.val() > limit.val())
          {
            state.friction_state = 2;
            for (unsigned int c = 0; c < dim; ++c)
              t[c] = limit * t_trial[c] / trial_norm;
          }
        double dissipation = 0.;
        for (unsigned int c = 0; c < dim; ++c)
          {
            f[c] += t[c];
            state.traction[c]       = t[c].val();
            state.trial_traction[c] = t_trial[c].val();
            dissipation +=
              t[c].val() * (slip[c].val() / A.val() -
                            (t[c].val() - old[c].val()) / p.tangential_penalty);
          }
        state.dissipation = A.val() * dissipation;
      }
    for (unsigned int c = 0; c < dim; ++c)
      {
        state.force_density[c] =
          state.pressure * a.normal[c] + state.traction[c];
        for (unsigned int d = 0; d < 10; ++d)
          state.jacobian[c][d] = f[c].fastAccessDx(d);
      }
    return state;
  }
} // namespace DuctileContact
