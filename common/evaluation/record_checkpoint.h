#pragma once
// The station's checkpoint: its mission record saved in the results folder while the mission
// runs, so that a station restarted mid-mission (a crash, a supervisor's restart) resumes the
// record instead of starting a new one. The team does not need the station to explore; only
// the record would be lost. The file is the proto message v1::StationCheckpoint
// (proto/station.proto), written beside and renamed so that a crash never leaves half a file.

#include <optional>
#include <stdexcept>
#include <string>

#include "common/core/team_config.h"
#include "hexplore/v1/station.pb.h"

namespace hexplore::evaluation {

inline constexpr const char* kCheckpointFileName = "station_checkpoint.pb";

// An unreadable, broken or foreign checkpoint file; the message says which and why.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes `checkpoint` to `path` (beside, then renamed). Throws CheckpointError.
void save_checkpoint(const v1::StationCheckpoint& checkpoint, const std::string& path);

// nullopt when there is no file at `path`. Throws CheckpointError when there is one that cannot
// be read or parsed, or that another format version wrote.
std::optional<v1::StationCheckpoint> load_checkpoint(const std::string& path);

// Why `checkpoint` is not a record of a mission of `team` (another scene, seed or robots); ""
// when it is.
std::string checkpoint_mismatch(const v1::StationCheckpoint& checkpoint, const core::TeamConfig& team);

}  // namespace hexplore::evaluation
