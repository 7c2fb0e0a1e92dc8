#pragma once
// Every `--key value` option a service reads, in one table. Hosts pass the same options to all
// the services they run (a launcher passes them to every process), so no single service can
// tell a typo from another service's option; the table can. A key no service reads is refused
// before anything runs (`--out DIR` for `--results DIR` used to run a whole mission with its
// results in the default folder), and Options refuses to read a key missing from the table,
// so the services and the table cannot drift apart. One name, one meaning: a key two services
// read is one option they share (--wait-for-start), never two options that happen to collide.

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace hexplore::service {

struct OptionInfo {
  std::string_view name;      // without the dashes
  std::string_view services;  // who reads it: "planning", "planning, safety"
  std::string_view summary;   // one line: what it sets, its unit and default
};

// The table: hexplore's services in alphabetical order, then what add_service_options added.
std::vector<OptionInfo> service_option_catalogue();

// A service built outside this tree (a planner of one's own, the tests' echo service) declares
// its options before its host starts; `options` must outlive the process (string literals).
// A name already in the catalogue is a logic_error: one name, one meaning.
void add_service_options(const std::vector<OptionInfo>& options);

bool is_service_option(std::string_view name);

// Why `name` is refused: "--out is no service's option (did you mean --results?)"; the
// suggestion is the catalogued name nearest by edit distance, when one is near.
std::string unknown_option_message(std::string_view name);

// Throws OptionError (options.h) for the first key of `arguments` that is no service's option.
void require_service_options(const std::map<std::string, std::string>& arguments);

// The table as lines for a --help text: "  --name  (services) summary".
std::string service_options_help();

}  // namespace hexplore::service
