// The Enforcement interface's defaults and its factory.
#include <ductile_contact/contact/augmented_lagrangian.h>
#include <ductile_contact/contact/enforcement.h>
#include <ductile_contact/contact/semi_smooth_newton.h>

namespace DuctileContact
{
  void
  Enforcement::check(const ContactPair &) const
  {
  }



  std::vector<std::vector<dealii::types::global_dof_index>>
  Enforcement::master_row_columns(const ContactPair &) const
  {
    return {};
  }



  bool
  Enforcement::outer_update(ContactPair &, const ContactPairSummary &) const
  {
    return true;
  }



  std::unique_ptr<Enforcement>
  make_enforcement(const ContactEnforcement kind, ContactProblem &problem)
  {
    if (kind == ContactEnforcement::semi_smooth_newton)
      return std::make_unique<SemiSmoothNewton>(problem);
    return std::make_unique<AugmentedLagrangian>(problem);
  }



  SlaveWeights
  ContactPair::slave_weights() const
  {
    return condenses() ? SlaveWeights::lumped : SlaveWeights::full;
  }



  bool
  ContactPair::condenses() const
  {
    return enforcement->condenses();
  }
} // namespace DuctileContact
