#pragma once
// What teammates decode of a message sent on the radio: the team codec's round trip, or the
// message itself when there is no codec for its type. A sender that also keeps what it sends
// (planning keeps its own team solution as a reference candidate, beside its teammates') keeps
// this copy, so that every robot reasons on the same values: the codecs round coordinates.

#include "common/transport/payload_codec.h"
#include "common/transport/type_id.h"

namespace hexplore::radio {

template <typename M>
M as_received(const M& message, const transport::CodecTable* codecs, const transport::Roster* roster) {
  const transport::PayloadCodec* codec =
      codecs != nullptr ? codecs->find(transport::type_id(M::descriptor()->full_name())) : nullptr;
  if (codec == nullptr) return message;
  std::string wire;
  codec->encode(message, roster, wire);
  M out;
  // A codec always decodes what it encoded; should it not, the original is the better copy.
  if (!codec->decode(wire, roster, out)) return message;
  return out;
}

}  // namespace hexplore::radio
