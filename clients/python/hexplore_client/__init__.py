"""hexplore_client: watch a live hexplore team and send it mission commands from Python
(Debian's python3-zmq and python3-protobuf). Run it as `python3 -m hexplore_client`;
clients/python/README.md says what it decodes and what it only counts."""
