"""The generated *_pb2 modules of proto/ (built into the build tree, never committed) and the
payload types by wire type id."""

import glob
import importlib
import os
import sys

from . import wire

# The build's default output (clients/python/CMakeLists.txt: target hexplore_python_pb).
_DEFAULT_DIR = os.path.join(os.path.dirname(__file__), "..", "..", "..", "build", "clients", "python", "hexplore_pb")


class MissingModules(RuntimeError):
    pass


class Messages:
    """Every hexplore.v1 message class of the generated modules, by name and by type id."""

    def __init__(self, pb_dir=None):
        pb_dir = os.path.abspath(pb_dir or os.environ.get("HEXPLORE_PB_DIR") or _DEFAULT_DIR)
        names = sorted(os.path.basename(p)[:-3] for p in glob.glob(os.path.join(pb_dir, "*_pb2.py")))
        if "mission_pb2" not in names:
            raise MissingModules(f"no generated protobuf modules in {pb_dir}: build them with "
                                 "'ninja hexplore_python_pb' in build/ (or pass --pb-dir / set HEXPLORE_PB_DIR)")
        # protoc writes flat imports ("import geometry_pb2"), so the folder itself goes on the path.
        if pb_dir not in sys.path:
            sys.path.insert(0, pb_dir)
        try:
            modules = [importlib.import_module(n) for n in names]
        except ImportError as e:
            raise MissingModules(f"cannot import the generated modules in {pb_dir}: {e} "
                                 "(Debian's python3-protobuf is needed)") from e
        header = sys.modules.get("header_pb2")
        if header is not None and header.SCHEMA_VERSION_CURRENT != wire.SCHEMA_VERSION:
            raise MissingModules(f"the modules in {pb_dir} speak wire schema {header.SCHEMA_VERSION_CURRENT}, "
                                 f"this client's wire.py reads {wire.SCHEMA_VERSION}: rebuild or update the client")
        self.by_name, self.by_type_id = {}, {}
        for module in modules:
            for name, descriptor in module.DESCRIPTOR.message_types_by_name.items():
                cls = getattr(module, name)
                self.by_name[descriptor.full_name] = cls
                self.by_type_id[wire.type_id(descriptor.full_name)] = cls
        self.pb_dir = pb_dir

    def __getattr__(self, short_name):
        """messages.RobotPose etc."""
        try:
            return self.__dict__["by_name"]["hexplore.v1." + short_name]
        except KeyError:
            raise AttributeError(short_name) from None
