#pragma once
// The payload type on the wire: a 16-bit id instead of the full protobuf name (which alone is
// longer than most team messages). The id is FNV-1a of the full name folded to 16 bits, so
// every build computes the same id without a central table; 0 is reserved for "no payload"
// (a request nobody serves). tests/transport checks that the ids of every hexplore.v1 type
// differ, and remember_type_name() reports a collision the first time one is seen at run time.

#include <cstdint>
#include <string>
#include <string_view>

namespace hexplore::transport {

uint16_t type_id(std::string_view full_name);
// Records `full_name` for type_label(); logs an error once when another name has its id.
void remember_type_name(std::string_view full_name);
// The name recorded for `id`, else "type 0x<id>" (for logs of frames nobody handles).
std::string type_label(uint16_t id);

}  // namespace hexplore::transport
