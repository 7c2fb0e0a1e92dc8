"""python3 -m hexplore_client watch|send ... (clients/python/README.md).

Exit codes: 0 done; 1 watch: a robot of the team file was never heard (--once, --duration),
send: no station answered or it refused; 2 bad arguments, team file or missing generated
modules; 3 send: relayed, but the team did not show the command's effect in time.
"""

import argparse
import sys
import time

from .messages import Messages, MissingModules
from .team import TeamFileError, load_team


def parse_args(argv):
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("--config", required=True, help="the team file the team runs with (robots, transport)")
    common.add_argument("--host", help="connect here instead of the team file's transport.host_template")
    common.add_argument("--pb-dir", help="folder of the generated *_pb2.py (default: build/clients/python/hexplore_pb)")
    parser = argparse.ArgumentParser(prog="hexplore_client", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="action", required=True)
    w = sub.add_parser("watch", parents=[common], help="show poses, statuses, planning rounds and topic rates")
    w.add_argument("--period", type=float, default=2.0, help="seconds between two prints (default 2)")
    w.add_argument("--duration", type=float, help="stop after this many seconds (default: until Ctrl-C)")
    w.add_argument("--once", action="store_true", help="listen --window seconds (or --duration), print once, exit")
    w.add_argument("--window", type=float, default=5.0, help="seconds the byte rates average over (default 5)")
    w.add_argument("--json", action="store_true", help="one JSON object per print instead of a table")
    w.add_argument("--all-topics", action="store_true",
                   help="also subscribe to the heavy robot-local topics (scans, voxels, fused maps)")
    s = sub.add_parser("send", parents=[common], help="send a mission command through the station")
    s.add_argument("what", help="start | stop | estop | planner=<name>")
    s.add_argument("--robot", default="", help="address one robot only (default: the whole team)")
    s.add_argument("--timeout", type=float, default=3.0, help="seconds to wait for the station's answer")
    s.add_argument("--confirm-s", type=float, default=5.0,
                   help="seconds to wait for the team to show the command's effect; 0: do not wait")
    args = parser.parse_args(argv)
    for name in ("period", "window", "duration", "timeout", "confirm_s"):
        value = getattr(args, name, None)
        if value is not None and (value < 0 or (value == 0 and name in ("period", "window", "timeout"))):
            parser.error(f"--{name.replace('_', '-')} must be > 0, got {value}")
    return args


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        team = load_team(args.config)
        messages = Messages(args.pb_dir)
        team.endpoint(team.robot_ids[0], "sim", 0, args.host)  # refuses an inproc team early
    except (TeamFileError, MissingModules) as e:
        print(f"hexplore_client: {e}", file=sys.stderr)
        return 2
    try:  # python3-zmq: imported here, so that a missing package is named rather than traced
        from . import command as commands
        from .watch import Watcher, run
    except ImportError as e:
        print(f"hexplore_client: {e} (Debian's python3-zmq is needed: scripts/install_deps.sh)", file=sys.stderr)
        return 2

    if args.action == "watch":
        watcher = Watcher(team, messages, args.host, args.all_topics, args.window)
        duration = args.duration if args.duration is not None else (args.window if args.once else None)
        try:
            return run(watcher, args.period, duration, args.once, args.json)
        except KeyboardInterrupt:
            return 0
        finally:
            watcher.close()

    if args.robot and args.robot not in team.robot_ids:
        print(f"hexplore_client: --robot '{args.robot}' is not in {args.config} ({', '.join(team.robot_ids)})",
              file=sys.stderr)
        return 2
    try:
        command = commands.parse_command(args.what, messages, args.robot)
    except ValueError as e:
        print(f"hexplore_client: {e}", file=sys.stderr)
        return 2
    # Subscribe before sending, so that the team's reaction is not missed while connecting.
    watcher = Watcher(team, messages, args.host) if args.confirm_s > 0 else None
    try:
        if watcher:
            watcher.poll(0.3)  # lets the subscriptions reach the publishers (ZeroMQ's slow joiner)
        sent_at = time.monotonic()
        try:
            detail = commands.send(team, messages, command, args.host, args.timeout)
        except commands.CommandError as e:
            print(f"hexplore_client: {e}", file=sys.stderr)
            return 1
        print(f"station: {detail}")
        if watcher is None:
            return 0
        ok, what, lines = commands.confirm(watcher, command, sent_at, args.confirm_s)
        for line in lines:
            print(f"  {line}")
        if ok:
            print(f"confirmed: {what}")
            return 0
        hint = (" (a planning service ignores a planner name it does not know: see its log)"
                if command.WhichOneof("command") == "switch_planner" else "")
        print(f"hexplore_client: not confirmed within {args.confirm_s:g} s: expected {what}{hint}", file=sys.stderr)
        return 3
    finally:
        if watcher:
            watcher.close()


if __name__ == "__main__":
    sys.exit(main())
