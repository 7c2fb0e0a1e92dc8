#pragma once
// The compact forms of hexplore's team messages (pose, map increment and repair snapshot,
// path fragment, team solution), set up for one team. Every service of a team uses the same
// table (service::ServiceContext), so what one robot encodes every other decodes.

#include <memory>

#include "common/core/team_config.h"
#include "common/transport/payload_codec.h"

namespace hexplore::radio {

std::shared_ptr<const transport::CodecTable> team_codecs(const core::TeamConfig& team);

}  // namespace hexplore::radio
