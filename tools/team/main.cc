// hexplore_team: a whole team in one process, the reproducible fast mode (the launcher's --compose).
//   hexplore_team --config TEAM.yaml --robot ID [--robot ID ...] [--results DIR] [--log-level L] [...]
// Every service of every listed robot and the station run on their own loop threads over
// inproc transport, in lockstep on sim time (common/service/lockstep_driver.h); the process
// ends when the station ends the mission (or a service fails).
#include "common/service/service.h"
#include "tools/team/team_services.h"

int main(int argc, char** argv) {
  return hexplore::service::run_team_main(argc, argv, hexplore::team::robot_services(),
                                          hexplore::team::station_service());
}
