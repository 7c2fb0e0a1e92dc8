#include "common/radio/wire_units.h"

namespace hexplore::radio {

void write_robot(transport::ByteWriter& w, const transport::Roster* roster, const std::string& id) {
  if (id.empty()) {
    w.varint(0);
    return;
  }
  if (const auto slot = roster != nullptr ? roster->slot(id) : std::nullopt) {
    w.varint(uint64_t{*slot} + 2);
    return;
  }
  w.varint(1);
  w.bytes(id);
}

bool read_robot(transport::ByteReader& r, const transport::Roster* roster, std::string& id) {
  const uint64_t code = r.varint();
  if (r.failed()) return false;
  if (code == 0) {
    id.clear();
    return true;
  }
  if (code == 1) {
    const std::string_view s = r.bytes(128);
    if (r.failed()) return false;
    id.assign(s);
    return true;
  }
  const transport::Roster::Member* m =
      roster != nullptr && code - 2 <= UINT32_MAX ? roster->member(static_cast<uint32_t>(code - 2)) : nullptr;
  if (m == nullptr) return r.fail(), false;
  id = m->id;
  return true;
}

}  // namespace hexplore::radio
