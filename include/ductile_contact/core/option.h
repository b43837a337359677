#pragma once

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <string>
#include <utility>
#include <vector>

namespace DuctileContact
{
  /**
   * The names of an option of the input file, one per value of its enum:
   * the one table from which both the Patterns::Selection of the entry and
   * the conversion of the text come, so that a value cannot be accepted by
   * the parser and then be unknown to the code (or the reverse).
   */
  template <typename Enum>
  using NameTable = std::vector<std::pair<Enum, std::string>>;

  /// "a|b|c" for Patterns::Selection.
  template <typename Enum>
  std::string
  selection(const NameTable<Enum> &table)
  {
    std::string s;
    for (const auto &[value, name] : table)
      s += (s.empty() ? "" : "|") + name;
    return s;
  }

  /// The value named @p name (one of the table: the pattern has checked it).
  template <typename Enum>
  Enum
  from_name(const NameTable<Enum> &table, const std::string &name)
  {
    for (const auto &[value, n] : table)
      if (n == name)
        return value;
    AssertThrow(false,
                dealii::ExcMessage("'" + name + "' is not one of " +
                                   selection(table)));
    return table.front().first;
  }

  /// The name of @p value.
  template <typename Enum>
  const std::string &
  name_of(const NameTable<Enum> &table, const Enum value)
  {
    for (const auto &[v, name] : table)
      if (v == value)
        return name;
    AssertThrow(false, dealii::ExcMessage("an option value without a name"));
    return table.front().second;
  }

  /// Declares the entry @p entry of the current subsection of @p prm with
  /// the names of @p table, the default @p value and @p help, and binds it
  /// to @p value (as ParameterHandler::add_parameter does for plain types).
  template <typename Enum>
  void
  add_option(dealii::ParameterHandler &prm,
             const std::string        &entry,
             Enum                     &value,
             const NameTable<Enum>    &table,
             const std::string        &help)
  {
    prm.declare_entry(entry,
                      name_of(table, value),
                      dealii::Patterns::Selection(selection(table)),
                      help);
    prm.add_action(entry, [&value, &table](const std::string &name) {
      value = from_name(table, name);
    });
  }
} // namespace DuctileContact
