#pragma once

#include <deal.II/base/table_handler.h>

#include <string>

namespace DuctileContact
{
  /**
   * The per-step table results/statistics (one row per accepted load step,
   * whitespace separated, one header line of column names): a script can
   * read it with numpy.loadtxt or pandas.read_csv(sep=r"\s+").
   * Rewritten after every step through a temporary file and a rename, so it
   * is complete and readable even when a run stops early.
   */
  class Statistics
  {
  public:
    explicit Statistics(const std::string &file_name);

    void
    add(const std::string &column, const double value);
    void
    add(const std::string &column, const unsigned int value);

    /// Writes the table (call on one rank only).
    void
    write() const;

    /// The table so far (checkpoints).
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &table;
    }

  private:
    std::string          file_name;
    dealii::TableHandler table;
  };
} // namespace DuctileContact
