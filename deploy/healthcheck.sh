#!/bin/bash
# Container health: the service's Prometheus exposer answers GET /metrics with 200 on
# HEXPLORE_METRICS_PORT. Uses bash's /dev/tcp so the slim image needs neither curl nor wget.
port=${HEXPLORE_METRICS_PORT:?HEXPLORE_METRICS_PORT must be the service metrics port}
exec 3<>"/dev/tcp/127.0.0.1/$port" || exit 1
printf 'GET /metrics HTTP/1.0\r\nHost: 127.0.0.1\r\n\r\n' >&3
IFS= read -r -t 3 status <&3 || exit 1
exec 3<&-
case "$status" in
  "HTTP/1."?" 200"*) exit 0 ;;
  *) echo "hexplore-healthcheck: 127.0.0.1:$port answered '$status'" >&2; exit 1 ;;
esac
