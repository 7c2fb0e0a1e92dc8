#include "tools/mtsp_solver/species_file.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "common/planning/mtsp/mtsp_problem.h"

namespace hexplore::mtsp {

SpeciesAssignment parse_species_file(std::istream& in, const std::string& origin, int salesmen, int nodes) {
  SpeciesAssignment out;
  out.salesman_species.assign(size_t(salesmen), -1);
  out.node_species.assign(size_t(nodes), planning::kPublic);
  auto species_id = [&](const std::string& name) {
    const auto it = std::find(out.species.begin(), out.species.end(), name);
    if (it != out.species.end()) return int(it - out.species.begin());
    out.species.push_back(name);
    return int(out.species.size()) - 1;
  };
  std::string line;
  int line_no = 0;
  auto fail = [&](const std::string& what) {
    throw SpeciesFileError(origin + ":" + std::to_string(line_no) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++line_no;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream ls(line);
    std::string directive;
    if (!(ls >> directive)) continue;
    long index;
    std::string name, extra;
    if (!(ls >> index >> name)) fail("expected '" + directive + " <number> <species>'");
    if (ls >> extra) fail("unexpected trailing text '" + extra + "'");
    if (directive == "salesman") {
      if (index < 1 || index > salesmen) fail("salesman " + std::to_string(index) + " outside 1.." + std::to_string(salesmen));
      if (name == "public") fail("a salesman needs a species, not 'public'");
      out.salesman_species[size_t(index - 1)] = species_id(name);
    } else if (directive == "city") {
      if (index < 1 || index > nodes) fail("city " + std::to_string(index) + " outside 1.." + std::to_string(nodes));
      out.node_species[size_t(index - 1)] = name == "public" ? planning::kPublic : species_id(name);
    } else {
      fail("unknown directive '" + directive + "' (salesman, city)");
    }
  }
  if (out.species.empty()) out.species.push_back("default");
  for (auto& s : out.salesman_species)
    if (s < 0) s = 0;
  return out;
}

SpeciesAssignment load_species_file(const std::string& path, int salesmen, int nodes) {
  std::ifstream in(path);
  if (!in) throw SpeciesFileError(path + ": cannot open file");
  return parse_species_file(in, path, salesmen, nodes);
}

}  // namespace hexplore::mtsp
