#include "common/radio/team_codecs.h"

#include "common/radio/fragment_codec.h"
#include "common/radio/map_codec.h"
#include "common/radio/plan_codec.h"
#include "common/radio/pose_codec.h"

namespace hexplore::radio {

std::shared_ptr<const transport::CodecTable> team_codecs(const core::TeamConfig& team) {
  auto table = std::make_shared<transport::CodecTable>();
  table->add(std::make_shared<PoseCodec>());
  table->add(std::make_shared<FragmentCodec>());
  table->add(std::make_shared<MapCodec>(false, team.params.eta_s_m));
  table->add(std::make_shared<MapCodec>(true, team.params.eta_s_m));
  table->add(std::make_shared<PlanCodec>(team.params.eta_s_m));
  return table;
}

}  // namespace hexplore::radio
