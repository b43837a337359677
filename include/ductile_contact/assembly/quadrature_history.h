#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <ductile_contact/materials/plasticity.h>

#include <vector>

namespace DuctileContact
{
  /// Internal state of one quadrature point at the last accepted step.
  struct PointHistory
  {
    /// (C^p_n)^{-1} and alpha_n (doc/model.md section 3).
    PlasticHistory plastic;
    /// max over accepted steps of the crack driving energy psi_D
    /// (crack_driving_energy(): psi^+ of (27) with the elastic driver):
    /// the history that makes s irreversible (doc/model.md section 2, Miehe
    /// 2010).
    double driving_energy_max = 0.;
  };

  /**
   * Quadrature-point history of every locally owned cell, indexed by the
   * active cell index. It is written only when a load step is accepted
   * (SystemAssembler::commit()), so a rejected or
   * cut-back step leaves no trace. The mesh must not change while it is
   * in use.
   */
  class QuadratureHistory
  {
  public:
    void
    reinit(const dealii::DoFHandler<dim> &dof_handler,
           const unsigned int             points_per_cell)
    {
      n_points = points_per_cell;
      data.assign(dof_handler.get_triangulation().n_active_cells() * n_points,
                  PointHistory());
    }

    template <typename CellIterator>
    const PointHistory *
    operator()(const CellIterator &cell) const
    {
      return &data[cell->active_cell_index() * n_points];
    }

    template <typename CellIterator>
    PointHistory *
    operator()(const CellIterator &cell)
    {
      return &data[cell->active_cell_index() * n_points];
    }

    /// Doubles per point in pack().
    static constexpr unsigned int packed_size =
      dealii::SymmetricTensor<2, material_dim>::n_independent_components + 4;

    /// The history of @p cell's points as one flat vector (checkpoints).
    template <typename CellIterator>
    std::vector<double>
    pack(const CellIterator &cell) const
    {
      std::vector<double> packed;
      packed.reserve(n_points * packed_size);
      const PointHistory *h = (*this)(cell);
      for (unsigned int q = 0; q < n_points; ++q)
        {
          for (unsigned int i = 0; i < packed_size - 4; ++i)
            packed.push_back(h[q].plastic.Cp_inv.access_raw_entry(i));
          packed.push_back(h[q].plastic.alpha);
          packed.push_back(h[q].plastic.r);
          packed.push_back(h[q].plastic.stretch);
          packed.push_back(h[q].driving_energy_max);
        }
      return packed;
    }

    /// Sets the history of @p cell from pack()'s vector; false if its size
    /// does not fit.
    template <typename CellIterator>
    bool
    unpack(const CellIterator &cell, const std::vector<double> &packed)
    {
      if (packed.size() != n_points * packed_size)
        return false;
      PointHistory *h = (*this)(cell);
      auto          p = packed.begin();
      for (unsigned int q = 0; q < n_points; ++q)
        {
          for (unsigned int i = 0; i < packed_size - 4; ++i)
            h[q].plastic.Cp_inv.access_raw_entry(i) = *p++;
          h[q].plastic.alpha      = *p++;
          h[q].plastic.r          = *p++;
          h[q].plastic.stretch    = *p++;
          h[q].driving_energy_max = *p++;
        }
      return true;
    }

  private:
    unsigned int              n_points = 0;
    std::vector<PointHistory> data;
  };
} // namespace DuctileContact
