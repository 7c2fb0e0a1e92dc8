#include "common/transport/payload_wire.h"

#include "common/transport/compression.h"
#include "common/transport/envelope.h"

namespace hexplore::transport {

uint8_t encode_payload(const google::protobuf::MessageLite& message, uint16_t type, bool team_topic,
                       const SocketOptions& options, std::string& out) {
  out.clear();
  uint8_t flags = 0;
  const PayloadCodec* codec = team_topic && options.codecs ? options.codecs->find(type) : nullptr;
  if (codec != nullptr) {
    codec->encode(message, options.roster.get(), out);
    flags |= kPayloadCodec;
  } else {
    message.SerializeToString(&out);
  }
  // Only the radio is worth the CPU: robot-local payloads stay as they are.
  if (team_topic && options.compress_min_bytes > 0 && out.size() >= options.compress_min_bytes) {
    std::string packed;
    const CompressionDictionary* dictionary = codec != nullptr ? codec->dictionary() : nullptr;
    if (dictionary != nullptr)
      dictionary->compress(out, options.compress_level, packed);
    else
      compress(out, options.compress_level, packed);
    if (!packed.empty() && packed.size() < out.size()) {
      out.swap(packed);
      flags |= kPayloadCompressed;
    }
  }
  return flags;
}

bool unpack_payload(std::string_view data, uint8_t flags, uint16_t type, const SocketOptions& options,
                    std::string& scratch, std::string_view& out) {
  if ((flags & kPayloadCompressed) == 0) {
    out = data;
    return true;
  }
  const size_t max_size = static_cast<size_t>(options.max_message_bytes);
  if (frame_dictionary_id(data) != 0) {
    // Compressed with the dictionary of its type's codec; a frame of any other dictionary (a
    // teammate built with another one) does not decompress.
    const PayloadCodec* codec = (flags & kPayloadCodec) && options.codecs ? options.codecs->find(type) : nullptr;
    const CompressionDictionary* dictionary = codec != nullptr ? codec->dictionary() : nullptr;
    if (dictionary == nullptr || !dictionary->decompress(data, max_size, scratch)) return false;
  } else if (!decompress(data, max_size, scratch)) {
    return false;
  }
  out = scratch;
  return true;
}

bool parse_payload(std::string_view bytes, uint8_t flags, uint16_t type, const SocketOptions& options,
                   google::protobuf::MessageLite& message) {
  message.Clear();
  if (flags & kPayloadCodec) {
    const PayloadCodec* codec = options.codecs ? options.codecs->find(type) : nullptr;
    return codec != nullptr && codec->decode(bytes, options.roster.get(), message);
  }
  return message.ParseFromArray(bytes.data(), static_cast<int>(bytes.size()));
}

}  // namespace hexplore::transport
