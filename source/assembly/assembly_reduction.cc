#include <deal.II/base/mpi.h>

#include <ductile_contact/assembly/assembly_data.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace DuctileContact
{
  using namespace dealii;

  void
  AssemblyReduction::add(const AssemblyReduction &o)
  {
    stored_energy += o.stored_energy;
    hardening_energy += o.hardening_energy;
    fracture_energy += o.fracture_energy;
    plastic_work_increment += o.plastic_work_increment;
    fracture_viscous_work_increment += o.fracture_viscous_work_increment;
    history_work_increment += o.history_work_increment;
    plastic_energy_release_increment += o.plastic_energy_release_increment;
    kinetic_energy += o.kinetic_energy;
    inertial_work_increment += o.inertial_work_increment;
    momentum += o.momentum;
    min_plastic_dissipation =
      std::min(min_plastic_dissipation, o.min_plastic_dissipation);
    min_alpha   = std::min(min_alpha, o.min_alpha);
    max_s_point = std::max(max_s_point, o.max_s_point);
    crack_area += o.crack_area;
    if (o.cracked_volume > 0.)
      {
        for (unsigned int d = 0; d < dim; ++d)
          {
            const bool empty = !(cracked_volume > 0.);
            cracked_min[d]   = empty ? o.cracked_min[d]
                                     : std::min(cracked_min[d], o.cracked_min[d]);
            cracked_max[d]   = empty ? o.cracked_max[d]
                                     : std::max(cracked_max[d], o.cracked_max[d]);
          }
        cracked_volume += o.cracked_volume;
      }
    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      {
        magnitude_squared[b] += o.magnitude_squared[b];
        scale_squared[b] += o.scale_squared[b];
      }
    if (o.min_J < min_J)
      {
        min_J      = o.min_J;
        min_J_site = o.min_J_site;
      }
    if (o.non_finite && !non_finite)
      {
        non_finite      = true;
        non_finite_site = o.non_finite_site;
      }
    max_alpha = std::max(max_alpha, o.max_alpha);
    min_yielding_alpha_increment =
      std::min(min_yielding_alpha_increment, o.min_yielding_alpha_increment);
    inverted = inverted || o.inverted;
    switch_flips += o.switch_flips;
  }



  AssemblyInfo
  AssemblyReduction::sum_over_ranks(const MPI_Comm comm) const
  {
    AssemblyInfo info;
    info.inverted = Utilities::MPI::max(inverted ? 1 : 0, comm) > 0;
    // The site of the smallest J and of the first non-finite row, from the
    // rank that has it.
    const auto min_J_rank = Utilities::MPI::min_max_avg(min_J, comm).min_index;
    info.min_J            = Utilities::MPI::min(min_J, comm);
    info.min_J_site.position =
      Utilities::MPI::broadcast(comm, min_J_site.position, min_J_rank);
    info.min_J_site.body =
      Utilities::MPI::broadcast(comm, min_J_site.body, min_J_rank);
    const unsigned int this_rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int first_non_finite = Utilities::MPI::min(
      non_finite ? this_rank : numbers::invalid_unsigned_int, comm);
    info.non_finite = first_non_finite != numbers::invalid_unsigned_int;
    if (info.non_finite)
      {
        info.non_finite_site.position =
          Utilities::MPI::broadcast(comm,
                                    non_finite_site.position,
                                    first_non_finite);
        info.non_finite_site.body =
          Utilities::MPI::broadcast(comm,
                                    non_finite_site.body,
                                    first_non_finite);
      }
    info.max_alpha   = Utilities::MPI::max(max_alpha, comm);
    info.min_alpha   = Utilities::MPI::min(min_alpha, comm);
    info.max_s_point = Utilities::MPI::max(max_s_point, comm);
    info.min_plastic_dissipation =
      Utilities::MPI::min(min_plastic_dissipation, comm);
    info.min_yielding_alpha_increment =
      Utilities::MPI::min(min_yielding_alpha_increment, comm);
    info.switch_flips   = Utilities::MPI::sum(switch_flips, comm);
    info.crack_area     = Utilities::MPI::sum(crack_area, comm);
    info.cracked_volume = Utilities::MPI::sum(cracked_volume, comm);
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double big = std::numeric_limits<double>::max();
        const double lo =
          Utilities::MPI::min(cracked_volume > 0. ? cracked_min[d] : big, comm);
        const double hi =
          Utilities::MPI::max(cracked_volume > 0. ? cracked_max[d] : -big,
                              comm);
        info.cracked_min[d] = info.cracked_volume > 0. ? lo : 0.;
        info.cracked_max[d] = info.cracked_volume > 0. ? hi : 0.;
      }
    std::vector<double> sums{stored_energy,
                             hardening_energy,
                             fracture_energy,
                             plastic_work_increment,
                             fracture_viscous_work_increment,
                             history_work_increment,
                             plastic_energy_release_increment,
                             kinetic_energy,
                             inertial_work_increment};
    for (unsigned int d = 0; d < dim; ++d)
      sums.push_back(momentum[d]);
    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      {
        sums.push_back(magnitude_squared[b]);
        sums.push_back(scale_squared[b]);
      }
    Utilities::MPI::sum(sums, comm, sums);
    info.stored_energy                    = sums[0];
    info.hardening_energy                 = sums[1];
    info.fracture_energy                  = sums[2];
    info.plastic_work_increment           = sums[3];
    info.fracture_viscous_work_increment  = sums[4];
    info.history_work_increment           = sums[5];
    info.plastic_energy_release_increment = sums[6];
    info.kinetic_energy                   = sums[7];
    info.inertial_work_increment          = sums[8];
    for (unsigned int d = 0; d < dim; ++d)
      info.momentum[d] = sums[9 + d];
    const unsigned int first_block = 9 + dim;
    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      {
        info.residual_magnitude[b] = std::sqrt(sums[first_block + 2 * b]);
        info.residual_scale[b]     = std::sqrt(sums[first_block + 1 + 2 * b]);
      }
    // The scale of the u rows is the size of their terms.
    info.force_magnitude = info.residual_magnitude[Block::displacement];
    info.residual_scale[Block::displacement] = info.force_magnitude;
    return info;
  }
} // namespace DuctileContact
