#pragma once
// transport_bench's wire rows: the bytes one typical team message takes on the radio, as
// schema v1 sent it (topic name, protobuf Header, protobuf payload) and as v2 does (topic
// code, compact header, compact codec form, zstd where it pays).

namespace hexplore::bench {

void print_team_message_bytes();

}  // namespace hexplore::bench
