#!/usr/bin/env python3
"""Checks that deploy/runtime-packages.txt installs every shared library the service
executables link directly, so the slim image of deploy/Dockerfile cannot miss one.

usage: check_runtime_packages.py [--exact] RUNTIME_PACKAGES_TXT EXECUTABLE...

--exact (given when every service executable is checked): a listed package that no executable
links is an error too, so the slim image stays slim.

For each executable: its direct NEEDED libraries (readelf -d), resolved to paths by ldd, mapped
to their Debian package by dpkg -S. Libraries those packages need in turn arrive through the
packages' own dependencies, so only direct ones are checked. Exit 77 (ctest skip) when no
executable exists yet or the tools are missing.
"""
import os
import re
import shutil
import subprocess
import sys

SKIP = 77
# Present in every Debian image (debian:12-slim included): apt itself needs them.
BASE_PACKAGES = {"libc6", "libstdc++6", "libgcc-s1"}


def read_package_list(path):
    packages = set()
    with open(path) as f:
        for number, line in enumerate(f, start=1):
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            if not re.fullmatch(r"[a-z0-9][a-z0-9+.-]+", line):
                sys.exit(f"{path}:{number}: '{line}' is not a Debian package name (one per line)")
            packages.add(line)
    return packages


def needed_libraries(exe):
    out = subprocess.run(["readelf", "-d", exe], capture_output=True, text=True, check=True).stdout
    return re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", out)


def resolved_paths(exe):
    """soname -> path, from ldd; a missing library is reported right away."""
    out = subprocess.run(["ldd", exe], capture_output=True, text=True, check=True).stdout
    paths = {}
    for line in out.splitlines():
        m = re.match(r"\s*(\S+) => (\S+)", line)
        if m:
            if m.group(2) == "not":
                sys.exit(f"{exe}: ldd cannot resolve {m.group(1)} on this machine")
            paths[m.group(1)] = m.group(2)
            continue
        m = re.match(r"\s*(/\S+) \(0x", line)  # the dynamic loader: listed by path only
        if m:
            paths[os.path.basename(m.group(1))] = m.group(1)
    return paths


def spellings(path):
    """The names dpkg may know `path` by on a /usr-merged system."""
    out = [path, os.path.realpath(path)]
    for p in list(out):
        if p.startswith("/lib"):
            out.append("/usr" + p)
        elif p.startswith("/usr/lib"):
            out.append(p[len("/usr"):])
    return list(dict.fromkeys(out))


def owning_packages(paths):
    """path -> Debian package that installed it (absent when none did); one dpkg call for all."""
    candidates = sorted({c for p in paths for c in spellings(p)})
    r = subprocess.run(["dpkg", "-S"] + candidates, capture_output=True, text=True)
    owner_of = {}
    for line in r.stdout.splitlines():
        # "libzmq5:amd64: /usr/lib/x86_64-linux-gnu/libzmq.so.5"; diversions have other lines.
        if ": /" not in line or line.startswith("diversion"):
            continue
        packages, path = line.split(": /", 1)
        owner_of["/" + path] = packages.split(",")[0].strip().split(":", 1)[0]
    return {p: next((owner_of[c] for c in spellings(p) if c in owner_of), None) for p in paths}


def main(argv):
    exact = "--exact" in argv
    argv = [a for a in argv if a != "--exact"]
    if len(argv) < 2:
        sys.exit(__doc__)
    for tool in ("readelf", "ldd", "dpkg"):
        if not shutil.which(tool):
            print(f"SKIP: {tool} is not installed; cannot check the runtime packages")
            return SKIP
    listed = read_package_list(argv[1])
    executables = [e for e in argv[2:] if os.path.isfile(e)]
    if not executables:
        print("SKIP: no service executable is built yet; nothing to check")
        return SKIP
    required = {}  # package -> [(exe, soname)]
    problems = []
    links = []  # (exe, soname, path)
    for exe in executables:
        paths = resolved_paths(exe)
        for soname in needed_libraries(exe):
            if soname not in paths:
                problems.append(f"{exe}: ldd does not resolve {soname}")
                continue
            links.append((exe, soname, paths[soname]))
    owners = owning_packages({path for _, _, path in links})
    for exe, soname, path in links:
        if owners[path] is None:
            problems.append(f"{exe}: {soname} ({path}) belongs to no Debian package; the image cannot install it")
            continue
        required.setdefault(owners[path], []).append((os.path.basename(exe), soname))
    for package in sorted(set(required) - BASE_PACKAGES - listed):
        users = ", ".join(sorted({f"{exe} needs {so}" for exe, so in required[package]}))
        problems.append(f"{argv[1]}: package '{package}' is missing ({users})")
    if shutil.which("apt-cache"):
        r = subprocess.run(["apt-cache", "show", "--no-all-versions"] + sorted(listed), capture_output=True, text=True)
        known = set(re.findall(r"^Package: (\S+)", r.stdout, re.M))
        for package in sorted(listed - known):
            problems.append(f"{argv[1]}: '{package}' is not a package apt knows on this machine")
    unused = sorted(listed - set(required))
    print(f"checked {len(executables)} executables: {len(required)} packages linked directly "
          f"({', '.join(sorted(required))})")
    if unused and exact:
        problems.append(f"{argv[1]}: no service links {', '.join(unused)}; drop it from the slim image")
    elif unused:
        print(f"note: listed but not linked directly by the checked executables: {', '.join(unused)}")
    if problems:
        print("\n".join(problems), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
