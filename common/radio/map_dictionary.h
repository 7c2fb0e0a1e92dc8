#pragma once
// The zstd dictionary of map increments and repair snapshots on the radio
// (dictionaries/map.zdict, compiled in: every robot must hold the same one, and a frame names
// the id of the dictionary it was compressed with). Trained by
// tools/radio/train_map_dictionary.sh on the tuning scenes' increments.

#include "common/transport/compression.h"

namespace hexplore::radio {

const transport::CompressionDictionary& map_dictionary();

}  // namespace hexplore::radio
