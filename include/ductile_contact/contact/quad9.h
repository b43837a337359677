#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <ductile_contact/core/types.h>

#include <array>

// The contact faces of the 3-D build; the plane-strain build's are Line3
// (contact_face.h).
#if DUCTILE_CONTACT_DIM == 3
namespace DuctileContact
{
  /**
   * A 9-node (biquadratic) surface patch x(xi, eta), (xi, eta) in [0, 1]^2:
   * the face of an FE_Q(2) hexahedron in the current configuration. Node
   * (a, b), a, b in {0, 1, 2}, sits at (xi, eta) = (a/2, b/2) and has index
   * a + 3 b. The nodes are ordered so that x_xi x x_eta points out of the
   * body.
   */
  struct Quad9
  {
    /// Number of nodes; the centre node (a, b) = (1, 1); the vertices in
    /// deal.II's order.
    static constexpr unsigned int                n_nodes     = 9;
    static constexpr unsigned int                centre_node = 4;
    static constexpr std::array<unsigned int, 4> vertices{{0, 2, 6, 8}};

    /// Parameter point of the centre.
    static dealii::Point<2>
    centre()
    {
      return {0.5, 0.5};
    }

    std::array<dealii::Point<dim>, 9> x;

    /// Lagrange shape functions N_i(xi, eta) and their derivatives.
    static void
    shape(const dealii::Point<2> &xi,
          std::array<double, 9>  &values,
          std::array<double, 9>  *d_xi  = nullptr,
          std::array<double, 9>  *d_eta = nullptr);

    dealii::Point<dim>
    position(const dealii::Point<2> &xi) const;

    /// Tangents x_xi, x_eta at @p xi.
    std::array<dealii::Tensor<1, dim>, 2>
    tangents(const dealii::Point<2> &xi) const;

    /// Outward unit normal at @p xi.
    dealii::Tensor<1, dim>
    normal(const dealii::Point<2> &xi) const;

    /// Derivatives of normal(@p xi) with respect to the node positions:
    /// entry [i][c][m] = d n_c / d x_i,m.
    std::array<dealii::Tensor<2, dim>, 9>
    normal_derivatives(const dealii::Point<2> &xi) const;

    /// The parameter point where the line p + t d meets the patch (Newton on
    /// (xi, eta, t) from @p start); returns false if Newton does not
    /// converge or the line is parallel to the patch.
    bool
    project_along(const dealii::Point<dim>     &p,
                  const dealii::Tensor<1, dim> &d,
                  const dealii::Point<2>       &start,
                  dealii::Point<2>             &xi) const;

    /// shape() in a number type that may carry derivatives.
    template <typename Number>
    static void
    shape_of(const std::array<Number, 2> &xi, std::array<Number, 9> &values)
    {
      std::array<Number, 3> la, lb;
      for (unsigned int d = 0; d < 2; ++d)
        {
          const Number          &t = xi[d];
          std::array<Number, 3> &l = d == 0 ? la : lb;
          l[0]                     = 2. * (t - 0.5) * (t - 1.);
          l[1]                     = 4. * t * (1. - t);
          l[2]                     = 2. * t * (t - 0.5);
        }
      for (unsigned int b = 0; b < 3; ++b)
        for (unsigned int a = 0; a < 3; ++a)
          values[a + 3 * b] = la[a] * lb[b];
    }

    /// Parameter point of node @p i.
    static dealii::Point<2>
    node_parameter(const unsigned int i)
    {
      return {0.5 * (i % 3), 0.5 * (i / 3)};
    }
  };
} // namespace DuctileContact
#endif
