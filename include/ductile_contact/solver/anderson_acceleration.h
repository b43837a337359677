#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <deque>

namespace DuctileContact
{
  /**
   * Anderson acceleration (Walker and Ni, SIAM J. Numer. Anal. 49, 2011) of
   * a fixed-point iteration x_{k+1} = G(x_k): with the residuals f_k =
   * G(x_k) - x_k and the differences of the last m of them and of the
   * images,
   *   gamma   = argmin | f_k - sum_i gamma_i (f_i+1 - f_i) |,
   *   x_{k+1} = G(x_k) - sum_i gamma_i (G(x_i+1) - G(x_i)).
   * With m = 0 it is the plain iteration. The staggered scheme uses it on
   * the phase field: G maps s to the phase field solved at the
   * displacement and hardening equilibrated with s (the alternate
   * minimisation converges linearly, slowly while a crack runs; Storvik et
   * al., Comput. Methods Appl. Mech. Engrg. 381, 2021, accelerate it so).
   *
   * The new iterate is an affine combination (the coefficients of the
   * images sum to one), so linear constraints that every image satisfies
   * (Dirichlet values, hanging nodes) hold for it too.
   */
  class AndersonAcceleration
  {
  public:
    /// @p depth: the number m of differences kept.
    explicit AndersonAcceleration(unsigned int depth);

    /// Forgets the history (a new load step).
    void
    reset();

    /**
     * @p x the iterate, @p image = G(x) on input, the next iterate on
     * output. The least-squares problem is solved through the normal
     * equations by a pseudo-inverse: directions of singular values below
     * 1e-12 of the largest (differences that are nearly dependent) do not
     * contribute.
     */
    void
    update(const dealii::TrilinosWrappers::MPI::Vector &x,
           dealii::TrilinosWrappers::MPI::Vector       &image);

  private:
    unsigned int                                      depth;
    std::deque<dealii::TrilinosWrappers::MPI::Vector> residual_differences;
    std::deque<dealii::TrilinosWrappers::MPI::Vector> image_differences;
    dealii::TrilinosWrappers::MPI::Vector             last_residual;
    dealii::TrilinosWrappers::MPI::Vector             last_image;
    bool                                              has_last = false;
  };
} // namespace DuctileContact
