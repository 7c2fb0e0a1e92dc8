#include "common/transport/payload_samples.h"

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <string>

#include "common/transport/payload_codec.h"

namespace hexplore::transport {

void sample_team_payload(const google::protobuf::MessageLite& message, uint16_t type, std::string_view type_name,
                         const SocketOptions& options) {
  static const char* const folder = std::getenv("HEXPLORE_PAYLOAD_SAMPLES");
  if (folder == nullptr || options.codecs == nullptr) return;
  const PayloadCodec* codec = options.codecs->find(type);
  if (codec == nullptr) return;
  static std::atomic<uint64_t> count{0};
  std::string bytes;
  codec->encode(message, options.roster.get(), bytes);
  const std::string path = std::string(folder) + "/" + std::string(type_name) + "-" + std::to_string(getpid()) + "-" +
                           std::to_string(count++) + ".bin";
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace hexplore::transport
