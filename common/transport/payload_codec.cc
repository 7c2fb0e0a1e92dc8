#include "common/transport/payload_codec.h"

#include <stdexcept>

#include "common/transport/type_id.h"

namespace hexplore::transport {

void CodecTable::add(std::shared_ptr<const PayloadCodec> codec) {
  const uint16_t id = type_id(codec->type());
  if (auto it = codecs_.find(id); it != codecs_.end())
    throw std::invalid_argument("transport: codecs for '" + it->second->type() + "' and '" + codec->type() +
                                "' share type id " + std::to_string(id));
  remember_type_name(codec->type());
  codecs_.emplace(id, std::move(codec));
}

const PayloadCodec* CodecTable::find(uint16_t type_id) const {
  auto it = codecs_.find(type_id);
  return it == codecs_.end() ? nullptr : it->second.get();
}

}  // namespace hexplore::transport
