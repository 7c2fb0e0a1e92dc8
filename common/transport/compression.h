#pragma once
// zstd for team payloads that are large enough to gain (map increments, repair snapshots).
// Decompression is bounded: a frame that claims or produces more than the limit is refused,
// so a hostile or corrupt frame cannot make a receiver allocate without bound.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

struct ZSTD_CDict_s;
struct ZSTD_DDict_s;

namespace hexplore::transport {

// The level team payloads are compressed at (SocketOptions::compress_level unless a socket
// says otherwise): they are small, so even the strongest level costs microseconds.
inline constexpr int kTeamCompressLevel = 19;

// Appends the zstd frame of `in` to `out` (level 1..19).
void compress(std::string_view in, int level, std::string& out);
// Replaces `out` with the decompressed `in`; false when `in` is not one complete zstd frame
// or its content exceeds `max_size` bytes.
bool decompress(std::string_view in, size_t max_size, std::string& out);

// The id of the dictionary `frame` was compressed with (0: none, or not a zstd frame).
uint32_t frame_dictionary_id(std::string_view frame);

// A zstd dictionary that both ends of the radio hold, trained on typical payloads of one type.
// A one-second map increment is a kilobyte or two: alone it gives zstd little history to find
// repetition in, and the dictionary supplies what such payloads have in common. Frames
// compressed with it carry its id, and a receiver refuses a frame whose id is not its own.
class CompressionDictionary {
 public:
  // `bytes`: a dictionary as `zstd --train` writes it. Throws std::invalid_argument when it
  // is not one (a raw-content dictionary has no id to check frames against).
  CompressionDictionary(std::string_view bytes, int level);
  ~CompressionDictionary();
  CompressionDictionary(const CompressionDictionary&) = delete;
  CompressionDictionary& operator=(const CompressionDictionary&) = delete;

  uint32_t id() const { return id_; }
  // Appends the zstd frame of `in`, compressed with this dictionary, to `out`. At this
  // dictionary's level the prepared tables are used; another level (1..19) loads it afresh.
  void compress(std::string_view in, int level, std::string& out) const;
  // As transport::decompress, and false when `in` was compressed with another dictionary.
  bool decompress(std::string_view in, size_t max_size, std::string& out) const;

 private:
  std::string bytes_;
  int level_;
  uint32_t id_;
  ZSTD_CDict_s* compress_tables_;
  ZSTD_DDict_s* decompress_tables_;
};

}  // namespace hexplore::transport
