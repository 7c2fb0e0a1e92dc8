#pragma once
// Compact wire forms of payload types on the team topics. The radio is the scarce link, so a
// team message may travel in a hand-made form (quantised coordinates, delta-coded keys, roster
// slots instead of robot ids) rather than as protobuf; handlers still receive the protobuf
// message. The transport only applies codecs; common/radio holds hexplore's.

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include <google/protobuf/message_lite.h>

#include "common/transport/compression.h"
#include "common/transport/roster.h"

namespace hexplore::transport {

class PayloadCodec {
 public:
  virtual ~PayloadCodec() = default;
  // Full protobuf name of the type this codec is for.
  virtual const std::string& type() const = 0;
  // Appends the compact form of `message` (of type()) to `out`. `roster` may be null.
  virtual void encode(const google::protobuf::MessageLite& message, const Roster* roster, std::string& out) const = 0;
  // Fills `message` (of type(), cleared by the caller) from `data`; false when `data` is not a
  // valid compact form. Must not trust anything in `data`: lengths, counts and indices are
  // checked before use.
  virtual bool decode(std::string_view data, const Roster* roster, google::protobuf::MessageLite& message) const = 0;
  // The dictionary this type's compact form is compressed with on the radio (null: plain zstd).
  virtual const CompressionDictionary* dictionary() const { return nullptr; }
};

// The codecs a socket applies, by wire type id.
class CodecTable {
 public:
  // Throws std::invalid_argument when two codecs share a type id.
  void add(std::shared_ptr<const PayloadCodec> codec);
  const PayloadCodec* find(uint16_t type_id) const;
  size_t size() const { return codecs_.size(); }

 private:
  std::map<uint16_t, std::shared_ptr<const PayloadCodec>> codecs_;
};

}  // namespace hexplore::transport
