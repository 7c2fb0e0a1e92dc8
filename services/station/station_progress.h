#pragma once
// What a progress display shows of a running mission (StationService::progress()).

namespace hexplore::station_service {

struct StationProgress {
  bool started = false;           // the mission has started
  double mission_time_s = 0.0;    // sim time since the start
  double team_completeness = 0.0; // of the team's union map, at the last snapshot round
  int live_robots = 0;
};

}  // namespace hexplore::station_service
