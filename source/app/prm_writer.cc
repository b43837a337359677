#include <ductile_contact/app/prm_writer.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <set>
#include <sstream>
#include <string>

namespace DuctileContact
{
  namespace
  {
    using Tree = boost::property_tree::ptree;

    /// The keys of a node that describe its entry, not subsections.
    bool
    is_entry_key(const std::string &key)
    {
      static const std::set<std::string> keys = {"value",
                                                 "default_value",
                                                 "documentation",
                                                 "pattern",
                                                 "pattern_description",
                                                 "actions",
                                                 "type"};
      return keys.count(key) > 0;
    }

    /// deal.II's names in the tree: each character other than a letter or
    /// a digit written as _XX (hex).
    std::string
    demangle(const std::string &name)
    {
      std::string out;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_' && i + 2 < name.size())
          {
            out +=
              static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          out += name[i];
      return out;
    }

    void
    write_documentation(const std::string &text,
                        const std::string &indent,
                        std::ostream      &out)
    {
      std::istringstream words(text);
      std::string        word, line;
      while (words >> word)
        {
          if (!line.empty() &&
              indent.size() + 2 + line.size() + 1 + word.size() > 78)
            {
              out << indent << "# " << line << "\n";
              line.clear();
            }
          line += (line.empty() ? "" : " ") + word;
        }
      if (!line.empty())
        out << indent << "# " << line << "\n";
    }

    void
    write_node(const Tree &node, const unsigned int depth, std::ostream &out)
    {
      const std::string indent(2 * depth, ' ');
      for (const auto &[key, child] : node)
        if (!is_entry_key(key) && child.get_optional<std::string>("value"))
          {
            write_documentation(child.get<std::string>("documentation", ""),
                                indent,
                                out);
            const std::string value = child.get<std::string>("value");
            const std::string fallback =
              child.get<std::string>("default_value", value);
            out << indent << "set " << demangle(key) << " = " << value;
            if (value != fallback)
              out << " # default: " << fallback;
            out << "\n\n";
          }
      for (const auto &[key, child] : node)
        {
          if (is_entry_key(key))
            continue;
          bool subsection = false;
          for (const auto &grandchild : child)
            subsection = subsection || !is_entry_key(grandchild.first);
          if (!subsection)
            continue;
          out << indent << "subsection " << demangle(key) << "\n";
          write_node(child, depth + 1, out);
          out << indent << "end\n\n";
        }
    }
  } // namespace



  void
  write_prm(const dealii::ParameterHandler &prm, std::ostream &out)
  {
    std::stringstream json;
    prm.print_parameters(json,
                         dealii::ParameterHandler::JSON |
                           dealii::ParameterHandler::KeepDeclarationOrder);
    Tree tree;
    boost::property_tree::read_json(json, tree);
    write_node(tree, 0, out);
  }
} // namespace DuctileContact
