#pragma once
// The solver's species side file: which species each salesman is and which cities are
// private to a species. Format (one directive per line, '#' starts a comment):
//   salesman <index 1..M> <species name>
//   city <TSPLIB node id> <species name | public>
// Species are numbered in order of first appearance. Errors name the file and line.

#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace hexplore::mtsp {

class SpeciesFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SpeciesAssignment {
  std::vector<std::string> species;  // names, index = species id
  std::vector<int> salesman_species; // per salesman
  std::vector<int> node_species;     // per node (0-based): planning::kPublic or species id
};

// salesmen and nodes give the valid ranges; unlisted salesmen get the first species (or a
// species named "default" when the file names none), unlisted cities are public.
SpeciesAssignment parse_species_file(std::istream& in, const std::string& origin, int salesmen, int nodes);
SpeciesAssignment load_species_file(const std::string& path, int salesmen, int nodes);

}  // namespace hexplore::mtsp
