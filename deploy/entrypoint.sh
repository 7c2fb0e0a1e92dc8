#!/bin/sh
# Container entry point: starts the service named by HEXPLORE_SERVICE for the robot named by
# HEXPLORE_ROBOT with the team file HEXPLORE_CONFIG; extra arguments go to the service.
set -eu
config=${HEXPLORE_CONFIG:?HEXPLORE_CONFIG must name the team file, e.g. /etc/hexplore/teams/multi-building.yaml}
service=${HEXPLORE_SERVICE:?HEXPLORE_SERVICE must be one of sim, mapping, hlmap, planning, safety, station}
case "$service" in
  station)
    exec hexplore_station --config "$config" "$@" ;;
  sim|mapping|hlmap|planning|safety)
    robot=${HEXPLORE_ROBOT:?HEXPLORE_ROBOT must name a robot id of $config}
    exec "hexplore_$service" --config "$config" --robot "$robot" "$@" ;;
  *)
    echo "hexplore-entrypoint: unknown HEXPLORE_SERVICE '$service' (known: sim, mapping, hlmap, planning, safety, station)" >&2
    exit 64 ;;
esac
