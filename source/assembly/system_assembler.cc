#include <deal.II/base/multithread_info.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/physics/elasticity/standard_tensors.h>

#include <ductile_contact/assembly/cell_rows.h>
#include <ductile_contact/assembly/cell_scratch.h>
#include <ductile_contact/assembly/scatter.h>
#include <ductile_contact/assembly/system_assembler.h>
#include <ductile_contact/materials/body_material.h>
#include <ductile_contact/materials/degradation.h>
#include <ductile_contact/materials/neo_hooke.h>
#include <ductile_contact/phase_field/c0ip.h>

#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;

  SystemAssembler::SystemAssembler(
    const Discretisation                                       &discretisation,
    const std::map<types::material_id, const BodyParameters *> &bodies,
    const std::deque<BoundaryCondition> &boundary_conditions,
    const bool                           crack_history)
      : discretisation(discretisation)
      , bodies(bodies)
      , boundary_conditions(boundary_conditions)
      , crack_history(crack_history)
  {
    for (const BoundaryCondition &bc : boundary_conditions)
      if (bc.has_traction)
        tractions[bc.boundary_id] = &bc;
    mesh_changed =
      discretisation.triangulation.signals.any_change.connect([this]() {
        crack_matrices.clear();
        cell_face_matrices.clear();
        cell_positions.clear();
      });
  }



  SystemAssembler::~SystemAssembler()
  {
    mesh_changed.disconnect();
  }



  AssemblyInfo
  SystemAssembler::assemble(const TrilinosWrappers::MPI::BlockVector &u,
                            const StepData                           &step,
                            const AffineConstraints<double> &constraints,
                            const AssemblyTargets           &targets,
                            const bool                       finish) const
  {
    zero(targets);
    const unsigned int n_cells = discretisation.triangulation.n_active_cells();
    if (targets.branches == Branches::record)
      targets.branch_record->reset(n_cells);
    AssertThrow(targets.branches != Branches::frozen ||
                  targets.branch_record->covers(n_cells),
                ExcMessage("frozen branches need recorded ones"));

    const AssemblyInfo info =
      run({&u, &step, &targets, nullptr, false}, constraints, nullptr);

    if (finish)
      compress(targets);
    return info;
  }



  void
  SystemAssembler::resize(CellQuantities &quantities) const
  {
    for (auto *v : {&quantities.von_mises,
                    &quantities.mean_stress,
                    &quantities.J,
                    &quantities.crack_driving_force})
      v->reinit(discretisation.triangulation.n_active_cells());
    for (auto *v : {&quantities.kirchhoff,
                    &quantities.cauchy,
                    &quantities.b,
                    &quantities.Cp})
      v->assign(discretisation.triangulation.n_active_cells(),
                SymmetricTensor<2, material_dim>());
  }



  AssemblyInfo
  SystemAssembler::commit(const TrilinosWrappers::MPI::BlockVector &u,
                          const StepData                           &step,
                          QuadratureHistory                        &updated,
                          CellQuantities &quantities) const
  {
    resize(quantities);
    return run({&u, &step, nullptr, &updated, true},
               discretisation.hanging_node_constraints,
               &quantities);
  }



  void
  SystemAssembler::cell_averages(const TrilinosWrappers::MPI::BlockVector &u,
                                 const StepData                           &step,
                                 CellQuantities &quantities) const
  {
    resize(quantities);
    run({&u, &step, nullptr, nullptr, true},
        discretisation.hanging_node_constraints,
        &quantities);
  }



  AssemblyInfo
  SystemAssembler::run(const Pass                      &pass,
                       const AffineConstraints<double> &constraints,
                       CellQuantities                  *quantities) const
  {
    AssemblyReduction sums;
    // The places of the cells' entries in the tangent, kept while its
    // pattern stays the same.
    CellPositions *positions = nullptr;
    if (pass.targets && pass.targets->tangent && pass.targets->pattern != 0)
      {
        cell_positions.use(pass.targets->pattern,
                           discretisation.triangulation.n_active_cells());
        positions = &cell_positions;
      }
    using Iterator = FilteredIterator<DoFHandler<dim>::active_cell_iterator>;
    const auto worker =
      [&](const Iterator &cell, CellScratch &scratch, CellCopy &copy) {
        cell_worker(cell, scratch, copy, pass);
      };
    const auto copier = [&](const CellCopy &copy) {
      sums.add(copy.sums);
      if (pass.targets)
        {
          const LocalRows &rows = copy.cell;
          scatter(rows.matrix,
                  rows.rhs,
                  rows.f_int,
                  rows.indices,
                  constraints,
                  discretisation.hanging_node_constraints,
                  *pass.targets,
                  positions,
                  copy.cell_index);
          for (unsigned int f = 0; f < copy.n_faces; ++f)
            {
              const LocalRows &face = copy.faces[f];
              scatter(face.matrix,
                      face.rhs,
                      face.f_int,
                      face.indices,
                      constraints,
                      discretisation.hanging_node_constraints,
                      *pass.targets);
            }
        }
      if (quantities && copy.has_averages)
        {
          const unsigned int i               = copy.cell_index;
          quantities->von_mises[i]           = copy.von_mises;
          quantities->mean_stress[i]         = copy.mean_stress;
          quantities->J[i]                   = copy.mean_J;
          quantities->crack_driving_force[i] = copy.crack_driving_force;
          quantities->kirchhoff[i]           = copy.kirchhoff;
          quantities->cauchy[i]              = copy.cauchy;
          quantities->b[i]                   = copy.b;
          quantities->Cp[i]                  = copy.Cp;
        }
    };
    const auto    &dof_handler = discretisation.dof_handler;
    const Iterator begin(IteratorFilters::LocallyOwnedCell(),
                         dof_handler.begin_active());
    const Iterator end(IteratorFilters::LocallyOwnedCell(), dof_handler.end());
    if (!scratch)
      scratch = std::make_unique<CellScratch>(discretisation);
    // Sized before the loop: the workers only fill their own cell's entry.
    crack_matrices.resize(discretisation.triangulation.n_active_cells());
    cell_face_matrices.resize(discretisation.triangulation.n_active_cells());
    if (MultithreadInfo::n_threads() == 1)
      {
        // The cached scratch directly: a copy would build the evaluation
        // objects again.
        if (!copy_data)
          copy_data = std::make_unique<CellCopy>();
        for (Iterator cell = begin; cell != end; ++cell)
          {
            worker(cell, *scratch, *copy_data);
            copier(*copy_data);
          }
      }
    else
      WorkStream::run(begin, end, worker, copier, *scratch, CellCopy());
    return sums.sum_over_ranks(dof_handler.get_communicator());
  }
  std::string
  SystemAssembler::fault(const AssemblyInfo &info) const
  {
    const auto where = [&](const FaultSite &site) {
      std::ostringstream s;
      s << "in the cell at (" << site.position << ") m of body " << site.body;
      const auto body = bodies.find(site.body);
      if (body != bodies.end())
        s << " '" << body->second->name << "'";
      return s.str();
    };
    std::ostringstream s;
    if (info.non_finite)
      s << "the residual is not finite (NaN or Inf) "
        << where(info.non_finite_site);
    else if (info.inverted)
      s << "an element inverts (J = " << info.min_J << " "
        << where(info.min_J_site) << ")";
    return s.str();
  }
} // namespace DuctileContact
