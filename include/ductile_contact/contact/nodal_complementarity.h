#pragma once

#include <deal.II/base/tensor.h>

#include <ductile_contact/contact/nodal_contact.h>
#include <ductile_contact/core/types.h>

#include <array>

namespace DuctileContact
{
  /// Number of arguments of nodal_complementarity(): the ten aggregates
  /// (A, G, H, n) of nodal_contact.h and the traction f.
  constexpr unsigned int complementarity_arguments = 13;

  /// Value and Jacobian of the complementarity function of one slave node.
  struct NodalComplementarity
  {
    /// C_j [N] (zero at a solution of the contact conditions).
    dealii::Tensor<1, dim> value;
    /// dC_j / d(A, G, H, n, f), exact for the branch taken.
    std::array<std::array<double, complementarity_arguments>, dim> jacobian{};
    /// Weighted gap g_j = n_j . G_j [m^3].
    double gap = 0.;
    /// lambda_j = n_j . f_j on the active set, 0 elsewhere [Pa].
    double pressure = 0.;
    bool   active   = false;
    /// Tangential traction (I - n n) f_j on the active set [Pa], slip
    /// s_j = (I - n n) H_j / A_j [m], 0 (none), 1 (stick) or 2 (slip).
    dealii::Tensor<1, dim> traction, slip;
    unsigned char          friction_state = 0;
    /// A_j t_j . s_j, the node's frictional dissipation in the step, with
    /// the traction at the end of the step (backward Euler, as the update)
    /// [J].
    double dissipation = 0.;
  };

  /**
   * Complementarity function of one slave node for the semi-smooth Newton
   * method (Hueber & Wohlmuth 2005; Coulomb friction as in Hueber, Stadler
   * & Wohlmuth 2008 and Gitterle et al. 2010), in force units. With the
   * nodal traction f_j (the condensed dual multiplier), lambda = n . f,
   * t = f - lambda n, the gap g = n . G / A, the slip s = (I - n n) H / A
   * and the augmented pressure lambda_aug = lambda - c_N g,
   *
   *   inactive (lambda_aug <= 0):   C = A f                  (f = 0)
   *   active, normal part:          C . n = c_N A g          (g = 0)
   *   active, mu = 0:               C_T = A t                (t = 0)
   *   stick, |t + c_T s| <= mu lambda_F:  C_T = -c_T A s     (s = 0)
   *   slip:  C_T = A (t - mu lambda_F (t + c_T s) / |t + c_T s|)
   *          (|t| = mu lambda, t along the slip)
   *
   * with the Coulomb bound's pressure lambda_F = lambda - w c_N g, w =
   * (c_N g)^2 / ((c_N g)^2 + (0.01 lambda)^2): lambda_aug for a node that
   * has just turned active (so that friction acts from its first
   * iteration), lambda once its gap has closed to the solver's accuracy
   * (c_N would amplify that gap into the bound and let its round-off decide
   * stick or slip at the edge of the cone). lambda_F = lambda_aug = lambda
   * at a solution.
   *
   * C is continuous across the branches, so its norm is a merit function
   * for the line search. c_N and c_T (Pa/m) are the pair's eps_N and eps_T;
   * they scale the branch tests, not the solution. A node also counts as
   * active when lambda_aug exceeds -activation_threshold (touching).
   */
  NodalComplementarity
  nodal_complementarity(const NodalAggregates        &a,
                        const dealii::Tensor<1, dim> &f,
                        const NodalContactParameters &parameters);
} // namespace DuctileContact
