#include <ductile_contact/output/statistics.h>

#include <cstdio>
#include <fstream>

namespace DuctileContact
{
  Statistics::Statistics(const std::string &file_name)
      : file_name(file_name)
  {
  }



  void
  Statistics::add(const std::string &column, const double value)
  {
    table.add_value(column, value);
    table.set_scientific(column, true);
    table.set_precision(column, 8);
  }



  void
  Statistics::add(const std::string &column, const unsigned int value)
  {
    table.add_value(column, value);
  }



  void
  Statistics::write() const
  {
    const std::string tmp = file_name + ".tmp";
    {
      std::ofstream out(tmp);
      table.write_text(out, dealii::TableHandler::table_with_headers);
    }
    std::rename(tmp.c_str(), file_name.c_str());
  }
} // namespace DuctileContact
